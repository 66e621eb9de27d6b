// Whitted ray tracing (course notes 43-45). See ray_tracing.hpp.
#include "algorithms/raster/ray_tracing.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "algorithms/solids/face_triangles.hpp"

namespace hlr {

bool exact_total_internal_reflection(const std::array<Rational, 3>& d, const std::array<Rational, 3>& n, const Rational& eta) {
  const Rational dn = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
  const Rational dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2], nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  // η²·sin²θ > 1 with sin²θ = 1 - (d·n)²/(|d|²|n|²), multiplied out by |d|²|n|² > 0.
  return eta * eta * (dd * nn - dn * dn) > dd * nn;
}

namespace {

double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3d add(const Vec3d& a, const Vec3d& b, double k = 1) { return {a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]}; }
Vec3d cross(const Vec3d& a, const Vec3d& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
Vec3d unit(const Vec3d& a) {
  double l = std::sqrt(dot(a, a));
  return l > 0 ? Vec3d{a[0] / l, a[1] / l, a[2] / l} : a;
}

}  // namespace

bool refract(const Vec3d& d, const Vec3d& n, double eta, Vec3d& t) {
  const double c = -dot(d, n);
  const double k = 1 - eta * eta * (1 - c * c);
  if (k < 0) return false;
  t = unit(add(Vec3d{eta * d[0], eta * d[1], eta * d[2]}, n, eta * c - std::sqrt(k)));
  return true;
}

struct WhittedScene::Impl {
  struct Tri {
    Vec3d a, e1, e2;
    int body, face;
  };
  struct Node {
    Vec3d lo, hi;
    int left = -1, right = -1, first = 0, count = 0;
  };
  std::vector<Tri> tris;
  std::vector<int> order;
  std::vector<Node> nodes;
  std::vector<std::vector<Vec3d>> normals;  // per body, per face: unit outward
  std::vector<Material> materials;
  Lighting lighting;
  WhittedOptions options;
  double eps = 1e-9;

  int build(int first, int end) {
    const int id = static_cast<int>(nodes.size());
    nodes.push_back(Node{});
    Vec3d lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY}, clo = lo, chi = hi;
    for (int k = first; k < end; ++k) {
      const Tri& t = tris[order[k]];
      for (const Vec3d& p : {t.a, add(t.a, t.e1), add(t.a, t.e2)})
        for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
      Vec3d m = add(t.a, add(t.e1, t.e2), 1.0 / 3);
      for (int c = 0; c < 3; ++c) clo[c] = std::min(clo[c], m[c]), chi[c] = std::max(chi[c], m[c]);
    }
    nodes[id].lo = lo, nodes[id].hi = hi;
    if (end - first <= 4) {
      nodes[id].first = first, nodes[id].count = end - first;
      return id;
    }
    int axis = 0;
    for (int c = 1; c < 3; ++c)
      if (chi[c] - clo[c] > chi[axis] - clo[axis]) axis = c;
    const int mid = (first + end) / 2;
    std::nth_element(order.begin() + first, order.begin() + mid, order.begin() + end, [&](int x, int y) {
      const Tri &p = tris[x], &q = tris[y];
      return 3 * p.a[axis] + p.e1[axis] + p.e2[axis] < 3 * q.a[axis] + q.e1[axis] + q.e2[axis];
    });
    int l = build(first, mid), r = build(mid, end);
    nodes[id].left = l, nodes[id].right = r;
    return id;
  }

  static bool box_hit(const Node& n, const Vec3d& o, const Vec3d& inv, double tmax, double tmin) {
    double t0 = tmin, t1 = tmax;
    for (int c = 0; c < 3; ++c) {
      double a = (n.lo[c] - o[c]) * inv[c], b = (n.hi[c] - o[c]) * inv[c];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
      if (t0 > t1) return false;
    }
    return true;
  }

  // Möller–Trumbore: the ray's distance to triangle t, or -1.
  double tri_hit(const Tri& t, const Vec3d& o, const Vec3d& d) const {
    const Vec3d p = cross(d, t.e2);
    const double det = dot(t.e1, p);
    if (det == 0) return -1;
    const double inv = 1 / det;
    const Vec3d s = add(o, t.a, -1);
    const double u = dot(s, p) * inv;
    if (u < 0 || u > 1) return -1;
    const Vec3d q = cross(s, t.e1);
    const double v = dot(d, q) * inv;
    if (v < 0 || u + v > 1) return -1;
    return dot(t.e2, q) * inv;
  }
};

WhittedScene::WhittedScene(const std::vector<const Polyhedron*>& bodies, std::vector<Material> materials, Lighting lighting,
                           const WhittedOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.materials = std::move(materials);
  m.lighting = std::move(lighting);
  m.options = options;
  Vec3d lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  m.normals.resize(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Polyhedron& p = *bodies[b];
    std::vector<Vec3d> v(p.num_vertices());
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Point3& q = p.vertices()[i];
      v[i] = {to_double(q.x()), to_double(q.y()), to_double(q.z())};
      for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], v[i][c]), hi[c] = std::max(hi[c], v[i][c]);
    }
    for (std::size_t f = 0; f < p.num_faces(); ++f) {
      const Plane& h = p.planes()[f];
      m.normals[b].push_back(unit({to_double(h.normal().x()), to_double(h.normal().y()), to_double(h.normal().z())}));
      if (h.is_degenerate()) continue;
      FaceTriangles ft = face_triangles(p, static_cast<int>(f));
      for (const FaceTriangle& t : ft.triangles) {
        const Vec3d& a = v[p.faces()[f][t.v[0]]];
        m.tris.push_back({a, add(v[p.faces()[f][t.v[1]]], a, -1), add(v[p.faces()[f][t.v[2]]], a, -1), static_cast<int>(b),
                          static_cast<int>(f)});
      }
    }
  }
  const double diag = std::sqrt(dot(add(hi, lo, -1), add(hi, lo, -1)));
  m.eps = 1e-9 * (std::isfinite(diag) && diag > 0 ? diag : 1);
  m.order.resize(m.tris.size());
  std::iota(m.order.begin(), m.order.end(), 0);
  if (!m.tris.empty()) m.build(0, static_cast<int>(m.tris.size()));
}

WhittedScene::~WhittedScene() = default;

bool WhittedScene::hit(const Vec3d& from, const Vec3d& dir, double& t, int& body, int& face, int from_body) const {
  const Impl& m = *impl_;
  if (m.nodes.empty()) return false;
  const Vec3d inv{1 / dir[0], 1 / dir[1], 1 / dir[2]};
  double best = INFINITY;
  body = from_body;
  const double near = from_body >= 0 ? -m.eps : 0;
  int stack[128], top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Impl::Node& n = m.nodes[stack[--top]];
    if (!Impl::box_hit(n, from, inv, best, near)) continue;
    if (n.left < 0) {
      for (int k = n.first; k < n.first + n.count; ++k) {
        const Impl::Tri& tr = m.tris[m.order[k]];
        double d = m.tri_hit(tr, from, dir);
        const bool ahead = d > m.eps || (from_body >= 0 && tr.body != from_body && d > -m.eps);
        if (!ahead) continue;
        // Surfaces that coincide (a glass body standing on the floor): the ray leaving a body
        // meets the other body's face there, whatever the order of the triangles.
        const bool other = tr.body != from_body && body == from_body;
        if (d < best - m.eps || (d < best + m.eps && (other || d < best)))
          if (!(d >= best - m.eps && body != from_body && tr.body == from_body)) best = d, body = tr.body, face = tr.face;
      }
      continue;
    }
    if (top + 2 <= 128) stack[top++] = n.left, stack[top++] = n.right;
  }
  if (!(best < INFINITY)) return false;
  t = best;
  return true;
}

Rgb WhittedScene::trace(const Vec3d& from, const Vec3d& dir, int depth, int from_body) const {
  double t;
  int b, f;
  if (!hit(from, dir, t, b, f, from_body)) return impl_->options.background;
  return shade(b, f, add(from, dir, t), dir, depth, -1);
}

Rgb WhittedScene::shade_first(int body, int face, const Vec3d& at, const Vec3d& dir, bool exact_tir) const {
  return shade(body, face, at, dir, impl_->options.depth, exact_tir ? 1 : 0);
}

Rgb WhittedScene::shade(int body, int face, const Vec3d& at, const Vec3d& dir, int depth, int tir) const {
  const Impl& m = *impl_;
  Material mat = m.materials[body];
  const Vec3d& out = m.normals[body][face];
  const bool front = dot(dir, out) < 0;  // entering the body (its outward side faces the ray)
  const Vec3d n = bumped_normal(mat, at, front ? out : Vec3d{-out[0], -out[1], -out[2]});
  mat.colour = surface_colour(mat, at, out);
  // The local part: each light scaled by what its shadow ray lets through (transparent faces
  // pass their transparency, opaque ones nothing).
  Lighting lit = m.lighting;
  lit.lights.clear();
  for (Light l : m.lighting.lights) {
    Vec3d to = l.type == Light::Type::Directional ? unit(l.direction) : add(l.position, at, -1);
    const double reach = l.type == Light::Type::Directional ? INFINITY : std::sqrt(dot(to, to));
    to = unit(to);
    double pass = 1;
    Vec3d from = at;
    double gone = 0;
    for (int k = 0; k < 32 && pass > 0; ++k) {
      double t;
      int b, f;
      if (!hit(from, to, t, b, f, k == 0 ? body : -1) || gone + t >= reach) break;
      pass *= m.materials[b].transparency;
      gone += t;
      from = add(from, to, t);
    }
    if (pass <= 0) continue;
    l.intensity *= pass;
    lit.lights.push_back(l);
  }
  const double kr = mat.reflection, kt = mat.transparency;
  Rgb local = hlr::shade(mat, lit, at, n, Vec3d{-dir[0], -dir[1], -dir[2]});
  if (depth <= 0 || (kr == 0 && kt == 0)) return local;
  const Vec3d r = unit(add(dir, n, -2 * dot(dir, n)));
  Rgb result{0, 0, 0};
  for (int c = 0; c < 3; ++c) result[c] = (1 - kr - kt) * local[c];
  double to_mirror = kr;
  if (kt > 0) {
    const double eta = front ? 1 / mat.ior : mat.ior;
    Vec3d t;
    const bool ok = refract(dir, n, eta, t);
    const bool total = tir >= 0 ? tir == 1 : !ok;
    if (total || !ok) {
      to_mirror += kt;
    } else {
      Rgb c = trace(at, t, depth - 1, body);
      for (int k = 0; k < 3; ++k) result[k] += kt * c[k];
    }
  }
  if (to_mirror > 0) {
    Rgb c = trace(at, r, depth - 1, body);
    for (int k = 0; k < 3; ++k) result[k] += to_mirror * c[k];
  }
  for (double& c : result) c = std::clamp(c, 0.0, 1.0);
  return result;
}

}  // namespace hlr
