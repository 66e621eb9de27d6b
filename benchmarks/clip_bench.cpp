// Segments per second for each clipping method and clipper: exact Cyrus-Beck against a box,
// the notes' viewing pyramid, an octahedron and a 100-sided prism (rational points on the
// circle), and midpoint subdivision (eps 1/1000) against the box and the pyramid. Random
// segments with 2-decimal coordinates, about half crossing the clipper.
// Run: build/benchmarks/clip_bench
#include <benchmark/benchmark.h>

#include <random>

#include "algorithms/clip/cyrus_beck.hpp"
#include "algorithms/clip/midpoint_clip.hpp"

using namespace hlr;

namespace {

std::vector<std::pair<Point3, Point3>> segments(int n) {
  std::mt19937 rng(1);
  std::uniform_int_distribution<int> c(-300, 300);
  std::vector<std::pair<Point3, Point3>> out;
  for (int i = 0; i < n; ++i) {
    auto R = [&] { return rational(c(rng), 100); };
    out.push_back({Point3(R(), R(), R()), Point3(R(), R(), R())});
  }
  return out;
}

ConvexClipper prism(int sides) {  // rational points on the unit circle: ((1-t^2)/(1+t^2), 2t/(1+t^2))
  std::vector<Point3> v;
  for (int k = 0; k < sides; ++k) {
    // t = tan(theta/2) runs over rationals; spread them with a rational map of the angle.
    Rational t = rational(2 * k - sides, sides);  // in [-1, 1): half the circle...
    Rational x = (1 - t * t) / (1 + t * t), y = 2 * t / (1 + t * t);
    v.emplace_back(x * 2, y * 2, -2);
  }
  // ...and the mirrored half for the other side.
  std::size_t half = v.size();
  for (std::size_t k = 0; k < half; ++k) v.emplace_back(-v[k].x(), -v[k].y(), Rational(-2));
  std::vector<Point3> ring(v.begin(), v.end());
  std::vector<Point3> all = ring;
  for (const Point3& p : ring) all.emplace_back(p.x(), p.y(), Rational(2));
  const int n = static_cast<int>(ring.size());
  std::vector<Face> faces;
  Face bottom, top;
  for (int k = 0; k < n; ++k) {
    bottom.push_back(n - 1 - k);
    top.push_back(n + k);
    faces.push_back({k, (k + 1) % n, n + (k + 1) % n, n + k});
  }
  faces.push_back(bottom);
  faces.push_back(top);
  return make_clipper(Polyhedron(all, faces), "prism");
}

template <class F>
void run(benchmark::State& st, F clip) {
  auto segs = segments(4096);
  std::size_t i = 0, visible = 0;
  for (auto _ : st) {
    visible += clip(segs[i % segs.size()].first, segs[i % segs.size()].second);
    ++i;
  }
  st.SetItemsProcessed(st.iterations());
  st.counters["visible_fraction"] = static_cast<double>(visible) / static_cast<double>(std::max<std::size_t>(i, 1));
}

void BM_CyrusBeck_Box(benchmark::State& st) {
  ConvexClipper c = box_clipper(-1, 1, -1, 1, -1, 1);
  run(st, [&](const Point3& a, const Point3& b) { return cyrus_beck(c, a, b, false).visible(); });
}
void BM_CyrusBeck_Frustum(benchmark::State& st) {
  ConvexClipper c = frustum_clipper(-2, 2, -2, 2, 1, -3, 5);
  run(st, [&](const Point3& a, const Point3& b) { return cyrus_beck(c, a, b, false).visible(); });
}
void BM_CyrusBeck_Octahedron(benchmark::State& st) {
  std::vector<Point3> v = {Point3(2, 0, 0), Point3(-2, 0, 0), Point3(0, 2, 0), Point3(0, -2, 0), Point3(0, 0, 2), Point3(0, 0, -2)};
  std::vector<Face> f = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  ConvexClipper c = make_clipper(Polyhedron(v, f), "octahedron");
  run(st, [&](const Point3& a, const Point3& b) { return cyrus_beck(c, a, b, false).visible(); });
}
void BM_CyrusBeck_Prism100(benchmark::State& st) {
  ConvexClipper c = prism(50);
  st.counters["faces"] = static_cast<double>(c.body.num_faces());
  run(st, [&](const Point3& a, const Point3& b) { return cyrus_beck(c, a, b, false).visible(); });
}
void BM_Midpoint_Box(benchmark::State& st) {
  Window w = BoxWindow{-1, 1, -1, 1, -1, 1};
  run(st, [&](const Point3& a, const Point3& b) { return midpoint_clip(w, a, b, rational(1, 1000)).visible; });
}
void BM_Midpoint_Frustum(benchmark::State& st) {
  Window w = FrustumWindow{-2, 2, -2, 2, 1, -3, 5};
  run(st, [&](const Point3& a, const Point3& b) { return midpoint_clip(w, a, b, rational(1, 1000)).visible; });
}

BENCHMARK(BM_CyrusBeck_Box);
BENCHMARK(BM_CyrusBeck_Frustum);
BENCHMARK(BM_CyrusBeck_Octahedron);
BENCHMARK(BM_CyrusBeck_Prism100);
BENCHMARK(BM_Midpoint_Box);
BENCHMARK(BM_Midpoint_Frustum);

}  // namespace

BENCHMARK_MAIN();
