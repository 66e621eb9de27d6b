// Exam mode, convexity, decomposition and transforms (see explain_parts.hpp; sections 20, 23).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "algorithms/solids/convex_decomposition.hpp"
#include "algorithms/solids/convexity.hpp"
#include "io/explain/explain_parts.hpp"

namespace hlr::explain_parts {

// The convexity verdict with the page's numbering (describe() counts from 0).
std::string describe_en(const ConvexityResult& r) {
  if (r.verdict != ConvexityResult::Verdict::NonConvex) return describe(r);
  return "not convex: face " + ix(r.face) + " has vertex " + ix(r.vertex_positive) + " on one side of its plane and vertex " +
         ix(r.vertex_negative) + " on the other";
}

// The convexity verdict in the course's Russian words.
std::string describe_ru(const ConvexityResult& r) {
  switch (r.verdict) {
    case ConvexityResult::Verdict::Convex: return "тело выпуклое";
    case ConvexityResult::Verdict::Flat: return "тело плоское (вырожденное): все вершины лежат в плоскости каждой грани";
    case ConvexityResult::Verdict::NoFaces: return "нет граней";
    case ConvexityResult::Verdict::NonConvex:
      return "тело невыпуклое: вершина " + ix(r.vertex_positive) + " лежит по одну сторону плоскости грани " + ix(r.face) +
             ", вершина " + ix(r.vertex_negative) + " — по другую";
  }
  return {};
}

J convexity_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  input_section(pr.scene, out);
  const Polyhedron& p = pr.scene.bodies[0].body;
  Section sec("convexity", pr.scene.bodies[0].name);
  std::vector<std::string> cols = {"face", "plane"};
  for (std::size_t v = 0; v < p.num_vertices(); ++v) cols.push_back("v" + ix(static_cast<long>(v)));
  cols.push_back("one_side");
  J& t = sec.table("signs", cols);
  for (std::size_t f = 0; f < p.num_faces(); ++f) {
    const Plane& h = p.planes()[f];
    J row = {ix(static_cast<long>(f)), row4(h.a(), h.b(), h.c(), h.d())};
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
  sec.value("verdict", describe_en(cv), describe_ru(cv));
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
  J& cuts = sec.table("cuts", {"n_cut", "plane"});
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
    v.push_back({ix(static_cast<long>(i)), Ti ? pt(apply(*Ti, after)) : "-", pt(after)});
    res.push_back(pt(after));
  }
  for (const std::string& n : b.notes) sec.value("note", n);
  out["sections"].push_back(sec.j);
  out["result"]["vertices"] = res;
  return out;
}


}  // namespace hlr::explain_parts
