// Small-number storage for GMP: see gmp_pool.hpp (course notes section 19).
#include "kernel/gmp_pool.hpp"

#include <gmp.h>
#include <sys/mman.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace hlr::gmp_pool {
namespace {

constexpr int kClasses = 4;                               // blocks of 8, 16, 24 and 32 bytes
constexpr std::size_t kMaxBlock = 8 * kClasses;
constexpr int kRangeShift = 34;                           // 16 GiB of addresses per class
constexpr std::size_t kRange = std::size_t{1} << kRangeShift;
constexpr std::size_t kChunk = std::size_t{2} << 20;      // a thread takes 2 MiB at a time
constexpr std::size_t kHugeAfter = std::size_t{16} << 20; // huge pages once a class passed 16 MiB

std::uintptr_t g_base = 0;  // 0: not installed
bool g_huge = false;
std::atomic<std::size_t> g_used[kClasses];

struct Local {
  char* bump;
  char* end;
  void* free;
};
thread_local Local t_local[kClasses];

[[noreturn]] void out_of_memory(std::size_t n) {
  std::fprintf(stderr, "hlr: out of memory (GMP asked for %zu bytes)\n", n);
  std::abort();  // what GMP's own allocator does
}

void* system_alloc(std::size_t n) {
  void* p = std::malloc(n == 0 ? 1 : n);
  if (!p) out_of_memory(n);
  return p;
}

inline std::size_t block_size(int c) { return std::size_t(8) * static_cast<std::size_t>(c + 1); }

// A new chunk for class c into this thread's bump range; false when the class's range is full.
bool refill(int c) {
  std::size_t at = g_used[c].fetch_add(kChunk, std::memory_order_relaxed);
  if (at + kChunk > kRange) return false;
  char* chunk = reinterpret_cast<char*>(g_base + (static_cast<std::uintptr_t>(c) << kRangeShift) + at);
  if (g_huge && at >= kHugeAfter) madvise(chunk, kChunk, MADV_HUGEPAGE);
  t_local[c].bump = chunk;
  t_local[c].end = chunk + kChunk - kChunk % block_size(c);
  return true;
}

void* pool_alloc(std::size_t n) {
  if (n == 0 || n > kMaxBlock) return system_alloc(n);
  int c = static_cast<int>((n - 1) >> 3);
  Local& l = t_local[c];
  if (l.free) {
    void* p = l.free;
    l.free = *static_cast<void**>(p);
    return p;
  }
  if (l.bump == l.end && !refill(c)) return system_alloc(n);
  void* p = l.bump;
  l.bump += block_size(c);
  return p;
}

// The class of a pool block, or -1 for memory from malloc.
inline int class_of(const void* p) {
  std::uintptr_t off = reinterpret_cast<std::uintptr_t>(p) - g_base;
  return off < kRange * kClasses ? static_cast<int>(off >> kRangeShift) : -1;
}

void pool_free(void* p, std::size_t) {
  int c = class_of(p);
  if (c < 0) {
    std::free(p);
    return;
  }
  *static_cast<void**>(p) = t_local[c].free;
  t_local[c].free = p;
}

void* pool_realloc(void* p, std::size_t, std::size_t n) {
  int c = class_of(p);
  if (c < 0) {
    void* q = std::realloc(p, n == 0 ? 1 : n);
    if (!q) out_of_memory(n);
    return q;
  }
  std::size_t have = block_size(c);
  if (n <= have) return p;
  void* q = pool_alloc(n);
  std::memcpy(q, p, have);  // the block holds `have` bytes, q at least n > have
  pool_free(p, have);
  return q;
}

}  // namespace

bool install(bool huge_pages) {
  if (g_base) return true;
  // One more chunk than needed, so that the ranges start on a chunk (huge-page) boundary.
  void* r = mmap(nullptr, kRange * kClasses + kChunk, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE,
                 -1, 0);
  if (r == MAP_FAILED) return false;
  g_base = (reinterpret_cast<std::uintptr_t>(r) + kChunk - 1) & ~static_cast<std::uintptr_t>(kChunk - 1);
  g_huge = huge_pages;
  mp_set_memory_functions(pool_alloc, pool_realloc, pool_free);
  return true;
}

bool installed() { return g_base != 0; }

std::size_t reserved_bytes() {
  std::size_t s = 0;
  for (const auto& u : g_used) s += std::min(u.load(std::memory_order_relaxed), kRange);
  return s;
}

}  // namespace hlr::gmp_pool
