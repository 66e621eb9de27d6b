// Atomic file output: temporary file in the target's folder, then rename (see atomic_file.hpp).
#include "io/writers/atomic_file.hpp"

#include "algorithms/support/parallel.hpp"

#include <iostream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string_view>
#include <vector>

namespace hlr {
namespace {

// The temporary file being written, removed if the process is interrupted (SIGINT, SIGTERM,
// SIGHUP) before the rename. A SIGKILL cannot be caught: the temporary file is then left, with
// a name that says what it is (.NAME.tmp-XXXXXX beside NAME), and never the target itself.
char g_temp[4096] = {0};
volatile std::sig_atomic_t g_temp_active = 0;

extern "C" void remove_temp_and_reraise(int sig) {
  if (g_temp_active) ::unlink(g_temp);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void install_handlers() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction sa {};
    sa.sa_handler = remove_temp_and_reraise;
    sigemptyset(&sa.sa_mask);
    ::sigaction(sig, &sa, nullptr);
  }
}

// Writes `views` at `offset` of `fd`, in pieces of 1 MiB at most on all cores (the copy into
// the page cache was a serial 10-20 ms of a 1M-triangle drawing); each piece at its own
// offset. Returns 0 or the first error's errno.
int write_views(int fd, const std::vector<std::string_view>& views, std::size_t offset) {
  constexpr std::size_t kPiece = std::size_t(1) << 20;  // (4 MiB pieces left one core copying alone)
  struct Piece {
    const char* data;
    std::size_t size, offset;
  };
  std::vector<Piece> list;
  for (std::string_view part : views)
    for (std::size_t at = 0; at < part.size(); at += kPiece) {
      const std::size_t n = std::min(kPiece, part.size() - at);
      list.push_back({part.data() + at, n, offset});
      offset += n;
    }
  const std::size_t pieces = list.size();
  std::vector<int> error(pieces, 0);
  auto write_piece = [&](std::size_t k) {
    std::size_t at = 0;
    const std::size_t end = list[k].size;
    while (at < end) {
      const ssize_t n = ::pwrite(fd, list[k].data + at, end - at, static_cast<off_t>(list[k].offset + at));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        error[k] = n < 0 ? errno : EIO;
        return;
      }
      at += static_cast<std::size_t>(n);
    }
  };
  if (pieces > 1) ParallelLoop().for_each(pieces, 1, write_piece);
  else if (pieces == 1) write_piece(0);
  for (int e : error)
    if (e != 0) return e;
  return 0;
}

// The text, batch by batch, to a temporary file renamed over `path`.
void write_text_atomically(const std::string& path, const PartText& text) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const std::string what = std::string("cannot write ").append(path);
  if (fs::is_directory(path, ec)) throw OutputError(what + ": it is a directory");
  fs::path target(path);
  fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::string base = target.filename().string();
  base.insert(0, 1, '.');
  base.append(".tmp-XXXXXX");
  std::string tmpl = (dir / base).string();
  std::vector<char> name(tmpl.begin(), tmpl.end());
  name.push_back('\0');
  install_handlers();
  int fd = ::mkstemp(name.data());
  if (fd < 0) throw OutputError(what + ": " + std::strerror(errno));
  const std::string tmp(name.data());
  if (tmp.size() < sizeof g_temp) {
    std::memcpy(g_temp, tmp.c_str(), tmp.size() + 1);
    g_temp_active = 1;
  }
  struct Done {
    ~Done() { g_temp_active = 0; }
  } guard;
  auto fail = [&](const std::string& step) {
    int err = errno;
    ::close(fd);
    ::unlink(tmp.c_str());
    throw OutputError(what + ": " + step + ": " + std::strerror(err));
  };
  std::size_t offset = 0;
  int error = 0;
  try {
    text.for_each_batch([&](const std::vector<std::string_view>& views) {
      if (error) return;
      error = write_views(fd, views, offset);
      for (std::string_view v : views) offset += v.size();
    });
  } catch (...) {  // the text could not be made: no file
    ::close(fd);
    ::unlink(tmp.c_str());
    throw;
  }
  if (error) {
    errno = error;
    fail("write failed");
  }
  ::fchmod(fd, 0644);
  if (::fsync(fd) != 0 && errno != EINVAL) fail("fsync failed");
  if (::close(fd) != 0) {
    ::unlink(tmp.c_str());
    throw OutputError(what + ": close failed");
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    int err = errno;
    ::unlink(tmp.c_str());
    throw OutputError(what + ": " + std::strerror(err));
  }
}

}  // namespace

void PartText::add(std::string text) { parts_.push_back(Part{std::move(text), {}, true, 0, nullptr}); }

void PartText::add_view(std::string_view text) { parts_.push_back(Part{std::string(), text, false, 0, nullptr}); }

void PartText::add_run(std::size_t count, Make make) { parts_.push_back(Part{std::string(), {}, true, count, std::move(make)}); }

void PartText::for_each_batch(const std::function<void(const std::vector<std::string_view>&)>& sink) const {
  std::vector<std::string> buffers;
  for (const Part& p : parts_) {
    if (!p.make) {
      const std::string_view text = p.owned ? std::string_view(p.text) : p.borrowed;
      if (!text.empty()) sink({text});
      continue;
    }
    const ParallelLoop loop;
    const std::size_t batch = std::min<std::size_t>(p.count, 8 * std::size_t{loop.workers()});
    buffers.resize(std::max(buffers.size(), batch));
    std::size_t most = 0;  // the longest piece so far
    for (std::size_t b = 0; b < p.count; b += batch) {
      const std::size_t n = std::min(batch, p.count - b);
      // The buffers grow here, on the calling thread, before the workers fill them: grown by
      // the workers, they came from each worker's own malloc arena, whose fresh pages (huge
      // pages for a large job) stayed resident.
      for (std::size_t i = 0; i < n; ++i) buffers[i].reserve(most + most / 4);
      loop.for_each(n, 1, [&](std::size_t i) {
        buffers[i].clear();
        p.make(b + i, buffers[i]);
      });
      std::vector<std::string_view> views;
      for (std::size_t i = 0; i < n; ++i) {
        most = std::max(most, buffers[i].size());
        if (!buffers[i].empty()) views.emplace_back(buffers[i]);
      }
      if (!views.empty()) sink(views);
    }
  }
}

std::string PartText::str() const {
  std::string out;
  for_each_batch([&](const std::vector<std::string_view>& views) {
    for (std::string_view v : views) out.append(v);
  });
  return out;
}

void write_file_atomically(const std::string& path, const std::string& content) {
  PartText text;
  text.add_view(content);
  write_text_atomically(path, text);
}

void write_file_atomically(const std::string& path, const std::vector<std::string>& parts) {
  PartText text;
  for (const std::string& p : parts) text.add_view(p);
  write_text_atomically(path, text);
}

void write_file_atomically(const std::string& path, const PartText& text) { write_text_atomically(path, text); }

void write_output(const std::string& path, const std::string& content) {
  if (path.empty() || path == "-")
    std::cout << content;
  else
    write_file_atomically(path, content);
}

void write_output(const std::string& path, const std::vector<std::string>& parts) {
  if (path.empty() || path == "-")
    for (const std::string& part : parts) std::cout << part;
  else
    write_file_atomically(path, parts);
}

void write_output(const std::string& path, const PartText& text) {
  if (path.empty() || path == "-")
    text.for_each_batch([](const std::vector<std::string_view>& views) {
      for (std::string_view v : views) std::cout << v;
    });
  else
    write_file_atomically(path, text);
}

}  // namespace hlr
