// Intersection lines (course notes section 28, "penetration lines"): where two faces
// of different bodies, or two non-adjacent faces of one body, cross, the drawing gets the
// segment they share. Exact: the segment of two triangles is built from the signs and values
// of their vertices against each other's plane in rationals. Coplanar (touching) triangles and
// segments lying along a mesh edge of either triangle add no line (that edge is drawn as itself).
#pragma once

#include <array>
#include <optional>
#include <utility>

#include "kernel/geometry.hpp"

namespace hlr {

struct TriangleRef {
  std::array<const Point3*, 3> p;
  std::array<bool, 3> edge;  // side k (p[k] -> p[k+1]) is a mesh edge (else a face diagonal)
};

/// The segment where triangles a and b cross (non-degenerate: from != to), or nothing.
std::optional<std::pair<Point3, Point3>> triangle_intersection(const TriangleRef& a, const TriangleRef& b);

}  // namespace hlr
