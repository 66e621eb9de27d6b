// Exact option values and negative numbers after a space (see arguments.hpp).
#include "cli/arguments.hpp"

#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "algorithms/support/progress.hpp"
#include "io/views/standard_views.hpp"

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

Vector3 parse_vector3(const std::string& option, const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    std::size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (parts.size() != 3) throw std::invalid_argument(option + " needs three numbers X,Y,Z, got '" + text + "'");
  Rational c[3];
  for (int i = 0; i < 3; ++i) {
    try {
      c[i] = parse_rational(parts[i]);
    } catch (const NumberError& e) {
      throw std::invalid_argument(option + ": " + e.what());
    }
  }
  return Vector3(c[0], c[1], c[2]);
}

ViewRequest parse_view_request(const std::string& view, const std::string& eye, const std::string& target,
                               const std::string& up, const std::string& up_axis) {
  ViewRequest v;
  auto point = [](const Vector3& x) { return Point3(x.x(), x.y(), x.z()); };
  if (!view.empty()) {
    if (auto named = standard_view(view, up_axis == "z")) {
      v.direction = named->direction;
      if (up.empty()) v.up = named->up;
    } else {
      v.direction = parse_vector3("--view", view);
    }
  }
  if (!eye.empty()) v.eye = point(parse_vector3("--eye", eye));
  if (!target.empty()) v.target = point(parse_vector3("--target", target));
  if (!up.empty()) v.up = parse_vector3("--up", up);
  return v;
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
