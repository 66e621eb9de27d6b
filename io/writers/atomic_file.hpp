// Writing output files so that nothing half-written is ever left behind: the content goes to
// a temporary file in the same folder, which is renamed over the target at the end. On any
// failure the temporary file is removed and OutputError says what went wrong.
#pragma once

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace hlr {

class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Text in parts, some made only as they are written (a 1M-triangle drawing's JSON is
/// 335 MB; made as it is written, it is never all in memory). A part is either text or a run
/// of `count` pieces, make(k, out) appending piece k to `out` (empty on entry) for k from 0.
class PartText {
 public:
  using Make = std::function<void(std::size_t k, std::string& out)>;
  PartText() = default;
  PartText(std::string text) { add(std::move(text)); }  // NOLINT: a string is a one-part text
  void add(std::string text);
  /// Text the caller keeps alive until the PartText is written (no copy).
  void add_view(std::string_view text);
  void add_run(std::size_t count, Make make);
  /// Calls sink with the text in order, in batches of views: a text part alone, a run's pieces
  /// a batch at a time, made on all cores into buffers the next batch reuses.
  void for_each_batch(const std::function<void(const std::vector<std::string_view>&)>& sink) const;
  /// The whole text.
  std::string str() const;

 private:
  struct Part {
    std::string text;  // owned, or
    std::string_view borrowed;
    bool owned = true;
    std::size_t count = 0;
    Make make;
  };
  std::vector<Part> parts_;
};

/// Writes `content` to `path` atomically (same-folder temporary file, then rename).
void write_file_atomically(const std::string& path, const std::string& content);
/// The same for content given in consecutive parts (written on all cores, never joined).
void write_file_atomically(const std::string& path, const std::vector<std::string>& parts);
/// The same for a PartText, written as it is made.
void write_file_atomically(const std::string& path, const PartText& text);

/// A command's output: standard output when `path` is empty or "-", else the file, atomically.
void write_output(const std::string& path, const std::string& content);
void write_output(const std::string& path, const std::vector<std::string>& parts);
void write_output(const std::string& path, const PartText& text);

}  // namespace hlr
