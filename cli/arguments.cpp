// Exact option values and negative numbers after a space (see arguments.hpp).
#include "cli/arguments.hpp"

#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "algorithms/support/progress.hpp"

namespace hlr::cli {

const std::vector<std::string>& value_options() {
  static const std::vector<std::string> opts = {"--view", "--eye", "--target", "--up", "--width", "--stroke", "--segment", "--near"};
  return opts;
}

std::vector<std::string> join_negative_values(int argc, char** argv) {
  std::vector<std::string> out;
  for (int i = 0; i < argc; ++i) {
    std::string a = argv[i];
    bool is_value_opt = false;
    for (const auto& o : value_options()) is_value_opt = is_value_opt || a == o;
    if (is_value_opt && i + 1 < argc) {
      std::string next = argv[i + 1];
      if (next.size() > 1 && next[0] == '-' && (std::isdigit(static_cast<unsigned char>(next[1])) || next[1] == '.')) {
        out.push_back(a + "=" + next);
        ++i;
        continue;
      }
    }
    out.push_back(a);
  }
  return out;
}

std::string output_format(const std::string& format, const std::string& output,
                          const std::vector<std::pair<std::string, std::string>>& by_extension, const std::string& fallback) {
  if (!format.empty()) return format;
  std::string ext = std::filesystem::path(output).extension().string();
  if (ext.empty()) return fallback;
  std::string lower;
  for (char c : ext) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::string known;
  for (const auto& [e, f] : by_extension) {
    if (lower == e) return f;
    known += (known.empty() ? "" : ", ") + e;
  }
  throw std::invalid_argument("cannot write '" + output + "': unknown output format '" + ext + "' (known: " + known +
                              "; or give --format)");
}

ProgressLine::ProgressLine(const std::string& command, bool progress_flag, bool quiet_flag)
    : on_(!quiet_flag && (progress_flag || isatty(2))) {
  if (!on_) return;
  const bool tty = isatty(2);
  set_progress_sink([command, tty](const std::string& m) {
    if (tty) std::cerr << "\rhlr " << command << ": " << m << "\x1b[K" << std::flush;
    else std::cerr << "hlr " << command << ": " << m << "\n";
  });
}

ProgressLine::~ProgressLine() {
  if (!on_) return;
  set_progress_sink({});
  if (isatty(2)) std::cerr << "\r\x1b[K" << std::flush;
}

namespace {
std::vector<std::string>& stored_command_line() {
  static std::vector<std::string> args;
  return args;
}
}  // namespace

void set_command_line(std::vector<std::string> args) { stored_command_line() = std::move(args); }
const std::vector<std::string>& command_line() { return stored_command_line(); }

}  // namespace hlr::cli
