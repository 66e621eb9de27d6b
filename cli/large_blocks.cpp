// Large blocks kept for the next large request (see process.hpp; docs/design.md, "Large blocks
// kept"). glibc maps a block over its mmap threshold (32 MiB, the most it allows) on its own and
// unmaps it when it is freed, so the next large array faults and zeroes its pages again: a
// 10M-triangle drawing freed 5.2 GB in such blocks and faulted 7.7 GB for a 3.8 GB peak. The
// program's operator new and sized delete keep up to kSlots freed blocks over the threshold and
// hand the smallest that fits to the next large request, its tail past the request given back
// to the system; for a large request that none fits, the largest kept blocks are freed first
// until they make up its size, so that the new block mostly takes their place. Every block is
// malloc's, so a block freed by any other route
// (free, unsized delete) stays correct. Off until keep_large_blocks() (not under
// HLR_MALLOC=system; sanitizer builds keep their own operator new); the output does not depend
// on it.
#include <malloc.h>
#include <sys/mman.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <new>

#include "cli/process.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define HLR_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
#define HLR_SANITIZED 1
#endif
#endif

namespace {

constexpr std::size_t kLarge = std::size_t{32} << 20;  // glibc's mmap threshold in hlr (process.cpp)
constexpr std::size_t kHuge = std::size_t{2} << 20;    // a transparent huge page
constexpr int kSlots = 8;

std::atomic<bool> keeping{false};
std::mutex guard;
struct Kept {
  void* p;
  std::size_t size;  // malloc_usable_size
};
Kept kept[kSlots];
int count = 0;
std::size_t requests = 0, served = 0;  // large requests, and those served from kept blocks

// The smallest kept block of at least n bytes, its pages past n (from the next huge page on)
// given back; else nullptr, the largest kept blocks freed until they make up n.
void* take(std::size_t n) {
  const std::lock_guard<std::mutex> lock(guard);
  ++requests;
  int best = -1;
  for (int i = 0; i < count; ++i)
    if (kept[i].size >= n && (best < 0 || kept[i].size < kept[best].size)) best = i;
  if (best < 0) {  // the largest kept blocks go back until they make up n
    std::size_t freed = 0;
    while (count > 0 && freed < n) {
      int largest = 0;
      for (int i = 1; i < count; ++i)
        if (kept[i].size > kept[largest].size) largest = i;
      freed += kept[largest].size;
      std::free(kept[largest].p);
      kept[largest] = kept[--count];
    }
    return nullptr;
  }
  ++served;
  Kept k = kept[best];
  kept[best] = kept[--count];
  const auto at = reinterpret_cast<std::uintptr_t>(k.p);
  const std::uintptr_t from = (at + n + kHuge - 1) & ~(kHuge - 1), end = (at + k.size) & ~(kHuge - 1);
  if (end > from) madvise(reinterpret_cast<void*>(from), end - from, MADV_DONTNEED);
  return k.p;
}

bool keep(void* p) {
  const std::lock_guard<std::mutex> lock(guard);
  if (count == kSlots) return false;
  kept[count++] = {p, malloc_usable_size(p)};
  return true;
}

bool malloc_shown() {
  const char* mode = std::getenv("HLR_MALLOC");
  return mode && std::strcmp(mode, "show") == 0;
}

void* allocate(std::size_t n) {
  if (n >= kLarge && keeping.load(std::memory_order_relaxed))
    if (void* p = take(n)) return p;
  for (;;) {
    if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
    const std::new_handler h = std::get_new_handler();
    if (!h) throw std::bad_alloc();
    h();
  }
}

void release(void* p, std::size_t n) noexcept {
  if (p && n >= kLarge && keeping.load(std::memory_order_relaxed) && keep(p)) return;
  std::free(p);
}

}  // namespace

namespace hlr::cli {

void report_large_blocks() {
  if (!malloc_shown()) return;
#ifdef HLR_SANITIZED
  std::fprintf(stderr, "hlr: large blocks: not kept (sanitizer build)\n");
#else
  const std::lock_guard<std::mutex> lock(guard);
  std::fprintf(stderr, "hlr: large blocks: %zu of %zu requests over 32 MiB from kept blocks\n", served, requests);
#endif
}

void keep_large_blocks() {
#ifndef HLR_SANITIZED  // the sanitizers' own operator new must see every block
  const char* mode = std::getenv("HLR_MALLOC");
  if (!(mode && std::strcmp(mode, "system") == 0)) keeping.store(true, std::memory_order_relaxed);
#endif
}

}  // namespace hlr::cli

#ifndef HLR_SANITIZED
void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t n) noexcept { release(p, n); }
void operator delete[](void* p, std::size_t n) noexcept { release(p, n); }
#endif
