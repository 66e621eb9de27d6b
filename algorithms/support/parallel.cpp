// The parallel loop (see parallel.hpp) on oneTBB: a task arena limits the threads, a
// blocked range with the caller's grain does the chunking.
#include "algorithms/support/parallel.hpp"

#include <malloc.h>
#include <sys/mman.h>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdint>

#include "kernel/polyhedron.hpp"

namespace hlr {

struct ParallelLoop::Arena {
  tbb::task_arena arena;
  // More threads than cores do not help and make oneTBB warn: at most the default concurrency.
  explicit Arena(unsigned threads)
      : arena(threads ? std::min(static_cast<int>(threads), tbb::info::default_concurrency()) : tbb::task_arena::automatic) {}
};

ParallelLoop::ParallelLoop(unsigned threads) : arena_(std::make_unique<Arena>(threads)) {}
ParallelLoop::~ParallelLoop() = default;

unsigned ParallelLoop::workers() const { return static_cast<unsigned>(arena_->arena.max_concurrency()); }

void ParallelLoop::run(std::size_t n, std::size_t grain,
                       const std::function<void(unsigned, std::size_t, std::size_t)>& body) const {
  if (n == 0) return;
  if (grain == 0) grain = 1;
  if (n <= grain || workers() <= 1) {  // no task overhead for small loops
    for (std::size_t b = 0; b < n; b += grain) body(0, b, std::min(n, b + grain));
    return;
  }
  arena_->arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain), [&](const tbb::blocked_range<std::size_t>& r) {
      int w = tbb::this_task_arena::current_thread_index();
      body(w < 0 ? 0u : static_cast<unsigned>(w), r.begin(), r.end());
    });
  });
}

void ParallelLoop::for_each(std::size_t n, std::size_t grain, const std::function<void(std::size_t)>& body) const {
  run(n, grain, [&](unsigned, std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) body(i);
  });
}

void touch_pages(void* p, std::size_t bytes, const ParallelLoop& loop) {
  constexpr std::size_t kPage = 4096, kBlock = std::size_t{2} << 20;  // a huge page per task
  if (bytes < kBlock) return;  // small: not worth a parallel loop
  auto* c = static_cast<volatile char*>(p);
  loop.run((bytes + kPage - 1) / kPage, kBlock / kPage, [&](unsigned, std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) c[i * kPage] = 0;
  });
}

void release_pages(void* p, std::size_t bytes) {
  constexpr std::uintptr_t kPage = 4096;
  const auto a = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t lo = (a + kPage - 1) & ~(kPage - 1), hi = (a + bytes) & ~(kPage - 1);
  if (hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_DONTNEED);  // (a failure only keeps them)
}

void release_free_pages() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

struct ThreadLimit::Control {
  tbb::global_control control;
  explicit Control(unsigned threads) : control(tbb::global_control::max_allowed_parallelism, threads) {}
};

ThreadLimit::ThreadLimit(unsigned threads) {
  if (threads > 0) control_ = std::make_unique<Control>(threads);
}
ThreadLimit::~ThreadLimit() = default;

void plane_all_faces(const Polyhedron& p, unsigned threads) {
  ParallelLoop loop(threads);
  p.compute_planes([&](std::size_t n, const std::function<void(std::size_t)>& body) { loop.for_each(n, 256, body); });
}

}  // namespace hlr
