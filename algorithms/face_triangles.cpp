// The triangles of a face (see face_triangles.hpp).
#include "algorithms/face_triangles.hpp"

namespace hlr {

std::string FaceTriangles::problem(int face) const {
  switch (status) {
    case Status::NonPlanar:
      return "a non-planar face (face " + std::to_string(face) + ", vertex " + std::to_string(off_plane_vertex) + " is off its plane)";
    case Status::SelfIntersecting: return "a self-intersecting face (face " + std::to_string(face) + ")";
    case Status::Degenerate: return "a degenerate face (face " + std::to_string(face) + ")";
    case Status::Ok: break;
  }
  return "";
}

FaceTriangles face_triangles(const Polyhedron& p, int f) {
  FaceTriangles out;
  const Face& face = p.faces()[f];
  if (face.size() == 3) {
    out.triangles.push_back({{0, 1, 2}, {true, true, true}});
    return out;
  }
  std::vector<const Point3*> pts;
  pts.reserve(face.size());
  for (int v : face) pts.push_back(&p.vertices()[v]);
  Plane h = plane_of_polygon(pts.data(), pts.size());
  if (h.is_degenerate()) {
    // Zero net area: truly degenerate only when every vertex is on one line (a symmetric
    // bow-tie has zero area too, and is refused like any self-intersecting face).
    switch (zero_area_kind(pts.data(), pts.size())) {
      case ZeroAreaKind::Collinear: out.status = FaceTriangles::Status::Degenerate; break;
      case ZeroAreaKind::Crossing: out.status = FaceTriangles::Status::SelfIntersecting; break;
      case ZeroAreaKind::NonPlanar:
        out.status = FaceTriangles::Status::NonPlanar;
        out.off_plane_vertex = face[0];
        break;
    }
    return out;
  }
  for (std::size_t k = 0; k < face.size(); ++k)
    if (h.value(*pts[k]) != 0) {
      out.status = FaceTriangles::Status::NonPlanar;
      out.off_plane_vertex = face[k];
      return out;
    }
  out.triangles = triangulate_face(p.vertices(), face, h.normal());
  if (out.triangles.empty()) out.status = FaceTriangles::Status::SelfIntersecting;
  return out;
}

}  // namespace hlr
