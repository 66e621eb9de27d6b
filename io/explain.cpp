// Exam-mode solutions (see explain.hpp).
#include "io/explain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "algorithms/convex_decomposition.hpp"
#include "algorithms/convexity.hpp"
#include "algorithms/roberts.hpp"
#include "io/json_writer.hpp"
#include "io/view_choice.hpp"
#include "kernel/predicates.hpp"

namespace hlr {
namespace {

using J = SolutionJson;

std::string q(const Rational& x) { return to_string(x); }
std::string pt(const Point3& p) { return "(" + q(p.x()) + ", " + q(p.y()) + ", " + q(p.z()) + ")"; }
std::string vec(const Vector3& p) { return "(" + q(p.x()) + ", " + q(p.y()) + ", " + q(p.z()) + ")"; }
std::string row4(const Rational& a, const Rational& b, const Rational& c, const Rational& d) {
  return "[" + q(a) + " " + q(b) + " " + q(c) + " " + q(d) + "]";
}

// A section: a title id, optional notes (id -> value), tables (caption id, column ids, rows).
struct Section {
  J j;
  explicit Section(const std::string& title, const std::string& subject = "") {
    j["title"] = title;
    if (!subject.empty()) j["subject"] = subject;
    j["values"] = J::object();
    j["tables"] = J::array();
  }
  void value(const std::string& id, const std::string& v) { j["values"][id] = v; }
  J& table(const std::string& caption, std::vector<std::string> columns) {
    J t;
    t["caption"] = caption;
    t["columns"] = columns;
    t["rows"] = J::array();
    j["tables"].push_back(t);
    return j["tables"].back()["rows"];
  }
};

void input_section(const Scene& s, J& out) {
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const SceneBody& b = s.bodies[i];
    Section sec("input", b.name);
    J& vr = sec.table("vertices", {"vertex", "x", "y", "z"});
    for (std::size_t v = 0; v < b.body.num_vertices(); ++v) {
      const Point3& p = b.body.vertices()[v];
      vr.push_back({std::to_string(v), q(p.x()), q(p.y()), q(p.z())});
    }
    J& fr = sec.table("faces", {"face", "vertices"});
    for (std::size_t f = 0; f < b.body.num_faces(); ++f) {
      std::string l;
      for (int v : b.body.faces()[f]) {
        if (!l.empty()) l += ' ';
        l += std::to_string(v);
      }
      fr.push_back({std::to_string(f), l});
    }
    out["sections"].push_back(sec.j);
  }
}

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
    ineq.push_back({std::to_string(j), q(p[j]), q(qq[j]), q(w[j]), q(p[j]) + " + " + q(qq[j]) + "·t + " + q(w[j]) + "·a > 0"});
  std::vector<Line> lines;
  for (int j = 0; j < n; ++j) lines.push_back({"h" + std::to_string(j), qq[j], w[j], -p[j]});
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
  return res;
}

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
  for (std::size_t i = 0; i < polys.size(); ++i) {
    const Polyhedron& p = *polys[i];
    const BodyMatrix& bm = r.matrices[i];
    Section sec("body_matrix", pr.scene.bodies[i].name);
    sec.value("interior_point", pt(bm.interior));
    J& rows = sec.table("planes", {"face", "plane", "S_V", "negated", "V"});
    for (std::size_t f = 0; f < p.num_faces(); ++f) {
      const Plane& h = p.planes()[f];
      int c = static_cast<int>(f);
      rows.push_back({std::to_string(f), row4(h.a(), h.b(), h.c(), h.d()), q(bm.s_v[f]), bm.negated[f] ? "yes" : "no",
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
          vt.push_back({std::to_string(c), row4(b0.V(0, c), b0.V(1, c), b0.V(2, c), b0.V(3, c)), row4(VT(0, c), VT(1, c), VT(2, c), VT(3, c))});
      }
    }
    out["sections"].push_back(sec.j);
    Section fac("facing", pr.scene.bodies[i].name);
    fac.value("E", cam.perspective ? "[" + q(-cam.eye.x()) + " " + q(-cam.eye.y()) + " " + q(-cam.eye.z()) + " -1]"
                                   : "[" + q(-cam.direction.x()) + " " + q(-cam.direction.y()) + " " + q(-cam.direction.z()) + " 0]");
    J& fr = fac.table("facing_table", {"face", "EV", "class"});
    for (std::size_t f = 0; f < r.ev[i].size(); ++f)
      fr.push_back({std::to_string(f), q(r.ev[i][f]), r.facing[i][f] < 0 ? "non-facing" : r.facing[i][f] == 0 ? "edge-on" : "facing"});
    J& sh = fac.table("self_hidden", {"edge", "face_pair"});
    for (const Segment& s : r.segments)
      if (s.body == static_cast<int>(i) && s.self_hidden)
        sh.push_back({std::to_string(s.v0) + "-" + std::to_string(s.v1), std::to_string(s.face0) + ", " + std::to_string(s.face1)});
    if (pr.scene.light) {
      const Vector3& L = *pr.scene.light;
      RowVector4 LE;
      LE << -L.x(), -L.y(), -L.z(), 0;
      std::vector<Rational> lv = row_times_matrix(LE, bm.V);
      fac.value("L", "[" + q(-L.x()) + " " + q(-L.y()) + " " + q(-L.z()) + " 0]");
      J& lt = fac.table("light_table", {"face", "LV", "self_shadowed", "visible_shadow"});
      for (std::size_t f = 0; f < lv.size(); ++f)
        lt.push_back({std::to_string(f), q(lv[f]), lv[f] < 0 ? "yes" : "no", lv[f] < 0 && r.ev[i][f] > 0 ? "yes" : "no"});
    }
    out["sections"].push_back(fac.j);
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
      Section sec("edge_vs_body", pr.scene.bodies[s.body].name + " " + std::to_string(s.v0) + "-" + std::to_string(s.v1) + " / " +
                                      pr.scene.bodies[k].name);
      sec.value("P1", pt(s.from()));
      sec.value("P2", pt(s.to()));
      J res = edge_body_table(s.from(), s.to(), r.matrices[k].V, g, sec, "");
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
      std::string what = s.kind == Segment::Kind::Edge ? pr.scene.bodies[s.body].name + " " + std::to_string(s.v0) + "-" + std::to_string(s.v1)
                                                       : pr.scene.bodies[s.body].name + " / " + pr.scene.bodies[s.body2].name;
      vr.push_back({what, pt(s.at(p.t0)), pt(s.at(p.t1))});
    }
  out["sections"].push_back(res.j);
  SvgOptions so;
  so.hidden_dashed = true;
  so.width_mm = 120;
  out["result"]["segments"] = segs;
  out["drawing_svg"] = to_svg(names, r, cam, so);
  return out;
}

J cyrus_beck_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  J results = J::array();
  for (std::size_t i = 0; i < pr.segments.size(); ++i) {
    const auto& [p1, p2] = pr.segments[i];
    CyrusBeckResult r = cyrus_beck(*pr.clipper, p1, p2, true);
    Section sec("cyrus_beck", std::to_string(i + 1));
    sec.value("clipper", pr.clipper_text);
    sec.value("P1", pt(p1));
    sec.value("P2", pt(p2));
    sec.value("D", vec(p2 - p1));
    J& t = sec.table("cb_table", {"face", "n", "Wn", "Dn", "t", "limit"});
    for (const CyrusBeckRow& row : r.table) {
      const char* kind = row.kind == CyrusBeckRow::Kind::Lower ? "lower" : row.kind == CyrusBeckRow::Kind::Upper ? "upper"
                         : row.kind == CyrusBeckRow::Kind::ParallelInside ? "parallel-inside" : "parallel-outside";
      t.push_back({std::to_string(row.face), vec(row.n), q(row.wn), q(row.dn), row.t ? q(*row.t) : "-", kind});
    }
    sec.value("t_lower", q(r.t_lower));
    sec.value("t_upper", q(r.t_upper));
    J res;
    res["segment"] = i + 1;
    if (r.visible()) {
      Point3 a = p1 + r.t_lower * (p2 - p1), b = p1 + r.t_upper * (p2 - p1);
      sec.value("visible_part", pt(a) + " - " + pt(b));
      res["visible"] = true;
      res["from"] = pt(a);
      res["to"] = pt(b);
      res["t"] = J::array({q(r.t_lower), q(r.t_upper)});
    } else {
      sec.value("visible_part", r.status == CyrusBeckResult::Status::Point ? "point" : "none");
      res["visible"] = false;
    }
    results.push_back(res);
    out["sections"].push_back(sec.j);
  }
  out["result"]["segments"] = results;
  return out;
}

J midpoint_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  J results = J::array();
  for (std::size_t i = 0; i < pr.segments.size(); ++i) {
    const auto& [p1, p2] = pr.segments[i];
    std::vector<MidpointStep> trace;
    MidpointResult m = midpoint_clip(*pr.window, p1, p2, pr.eps, &trace);
    CyrusBeckResult cb = cyrus_beck(*pr.clipper, p1, p2, false);
    Section sec("midpoint", std::to_string(i + 1));
    sec.value("clipper", pr.clipper_text);
    sec.value("eps", q(pr.eps));
    J& t = sec.table("outcodes", {"end", "point", "outcode", "notes_outcode"});
    t.push_back({"P1", pt(p1), outcode_bits(outcode(*pr.window, p1)), outcode_bits(notes_outcode(*pr.window, p1))});
    t.push_back({"P2", pt(p2), outcode_bits(outcode(*pr.window, p2)), outcode_bits(notes_outcode(*pr.window, p2))});
    J& st = sec.table("steps", {"n_step", "phase", "point", "outcode"});
    for (std::size_t k = 0; k < trace.size(); ++k)
      st.push_back({std::to_string(k + 1), trace[k].phase, pt(trace[k].point), outcode_bits(trace[k].code)});
    sec.value("trivial", m.trivially_accepted ? "accepted" : m.trivially_rejected ? "rejected" : "no");
    sec.value("subdivisions", std::to_string(m.subdivisions));
    J res;
    res["segment"] = i + 1;
    res["visible"] = m.visible;
    if (m.visible) {
      sec.value("visible_part", pt(m.from) + " - " + pt(m.to));
      res["from"] = pt(m.from);
      res["to"] = pt(m.to);
    } else {
      sec.value("visible_part", "none");
    }
    if (cb.visible())
      sec.value("exact_part", pt(p1 + cb.t_lower * (p2 - p1)) + " - " + pt(p1 + cb.t_upper * (p2 - p1)));
    results.push_back(res);
    out["sections"].push_back(sec.j);
  }
  out["result"]["segments"] = results;
  return out;
}

J convexity_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  input_section(pr.scene, out);
  const Polyhedron& p = pr.scene.bodies[0].body;
  Section sec("convexity", pr.scene.bodies[0].name);
  std::vector<std::string> cols = {"face", "plane"};
  for (std::size_t v = 0; v < p.num_vertices(); ++v) cols.push_back(std::string("v").append(std::to_string(v)));
  cols.push_back("one_side");
  J& t = sec.table("signs", cols);
  for (std::size_t f = 0; f < p.num_faces(); ++f) {
    const Plane& h = p.planes()[f];
    J row = {std::to_string(f), row4(h.a(), h.b(), h.c(), h.d())};
    bool pos = false, neg = false;
    for (const Point3& v : p.vertices()) {
      Sign s = side_of_plane(h, v);
      pos = pos || s == Sign::Positive;
      neg = neg || s == Sign::Negative;
      row.push_back(s == Sign::Positive ? "+" : s == Sign::Negative ? "-" : "0");
    }
    row.push_back(pos && neg ? "no" : "yes");
    t.push_back(row);
  }
  ConvexityResult cv = convexity(p);
  sec.value("verdict", describe(cv));
  out["sections"].push_back(sec.j);
  out["result"]["convex"] = cv.convex();
  out["result"]["verdict"] = describe(cv);
  return out;
}

J decompose_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  input_section(pr.scene, out);
  const Polyhedron& p = pr.scene.bodies[0].body;
  Decomposition d = convex_decomposition(p);
  Section sec("decompose", pr.scene.bodies[0].name);
  J& cuts = sec.table("cuts", {"step", "plane"});
  for (std::size_t i = 0; i < d.cuts.size(); ++i) cuts.push_back({std::to_string(i + 1), row4(d.cuts[i].a(), d.cuts[i].b(), d.cuts[i].c(), d.cuts[i].d())});
  J& pieces = sec.table("pieces", {"piece", "vertices", "faces", "volume", "surface", "cut", "both"});
  J res = J::array();
  Rational total = 0;
  for (std::size_t i = 0; i < d.pieces.size(); ++i) {
    const ConvexPiece& c = d.pieces[i];
    std::size_t n[3] = {0, 0, 0};
    for (FaceOrigin o : c.faces) ++n[static_cast<int>(o)];
    Rational vol = six_volume(c.body) / 6;
    total += vol;
    std::string vs;
    for (const Point3& v : c.body.vertices()) {
      if (!vs.empty()) vs += ' ';
      vs += pt(v);
    }
    pieces.push_back({std::to_string(i + 1), vs, std::to_string(c.body.num_faces()), q(vol), std::to_string(n[0]), std::to_string(n[1]), std::to_string(n[2])});
    J pj;
    pj["volume"] = q(vol);
    pj["vertices"] = J::array();
    for (const Point3& v : c.body.vertices()) pj["vertices"].push_back(pt(v));
    res.push_back(pj);
  }
  sec.value("total_volume", q(total));
  sec.value("body_volume", q(six_volume(p) / 6));
  out["sections"].push_back(sec.j);
  out["result"]["pieces"] = res;
  return out;
}

J transform_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  const SceneBody& b = pr.scene.bodies[0];
  Section sec("transform", b.name);
  for (std::size_t k = 0; k < b.steps.size(); ++k) {
    J& st = sec.table("step", {"row", "c1", "c2", "c3", "c4"});
    const Matrix4& m = b.steps[k].second;
    for (int a = 0; a < 4; ++a) st.push_back({std::to_string(a + 1), q(m(a, 0)), q(m(a, 1)), q(m(a, 2)), q(m(a, 3))});
    sec.j["tables"].back()["caption"] = "step";
    sec.j["tables"].back()["step"] = std::to_string(k + 1) + ": " + b.steps[k].first;
  }
  J& t = sec.table("T", {"row", "c1", "c2", "c3", "c4"});
  for (int a = 0; a < 4; ++a)
    t.push_back({std::to_string(a + 1), q(b.transform(a, 0)), q(b.transform(a, 1)), q(b.transform(a, 2)), q(b.transform(a, 3))});
  auto Ti = inverse(b.transform);
  J& v = sec.table("vertices_moved", {"vertex", "before", "after"});
  J res = J::array();
  for (std::size_t i = 0; i < b.body.num_vertices(); ++i) {
    const Point3& after = b.body.vertices()[i];
    v.push_back({std::to_string(i), Ti ? pt(apply(*Ti, after)) : "-", pt(after)});
    res.push_back(pt(after));
  }
  for (const std::string& n : b.notes) sec.value("note", n);
  out["sections"].push_back(sec.j);
  out["result"]["vertices"] = res;
  return out;
}

// ---------------------------------------------------------------- words
const std::map<std::string, std::pair<std::string, std::string>>& words() {
  static const std::map<std::string, std::pair<std::string, std::string>> w = {
      {"input", {"Input", "Исходные данные"}},
      {"vertices", {"Vertices", "Вершины"}},
      {"faces", {"Faces", "Грани"}},
      {"vertex", {"vertex", "вершина"}},
      {"face", {"face", "грань"}},
      {"body_matrix", {"Body matrix", "Матрица тела"}},
      {"planes", {"Face planes, [S]·[V] and the corrected body matrix", "Плоскости граней, [S]·[V] и исправленная матрица тела"}},
      {"plane", {"plane [a b c d]", "плоскость [a b c d]"}},
      {"S_V", {"[S]·[V]", "[S]·[V]"}},
      {"negated", {"column negated", "столбец умножен на -1"}},
      {"V", {"column of [V]", "столбец [V]"}},
      {"VT", {"[VT] = [T]^-1·[V]", "[VT] = [T]^-1·[V]"}},
      {"T", {"[T]", "[T]"}},
      {"T_inverse", {"[T]^-1", "[T]^-1"}},
      {"interior_point", {"interior point [S]", "внутренняя точка [S]"}},
      {"facing", {"Non-facing faces and self-hidden edges", "Нелицевые грани и самоскрытые рёбра"}},
      {"facing_table", {"E·[VT] per face", "E·[VT] для каждой грани"}},
      {"EV", {"E·[VT]", "E·[VT]"}},
      {"class", {"class", "вид"}},
      {"v:non-facing", {"non-facing", "нелицевая"}},
      {"v:facing", {"facing", "лицевая"}},
      {"v:edge-on", {"edge-on", "видна с ребра"}},
      {"v:parallel", {"parallel", "параллельны"}},
      {"v:parallel-inside", {"parallel, inside", "параллельна, внутри"}},
      {"v:parallel-outside", {"parallel, outside", "параллельна, снаружи"}},
      {"v:accepted", {"accepted", "принят"}},
      {"v:rejected", {"rejected", "отброшен"}},
      {"v:point", {"a single point", "одна точка"}},
      {"v:yes", {"yes", "да"}},
      {"v:no", {"no", "нет"}},
      {"v:none", {"none", "нет"}},
      {"v:lower", {"lower", "нижний"}},
      {"v:upper", {"upper", "верхний"}},
      {"face_pair", {"faces", "грани"}},
      {"self_hidden", {"Self-hidden edges (both faces non-facing)", "Самоскрытые рёбра (обе грани нелицевые)"}},
      {"edge", {"edge", "ребро"}},
      {"light_table", {"L·[VT] per face (light)", "L·[VT] для каждой грани (свет)"}},
      {"LV", {"L·[VT]", "L·[VT]"}},
      {"self_shadowed", {"self-shadowed", "в собственной тени"}},
      {"visible_shadow", {"visible and in shadow", "видима и в тени"}},
      {"edge_vs_body", {"Edge against body", "Ребро и тело"}},
      {"inequalities", {"p = P1·[VT], q = (P2 - P1)·[VT], w = g·[VT], h_j > 0", "p = P1·[VT], q = (P2 - P1)·[VT], w = g·[VT], h_j > 0"}},
      {"candidates", {"Candidate vertices of the region (pairs of boundary lines)", "Вершины-кандидаты области (пары граничных прямых)"}},
      {"lines", {"lines", "прямые"}},
      {"feasible", {"feasible", "допустима"}},
      {"hidden_interval", {"hidden part of the edge (t)", "скрытая часть ребра (t)"}},
      {"junction_lines", {"Penetration (junction) lines", "Линии взаимного проникновения"}},
      {"junctions", {"Junction lines", "Линии проникновения"}},
      {"bodies", {"bodies", "тела"}},
      {"visible_segments", {"Visible segments", "Видимые отрезки"}},
      {"visible", {"Visible pieces", "Видимые части"}},
      {"line", {"line", "линия"}},
      {"from", {"from", "от"}},
      {"to", {"to", "до"}},
      {"cyrus_beck", {"Cyrus-Beck clipping, segment", "Отсечение Кируса-Бека, отрезок"}},
      {"cb_table", {"Per face: inner normal n, W·n, D·n, t = -(W·n)/(D·n)", "Для каждой грани: внутренняя нормаль n, W·n, D·n, t = -(W·n)/(D·n)"}},
      {"n", {"n", "n"}},
      {"Wn", {"W·n", "W·n"}},
      {"Dn", {"D·n", "D·n"}},
      {"limit", {"limit", "предел"}},
      {"lower", {"lower", "нижний"}},
      {"upper", {"upper", "верхний"}},
      {"t_lower", {"t lower", "t нижнее"}},
      {"t_upper", {"t upper", "t верхнее"}},
      {"visible_part", {"visible part", "видимая часть"}},
      {"exact_part", {"exact visible part (Cyrus-Beck)", "точная видимая часть (Кирус-Бек)"}},
      {"midpoint", {"Midpoint subdivision, segment", "Разбиение средней точкой, отрезок"}},
      {"outcodes", {"Outcodes (LRBTNF)", "Коды концов (ЛПНВБД)"}},
      {"outcode", {"outcode", "код"}},
      {"notes_outcode", {"outcode by the notes' rule", "код по правилу конспекта"}},
      {"end", {"end", "конец"}},
      {"point", {"point", "точка"}},
      {"trivial", {"trivially", "тривиально"}},
      {"subdivisions", {"subdivisions", "делений"}},
      {"convexity", {"Convexity test", "Проверка выпуклости"}},
      {"signs", {"Side of every vertex per face plane", "Положение каждой вершины относительно плоскости грани"}},
      {"one_side", {"all on one side", "все с одной стороны"}},
      {"verdict", {"verdict", "вывод"}},
      {"decompose", {"Convex decomposition", "Разбиение на выпуклые части"}},
      {"cuts", {"Cuts (planes of faces at which the body is not convex)", "Разрезы (плоскости граней, относительно которых тело невыпукло)"}},
      {"pieces", {"Pieces", "Части"}},
      {"piece", {"piece", "часть"}},
      {"volume", {"volume", "объём"}},
      {"surface", {"faces on the surface", "граней на поверхности"}},
      {"cut", {"faces on a cut", "граней на разрезе"}},
      {"both", {"faces on both", "граней на обоих"}},
      {"total_volume", {"total volume of the pieces", "суммарный объём частей"}},
      {"body_volume", {"volume of the body", "объём тела"}},
      {"transform", {"Transformation", "Преобразование"}},
      {"vertices_moved", {"Vertices [X]·[T]", "Вершины [X]·[T]"}},
      {"before", {"before", "до"}},
      {"after", {"after", "после"}},
      {"row", {"row", "строка"}},
      {"step", {"[T] of step", "[T] шага"}},
      {"steps", {"Midpoints in order", "Средние точки по порядку"}},
      {"phase", {"phase", "этап"}},
      {"n_step", {"step", "шаг"}},
      {"v:search", {"search for an inside point", "поиск внутренней точки"}},
      {"v:end 1", {"halving toward end 1", "деление к концу 1"}},
      {"v:end 2", {"halving toward end 2", "деление к концу 2"}},
      {"penetration", {"penetration points (a = 0)", "точки проникновения (a = 0)"}},
      {"yes", {"yes", "да"}},
      {"no", {"no", "нет"}},
      {"none", {"none", "нет"}},
      {"clipper", {"clipper", "отсекатель"}},
      {"eps", {"eps", "eps"}},
      {"segment", {"segment", "отрезок"}},
      {"note", {"note", "примечание"}},
      {"problem", {"Problem", "Задача"}},
      {"solution", {"Solution", "Решение"}},
      {"drawing", {"Drawing", "Рисунок"}},
      {"region", {"The region of hidden points in the (t, a) plane", "Область скрытых точек на плоскости (t, a)"}},
  };
  return w;
}

std::string word(const std::string& id, Lang lang) {
  const auto& w = words();
  auto it = w.find(id);
  if (it == w.end()) return id;
  return lang == Lang::Ru ? it->second.second : it->second.first;
}

// Cell text: classes and yes/no are words too (ids "v:...").
std::string cell(const J& c, Lang lang) {
  std::string s = c.get<std::string>();
  if (words().count("v:" + s)) return word("v:" + s, lang);
  return s;
}

}  // namespace

SolutionJson explain(const Problem& pr) {
  J out;
  out["problem"] = to_string(pr.type);
  out["file"] = std::filesystem::path(pr.file).filename().string();
  if (!pr.title.empty()) out["title"] = pr.title;
  J body;
  switch (pr.type) {
    case Problem::Type::Roberts: body = roberts_solution(pr); break;
    case Problem::Type::CyrusBeck: body = cyrus_beck_solution(pr); break;
    case Problem::Type::Midpoint: body = midpoint_solution(pr); break;
    case Problem::Type::Convexity: body = convexity_solution(pr); break;
    case Problem::Type::Decompose: body = decompose_solution(pr); break;
    case Problem::Type::Transform: body = transform_solution(pr); break;
  }
  for (auto it = body.begin(); it != body.end(); ++it) out[it.key()] = it.value();
  return out;
}

std::string explain_markdown(const SolutionJson& s, Lang lang) {
  std::string o = "# " + word("problem", lang) + ": " + s["problem"].get<std::string>();
  if (s.contains("title")) o += " — " + s["title"].get<std::string>();
  o += "\n\n";
  for (const J& sec : s["sections"]) {
    o += "## " + word(sec["title"], lang);
    if (sec.contains("subject")) o += ": " + sec["subject"].get<std::string>();
    o += "\n\n";
    for (auto it = sec["values"].begin(); it != sec["values"].end(); ++it)
      o += "- " + word(it.key(), lang) + ": " + cell(it.value(), lang) + "\n";
    if (!sec["values"].empty()) o += "\n";
    for (const J& t : sec["tables"]) {
      o += "**" + word(t["caption"], lang) + (t.contains("step") ? " " + t["step"].get<std::string>() : "") + "**\n\n";
      if (t["rows"].empty()) {
        o += "(" + word("none", lang) + ")\n\n";
        continue;
      }
      o += "|";
      for (const J& c : t["columns"]) {
        o += ' ';
        o += word(c, lang);
        o += " |";
      }
      o += "\n|";
      for (std::size_t i = 0; i < t["columns"].size(); ++i) o += "---|";
      o += "\n";
      for (const J& r : t["rows"]) {
        o += "|";
        for (const J& c : r) {
          o += ' ';
          o += cell(c, lang);
          o += " |";
        }
        o += "\n";
      }
      o += "\n";
    }
  }
  return o;
}

std::string explain_html(const SolutionJson& s, Lang lang) {
  auto esc = [](const std::string& x) {
    std::string e;
    for (char c : x) {
      if (c == '&') e += "&amp;";
      else if (c == '<') e += "&lt;";
      else if (c == '>') e += "&gt;";
      else e += c;
    }
    return e;
  };
  std::string title = word("problem", lang) + ": " + s["problem"].get<std::string>();
  if (s.contains("title")) title += " — " + s["title"].get<std::string>();
  std::string o = "<!DOCTYPE html>\n<html lang=\"" + std::string(lang == Lang::Ru ? "ru" : "en") +
                  "\">\n<head><meta charset=\"utf-8\"><title>" + esc(title) +
                  "</title>\n<style>body{font-family:sans-serif;max-width:60em;margin:2em auto}table{border-collapse:collapse;margin:.5em 0}"
                  "td,th{border:1px solid #999;padding:.2em .5em;font-family:monospace}</style></head>\n<body>\n<h1>" +
                  esc(title) + "</h1>\n";
  if (s.contains("drawing_svg")) {
    std::string svg = s["drawing_svg"];
    auto at = svg.find("<svg");
    o += "<h2>" + esc(word("drawing", lang)) + "</h2>\n" + (at == std::string::npos ? "" : svg.substr(at)) + "\n";
  }
  for (const J& sec : s["sections"]) {
    o += "<h2>" + esc(word(sec["title"], lang)) + (sec.contains("subject") ? ": " + esc(sec["subject"]) : "") + "</h2>\n";
    if (!sec["values"].empty()) {
      o += "<ul>\n";
      for (auto it = sec["values"].begin(); it != sec["values"].end(); ++it)
        o += "<li>" + esc(word(it.key(), lang)) + ": " + esc(cell(it.value(), lang)) + "</li>\n";
      o += "</ul>\n";
    }
    if (sec.contains("svg")) o += "<p>" + esc(word("region", lang)) + "</p>\n" + sec["svg"].get<std::string>() + "\n";
    for (const J& t : sec["tables"]) {
      o += "<p><b>" + esc(word(t["caption"], lang)) + (t.contains("step") ? " " + esc(t["step"]) : "") + "</b></p>\n<table><tr>";
      for (const J& c : t["columns"]) o += "<th>" + esc(word(c, lang)) + "</th>";
      o += "</tr>\n";
      for (const J& r : t["rows"]) {
        o += "<tr>";
        for (const J& c : r) o += "<td>" + esc(cell(c, lang)) + "</td>";
        o += "</tr>\n";
      }
      o += "</table>\n";
    }
  }
  o += "</body>\n</html>\n";
  return o;
}

}  // namespace hlr
