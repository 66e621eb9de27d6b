// Reading input files: the whole file into memory (with a clear error when it cannot be
// read), and a whitespace token stream with line numbers and '#' comments, used by the OFF,
// OBJ, ASCII STL and ASCII PLY readers.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "io/readers/input_error.hpp"
#include "kernel/number.hpp"

namespace hlr {

/// The largest input file hlr reads (bytes).
inline constexpr std::uintmax_t kMaxInputBytes = std::uintmax_t(4) << 30;

/// The bytes of a file. Throws InputError (missing file, a folder, not a regular file such as
/// /dev/zero, larger than kMaxInputBytes, unreadable).
std::string read_file_bytes(const std::string& path);

class TokenStream {
 public:
  TokenStream(std::string_view text, std::string file, std::size_t offset = 0);
  /// From `offset`, which is on line `line` (no counting: a chunk of a large file).
  TokenStream(std::string_view text, std::string file, std::size_t offset, int line);

  /// Next token; false at the end. `line()` is then the token's line.
  bool next(std::string_view& token);
  /// Next token or an error "unexpected end of file, expected <what>".
  std::string_view expect(const char* what);
  /// Next token as an exact number, or an error naming the token.
  Rational number(const char* what);
  /// The same into an existing number (its storage reused).
  void number_into(const char* what, Rational& out);
  /// Next token as an integer in [lo, hi], or an error.
  long integer(const char* what, long lo, long hi);
  /// Skips what is left of the current token's line.
  void skip_rest_of_line();
  /// True when no token is left.
  bool at_end();
  /// Bytes not yet read (for sanity checks of declared counts).
  std::size_t remaining_bytes() const { return text_.size() - pos_; }
  int line() const { return token_line_; }
  /// Where the stream is: the byte offset and its line.
  std::size_t position() const { return pos_; }
  int position_line() const { return line_; }
  const std::string& file() const { return file_; }
  [[noreturn]] void fail(const std::string& message) const;

 private:
  void skip_space();
  std::string_view text_;
  std::string file_;
  std::size_t pos_;
  int line_ = 1;        // line at pos_
  int token_line_ = 1;  // line of the last token returned
};

}  // namespace hlr
