// File bytes and a token stream with line numbers (see text_reader.hpp).
#include "io/readers/text_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>

#include <fcntl.h>
#include <unistd.h>

#include "algorithms/support/parallel.hpp"

namespace hlr {
namespace {

// A large regular file read in pieces on all cores (the kernel's copy was a serial 20 ms of a
// 40 MB mesh). nullopt when anything is unusual (a short read: the file changed; more bytes
// past `size`: it grew), and the caller reads it in order.
std::optional<std::string> read_in_parallel(const std::string& path, std::size_t size) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  struct Close {
    int fd;
    ~Close() { ::close(fd); }
  } close_it{fd};
  const ParallelLoop loop;
  std::string out;
  out.reserve(size);
  touch_pages(out.data(), size, loop);  // fresh pages zeroed on all cores, not by the resize alone
  out.resize(size);
  constexpr std::size_t kPiece = std::size_t(4) << 20;
  const std::size_t pieces = (size + kPiece - 1) / kPiece;
  std::vector<char> ok(pieces, 1);
  loop.for_each(pieces, 1, [&](std::size_t k) {
    std::size_t at = k * kPiece;
    const std::size_t end = std::min(size, at + kPiece);
    while (at < end) {
      const ssize_t n = ::pread(fd, out.data() + at, end - at, static_cast<off_t>(at));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        ok[k] = 0;
        return;
      }
      at += static_cast<std::size_t>(n);
    }
  });
  if (std::find(ok.begin(), ok.end(), 0) != ok.end()) return std::nullopt;
  char probe;
  if (::pread(fd, &probe, 1, static_cast<off_t>(size)) != 0) return std::nullopt;
  return out;
}

}  // namespace

std::string read_file_bytes(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, 0, "is a directory, not a file");
  auto status = std::filesystem::status(path, ec);
  if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw InputError(path, 0, "is not a regular file");
  if (!ec && std::filesystem::exists(status) && std::filesystem::file_size(path, ec) > kMaxInputBytes)
    throw InputError(path, 0, "is larger than " + std::to_string(kMaxInputBytes >> 30) + " GiB, the most hlr reads");
  if (!ec && std::filesystem::is_regular_file(status)) {
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size >= (std::uintmax_t(16) << 20))
      if (auto bytes = read_in_parallel(path, static_cast<std::size_t>(size))) return std::move(*bytes);
    ec.clear();
  }
  // One read into a string of the file's size (a stream copy grew its buffer by doubling and
  // copied 38 MB several times), then whatever more there is (a file still growing, a pipe).
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!in) throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  std::uintmax_t size = !ec && std::filesystem::is_regular_file(status) ? std::filesystem::file_size(path, ec) : 0;
  if (ec) size = 0;
  std::string out(static_cast<std::size_t>(size), '\0');
  std::size_t got = size > 0 ? std::fread(out.data(), 1, out.size(), in.get()) : 0;
  out.resize(got);
  char buf[1 << 16];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, in.get())) > 0;) {
    if (out.size() + n > kMaxInputBytes) throw InputError(path, 0, "is larger than " + std::to_string(kMaxInputBytes >> 30) + " GiB, the most hlr reads");
    out.append(buf, n);
  }
  if (std::ferror(in.get())) throw InputError(path, 0, "read error");
  return out;
}

TokenStream::TokenStream(std::string_view text, std::string file, std::size_t offset)
    : text_(text), file_(std::move(file)), pos_(offset) {
  for (std::size_t i = 0; i < offset && i < text.size(); ++i)
    if (text[i] == '\n') ++line_;
}

TokenStream::TokenStream(std::string_view text, std::string file, std::size_t offset, int line)
    : text_(text), file_(std::move(file)), pos_(offset), line_(line), token_line_(line) {}

void TokenStream::skip_space() {
  while (pos_ < text_.size()) {
    char c = text_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++pos_;
    } else if (c == '#') {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else {
      break;
    }
  }
}

bool TokenStream::next(std::string_view& token) {
  skip_space();
  if (pos_ >= text_.size()) {
    token_line_ = line_;
    return false;
  }
  std::size_t start = pos_;
  while (pos_ < text_.size()) {
    char c = text_[pos_];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v' || c == '#') break;
    ++pos_;
  }
  token = text_.substr(start, pos_ - start);
  token_line_ = line_;
  return true;
}

bool TokenStream::at_end() {
  skip_space();
  return pos_ >= text_.size();
}

std::string_view TokenStream::expect(const char* what) {
  std::string_view t;
  if (!next(t)) fail(std::string("unexpected end of file, expected ") + what);
  return t;
}

Rational TokenStream::number(const char* what) {
  std::string_view t = expect(what);
  try {
    return parse_rational(t);
  } catch (const NumberError& e) {
    fail(std::string(what) + ": " + e.what());
  }
}

void TokenStream::number_into(const char* what, Rational& out) {
  std::string_view t = expect(what);
  try {
    parse_rational_into(t, out);
  } catch (const NumberError& e) {
    fail(std::string(what) + ": " + e.what());
  }
}

long TokenStream::integer(const char* what, long lo, long hi) {
  std::string_view t = expect(what);
  std::size_t i = 0;
  bool neg = false;
  if (i < t.size() && (t[i] == '-' || t[i] == '+')) neg = t[i++] == '-';
  if (i == t.size()) fail(std::string(what) + ": '" + std::string(t) + "' is not an integer");
  long v = 0;
  const std::size_t first_digit = i;
  for (; i < t.size(); ++i) {
    if (t[i] < '0' || t[i] > '9')
      fail(std::string(what) + ": '" + std::string(t.substr(0, 40)) + "' is not an integer");
    // 18 digits always fit in a long; more are out of every range used here.
    if (i - first_digit >= 18) fail(std::string(what) + " " + std::string(t.substr(0, 40)) + " is out of range");
    v = v * 10 + (t[i] - '0');
  }
  if (neg) v = -v;
  if (v < lo || v > hi)
    fail(std::string(what) + " " + std::string(t) + " is out of range [" + std::to_string(lo) + ", " +
         std::to_string(hi) + "]");
  return v;
}

void TokenStream::skip_rest_of_line() {
  while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
}

void TokenStream::fail(const std::string& message) const { throw InputError(file_, token_line_, message); }

}  // namespace hlr
