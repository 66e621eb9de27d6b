// Roberts' algorithm on n random boxes (n = 10, 100, 1000, 10000), view (1, 1.3, 1.7): time,
// heap held by the result, (edge, body) pairs tested and skipped by the pre-filter, and how
// the time grows with n. Boxes are placed at constant density (the region grows as n^(1/3)),
// with 1-decimal coordinates, so some interpenetrate.
// Run: build/benchmarks/roberts_bench
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <cmath>
#include <random>

#include "algorithms/hlr/roberts.hpp"
#include "io/readers/scene.hpp"

using namespace hlr;

namespace {

std::vector<Polyhedron> random_boxes(int n) {
  std::mt19937 rng(7);
  const int side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(n)) * 40));  // tenths
  std::uniform_int_distribution<int> pos(0, side), size(5, 25);
  std::vector<Polyhedron> boxes;
  for (int i = 0; i < n; ++i) {
    int x = pos(rng), y = pos(rng), z = pos(rng);
    boxes.push_back(make_box(Point3(rational(x, 10), rational(y, 10), rational(z, 10)),
                             Point3(rational(x + size(rng), 10), rational(y + size(rng), 10), rational(z + size(rng), 10))));
  }
  return boxes;
}

void BM_RobertsRandomBoxes(benchmark::State& st) {
  std::vector<Polyhedron> boxes = random_boxes(static_cast<int>(st.range(0)));
  std::vector<const Polyhedron*> ptrs;
  for (auto& b : boxes) ptrs.push_back(&b);
  Camera cam = make_orthographic(Vector3(1, rational(13, 10), rational(17, 10)));
  DrawingStats stats;
  std::size_t heap = 0, segments = 0, hidden = 0;
  for (auto _ : st) {
    malloc_trim(0);
    std::size_t before = mallinfo2().uordblks;
    RobertsResult r = roberts(ptrs, cam);
    heap = mallinfo2().uordblks - before;
    stats = r.stats;
    segments = r.segments.size();
    hidden = 0;
    for (const auto& s : r.segments)
      for (const auto& p : s.pieces) hidden += !p.visible;
  }
  st.counters["segments"] = static_cast<double>(segments);
  st.counters["hidden_pieces"] = static_cast<double>(hidden);
  st.counters["junctions"] = static_cast<double>(stats.intersection_segments);
  st.counters["pairs_tested"] = static_cast<double>(stats.pairs_tested);
  st.counters["pairs_skipped"] = static_cast<double>(stats.pairs_skipped);
  st.counters["pairs_rational"] = static_cast<double>(stats.pairs_rational);
  st.counters["result_MB"] = static_cast<double>(heap) / 1e6;
  st.SetComplexityN(st.range(0));
}
BENCHMARK(BM_RobertsRandomBoxes)->RangeMultiplier(10)->Range(10, 10000)->Unit(benchmark::kMillisecond)->Iterations(1)->Complexity();

}  // namespace

BENCHMARK_MAIN();
