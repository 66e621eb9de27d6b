// Writing output files so that nothing half-written is ever left behind: the content goes to
// a temporary file in the same folder, which is renamed over the target at the end. On any
// failure the temporary file is removed and OutputError says what went wrong.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace hlr {

class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes `content` to `path` atomically (same-folder temporary file, then rename).
void write_file_atomically(const std::string& path, const std::string& content);
/// The same for content given in consecutive parts (written on all cores, never joined).
void write_file_atomically(const std::string& path, const std::vector<std::string>& parts);

/// A command's output: standard output when `path` is empty or "-", else the file, atomically.
void write_output(const std::string& path, const std::string& content);
void write_output(const std::string& path, const std::vector<std::string>& parts);

}  // namespace hlr
