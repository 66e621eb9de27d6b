// Hatch lines clipped exactly to a planar region (see hatch.hpp). For each line's plane g(X) =
// N·X − d, an edge ab crosses where the signs of g(a) < 0 and g(b) < 0 differ (the half-open
// rule: a line through a vertex counts the vertex once, a line along an edge counts it on one
// side), so every line meets the closed loops an even number of times; the crossing points,
// sorted along the line, pair into the inside pieces.
#include "algorithms/sections/hatch.hpp"

#include <algorithm>
#include <utility>

namespace hlr {
namespace {

struct LinePlane {
  Vector3 n;
  Rational d;
};

LinePlane plane_of(const HatchFamily& fam, const Rational& c) {
  if (!fam.perspective) return {fam.m, c * fam.k + fam.o};
  Vector3 n = fam.m + (Rational(-c) * fam.f);
  Rational d = dot(n, fam.eye - Point3());
  return {n, d};
}

}  // namespace

std::vector<std::array<Point3, 2>> hatch_region(const std::vector<Point3>& pts, const std::vector<std::array<int, 2>>& boundary,
                                                const Vector3& normal, const HatchFamily& family) {
  std::vector<std::array<Point3, 2>> out;
  if (boundary.empty() || family.step <= 0) return out;
  std::vector<std::pair<Rational, Point3>> hits;
  for (Rational c = family.first; c <= family.last; c += family.step) {
    const LinePlane lp = plane_of(family, c);
    const Vector3 along = cross(normal, lp.n);
    if (along.is_zero()) continue;  // the region's plane holds the line's plane's normal: seen edge-on
    hits.clear();
    for (const auto& e : boundary) {
      const Point3& a = pts[e[0]];
      const Point3& b = pts[e[1]];
      const Rational ga = dot(lp.n, a - Point3()) - lp.d, gb = dot(lp.n, b - Point3()) - lp.d;
      if ((ga < 0) == (gb < 0)) continue;
      Point3 x = a + Rational(ga / (ga - gb)) * (b - a);
      Rational key = dot(along, x - Point3());
      hits.emplace_back(std::move(key), std::move(x));
    }
    std::sort(hits.begin(), hits.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
    for (std::size_t i = 0; i + 1 < hits.size(); i += 2)
      if (hits[i].first < hits[i + 1].first) out.push_back({hits[i].second, hits[i + 1].second});
  }
  return out;
}

}  // namespace hlr
