// The parallel loop and the process-wide thread limit (algorithms/parallel.hpp; issue 14):
// `--threads 1` must mean one thread for every stage, sorts and readers included.
#include <gtest/gtest.h>

#include <algorithm>
#include <execution>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "algorithms/parallel.hpp"

using namespace hlr;

namespace {

std::size_t threads_used(unsigned loop_threads) {
  std::mutex m;
  std::set<std::thread::id> ids;
  ParallelLoop(loop_threads).for_each(20000, 16, [&](std::size_t) {
    volatile double x = 0;
    for (int k = 0; k < 2000; ++k) x = x + k;  // enough work for the workers to join in
    std::lock_guard<std::mutex> g(m);
    ids.insert(std::this_thread::get_id());
  });
  return ids.size();
}

TEST(Parallel, ThreadLimitHoldsEveryLoop) {
  {
    const ThreadLimit one(1);
    EXPECT_EQ(threads_used(0), 1u);  // a loop asking for all cores
    EXPECT_EQ(threads_used(8), 1u);
  }
  if (std::thread::hardware_concurrency() >= 2) EXPECT_GE(threads_used(0), 2u) << "without the limit, more cores work";
}

TEST(Parallel, EveryIndexOnceInOrderOfRanges) {
  std::vector<int> seen(100003, 0);
  ParallelLoop(0).for_each(seen.size(), 97, [&](std::size_t i) { ++seen[i]; });
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
}

}  // namespace
