// Atomic file output: temporary file in the target's folder, then rename (see atomic_file.hpp).
#include "io/atomic_file.hpp"

#include "algorithms/parallel.hpp"

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

// The content given in consecutive parts.
void write_views_atomically(const std::string& path, const std::vector<std::string_view>& parts) {
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
  // Large outputs in pieces of 1 MiB at most on all cores (the copy into the page cache was a
  // serial 10-20 ms of a 1M-triangle drawing); each piece at its own offset.
  constexpr std::size_t kPiece = std::size_t(1) << 20;  // (4 MiB pieces left one core copying alone)
  struct Piece {
    const char* data;
    std::size_t size, offset;
  };
  std::vector<Piece> list;
  std::size_t offset = 0;
  for (std::string_view part : parts)
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
    if (e != 0) {
      errno = e;
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

void write_file_atomically(const std::string& path, const std::string& content) {
  write_views_atomically(path, std::vector<std::string_view>{content});
}

void write_file_atomically(const std::string& path, const std::vector<std::string>& parts) {
  write_views_atomically(path, std::vector<std::string_view>(parts.begin(), parts.end()));
}

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

}  // namespace hlr
