// The hlr process (see process.hpp). Exact geometry allocates much (GMP numbers, per-piece
// vectors, strip envelopes): on a machine whose page faults are costly (virtual machines) the
// first touch of fresh memory took half the time of a 1M-triangle render. glibc reads its
// malloc settings only when a process starts, so for a large job the tool sets them and starts
// itself again (one exec: 10-20 ms, an eighth of a small job); a small one sets what mallopt can
// and advises its heap's first 256 MiB itself. The output does not depend on it;
// HLR_MALLOC=system turns it off, =restart and =inprocess choose, =show prints the settings in
// effect (tests/thread_identity.sh). At the end,
// exit_without_teardown() leaves the freeing to the system.
#include "cli/process.hpp"

#include <malloc.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include "kernel/gmp_pool.hpp"

namespace hlr::cli {

namespace {

constexpr std::uintmax_t kSmallJob = std::uintmax_t{8} << 20;  // input bytes: see use_huge_pages
constexpr int kTopPad = 256 << 20;

bool ends_with(const std::string& s, const char* tail) {
  const std::size_t n = std::strlen(tail);
  return s.size() >= n && s.compare(s.size() - n, n, tail) == 0;
}

// The bytes of the mesh files a scene file names (its `mesh:` values, relative to its folder),
// and its own; a name that cannot be read counts nothing (its error comes later). A guess for
// choosing the heap's settings only: scenes over 1 MiB count as large.
std::uintmax_t scene_bytes(const std::string& path, std::uintmax_t own) {
  if (own > (std::uintmax_t{1} << 20)) return kSmallJob + 1;
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  std::uintmax_t bytes = own;
  for (std::size_t at = text.find("mesh"); at != std::string::npos; at = text.find("mesh", at + 4)) {
    std::size_t i = at + 4;
    while (i < text.size() && (text[i] == '"' || text[i] == '\'' || text[i] == ' ' || text[i] == ':')) ++i;
    std::size_t j = i;
    while (j < text.size() && std::strchr("\"'\r\n,}", text[j]) == nullptr) ++j;
    if (j == i || j - i > 4096) continue;
    std::filesystem::path mesh = text.substr(i, j - i);
    while (!mesh.empty() && mesh.string().back() == ' ') mesh = mesh.string().substr(0, mesh.string().size() - 1);
    if (mesh.is_relative()) mesh = dir / mesh;
    struct stat st {};
    if (stat(mesh.c_str(), &st) == 0 && S_ISREG(st.st_mode)) bytes += static_cast<std::uintmax_t>(st.st_size);
  }
  return bytes;
}

// Whether the command line is a small job: a command whose memory follows its input files, and
// input of kSmallJob bytes at most (mesh files, scene files with the meshes they name).
// Existing files only; an output file that already exists counts too (a larger guess, never a
// smaller one).
bool small_job(char** argv) {
  if (!argv[0] || !argv[1]) return true;  // no command: usage
  const std::string command = argv[1];
  if (command != "render" && command != "info" && command != "explain" && command != "clip" && command != "decompose")
    return command.empty() || command[0] == '-';  // --version, --help
  std::uintmax_t bytes = 0;
  for (char** a = argv + 2; *a; ++a) {
    struct stat st {};
    if ((*a)[0] == '-' || stat(*a, &st) != 0 || !S_ISREG(st.st_mode)) continue;
    std::string name = *a;
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const auto own = static_cast<std::uintmax_t>(st.st_size);
    const bool scene = ends_with(name, ".yaml") || ends_with(name, ".yml") || ends_with(name, ".json");
    bytes += scene ? scene_bytes(*a, own) : own;
  }
  return bytes <= kSmallJob;
}

// The restart's settings made with mallopt, and the heap grown once by top_pad and advised onto
// huge pages: what glibc.malloc.hugetlb does as the heap grows, here for its first 256 MiB
// only (the main arena's; the number pool advises its own slabs).
void tune_in_process() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TOP_PAD, kTopPad);
  mallopt(M_TRIM_THRESHOLD, 2147483647);
  const auto before = reinterpret_cast<std::uintptr_t>(sbrk(0));
  void* volatile block = std::malloc(1 << 20);  // volatile: the pair must not be optimised away
  std::free(block);
  const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
  const std::uintptr_t page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const std::uintptr_t lo = (before + page - 1) & ~(page - 1);
  if (after > lo) madvise(reinterpret_cast<void*>(lo), after - lo, MADV_HUGEPAGE);
}

}  // namespace

void use_huge_pages(char** argv) {
  const char* mode = std::getenv("HLR_MALLOC");
  if (mode && std::strcmp(mode, "system") == 0) return;
  const bool show = mode && std::strcmp(mode, "show") == 0;
  const char* old = std::getenv("GLIBC_TUNABLES");
  if (old && std::strstr(old, "glibc.malloc.hugetlb")) {  // set by the user, or by the restart
    if (show) std::fprintf(stderr, "hlr: GLIBC_TUNABLES=%s\n", old);
    return;
  }
  if ((mode && std::strcmp(mode, "inprocess") == 0) || ((!mode || show) && small_job(argv))) {
    tune_in_process();
    if (show) std::fprintf(stderr, "hlr: in process: mmap_threshold=33554432 top_pad=268435456 trim_threshold=2147483647, heap advised\n");
    return;
  }
  // hugetlb=1: madvise(MADV_HUGEPAGE) on the heap as it grows; top_pad: grow it 256 MiB at a
  // time (address space; pages are touched only when used); trim_threshold: never give freed
  // memory back to the system mid-run (zeroing it again when it returns cost a third of the
  // horizon's time); mmap_threshold: blocks up to 32 MiB (the largest it takes) from the heap;
  // mmap_max=0: larger blocks too (the main thread's), so that a stage's freed arrays are the
  // next stage's without the system zeroing them again (10M triangles: 7.5 -> 3.7 GB faulted).
  std::string tunables =
      "glibc.malloc.hugetlb=1:glibc.malloc.top_pad=268435456:glibc.malloc.trim_threshold=4294967295:"
      "glibc.malloc.mmap_threshold=33554432:glibc.malloc.mmap_max=0";
  if (old && *old) tunables = std::string(old) + ":" + tunables;
  if (setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
  unsetenv("GLIBC_TUNABLES");  // the restart failed: go on as we are
  if (old) setenv("GLIBC_TUNABLES", old, 1);
}

#if defined(__SANITIZE_ADDRESS__)
#define HLR_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
#define HLR_SANITIZED 1
#endif
#endif

void use_number_pool() {
#ifndef HLR_SANITIZED  // AddressSanitizer must see every GMP block on its own
  const char* mode = std::getenv("HLR_MALLOC");
  if (mode && std::strcmp(mode, "system") == 0) return;
  gmp_pool::install(true);
#endif
}

void report_arithmetic_faults() {
#ifndef HLR_SANITIZED  // the sanitizers report a fault with its stack themselves
  struct sigaction action {};
  action.sa_handler = [](int) {
    static const char message[] =
        "hlr: internal error: an arithmetic fault (a number that is not finite reached an exact conversion, or a division by "
        "zero); no file was written. Please report it with the command line.\n";
    const ssize_t written = write(STDERR_FILENO, message, sizeof(message) - 1);
    (void)written;
    _exit(1);
  };
  sigemptyset(&action.sa_mask);
  sigaction(SIGFPE, &action, nullptr);
#endif
}

void exit_without_teardown(int code) {
#ifdef HLR_SANITIZED
  (void)code;
#else
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  std::_Exit(code);
#endif
}

}  // namespace hlr::cli
