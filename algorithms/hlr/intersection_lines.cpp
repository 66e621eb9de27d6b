// Exact triangle-triangle intersection segments (see intersection_lines.hpp).
#include "algorithms/hlr/intersection_lines.hpp"

#include <vector>

namespace hlr {
namespace {

struct Cut {
  std::vector<Point3> pts;  // 0, 1 or 2 points of the triangle on the other plane
  bool along_mesh_edge = false;
};

// The part of triangle t on the plane through q with normal n.
Cut cut(const TriangleRef& t, const Vector3& n, const Point3& q) {
  Rational s[3];
  for (int k = 0; k < 3; ++k) s[k] = dot(n, *t.p[k] - q);
  Cut c;
  int zeros = 0;
  for (int k = 0; k < 3; ++k) zeros += sgn(s[k]) == 0;
  if (zeros == 3) return c;  // coplanar: touching, no line
  for (int k = 0; k < 3; ++k) {
    int j = (k + 1) % 3;
    if (sgn(s[k]) == 0) c.pts.push_back(*t.p[k]);
    if (sgn(s[k]) * sgn(s[j]) < 0) {
      Rational u = s[k] / (s[k] - s[j]);
      c.pts.push_back(*t.p[k] + u * (*t.p[j] - *t.p[k]));
    }
    if (sgn(s[k]) == 0 && sgn(s[j]) == 0 && t.edge[k]) c.along_mesh_edge = true;
  }
  return c;
}

}  // namespace

std::optional<std::pair<Point3, Point3>> triangle_intersection(const TriangleRef& a, const TriangleRef& b) {
  Vector3 na = cross(*a.p[1] - *a.p[0], *a.p[2] - *a.p[0]);
  Vector3 nb = cross(*b.p[1] - *b.p[0], *b.p[2] - *b.p[0]);
  Vector3 u = cross(na, nb);
  if (u.is_zero()) return std::nullopt;  // parallel planes
  Cut ca = cut(a, nb, *b.p[0]), cb = cut(b, na, *a.p[0]);
  if (ca.pts.size() < 2 || cb.pts.size() < 2) return std::nullopt;
  if (ca.along_mesh_edge || cb.along_mesh_edge) return std::nullopt;
  // Both cuts lie on the line of the two planes: order along u.
  auto par = [&](const Point3& p) { return dot(u, p - Point3()); };
  auto order = [&](Cut& c) {
    if (par(c.pts[1]) < par(c.pts[0])) std::swap(c.pts[0], c.pts[1]);
  };
  order(ca);
  order(cb);
  const Point3& lo = par(ca.pts[0]) >= par(cb.pts[0]) ? ca.pts[0] : cb.pts[0];
  const Point3& hi = par(ca.pts[1]) <= par(cb.pts[1]) ? ca.pts[1] : cb.pts[1];
  if (!(par(lo) < par(hi))) return std::nullopt;
  return std::make_pair(lo, hi);
}

}  // namespace hlr
