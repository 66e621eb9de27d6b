// The triangles of a face (see face_triangles.hpp).
#include "algorithms/solids/face_triangles.hpp"

#include <algorithm>

#include "kernel/exact_int.hpp"
#include "kernel/int128.hpp"
#include "kernel/simple_polygon.hpp"

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

namespace {

// The common case in 128-bit integers: a face of 4 to kConvexFanLimit vertices whose
// coordinates share a denominator below 2^62 and scale below 2^40 (decimal input), planar and
// convex, fanned from its first vertex: the decisions and the triangles of the rational route
// below (Newell's normal, every vertex on the plane, polygon_is_convex in the view that drops
// the normal's largest axis, triangulate_simple_polygon's fan), exactly. Anything else
// (degenerate, not planar, not convex, numbers too large) returns false for that route.
bool convex_fan_int(const Polyhedron& p, const Face& face, FaceTriangles& out) {
  const int n = static_cast<int>(face.size());
  if (n < 4 || n > kConvexFanLimit) return false;
  const Rational* qs[3 * kConvexFanLimit];
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < 3; ++c) qs[3 * k + c] = &p.vertices()[face[k]][c];
  std::uint64_t L;
  constexpr Int128 kLimit = bounds::kWideCoordinateLimit;
  if (!common_denominator(qs, 3 * n, static_cast<std::uint64_t>(kLimit), L)) return false;
  Int128 X[kConvexFanLimit][3];
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < 3; ++c)
      if (!scaled_integer(*qs[3 * k + c], L, kLimit, X[k][c])) return false;
  // Newell's normal as a fan from X[0] (a positive multiple, L², of the rational one):
  // differences < 2^41, products < 2^83, at most 12 terms.
  Int128 nrm[3] = {0, 0, 0};
  for (int k = 1; k + 1 < n; ++k) {
    Int128 a[3], b[3];
    for (int c = 0; c < 3; ++c) a[c] = X[k][c] - X[0][c], b[c] = X[k + 1][c] - X[0][c];
    nrm[0] += a[1] * b[2] - a[2] * b[1];
    nrm[1] += a[2] * b[0] - a[0] * b[2];
    nrm[2] += a[0] * b[1] - a[1] * b[0];
  }
  if (nrm[0] == 0 && nrm[1] == 0 && nrm[2] == 0) return false;
  // Every vertex on the plane: nrm·(X_k - X_0) = 0, in 128 bits when the sizes allow.
  const int nb = std::max({bit_length(nrm[0]), bit_length(nrm[1]), bit_length(nrm[2])});
  for (int k = 1; k < n; ++k) {
    Int128 d[3];
    for (int c = 0; c < 3; ++c) d[c] = X[k][c] - X[0][c];
    const int db = std::max({bit_length(d[0]), bit_length(d[1]), bit_length(d[2])});
    if (nb + db + 2 > 126) return false;
    if (nrm[0] * d[0] + nrm[1] * d[1] + nrm[2] * d[2] != 0) return false;
  }
  // polygon_is_convex in the view of polygon_view: drop the largest |normal| axis (the first
  // on a tie), counter-clockwise when that component is positive.
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (abs128(nrm[a]) > abs128(nrm[axis])) axis = a;
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  const bool ccw = nrm[axis] > 0;
  int changes = 0, last = 0;
  for (int k = 0; k < n; ++k) {
    const Int128 *a = X[k], *b = X[(k + 1) % n], *c = X[(k + 2) % n];
    const Int128 d = (b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i]);  // < 2^83
    if ((ccw ? d : -d) <= 0) return false;
    const int s = b[i] > a[i] ? 1 : (b[i] < a[i] ? -1 : 0);
    if (s != 0) {
      if (last != 0 && s != last) ++changes;
      last = s;
    }
  }
  for (int k = 0; k < n; ++k) {
    const Int128 dx = X[(k + 1) % n][i] - X[k][i];
    if (dx != 0) {
      if ((dx > 0 ? 1 : -1) != last) ++changes;
      break;
    }
  }
  if (changes > 2) return false;
  for (int k = 1; k + 1 < n; ++k) out.triangles.push_back({{0, k, k + 1}, {k == 1, true, k + 1 == n - 1}});
  return true;
}

}  // namespace

bool proven_convex_face(const Polyhedron& p, int f) {
  FaceTriangles scratch;
  return convex_fan_int(p, p.faces()[f], scratch);
}

FaceTriangles face_triangles(const Polyhedron& p, int f) {
  FaceTriangles out;
  const Face& face = p.faces()[f];
  if (face.size() == 3) {
    out.triangles.push_back({{0, 1, 2}, {true, true, true}});
    return out;
  }
  if (convex_fan_int(p, face, out)) return out;
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
