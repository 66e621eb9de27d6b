// The convex hull of a point set as triangles of its points (course notes section 23: a body
// is convex when each of its face planes leaves every vertex on one side, that is, when each is
// the plane of a facet of the vertices' convex hull). CGAL's convex_hull_3 with exact
// predicates (Epeck); kept out of widely included headers (a CGAL unit compiles slowly).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "kernel/geometry.hpp"

namespace hlr {

/// The boundary of the convex hull of `points`, triangulated, each triangle as three indices
/// into `points` (a hull vertex is an input point; of equal points, any one), counter-clockwise
/// seen from outside; nothing when the points do not span space (all in one plane).
std::vector<std::array<std::size_t, 3>> hull_triangles(const std::vector<Point3>& points);

}  // namespace hlr
