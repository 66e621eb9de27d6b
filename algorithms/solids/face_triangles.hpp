// The triangles of a polygon face, checked (course notes section 23 treats faces as planar
// polygons): the face's exact plane, every vertex on it, and an exact ear-clipping
// triangulation (triangulate.hpp) that keeps the face's orientation and marks which triangle
// sides are polygon edges. Every route that needs triangles (the per-face occluders,
// intersection lines, later visible-surface polygons and rasterisers) takes them from here.
#pragma once

#include <vector>

#include "algorithms/solids/triangulate.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr {

struct FaceTriangles {
  enum class Status { Ok, Degenerate, NonPlanar, SelfIntersecting };
  Status status = Status::Ok;
  std::vector<FaceTriangle> triangles;  // Ok only
  int off_plane_vertex = -1;            // NonPlanar: a vertex (mesh index) off the face's plane
  /// What is wrong, after "has ": "a non-planar face (face 3, vertex 7 is off its plane)".
  std::string problem(int face) const;
};

/// The triangles of face `f` of `p`. A triangle is returned as itself without checks (the
/// caller decides its area on its own numbers); a polygon is Degenerate when its Newell normal
/// is zero, NonPlanar when a vertex is off its plane, SelfIntersecting when no ear is found.
FaceTriangles face_triangles(const Polyhedron& p, int f);

/// Whether face f (4 to kConvexFanLimit vertices) is proven planar and strictly convex (every
/// turn strictly one way, winding once) by the 128-bit integer test that face_triangles tries
/// first; false when it is not, or when the numbers are too large for that test. A triangle
/// gives false too (callers treat triangles apart).
bool proven_convex_face(const Polyhedron& p, int f);

}  // namespace hlr
