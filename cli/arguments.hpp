// Command-line helpers: negative numbers after a space (`--view -1,0.25,0.5`), which option
// parsers otherwise take for options; the output format by extension; the progress line.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace hlr::cli {

/// Options whose value is a vector or number that may start with '-'.
const std::vector<std::string>& value_options();

/// argv with "--opt -1,2,3" joined into "--opt=-1,2,3" for the value options.
std::vector<std::string> join_negative_values(int argc, char** argv);

/// The whole command line (after join_negative_values), kept by main: tile files record it.
void set_command_line(std::vector<std::string> args);
const std::vector<std::string>& command_line();

/// The output format: `format` when given, else from the output file's extension (case does
/// not matter) looked up in `by_extension` ({".json", "json"}, ...), else `fallback` when there
/// is no output file or no extension. An unknown extension is an error naming the file and the
/// known extensions (`-o x.pdf` must not write another format under that name).
std::string output_format(const std::string& format, const std::string& output,
                          const std::vector<std::pair<std::string, std::string>>& by_extension, const std::string& fallback);

/// Progress messages of the library (algorithms/support/progress.hpp) on one line of standard error,
/// "hlr COMMAND: message", while this object lives: when `--progress`, or when standard error
/// is a terminal and not `--quiet`. The line is cleared at the end.
class ProgressLine {
 public:
  ProgressLine(const std::string& command, bool progress_flag, bool quiet_flag);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

 private:
  bool on_ = false;
};

}  // namespace hlr::cli
