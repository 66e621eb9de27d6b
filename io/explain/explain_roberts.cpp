// Exam mode, Roberts (see explain_parts.hpp; course notes sections 26-28 and 40).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "algorithms/hlr/roberts.hpp"
#include "algorithms/model/facing.hpp"
#include "io/explain/explain_parts.hpp"
#include "io/views/view_choice.hpp"
#include "io/writers/json_writer.hpp"
#include "kernel/predicates.hpp"

namespace hlr::explain_parts {

namespace {

// The course's candidate-vertex table for one edge against one body: the boundary lines
// h_j = 0, t = 0, t = 1, a = 0 intersected pairwise, each point checked against all of them.
struct Line {
  std::string name;
  Rational a, b, c;  // a·t + b·w = c  (w = the ray parameter "a" of the notes)
};

// The feasible region in the (t, a) plane as an SVG picture (drawing only, doubles): the
// region cut at a height A above its highest vertex, axes, t_min and t_max marked.
std::string region_svg(std::vector<Line> lines, const std::vector<Rational>& p, const std::vector<Rational>& qq,
                       const std::vector<Rational>& w, const Rational& tmin, const Rational& tmax) {
  const int n = static_cast<int>(p.size());
  Rational top = 0;
  std::vector<std::pair<Rational, Rational>> pts;
  auto solve = [&](bool with_cap, const Rational& A) {
    pts.clear();
    if (with_cap) lines.push_back({"a=A", 0, 1, A});
    for (std::size_t x = 0; x < lines.size(); ++x)
      for (std::size_t y = x + 1; y < lines.size(); ++y) {
        Rational det = lines[x].a * lines[y].b - lines[y].a * lines[x].b;
        if (det == 0) continue;
        Rational t = (lines[x].c * lines[y].b - lines[y].c * lines[x].b) / det;
        Rational a = (lines[x].a * lines[y].c - lines[y].a * lines[x].c) / det;
        bool ok = t >= 0 && t <= 1 && a >= 0 && (!with_cap || a <= A);
        for (int j = 0; j < n && ok; ++j) ok = p[j] + qq[j] * t + w[j] * a >= 0;
        if (ok) pts.push_back({t, a});
      }
    if (with_cap) lines.pop_back();
  };
  solve(false, 0);
  for (const auto& [t, a] : pts) top = std::max(top, a);
  Rational A = top * 3 / 2 + 1;
  solve(true, A);
  std::vector<std::pair<double, double>> d;
  for (const auto& [t, a] : pts) d.push_back({to_double(t), to_double(a)});
  double cx = 0, cy = 0;
  for (auto& [x, y] : d) cx += x / d.size(), cy += y / d.size();
  std::sort(d.begin(), d.end(), [&](auto& u, auto& v) { return std::atan2(u.second - cy, u.first - cx) < std::atan2(v.second - cy, v.first - cx); });
  const double W = 320, H = 200, m = 30, ah = to_double(A);
  auto X = [&](double t) { return m + t * (W - 2 * m); };
  auto Y = [&](double a) { return H - m - a / ah * (H - 2 * m); };
  char buf[128];
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"320\" height=\"200\" viewBox=\"0 0 320 200\">";
  svg += "<polygon fill=\"#ddd\" stroke=\"#000\" points=\"";
  for (auto& [x, y] : d) {
    std::snprintf(buf, sizeof buf, "%.1f,%.1f ", X(x), Y(y));
    svg += buf;
  }
  svg += "\"/>";
  std::snprintf(buf, sizeof buf, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#000\"/>", X(0), Y(0), X(1), Y(0));
  svg += buf;
  std::snprintf(buf, sizeof buf, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#000\"/>", X(0), Y(0), X(0), Y(ah));
  svg += buf;
  for (auto [t, label] : {std::make_pair(to_double(tmin), "t_min"), std::make_pair(to_double(tmax), "t_max")}) {
    std::snprintf(buf, sizeof buf, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#c00\" stroke-dasharray=\"4 3\"/>",
                  X(t), Y(0), X(t), Y(ah));
    svg += buf;
    std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" fill=\"#c00\">%s</text>", X(t) + 2, m - 8, label);
    svg += buf;
  }
  std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\">t</text><text x=\"%.1f\" y=\"%.1f\" font-size=\"11\">a</text>",
                X(1) + 4, Y(0) + 4, X(0) - 12, Y(ah) + 4);
  svg += buf;
  std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"9\">0</text><text x=\"%.1f\" y=\"%.1f\" font-size=\"9\">1</text>",
                X(0) - 3, Y(0) + 12, X(1) - 3, Y(0) + 12);
  svg += buf;
  return svg + "</svg>";
}

// p + q·t + w·a as a student writes it: "2 − 4t − a" (zero terms left out, unit coefficients
// bare, minus signs as operators, fractions as 3/5·t).
std::string linear_text(const Rational& p, const Rational& qt, const Rational& w) {
  std::string out;
  auto term = [&](const Rational& c, const std::string& var) {
    if (c == 0) return;
    Rational a = abs(c);
    std::string mag = var.empty() ? q(a) : a == 1 ? var : q(a) + (a.get_den() == 1 ? "" : "·") + var;
    if (out.empty())
      out = (c < 0 ? "−" : "") + mag;
    else
      out += (c < 0 ? " − " : " + ") + mag;
  };
  term(p, "");
  term(qt, "t");
  term(w, "a");
  return out.empty() ? "0" : out;
}

J edge_body_table(const Point3& p1, const Point3& p2, const BodyMatrixData& V, const RowVector4& g, Section& sec,
                  const std::string& prefix) {
  const int n = static_cast<int>(V.cols());
  Vector3 d = p2 - p1;
  RowVector4 P, D;
  P << p1.x(), p1.y(), p1.z(), 1;
  D << d.x(), d.y(), d.z(), 0;
  std::vector<Rational> p = row_times_matrix(P, V), qq = row_times_matrix(D, V), w = row_times_matrix(g, V);
  J& ineq = sec.table(prefix + "inequalities", {"face", "p", "q", "w", "h"});
  for (int j = 0; j < n; ++j)
    ineq.push_back({ix(j), q(p[j]), q(qq[j]), q(w[j]), linear_text(p[j], qq[j], w[j]) + " > 0"});
  std::vector<Line> lines;
  for (int j = 0; j < n; ++j) lines.push_back({"h" + ix(j), qq[j], w[j], -p[j]});
  lines.push_back({"t=0", 1, 0, 0});
  lines.push_back({"t=1", 1, 0, 1});
  lines.push_back({"a=0", 0, 1, 0});
  J& cand = sec.table(prefix + "candidates", {"lines", "t", "a", "feasible"});
  std::optional<Rational> tmin, tmax;
  std::vector<Rational> pierce;  // feasible vertices on a = 0: where the edge pierces the body
  for (std::size_t x = 0; x < lines.size(); ++x)
    for (std::size_t y = x + 1; y < lines.size(); ++y) {
      const Line &L1 = lines[x], &L2 = lines[y];
      Rational det = L1.a * L2.b - L2.a * L1.b;
      if (det == 0) {
        cand.push_back({L1.name + " ∩ " + L2.name, "-", "-", "parallel"});
        continue;
      }
      Rational t = (L1.c * L2.b - L2.c * L1.b) / det, a = (L1.a * L2.c - L2.a * L1.c) / det;
      bool ok = t >= 0 && t <= 1 && a >= 0;
      for (int j = 0; j < n && ok; ++j) ok = p[j] + qq[j] * t + w[j] * a >= 0;
      cand.push_back({L1.name + " ∩ " + L2.name, q(t), q(a), ok ? "yes" : "no"});
      if (ok && a == 0 && t > 0 && t < 1 && std::find(pierce.begin(), pierce.end(), t) == pierce.end()) pierce.push_back(t);
      if (ok) {
        if (!tmin || t < *tmin) tmin = t;
        if (!tmax || t > *tmax) tmax = t;
      }
    }
  OpenInterval iv = hidden_interval(p1, p2, V, g);
  if (tmin && tmax && *tmin < *tmax) sec.j["svg"] = region_svg(lines, p, qq, w, *tmin, *tmax);
  if (!pierce.empty()) {
    std::sort(pierce.begin(), pierce.end());
    std::string list;
    for (const Rational& t : pierce) list += (list.empty() ? "" : ", ") + std::string("t = ") + q(t) + " " + pt(p1 + t * (p2 - p1));
    sec.value("penetration", list);
  }
  J res;
  res["t_min"] = tmin ? q(*tmin) : "-";
  res["t_max"] = tmax ? q(*tmax) : "-";
  Rational lo = iv.lo && *iv.lo > 0 ? *iv.lo : Rational(0), hi = iv.hi && *iv.hi < 1 ? *iv.hi : Rational(1);
  res["hidden"] = !iv.empty && lo < hi ? "(" + q(lo) + ", " + q(hi) + ")" : "none";
  // t_min and t_max (and the penetration points) come from the closed region h_j >= 0; a point
  // is hidden only where every h_j > 0 (the strict test). Say so where the two differ.
  const bool hidden = !iv.empty && lo < hi;
  if (tmin && tmax && *tmin < *tmax && (!hidden || lo != *tmin || hi != *tmax)) {
    std::string faces;
    for (int j = 0; j < n; ++j)
      if (p[j] == 0 && qq[j] == 0) faces += (faces.empty() ? "" : ", ") + ix(j);
    std::string en = "t_min and t_max bound the closed region (h_j ≥ 0); a point is hidden only where every h_j > 0. ";
    std::string ru = "t_min и t_max ограничивают замкнутую область (h_j ≥ 0); точка скрыта, только если все h_j > 0. ";
    if (!hidden) {
      en += "No point of the region passes the strict test";
      ru += "Ни одна точка области не проходит строгую проверку";
      if (!faces.empty()) {
        en += ": the edge lies in the plane of face " + faces + " (p = q = 0 there, so h = w·a > 0 would need the region beyond that face)";
        ru += ": ребро лежит в плоскости грани " + faces + " (там p = q = 0, и h = w·a > 0 требует точек за этой гранью)";
      }
      en += ", so no part of the edge is hidden by this body.";
      ru += ", поэтому эта часть ребра не скрыта этим телом.";
    } else {
      en += "The strict test keeps " + res["hidden"].get<std::string>() + ".";
      ru += "Строгая проверка оставляет " + res["hidden"].get<std::string>() + ".";
    }
    sec.value("strict_test", en, ru);
  }
  return res;
}

}  // namespace

namespace {

// The cast shadow of a convex body on the ground plane (axis k = value): each vertex V moved
// away from the light along the light vector L to the plane, S = V − s·L with
// s = (V_k − value) / L_k, and the shadow's outline, the convex hull of the S (exact).
void cast_shadow_section(const SceneBody& body, const std::pair<int, Rational>& ground, const Vector3& L, J& out) {
  const int k = ground.first, u = (k + 1) % 3, w = (k + 2) % 3;
  const char* axis[3] = {"x", "y", "z"};
  Section sec("cast_shadow", body.name);
  sec.value("ground", std::string(axis[k]) + " = " + q(ground.second));
  if (L[k] <= 0) {
    sec.value("no_cast_shadow", "the light is not above the ground (L_" + std::string(axis[k]) + " ≤ 0): no shadow falls on it",
              "источник не над землёй (L_" + std::string(axis[k]) + " ≤ 0): тень на неё не падает");
    out["sections"].push_back(sec.j);
    return;
  }
  J& t = sec.table("shadow_vertices", {"vertex", "V_point", "s", "S"});
  std::vector<Exact2> pts;
  std::vector<Point3> shadow;
  for (std::size_t v = 0; v < body.body.num_vertices(); ++v) {
    const Point3& p = body.body.vertices()[v];
    Rational s = (p[k] - ground.second) / L[k];
    Point3 S(p.x() - s * L.x(), p.y() - s * L.y(), p.z() - s * L.z());
    t.push_back({ix(static_cast<long>(v)), pt(p), q(s), pt(S)});
    pts.push_back({S[u], S[w]});
    shadow.push_back(S);
  }
  // Monotone chain, counter-clockwise seen from the light's side of the ground.
  std::vector<std::size_t> idx(pts.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return pts[a] < pts[b]; });
  idx.erase(std::unique(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return pts[a] == pts[b]; }), idx.end());
  std::vector<std::size_t> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t start = hull.size();
    for (std::size_t n = 0; n < idx.size(); ++n) {
      std::size_t i = pass == 0 ? idx[n] : idx[idx.size() - 1 - n];
      while (hull.size() >= start + 2 && orient2d(pts[hull[hull.size() - 2]], pts[hull.back()], pts[i]) <= 0) hull.pop_back();
      hull.push_back(i);
    }
    hull.pop_back();
  }
  std::string corners;
  Rational area2 = 0;
  for (std::size_t n = 0; n < hull.size(); ++n) {
    corners += (corners.empty() ? "" : ", ") + pt(shadow[hull[n]]);
    const Exact2 &a = pts[hull[n]], &b = pts[hull[(n + 1) % hull.size()]];
    area2 += a[0] * b[1] - a[1] * b[0];
  }
  sec.value("shadow_outline", corners);
  sec.value("shadow_area", q(area2 / 2));
  out["sections"].push_back(sec.j);
}

}  // namespace

J roberts_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  input_section(pr.scene, out);
  std::vector<const Polyhedron*> polys;
  std::vector<DrawingBody> names;
  for (const SceneBody& b : pr.scene.bodies) {
    polys.push_back(&b.body);
    names.push_back({b.name, b.source});
  }
  Camera cam = choose_camera({}, &pr.scene.view, polys);
  LineOptions ro;
  ro.edges = EdgeSelection::All;
  RobertsResult r = roberts(polys, cam, ro);
  const RowVector4 g = cam.viewpoint();
  // The matrix every later value of a body is computed with: [VT] = [T]^-1·[V] of the body as
  // typed when it is transformed (the course's route, printed in its table), else its [V]. Its
  // columns are positive multiples of the world matrix's, so every sign is the same.
  std::vector<BodyMatrixData> shown;
  for (std::size_t i = 0; i < polys.size(); ++i) shown.push_back(r.matrices[i].V);
  for (std::size_t i = 0; i < polys.size(); ++i) {
    const Polyhedron& p = *polys[i];
    const BodyMatrix& bm = r.matrices[i];
    Section sec("body_matrix", pr.scene.bodies[i].name);
    sec.value("interior_point", pt(bm.interior));
    J& rows = sec.table("planes", {"face", "plane", "S_V", "negated", "V"});
    // The plane of each face from its vertex order as typed (a turned face gives the opposite
    // plane, so [S]·[V] changes sign and so does the decision to negate the column; the
    // corrected column is the same).
    const SceneBody& sb = pr.scene.bodies[i];
    const bool typed = sb.typed_faces.size() == p.num_faces();
    for (std::size_t f = 0; f < p.num_faces(); ++f) {
      const bool turned = typed && sb.typed_faces[f] != p.faces()[f];
      const Plane h = turned ? p.planes()[f].opposite() : p.planes()[f];
      const Rational sv = turned ? -bm.s_v[f] : bm.s_v[f];
      int c = static_cast<int>(f);
      rows.push_back({ix(static_cast<long>(f)), row4(h.a(), h.b(), h.c(), h.d()), q(sv), sv < 0 ? "yes" : "no",
                      row4(bm.V(0, c), bm.V(1, c), bm.V(2, c), bm.V(3, c))});
    }
    const Matrix4& T = pr.scene.bodies[i].transform;
    if (T != identity_transform()) {
      auto Ti = inverse(T);
      auto mat = [&](const Matrix4& m, const std::string& caption) {
        J& t = sec.table(caption, {"row", "c1", "c2", "c3", "c4"});
        for (int a = 0; a < 4; ++a) t.push_back({std::to_string(a + 1), q(m(a, 0)), q(m(a, 1)), q(m(a, 2)), q(m(a, 3))});
      };
      mat(T, "T");
      if (Ti) {
        mat(*Ti, "T_inverse");
        std::vector<Point3> orig;
        for (const Point3& v : p.vertices()) orig.push_back(apply(*Ti, v));
        Polyhedron original(orig, p.faces());
        BodyMatrix b0 = body_matrix(original);
        BodyMatrixData VT = transformed_body_matrix(b0.V, T);
        J& vt = sec.table("VT", {"face", "V", "VT"});
        for (int c = 0; c < VT.cols(); ++c)
          vt.push_back({ix(c), row4(b0.V(0, c), b0.V(1, c), b0.V(2, c), b0.V(3, c)), row4(VT(0, c), VT(1, c), VT(2, c), VT(3, c))});
        shown[i] = VT;
      }
    }
    out["sections"].push_back(sec.j);
    Section fac("facing", pr.scene.bodies[i].name);
    J cast;  // the cast shadow on the ground, after the facing
    cast["sections"] = J::array();
    fac.value("E", cam.perspective ? "[" + q(-cam.eye.x()) + " " + q(-cam.eye.y()) + " " + q(-cam.eye.z()) + " -1]"
                                   : "[" + q(-cam.direction.x()) + " " + q(-cam.direction.y()) + " " + q(-cam.direction.z()) + " 0]");
    RowVector4 E;
    if (cam.perspective)
      E << -cam.eye.x(), -cam.eye.y(), -cam.eye.z(), -1;
    else
      E << -cam.direction.x(), -cam.direction.y(), -cam.direction.z(), 0;
    const std::vector<Rational> ev = row_times_matrix(E, shown[i]);
    J& fr = fac.table("facing_table", {"face", "EV", "class"});
    for (std::size_t f = 0; f < ev.size(); ++f)
      fr.push_back({ix(static_cast<long>(f)), q(ev[f]), r.facing[i][f] < 0 ? "non-facing" : r.facing[i][f] == 0 ? "edge-on" : "facing"});
    J& sh = fac.table("self_hidden", {"edge", "face_pair"});
    for (const Segment& s : r.segments)
      if (s.body == static_cast<int>(i) && s.self_hidden)
        sh.push_back({ix(s.v0) + "-" + ix(s.v1), ix(s.face0) + ", " + ix(s.face1)});
    if (pr.scene.light) {
      const Vector3& L = *pr.scene.light;
      RowVector4 LE;
      LE << -L.x(), -L.y(), -L.z(), 0;
      std::vector<Rational> lv = row_times_matrix(LE, shown[i]);
      fac.value("L", "[" + q(-L.x()) + " " + q(-L.y()) + " " + q(-L.z()) + " 0]");
      J& lt = fac.table("light_table", {"face", "LV", "self_shadowed", "visible_shadow"});
      RowVector4 toward_light;  // facing from the light: the same test as from the viewer
      toward_light << L.x(), L.y(), L.z(), 0;
      std::vector<std::size_t> visible_shadow;
      for (std::size_t f = 0; f < lv.size(); ++f) {
        const int j = static_cast<int>(f);
        bool shadowed = facing_sign(Plane(-bm.V(0, j), -bm.V(1, j), -bm.V(2, j), -bm.V(3, j)), toward_light) < 0;
        lt.push_back({ix(static_cast<long>(f)), q(lv[f]), shadowed ? "yes" : "no", shadowed && r.facing[i][f] > 0 ? "yes" : "no"});
        if (shadowed && r.facing[i][f] > 0) visible_shadow.push_back(f);
      }
      // The notes' answer: each visible shadow face with its plane (the column of [VT]).
      J& vp = fac.table("visible_shadow_planes", {"face", "plane_equation"});
      for (std::size_t f : visible_shadow) {
        const int c = static_cast<int>(f);
        vp.push_back({ix(static_cast<long>(f)), linear_text(shown[i](0, c), shown[i](1, c), shown[i](2, c), shown[i](3, c)) + " = 0"});
      }
      if (pr.scene.ground) cast_shadow_section(pr.scene.bodies[i], *pr.scene.ground, L, cast);
    }
    out["sections"].push_back(fac.j);
    for (const auto& c : cast["sections"]) out["sections"].push_back(c);
  }
  // Every edge (or the ones asked for) against every other body.
  for (const Segment& s : r.segments) {
    if (s.kind != Segment::Kind::Edge || s.self_hidden) continue;
    if (!pr.edges.empty()) {
      bool asked = false;
      for (const auto& e : pr.edges) asked = asked || (e[0] == s.body && e[1] == s.v0 && e[2] == s.v1);
      if (!asked) continue;
    }
    for (std::size_t k = 0; k < polys.size(); ++k) {
      if (static_cast<int>(k) == s.body) continue;
      Section sec("edge_vs_body", pr.scene.bodies[s.body].name + " " + ix(s.v0) + "-" + ix(s.v1) + " / " +
                                      pr.scene.bodies[k].name);
      sec.value("P1", pt(s.from()));
      sec.value("P2", pt(s.to()));
      sec.value("g", row4(g(0), g(1), g(2), g(3)));
      J res = edge_body_table(s.from(), s.to(), shown[k], g, sec, "");
      sec.value("t_min", res["t_min"].get<std::string>());
      sec.value("t_max", res["t_max"].get<std::string>());
      sec.value("hidden_interval", res["hidden"].get<std::string>());
      out["sections"].push_back(sec.j);
    }
  }
  Section jl("junction_lines");
  J& jr = jl.table("junctions", {"bodies", "from", "to"});
  for (const Segment& s : r.segments)
    if (s.kind == Segment::Kind::Intersection)
      jr.push_back({pr.scene.bodies[s.body].name + " / " + pr.scene.bodies[s.body2].name, pt(s.from()), pt(s.to())});
  out["sections"].push_back(jl.j);
  Section res("visible_segments");
  J& vr = res.table("visible", {"line", "from", "to"});
  J segs = J::array();
  for (const Segment& s : r.segments)
    for (const Piece& p : s.pieces) {
      segs.push_back(piece_json(s, p));
      if (!p.visible) continue;
      std::string what = s.kind == Segment::Kind::Edge ? pr.scene.bodies[s.body].name + " " + ix(s.v0) + "-" + ix(s.v1)
                                                       : pr.scene.bodies[s.body].name + " / " + pr.scene.bodies[s.body2].name;
      vr.push_back({what, pt(s.at(p.t0)), pt(s.at(p.t1))});
    }
  out["sections"].push_back(res.j);
  SvgOptions so;
  so.hidden_dashed = true;
  so.width_mm = 120;
  so.vertex_labels = true;  // every table names vertices by number
  so.label_base = index_base;
  out["result"]["segments"] = segs;
  out["drawing_svg"] = to_svg(names, r, cam, so);
  return out;
}


}  // namespace hlr::explain_parts
