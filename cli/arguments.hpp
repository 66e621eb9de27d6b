// Command-line helpers: exact vectors from "X,Y,Z" text, and negative numbers after a space
// (`--view -1,0.25,0.5`), which option parsers otherwise take for options.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "io/views/view_choice.hpp"
#include "kernel/geometry.hpp"

namespace hlr::cli {

/// Options whose value is a vector or number that may start with '-'.
const std::vector<std::string>& value_options();

/// argv with "--opt -1,2,3" joined into "--opt=-1,2,3" for the value options.
std::vector<std::string> join_negative_values(int argc, char** argv);

/// The whole command line (after join_negative_values), kept by main: tile files record it.
void set_command_line(std::vector<std::string> args);
const std::vector<std::string>& command_line();

/// Parses "X,Y,Z" exactly; throws std::invalid_argument naming the option and the bad part.
Vector3 parse_vector3(const std::string& option, const std::string& text);

/// The view of `--view` (a standard view name, with `up_axis` "y" or "z", or a direction),
/// `--eye`, `--target` and `--up` (empty: not given), exactly; shared by render and raster.
ViewRequest parse_view_request(const std::string& view, const std::string& eye, const std::string& target,
                               const std::string& up, const std::string& up_axis);

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
