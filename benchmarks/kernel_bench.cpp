// Kernel choice: throughput of the orientation predicate and memory per point for
//  - hlr::Point3: exact rationals with certified double bounds cached beside them, interval
//    filter (CGAL::Interval_nt) then exact fallback (what exact-hlr uses);
//  - CGAL Epeck (lazy exact, filtered), points built from the same rationals;
//  - plain rationals (no filter);
//  - CGAL Epick on the nearest doubles, for reference only: it cannot represent 0.1 exactly.
// Inputs are decimals with 6 digits, as in mesh files, and a degenerate (coplanar) set where
// every filter fails. Run: build/benchmarks/kernel_bench
#include <benchmark/benchmark.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <malloc.h>

#include <random>

#include "kernel/epeck_bridge.hpp"
#include "kernel/predicates.hpp"

using namespace hlr;

namespace {

std::vector<Point3> random_points(std::size_t n, bool coplanar) {
  std::mt19937_64 rng(42);
  std::uniform_int_distribution<long> d(-1000000, 1000000);
  std::vector<Point3> pts;
  pts.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    Rational x(d(rng), 1000000), y(d(rng), 1000000), z(d(rng), 1000000);
    x.canonicalize();
    y.canonicalize();
    z.canonicalize();
    if (coplanar) z = (x + y) / 3;  // all on the plane x + y - 3z = 0
    pts.emplace_back(x, y, z);
  }
  return pts;
}

constexpr std::size_t kN = 4096;

void BM_Orientation_Hlr(benchmark::State& st) {
  auto pts = random_points(kN, st.range(0));
  predicate_stats() = {};
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(orientation(pts[i % kN], pts[(i + 1) % kN], pts[(i + 2) % kN], pts[(i + 3) % kN]));
    ++i;
  }
  st.counters["fallback_pct"] = 100.0 * predicate_stats().exact_fallbacks / std::max<std::uint64_t>(1, predicate_stats().evaluations);
  st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_Orientation_Hlr)->Arg(0)->Arg(1)->ArgName("coplanar");

void BM_Orientation_Epeck(benchmark::State& st) {
  auto src = random_points(kN, st.range(0));
  std::vector<Epeck::Point_3> pts;
  for (const auto& p : src) pts.push_back(to_epeck(p));
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(CGAL::orientation(pts[i % kN], pts[(i + 1) % kN], pts[(i + 2) % kN], pts[(i + 3) % kN]));
    ++i;
  }
  st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_Orientation_Epeck)->Arg(0)->Arg(1)->ArgName("coplanar");

void BM_Orientation_PlainRational(benchmark::State& st) {
  auto pts = random_points(kN, st.range(0));
  std::size_t i = 0;
  for (auto _ : st) {
    const Point3 &p = pts[i % kN], &q = pts[(i + 1) % kN], &r = pts[(i + 2) % kN], &s = pts[(i + 3) % kN];
    benchmark::DoNotOptimize(sgn(dot(q - p, cross(r - p, s - p))));
    ++i;
  }
  st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_Orientation_PlainRational)->Arg(0)->Arg(1)->ArgName("coplanar");

void BM_Orientation_EpickDoubles_Reference(benchmark::State& st) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto src = random_points(kN, st.range(0));
  std::vector<K::Point_3> pts;
  for (const auto& p : src) pts.emplace_back(to_double(p.x()), to_double(p.y()), to_double(p.z()));
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(CGAL::orientation(pts[i % kN], pts[(i + 1) % kN], pts[(i + 2) % kN], pts[(i + 3) % kN]));
    ++i;
  }
  st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_Orientation_EpickDoubles_Reference)->Arg(0)->Arg(1)->ArgName("coplanar");

// Heap bytes per point, measured with mallinfo2 around building 100k points.
template <class Build>
double bytes_per_point(Build build) {
  malloc_trim(0);
  std::size_t before = mallinfo2().uordblks;
  auto keep = build();
  std::size_t after = mallinfo2().uordblks;
  benchmark::DoNotOptimize(keep.data());
  return static_cast<double>(after - before) / keep.size();
}

void BM_MemoryPerPoint(benchmark::State& st) {
  const std::size_t n = 100000;
  auto src = random_points(n, false);
  double hlr_b = 0, epeck_b = 0;
  for (auto _ : st) {
    hlr_b = bytes_per_point([&] { return std::vector<Point3>(src.begin(), src.end()); });
    epeck_b = bytes_per_point([&] {
      std::vector<Epeck::Point_3> v;
      v.reserve(n);
      for (const auto& p : src) v.push_back(to_epeck(p));
      return v;
    });
  }
  st.counters["hlr_bytes"] = hlr_b;
  st.counters["epeck_bytes"] = epeck_b;
}
BENCHMARK(BM_MemoryPerPoint)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
