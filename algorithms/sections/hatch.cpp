// Hatch lines clipped exactly to a planar region (see hatch.hpp). For each line's plane g(X) =
// N·X − d, an edge ab crosses where the signs of g(a) < 0 and g(b) < 0 differ (the half-open
// rule: a line through a vertex counts the vertex once, a line along an edge counts it on one
// side), so every line meets the closed loops an even number of times; the crossing points,
// sorted along the line, pair into the inside pieces.
#include "algorithms/sections/hatch.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace hlr {
namespace {

// g(X) = A − c·B for the line at c (hatch.hpp's planes, rearranged): orthographic A = m·X − o,
// B = k; perspective A = m·(X − eye), B = f·(X − eye).
struct Affine {
  Rational a, b;
  double ad, bd;
};

Affine affine_at(const HatchFamily& fam, const Point3& x) {
  Affine v;
  if (fam.perspective) {
    const Vector3 d = x - fam.eye;
    v.a = dot(fam.m, d);
    v.b = dot(fam.f, d);
  } else {
    v.a = dot(fam.m, x - Point3()) - fam.o;
    v.b = fam.k;
  }
  v.ad = to_double(v.a), v.bd = to_double(v.b);
  return v;
}

// The sign of A − c·B < 0: decided in doubles when the gap is over 1e-9 of the terms' size (the
// doubles' error is a few units of 2^-53 of it), else exactly.
bool below(const Affine& v, const Rational& c, double cd) {
  const double g = v.ad - cd * v.bd, size = std::fabs(v.ad) + std::fabs(cd * v.bd);
  if (std::isfinite(g) && std::isfinite(size) && std::fabs(g) > 1e-9 * size + 1e-300) return g < 0;
  return v.a - c * v.b < 0;
}

}  // namespace

std::vector<std::array<Point3, 2>> hatch_region(const std::vector<Point3>& pts, const std::vector<std::array<int, 2>>& boundary,
                                                const Vector3& normal, const HatchFamily& family) {
  std::vector<std::array<Point3, 2>> out;
  if (boundary.empty() || family.step <= 0) return out;
  std::map<int, Affine> at;  // the boundary's corners
  for (const auto& e : boundary)
    for (int v : e)
      if (!at.count(v)) at.emplace(v, affine_at(family, pts[v]));
  std::vector<std::pair<Rational, Point3>> hits;
  for (Rational c = family.first; c <= family.last; c += family.step) {
    const double cd = to_double(c);
    const Vector3 n = family.perspective ? family.m + Rational(-c) * family.f : family.m;  // the line's plane's normal
    const Vector3 along = cross(normal, n);
    if (along.is_zero()) continue;  // the region's plane holds the line's plane's normal: seen edge-on
    hits.clear();
    for (const auto& e : boundary) {
      const Affine &va = at.at(e[0]), &vb = at.at(e[1]);
      if (below(va, c, cd) == below(vb, c, cd)) continue;
      const Rational ga = va.a - c * va.b, gb = vb.a - c * vb.b;
      const Point3& a = pts[e[0]];
      Point3 x = a + Rational(ga / (ga - gb)) * (pts[e[1]] - a);
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
