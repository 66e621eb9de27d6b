// Shading arithmetic in doubles (course notes sections 36-39). See face_shading.hpp.
#include "algorithms/shading/face_shading.hpp"

#include <algorithm>
#include <climits>

#include "algorithms/picture/picture_plane.hpp"
#include "algorithms/support/parallel.hpp"

namespace hlr {

Vec3d face_normal(const Polyhedron& p, std::size_t f) {
  const Face& face = p.faces()[f];
  std::array<double, 3> n{0, 0, 0};
  const std::array<double, 3> o = d3(p.vertices()[face[0]]);
  for (std::size_t i = 1; i + 1 < face.size(); ++i) {  // Newell's sum as a fan from the first vertex
    const std::array<double, 3> a = d3(p.vertices()[face[i]]), b = d3(p.vertices()[face[i + 1]]);
    const double u[3] = {a[0] - o[0], a[1] - o[1], a[2] - o[2]}, v[3] = {b[0] - o[0], b[1] - o[1], b[2] - o[2]};
    n[0] += u[1] * v[2] - u[2] * v[1], n[1] += u[2] * v[0] - u[0] * v[2], n[2] += u[0] * v[1] - u[1] * v[0];
  }
  const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (std::isfinite(l) && l > 0x1p-500) return {n[0] / l, n[1] / l, n[2] / l};
  std::vector<const Point3*> pts;
  for (int v : face) pts.push_back(&p.vertices()[v]);
  const Plane h = primitive_plane_of_polygon(pts.data(), pts.size());  // exact: beyond the doubles' range
  // Scaled by a power of two so that the largest component is near 1 (integers of any size).
  int e = INT_MIN;
  for (int k = 0; k < 3; ++k)
    if (sgn(h[k]) != 0) e = std::max(e, static_cast<int>(mpz_sizeinbase(h[k].get_num().get_mpz_t(), 2)));
  if (e == INT_MIN) return {0, 0, 1};
  std::array<double, 3> m;
  for (int k = 0; k < 3; ++k) {
    mpz_class q = h[k].get_num();
    m[k] = e > 900 ? mpz_class(q >> (e - 900)).get_d() : q.get_d();
  }
  return unit(m);
}

Rgb flat_face_colour(const Polyhedron& p, std::size_t f, const Material& m, const Lighting& light, bool back, Vec3d n, bool perspective,
                     const ViewDoubles& vd) {
  const Vec3d &eye = vd.eye, &view = vd.view;
  if (back) n = {-n[0], -n[1], -n[2]};
  Vec3d c{0, 0, 0};
  for (int v : p.faces()[f]) {
    auto q = d3(p.vertices()[v]);
    for (int k = 0; k < 3; ++k) c[k] += q[k] / static_cast<double>(p.faces()[f].size());
  }
  Vec3d to_viewer = perspective ? unit({eye[0] - c[0], eye[1] - c[1], eye[2] - c[2]}) : view;
  return shade(m, light, c, n, to_viewer);
}

Lighting camera_lighting(const Camera& cam) {
  auto v = unit(cam.perspective ? d3(Vector3(cam.eye - cam.target)) : d3(cam.direction));
  auto right = unit(cross3(d3(cam.up), v)), up = cross3(v, right);
  Lighting l = default_lighting(v, up, right);
  // Shadows decide with exact light directions: snap the default lights to sixty-fourths (a
  // change of under a degree), small numbers that keep the exact arithmetic fast.
  for (Light& x : l.lights) {
    x.exact = true;
    for (int k = 0; k < 3; ++k) x.exact_direction[k] = rational(std::lround(x.direction[k] * 64), 64);
    x.direction = unit({to_double(x.exact_direction[0]), to_double(x.exact_direction[1]), to_double(x.exact_direction[2])});
    for (int k = 0; k < 3; ++k) x.exact_position[k] = rational_from_double(x.position[k]);
  }
  return l;
}

Lift::Lift(const Camera& cam) : persp(cam.perspective) {
  PicturePlane pp(cam);
  r = d3(pp.r()), u = d3(pp.u()), d = d3(pp.d());
  rr = dot3(r, r), uu = dot3(u, u), dd = dot3(d, d);
  e = d3(cam.eye);
  v = d3(cam.direction);
}

Vec3d Lift::at(double x, double y, const Vec3d& n, double c) const {
  if (!persp) {
    Vec3d b{x / rr * r[0] + y / uu * u[0], x / rr * r[1] + y / uu * u[1], x / rr * r[2] + y / uu * u[2]};
    double s = -(dot3(n, b) + c) / dot3(n, v);
    return {b[0] + s * v[0], b[1] + s * v[1], b[2] + s * v[2]};
  }
  Vec3d dir{x * dd / rr * r[0] + y * dd / uu * u[0] + d[0], x * dd / rr * r[1] + y * dd / uu * u[1] + d[1],
            x * dd / rr * r[2] + y * dd / uu * u[2] + d[2]};
  double l = -(dot3(n, e) + c) / dot3(n, dir);
  return {e[0] + l * dir[0], e[1] + l * dir[1], e[2] + l * dir[2]};
}

BodyNormals body_normals(const Polyhedron& p) {
  BodyNormals n;
  n.face.resize(p.num_faces());
  n.around.resize(p.num_vertices());
  ParallelLoop().for_each(p.num_faces(), 1024, [&](std::size_t f) { n.face[f] = face_normal(p, f); });
  for (std::size_t f = 0; f < p.num_faces(); ++f)
    for (int v : p.faces()[f]) n.around[v].push_back(static_cast<int>(f));
  return n;
}

Vec3d vertex_normal(const BodyNormals& n, int f, int v, double cos_smooth) {
  Vec3d s{0, 0, 0};
  for (int g : n.around[v])
    if (dot3(n.face[g], n.face[f]) >= cos_smooth)
      for (int k = 0; k < 3; ++k) s[k] += n.face[g][k];
  return unit(s);
}

// Barycentric weights of p over the fan triangle (0, k, k + 1) of the polygon's corners that
// holds it (in the plane of normal n: the dominant axis dropped). Returns the triangle's k.
int fan_weights(const std::vector<Vec3d>& c, const Vec3d& n, const Vec3d& p, double w[3]) {
  const int drop = std::fabs(n[0]) >= std::fabs(n[1]) && std::fabs(n[0]) >= std::fabs(n[2]) ? 0 : std::fabs(n[1]) >= std::fabs(n[2]) ? 1 : 2;
  const int a = drop == 0 ? 1 : 0, b = drop == 2 ? 1 : 2;
  auto area = [&](const Vec3d& x, const Vec3d& y, const Vec3d& z) { return (y[a] - x[a]) * (z[b] - x[b]) - (y[b] - x[b]) * (z[a] - x[a]); };
  int best = 1;
  double best_min = -INFINITY, bw[3] = {1, 0, 0};
  for (std::size_t k = 1; k + 1 < c.size(); ++k) {
    double t = area(c[0], c[k], c[k + 1]);
    if (t == 0) continue;
    double w0 = area(p, c[k], c[k + 1]) / t, w1 = area(c[0], p, c[k + 1]) / t, w2 = 1 - w0 - w1;
    double m = std::min({w0, w1, w2});
    if (m > best_min) best_min = m, best = static_cast<int>(k), bw[0] = w0, bw[1] = w1, bw[2] = w2;
    if (m >= 0) break;
  }
  w[0] = bw[0], w[1] = bw[1], w[2] = bw[2];
  return best;
}

}  // namespace hlr
