// Simple polygons (course notes section 23 treats faces as planar polygons): the exact test
// that a face's polygon does not cross or touch itself, and its triangulation, both in
// O(n log n) through CGAL on an exact kernel (a sweep for the test, a constrained Delaunay
// triangulation for the triangles). CGAL stays in simple_polygon.cpp.
#pragma once

#include <array>
#include <vector>

#include "kernel/geometry.hpp"

namespace hlr {

/// Convex polygons with at most this many vertices are fanned from their first vertex
/// (triangulate_simple_polygon); larger convex ones are halved recursively.
inline constexpr int kConvexFanLimit = 12;

/// The coordinate plane a planar polygon is seen in: the axis of the largest component of its
/// normal is dropped, (i, j) are the kept axes; `ccw` when the polygon runs counter-clockwise
/// in (i, j) (the normal's dropped component is positive).
struct PolygonView {
  int i, j;
  bool ccw;
};
PolygonView polygon_view(const Vector3& normal);

/// Is the polygon pts[poly[0]], pts[poly[1]], ... simple in `view`: no two edges meet except
/// adjacent ones at their common vertex (a vertex on another edge, a repeated point, a spike
/// that turns back along its edge and a crossing all make it not simple). Exact.
bool polygon_is_simple(const std::vector<Point3>& pts, const std::vector<int>& poly, const PolygonView& view);

/// Is the polygon strictly convex and simple in `view` (every turn strictly to the same side,
/// and the edge directions going round once)? O(n), exact; a cheap first test.
bool polygon_is_convex(const std::vector<Point3>& pts, const std::vector<int>& poly, const PolygonView& view);

/// Triangles of a simple polygon (polygon_is_simple), as positions in `poly` in the polygon's
/// own orientation; `edge[k]` is set when side v[k] -> v[k+1] is a polygon edge. A collinear
/// run of vertices gives no zero-area triangle.
struct PolygonTriangle {
  std::array<int, 3> v;
  std::array<bool, 3> edge;
};
std::vector<PolygonTriangle> triangulate_simple_polygon(const std::vector<Point3>& pts, const std::vector<int>& poly,
                                                        const PolygonView& view);

/// Triangles of the region that closed loops of edges bound in one plane (outer boundaries,
/// holes, islands in holes, nested to any depth: the region is where a ray crosses an odd
/// number of edges), as indices into `pts`, each triangle in the orientation `view` calls
/// counter-clockwise when view.ccw (else clockwise): the orientation of a face whose normal
/// gave `view`. Edges may touch at their ends but not cross. No new points: every corner is
/// an end of an edge.
std::vector<std::array<int, 3>> triangulate_loops(const std::vector<Point3>& pts, const std::vector<std::array<int, 2>>& edges,
                                                  const PolygonView& view);

}  // namespace hlr
