// The hlr process (see process.hpp). Exact geometry allocates much (GMP numbers, per-piece
// vectors, strip envelopes): on a machine whose page faults are costly (virtual machines) the
// first touch of fresh memory took half the time of a 1M-triangle render. glibc reads its
// malloc settings only when a process starts, so the tool sets them and starts itself again
// (one exec, a few milliseconds). The output does not depend on it; HLR_MALLOC=system turns it
// off, HLR_MALLOC=show prints the settings in effect (tests/thread_identity.sh). At the end,
// exit_without_teardown() leaves the freeing to the system.
#include "cli/process.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include "kernel/gmp_pool.hpp"

namespace hlr::cli {

void use_huge_pages(char** argv) {
  const char* mode = std::getenv("HLR_MALLOC");
  if (mode && std::strcmp(mode, "system") == 0) return;
  const char* old = std::getenv("GLIBC_TUNABLES");
  if (old && std::strstr(old, "glibc.malloc.hugetlb")) {  // set by the user, or by the restart
    if (mode && std::strcmp(mode, "show") == 0) std::fprintf(stderr, "hlr: GLIBC_TUNABLES=%s\n", old);
    return;
  }
  // hugetlb=1: madvise(MADV_HUGEPAGE) on the heap as it grows; top_pad: grow it 256 MiB at a
  // time (address space; pages are touched only when used); trim_threshold: never give freed
  // memory back to the system mid-run (zeroing it again when it returns cost a third of the
  // horizon's time); mmap_threshold: blocks up to 32 MiB (the largest it takes) from the heap.
  std::string tunables =
      "glibc.malloc.hugetlb=1:glibc.malloc.top_pad=268435456:glibc.malloc.trim_threshold=4294967295:"
      "glibc.malloc.mmap_threshold=33554432";
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
