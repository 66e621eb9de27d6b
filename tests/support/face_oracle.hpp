// An independent exact oracle's faces: each face polygon of the scene with its own Newell plane
// and point-in-polygon in the face's dominant plane, and a picture box in doubles that only
// skips faces far from a point (no filter where doubles cannot hold the scene). Shares no code
// with the algorithms it checks (priority_list_test, shadows_test).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "algorithms/model/camera.hpp"
#include "algorithms/picture/picture_plane.hpp"
#include "algorithms/surfaces/shadows.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr::test {

struct OracleFace {
  int body, face, id;
  std::vector<Point3> v;
  std::array<double, 4> box;  // picture box, widened by 1e-6 of its size: only skips far faces
  Rational a, b, c, d;  // Newell plane
  int drop;
};

inline std::array<double, 4> box_of(const std::vector<Exact2>& pts) {
  std::array<double, 4> b{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (const Exact2& p : pts) {
    double x = p[0].get_d(), y = p[1].get_d();
    b = {std::min(b[0], x), std::min(b[1], y), std::max(b[2], x), std::max(b[3], y)};
  }
  for (double x : b)
    if (!std::isfinite(x) || std::fabs(x) < 1e-280) return {-INFINITY, -INFINITY, INFINITY, INFINITY};  // doubles lost it: no filter
  double pad = 1e-6 * (std::fabs(b[0]) + std::fabs(b[1]) + std::fabs(b[2]) + std::fabs(b[3]));
  return {b[0] - pad, b[1] - pad, b[2] + pad, b[3] + pad};
}
inline bool in_box(const std::array<double, 4>& b, const std::array<double, 2>& q) {
  if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || std::fabs(q[0]) < 1e-280 || std::fabs(q[1]) < 1e-280) return true;
  return b[0] <= q[0] && q[0] <= b[2] && b[1] <= q[1] && q[1] <= b[3];
}

/// The faces with no picture box (every face tested at every point): for views with the eye
/// among the bodies, whose vertices behind the eye have no picture.
inline std::vector<OracleFace> oracle_faces(const std::vector<const Polyhedron*>& bodies) {
  std::vector<OracleFace> out;
  int id = 0;
  for (std::size_t bi = 0; bi < bodies.size(); ++bi)
    for (std::size_t fi = 0; fi < bodies[bi]->num_faces(); ++fi, ++id) {
      OracleFace of{static_cast<int>(bi), static_cast<int>(fi), id, {}, {-INFINITY, -INFINITY, INFINITY, INFINITY}, 0, 0, 0, 0, 0};
      for (int i : bodies[bi]->faces()[fi]) of.v.push_back(bodies[bi]->vertices()[i]);
      for (std::size_t i = 0; i < of.v.size(); ++i) {
        const Point3 &A = of.v[i], &B = of.v[(i + 1) % of.v.size()];
        of.a += (A.y() - B.y()) * (A.z() + B.z());
        of.b += (A.z() - B.z()) * (A.x() + B.x());
        of.c += (A.x() - B.x()) * (A.y() + B.y());
      }
      of.d = -(of.a * of.v[0].x() + of.b * of.v[0].y() + of.c * of.v[0].z());
      Rational ax = abs(of.a), ay = abs(of.b), az = abs(of.c);
      of.drop = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
      out.push_back(std::move(of));
    }
  return out;
}

inline std::vector<OracleFace> oracle_faces(const std::vector<const Polyhedron*>& bodies, const PicturePlane& pp) {
  std::vector<OracleFace> out = oracle_faces(bodies);
  for (OracleFace& of : out) {
    std::vector<Exact2> pic;
    for (const Point3& v : of.v) pic.push_back(pp.project(v));
    of.box = box_of(pic);
  }
  return out;
}

// 1 strictly inside, 0 on the border, -1 outside (x in the face's plane).
inline int in_face(const OracleFace& f, const std::array<Rational, 3>& x) {
  int u = f.drop == 0 ? 1 : 0, w = f.drop == 2 ? 1 : 2;
  bool in = false;
  for (std::size_t i = 0; i < f.v.size(); ++i) {
    const Point3 &A = f.v[i], &B = f.v[(i + 1) % f.v.size()];
    Rational cr = (B[u] - A[u]) * (x[w] - A[w]) - (B[w] - A[w]) * (x[u] - A[u]);
    if (cr == 0 && std::min(A[u], B[u]) <= x[u] && x[u] <= std::max(A[u], B[u]) && std::min(A[w], B[w]) <= x[w] &&
        x[w] <= std::max(A[w], B[w]))
      return 0;
    bool ua = A[w] > x[w], ub = B[w] > x[w];
    if (ua != ub && ((cr > 0) == ub)) in = !in;
  }
  return in ? 1 : -1;
}


/// 1 inside, 0 on the border, -1 outside a picture ring (even-odd; either orientation).
inline int in_ring(const std::vector<Exact2>& r, const Exact2& q) {
  bool in = false;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Exact2 &a = r[i], &b = r[(i + 1) % r.size()];
    int o = orient2d(a, b, q);
    if (o == 0 && std::min(a[0], b[0]) <= q[0] && q[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= q[1] &&
        q[1] <= std::max(a[1], b[1]))
      return 0;
    bool ua = a[1] > q[1], ub = b[1] > q[1];
    if (ua != ub && ((o > 0) == ub)) in = !in;
  }
  return in ? 1 : -1;
}

/// The same for a polygon with holes (outer ring, hole rings).
inline int in_rings(const std::vector<Exact2>& outer, const std::vector<std::vector<Exact2>>& holes, const Exact2& q) {
  int o = in_ring(outer, q);
  if (o <= 0) return o;
  for (const auto& h : holes) {
    int i = in_ring(h, q);
    if (i == 0) return 0;
    if (i > 0) return -1;
  }
  return 1;
}

/// The sight ray through picture point q: base + t·dir. Orthographic: dir is the direction
/// toward the viewer (larger t nearer); perspective: from the eye, t > 0 in front (smaller t
/// nearer).
struct SightRay {
  std::array<Rational, 3> base, dir;
};
inline SightRay sight_ray(const Camera& cam, const PicturePlane& pp, const Exact2& q) {
  const Vector3 &r = pp.r(), &u = pp.u(), &d = pp.d();
  const Rational rr = dot(r, r), uu = dot(u, u), dd = dot(d, d);
  SightRay ray;
  for (int k = 0; k < 3; ++k) {
    if (cam.perspective) ray.base[k] = cam.eye[k], ray.dir[k] = q[0] * dd / rr * r[k] + q[1] * dd / uu * u[k] + d[k];
    else ray.base[k] = q[0] / rr * r[k] + q[1] / uu * u[k], ray.dir[k] = cam.direction[k];
  }
  return ray;
}

/// A face the sight ray meets: how near (larger nearer), the face's id, the point, and
/// in_face there (1 inside, 0 on its border).
struct SightHit {
  Rational nearness;
  int id, in;
  std::array<Rational, 3> at;
};

/// Every face the sight ray through q meets, far to near (faces far from q in the picture are
/// skipped by their boxes; faces seen edge-on are not met).
inline std::vector<SightHit> sight_hits(const std::vector<OracleFace>& faces, const Camera& cam, const PicturePlane& pp, const Exact2& q) {
  const SightRay ray = sight_ray(cam, pp, q);
  const std::array<double, 2> qd{q[0].get_d(), q[1].get_d()};
  std::vector<SightHit> hits;
  for (const OracleFace& f : faces) {
    if (!in_box(f.box, qd)) continue;
    const Rational nd = f.a * ray.dir[0] + f.b * ray.dir[1] + f.c * ray.dir[2];
    if (nd == 0) continue;
    const Rational t = -(f.a * ray.base[0] + f.b * ray.base[1] + f.c * ray.base[2] + f.d) / nd;
    if (cam.perspective && t <= 0) continue;
    std::array<Rational, 3> x{ray.base[0] + t * ray.dir[0], ray.base[1] + t * ray.dir[1], ray.base[2] + t * ray.dir[2]};
    const int in = in_face(f, x);
    if (in < 0) continue;
    hits.push_back({cam.perspective ? Rational(-t) : t, f.id, in, std::move(x)});
  }
  std::sort(hits.begin(), hits.end(), [](const SightHit& a, const SightHit& b) { return a.nearness < b.nearness; });
  return hits;
}

/// Does the light reach x on face `self`, on the side the viewer sees? -1: unsure (a face in a plane
/// through the light is in its shadow).
inline int lit(const std::vector<test::OracleFace>& faces, const test::OracleFace& self, const Camera& cam, const LightPlace& l,
               const std::array<Rational, 3>& x) {
  auto f = [](const test::OracleFace& g, const Rational& px, const Rational& py, const Rational& pz) {
    return Rational(g.a * px + g.b * py + g.c * pz + g.d);
  };
  const int viewer = cam.perspective ? sgn(f(self, cam.eye.x(), cam.eye.y(), cam.eye.z()))
                                     : sgn(self.a * cam.direction.x() + self.b * cam.direction.y() + self.c * cam.direction.z());
  const int light = l.directional ? sgn(self.a * l.toward.x() + self.b * l.toward.y() + self.c * l.toward.z())
                                  : sgn(f(self, l.position.x(), l.position.y(), l.position.z()));
  if (light == 0) return 0;  // the face lies in a plane through the light: in its shadow (documented)
  if (light != viewer) return 0;
  std::array<Rational, 3> dir;
  for (int k = 0; k < 3; ++k) dir[k] = l.directional ? l.toward[k] : l.position[k] - x[k];
  bool unsure = false;
  for (const test::OracleFace& g : faces) {
    if (g.id == self.id) continue;
    Rational nd = g.a * dir[0] + g.b * dir[1] + g.c * dir[2];
    if (nd == 0) continue;
    Rational t = -(g.a * x[0] + g.b * x[1] + g.c * x[2] + g.d) / nd;
    if (t < 0 || (!l.directional && t > 1)) continue;
    int in = test::in_face(g, {x[0] + t * dir[0], x[1] + t * dir[1], x[2] + t * dir[2]});
    if (in < 0) continue;
    if (t == 0 || in == 0) {
      unsure = true;
      continue;
    }
    return 0;
  }
  return unsure ? -1 : 1;
}

}  // namespace hlr::test
