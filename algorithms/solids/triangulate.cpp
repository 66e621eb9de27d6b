// Exact triangulation of a planar polygon face (see triangulate.hpp): the simple-polygon test
// and triangulation of kernel/simple_polygon.hpp (a fan for convex faces, a constrained
// Delaunay triangulation otherwise, both O(n log n)).
#include "algorithms/solids/triangulate.hpp"

#include "kernel/simple_polygon.hpp"

namespace hlr {

std::vector<FaceTriangle> triangulate_face(const std::vector<Point3>& pts, const std::vector<int>& poly,
                                           const Vector3& normal) {
  std::vector<FaceTriangle> out;
  if (poly.size() == 3) {
    out.push_back({{0, 1, 2}, {true, true, true}});
    return out;
  }
  const PolygonView view = polygon_view(normal);
  if (!polygon_is_simple(pts, poly, view)) return out;
  for (const PolygonTriangle& t : triangulate_simple_polygon(pts, poly, view)) out.push_back({t.v, t.edge});
  return out;
}

}  // namespace hlr
