// Exam mode, the ray tree of Whitted ray tracing (see explain_parts.hpp; course notes sections
// 43-45): one primary ray, and at every surface it meets the reflected ray r = d − 2(d·n)/(n·n)·n
// and the refracted ray by Snell's law t = η·d + (η·c − √k)·n (unit d, n; c = −d·n,
// k = 1 − η²(1 − c²)), total internal reflection where k < 0. While a ray's origin and
// direction are rational (the primary ray, and reflections of exact rays), its hit, t, the
// point, cos²θ and k are exact and the reflection is exact; a refracted direction has √k, so
// from there on the values are decimals (marked ≈), as the ray tracer computes them.
#include <cmath>
#include <cstdio>

#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/raster/ray_tracing.hpp"
#include "io/explain/explain_parts.hpp"
#include "io/views/view_choice.hpp"

namespace hlr::explain_parts {

namespace {

std::string dec(double v) {
  if (std::fabs(v) < 1e-12) v = 0;  // rounding noise of the doubles, not a value
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}
std::string dec3(const Vec3d& v) { return "≈ (" + dec(v[0]) + ", " + dec(v[1]) + ", " + dec(v[2]) + ")"; }
Vec3d d3(const Point3& p) { return {to_double(p.x()), to_double(p.y()), to_double(p.z())}; }
Vec3d d3(const Vector3& p) { return {to_double(p.x()), to_double(p.y()), to_double(p.z())}; }
double dotd(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3d unitd(const Vec3d& a) {
  const double l = std::sqrt(dotd(a, a));
  return {a[0] / l, a[1] / l, a[2] / l};
}

// Point x of face f's plane inside the closed polygon (crossings in the plane's dominant projection).
bool in_polygon(const Polyhedron& p, int f, const Point3& x) {
  const Vector3 n = p.planes()[f].normal();
  const Rational ax = abs(n.x()), ay = abs(n.y()), az = abs(n.z());
  const int drop = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2, u = drop == 0 ? 1 : 0, w = drop == 2 ? 1 : 2;
  const Face& face = p.faces()[f];
  bool in = false;
  for (std::size_t i = 0; i < face.size(); ++i) {
    const Point3 &a = p.vertices()[face[i]], &b = p.vertices()[face[(i + 1) % face.size()]];
    const Rational cr = (b[u] - a[u]) * (x[w] - a[w]) - (b[w] - a[w]) * (x[u] - a[u]);
    if (cr == 0 && std::min(a[u], b[u]) <= x[u] && x[u] <= std::max(a[u], b[u]) && std::min(a[w], b[w]) <= x[w] && x[w] <= std::max(a[w], b[w]))
      return true;
    const bool ua = a[w] > x[w], ub = b[w] > x[w];
    if (ua != ub && ((cr > 0) == ub)) in = !in;
  }
  return in;
}

struct Node {
  int parent = -1;
  J kind;
  bool exact = true;
  Point3 o;
  Vector3 d;      // exact rays
  Vec3d od, dd;   // every ray, doubles
  int from_body = -1;
  int level = 0;
};

}  // namespace

J ray_tree_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  input_section(pr.scene, out);
  std::vector<const Polyhedron*> polys;
  std::vector<Material> materials;
  for (const SceneBody& b : pr.scene.bodies) {
    polys.push_back(&b.body);
    materials.push_back(b.material.value_or(Material{}));
  }
  WhittedScene doubles(polys, materials, Lighting{}, WhittedOptions{pr.ray_depth, {1, 1, 1}});

  Section in("rt_input");
  in.value("rt_origin", pt(pr.ray_from));
  in.value("rt_direction", vec(pr.ray_direction));
  in.value("rt_depth", std::to_string(pr.ray_depth));
  J& mt = in.table("rt_materials", {"rt_body", "rt_kr", "rt_kt", "rt_ior"});
  for (std::size_t b = 0; b < materials.size(); ++b)
    mt.push_back({pr.scene.bodies[b].name, dec(materials[b].reflection), dec(materials[b].transparency),
                  materials[b].transparency > 0 ? q(materials[b].ior_exact) : "-"});
  out["sections"].push_back(in.j);

  Section tree("rt_tree");
  J& t = tree.table("rt_nodes", {"rt_node", "rt_parent", "rt_kind", "rt_origin", "rt_direction", "rt_hit", "rt_t", "rt_point", "rt_eta", "rt_cos2", "rt_k",
                                 "rt_tir"});
  std::vector<Node> nodes;
  Node root;
  root.kind = J{{"en", "primary"}, {"ru", "первичный"}};
  root.o = pr.ray_from, root.d = pr.ray_direction, root.od = d3(pr.ray_from), root.dd = d3(pr.ray_direction);
  nodes.push_back(root);
  J result = J::array();
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Node nd = nodes[k];
    J cells = J::array({std::to_string(k), nd.parent < 0 ? std::string("-") : std::to_string(nd.parent), nd.kind, nd.exact ? pt(nd.o) : dec3(nd.od), nd.exact ? vec(nd.d) : dec3(nd.dd)});
    int body = -1, face = -1;
    Rational te;
    double td = 0;
    if (nd.exact) {  // every face of the scene, exactly: the nearest hit beyond the origin
      for (std::size_t b = 0; b < polys.size(); ++b)
        for (std::size_t f = 0; f < polys[b]->num_faces(); ++f) {
          const Plane& h = polys[b]->planes()[f];
          if (h.is_degenerate()) continue;
          const Rational nd_ = dot(h.normal(), nd.d);
          if (nd_ == 0) continue;
          const Rational s = -h.value(nd.o) / nd_;
          if (s <= 0 || (body >= 0 && s >= te)) continue;
          const Point3 x = nd.o + s * nd.d;
          if (!in_polygon(*polys[b], static_cast<int>(f), x)) continue;
          body = static_cast<int>(b), face = static_cast<int>(f), te = s;
        }
    } else if (!doubles.hit(nd.od, nd.dd, td, body, face, nd.from_body)) {
      body = -1;
    }
    if (body < 0) {
      cells.push_back(J{{"en", "leaves the scene"}, {"ru", "уходит из сцены"}});
      for (int c = 0; c < 6; ++c) cells.push_back("-");
      t.push_back(cells);
      result.push_back({{"node", k}, {"hit", nullptr}});
      continue;
    }
    const Material& m = materials[body];
    const Plane& h = polys[body]->planes()[face];
    const Vector3 n = h.normal();
    Point3 xe;
    Vec3d xd;
    if (nd.exact) xe = nd.o + te * nd.d, xd = d3(xe);
    else xd = {nd.od[0] + td * nd.dd[0], nd.od[1] + td * nd.dd[1], nd.od[2] + td * nd.dd[2]};
    // Entering the body (its outward normal against the ray): η = 1/ior; leaving: η = ior.
    const bool entering = nd.exact ? dot(n, nd.d) < 0 : dotd(d3(n), nd.dd) < 0;
    const Rational eta_e = entering ? Rational(1 / m.ior_exact) : m.ior_exact;
    std::string cos2, kk, tir_text;
    bool tir = false;
    if (nd.exact) {
      const Rational dn = dot(nd.d, n);
      const Rational c2 = dn * dn / (dot(nd.d, nd.d) * dot(n, n));
      const Rational kr = 1 - eta_e * eta_e * (1 - c2);
      cos2 = q(c2), kk = q(kr), tir = kr < 0;
    } else {
      const double c = dotd(unitd(nd.dd), unitd(d3(n)));
      const double e = to_double(eta_e), kr = 1 - e * e * (1 - c * c);
      cos2 = "≈ " + dec(c * c), kk = "≈ " + dec(kr), tir = kr < 0;
    }
    const bool refracting = m.transparency > 0;
    cells.push_back(pr.scene.bodies[body].name + "/" + ix(face));
    cells.push_back(nd.exact ? q(te) : "≈ " + dec(td));
    cells.push_back(nd.exact ? pt(xe) : dec3(xd));
    cells.push_back(refracting ? q(eta_e) : "-");
    cells.push_back(refracting ? cos2 : "-");
    cells.push_back(refracting ? kk : "-");
    cells.push_back(refracting ? (tir ? "yes" : "no") : "-");
    t.push_back(cells);
    result.push_back({{"node", k}, {"body", body}, {"face", face}, {"exact", nd.exact}});
    if (nd.level >= pr.ray_depth) continue;
    // Children: the reflected ray (mirrors, and all of kt on total internal reflection), the refracted one.
    if (m.reflection > 0 || (refracting && tir)) {
      Node r;
      r.parent = static_cast<int>(k), r.level = nd.level + 1, r.from_body = body;
      r.kind = tir && m.reflection == 0 ? J{{"en", "reflected (total internal reflection)"}, {"ru", "отражённый (полное внутреннее отражение)"}}
                                        : J{{"en", "reflected"}, {"ru", "отражённый"}};
      if (nd.exact) {
        r.o = xe, r.d = nd.d + Rational(-2 * dot(nd.d, n) / dot(n, n)) * n;
        r.od = d3(r.o), r.dd = d3(r.d);
      } else {
        const Vec3d nu = unitd(d3(n));
        const double k2 = 2 * dotd(nd.dd, nu);
        r.exact = false, r.od = xd, r.dd = {nd.dd[0] - k2 * nu[0], nd.dd[1] - k2 * nu[1], nd.dd[2] - k2 * nu[2]};
      }
      nodes.push_back(r);
    }
    if (refracting && !tir) {
      Node r;
      r.parent = static_cast<int>(k), r.level = nd.level + 1, r.from_body = body, r.exact = false;
      r.kind = J{{"en", "refracted"}, {"ru", "преломлённый"}};
      Vec3d nu = unitd(d3(n));
      if (!entering) nu = {-nu[0], -nu[1], -nu[2]};
      Vec3d dir;
      refract(unitd(nd.dd), nu, to_double(eta_e), dir);
      r.od = xd, r.dd = dir;
      nodes.push_back(r);
    }
  }
  tree.value("rt_note", "exact while the ray is rational (the primary ray and reflections of exact rays); a refracted direction holds √k, so its subtree is in decimals (≈)",
             "точно, пока луч рационален (первичный луч и отражения точных лучей); в преломлённом направлении есть √k, поэтому его поддерево — в десятичных числах (≈)");
  out["sections"].push_back(tree.j);
  out["result"]["nodes"] = result;
  return out;
}

}  // namespace hlr::explain_parts
