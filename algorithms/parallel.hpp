// The one parallel loop of the library (oneTBB underneath): every stage that runs on all
// cores goes through it, so thread counts, chunking and per-thread scratch are handled in one
// place. Results must not depend on the thread count: each index writes only its own output,
// and per-worker scratch (counters, stamps) is combined in worker order afterwards.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>

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

class Polyhedron;

/// Every face plane of `p` computed once, on `threads` cores (0: all); before parallel stages
/// that read Polyhedron::planes().
void plane_all_faces(const Polyhedron& p, unsigned threads = 0);

}  // namespace hlr
