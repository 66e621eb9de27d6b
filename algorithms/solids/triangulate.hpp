// Exact triangulation of a planar polygon face (simple, possibly non-convex) in the coordinate
// plane where the face's projection is largest (kernel/simple_polygon.hpp, O(n log n)). Used to turn any face into the
// triangular occluders of the per-face route (course notes section 23 treats faces as planar polygons).
// Orientations are exact; the triangles keep the face's vertex order (same normal direction).
#pragma once

#include <array>
#include <vector>

#include "kernel/geometry.hpp"

namespace hlr {

struct FaceTriangle {
  std::array<int, 3> v;      // positions in the face's vertex list, face's orientation
  std::array<bool, 3> edge;  // side k (v[k] -> v[k+1]) is an edge of the polygon (else a diagonal)
};

/// Triangulates the face `poly` (indices into `points`) whose exact plane normal is `normal`
/// (non-zero). Convex faces are fanned from their first vertex. Returns an empty list when the
/// polygon is not simple (its edges cross or touch).
std::vector<FaceTriangle> triangulate_face(const std::vector<Point3>& points, const std::vector<int>& poly,
                                           const Vector3& normal);

}  // namespace hlr
