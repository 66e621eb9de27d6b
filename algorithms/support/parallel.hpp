// The one parallel loop of the library (oneTBB underneath): every stage that runs on all
// cores goes through it, so thread counts, chunking and per-thread scratch are handled in one
// place. Results must not depend on the thread count: each index writes only its own output,
// and per-worker scratch (counters, stamps) is combined in worker order afterwards.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace hlr {

class ParallelLoop {
 public:
  /// `threads` = 0: all cores.
  explicit ParallelLoop(unsigned threads = 0);
  ~ParallelLoop();
  ParallelLoop(const ParallelLoop&) = delete;
  ParallelLoop& operator=(const ParallelLoop&) = delete;

  /// Number of worker slots: `worker` passed to the body is below this.
  unsigned workers() const;

  /// Calls body(worker, begin, end) for consecutive ranges covering [0, n), at most `grain`
  /// long, on up to workers() threads; returns when all are done.
  void run(std::size_t n, std::size_t grain, const std::function<void(unsigned worker, std::size_t begin, std::size_t end)>& body) const;

  /// body(i) for every i in [0, n).
  void for_each(std::size_t n, std::size_t grain, const std::function<void(std::size_t i)>& body) const;

 private:
  struct Arena;
  std::unique_ptr<Arena> arena_;
};

/// One T per worker of a loop, each on cache lines of its own: a worker that updates its slot
/// inside a loop does not slow the others by sharing a line with them (false sharing: two
/// workers' adjacent counters made a stage slower on two threads than on one).
template <class T>
class PerWorker {
 public:
  explicit PerWorker(const ParallelLoop& loop, const T& init = T()) : slots_(loop.workers(), Slot{init}) {}
  T& operator[](unsigned w) { return slots_[w].value; }
  const T& operator[](unsigned w) const { return slots_[w].value; }
  unsigned size() const { return static_cast<unsigned>(slots_.size()); }

 private:
  struct alignas(128) Slot {  // two lines: the prefetcher fetches lines in pairs
    T value;
  };
  std::vector<Slot> slots_;
};

/// While it lives, no parallel work of the process (ParallelLoop, parallel sorts, any oneTBB
/// use) runs on more than `threads` threads (0: no limit): `--threads N` of the commands.
class ThreadLimit {
 public:
  explicit ThreadLimit(unsigned threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  struct Control;
  std::unique_ptr<Control> control_;
};

/// Touches every page of [p, p + bytes) on the loop's threads. The system zeroes a fresh page
/// on its first touch, which on virtual machines cost up to a third of a large run; touched
/// here, that work is shared by the cores instead of falling on the one thread that fills a
/// big array in order. Writes zero bytes into raw storage (no object may live there yet).
void touch_pages(void* p, std::size_t bytes, const ParallelLoop& loop);

/// Gives the whole pages inside [p, p + bytes) back to the system (they read as zeros after):
/// for a large array whose front part is spent while what it became is being made, so that the
/// two do not add up at their peak. Only for objects whose all-zero bytes the destructor
/// accepts (moved-from lists, plain records), never read again but as such.
void release_pages(void* p, std::size_t bytes);

/// Gives the whole pages of the heap's free blocks back to the system (glibc's malloc_trim):
/// before a stage of large new arrays, so that the holes earlier stages left (resident, and
/// too small or too late for the new arrays) do not add to the peak beside them. Those pages
/// are zeroed again when reused, so only where the peak is.
void release_free_pages();
/// A stage that makes arrays of at least this many records (a drawing of four million
/// triangles or segments) gives the free pages back first; a smaller one keeps them for its
/// next arrays (reused without the system zeroing them again: a 1M-triangle drawing is faster
/// so, and its peak is far from any limit).
inline constexpr std::size_t kLargeArrays = std::size_t{1} << 22;

/// v.reserve(n), the new storage's pages touched on all cores (touch_pages): for large
/// arrays that one thread then fills or constructs in order.
template <class T>
void reserve_touched(std::vector<T>& v, std::size_t n, const ParallelLoop& loop) {
  if (n <= v.capacity()) return;
  v.reserve(n);
  touch_pages(static_cast<void*>(v.data() + v.size()), (v.capacity() - v.size()) * sizeof(T), loop);
}

class Polyhedron;

/// Every face plane of `p` computed once, on `threads` cores (0: all); before parallel stages
/// that read Polyhedron::planes().
void plane_all_faces(const Polyhedron& p, unsigned threads = 0);

}  // namespace hlr
