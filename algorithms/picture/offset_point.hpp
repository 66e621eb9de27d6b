// A point beside an edge of an exact planar arrangement, offset symbolically: q = m + δ·n with
// m a point of the edge and n its left normal, δ > 0 infinitely small (course notes section 31:
// regions of the picture are labelled by what covers them). Each sign about q is decided
// lexicographically, first at m, then along n, so q is never on a border that the arrangement
// holds (docs/design.md, "Shadows as exact polygons"). Used by shadows.cpp and transparency.cpp.
#pragma once

#include <vector>

#include "algorithms/picture/picture_plane.hpp"

namespace hlr {

/// The sign of y(p) − y(q).
inline int offset_above(const Exact2& p, const Exact2& m, const Exact2& n) {
  int s = sgn(p[1] - m[1]);
  return s != 0 ? s : -sgn(n[1]);
}

/// The orientation of q against the line a -> b.
inline int offset_orient(const Exact2& a, const Exact2& b, const Exact2& m, const Exact2& n) {
  int o = orient2d(a, b, m);
  if (o != 0) return o;
  return sgn((b[0] - a[0]) * n[1] - (b[1] - a[1]) * n[0]);
}

/// Even-odd: q inside a set of rings (outer boundaries and holes)?
inline bool offset_inside(const std::vector<std::vector<Exact2>>& rings, const Exact2& m, const Exact2& n) {
  bool in = false;
  for (const auto& r : rings)
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Exact2 &a = r[i], &b = r[(i + 1) % r.size()];
      bool ua = offset_above(a, m, n) > 0, ub = offset_above(b, m, n) > 0;
      if (ua != ub && ((offset_orient(a, b, m, n) > 0) == ub)) in = !in;
    }
  return in;
}

/// q inside a convex counter-clockwise polygon?
inline bool offset_inside_convex(const std::vector<Exact2>& p, const Exact2& m, const Exact2& n) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (offset_orient(p[i], p[(i + 1) % p.size()], m, n) <= 0) return false;
  return true;
}

}  // namespace hlr
