// Exam mode, a section of a body by a plane (see explain_parts.hpp; course notes sections
// 21-22: the clipping plane's test function applied to a solid, docs/design.md "Sections"):
// the test function at every vertex, the edges it crosses with their exact parameters and
// points, and the cap polygon in order. The cut is cut_solid's, as `hlr render --section`
// makes it.
#include <map>
#include <set>

#include "algorithms/sections/section_cut.hpp"
#include "io/explain/explain_parts.hpp"

namespace hlr::explain_parts {
namespace {

std::string side_word(const Rational& f) { return f < 0 ? "kept" : f > 0 ? "removed" : "on-plane"; }

// The cap's border as loops of vertex indices of the cut solid, each in the order its faces
// run (counter-clockwise seen from the removed side).
std::vector<std::vector<int>> cap_loops(const CutSolid& cut) {
  std::set<std::pair<int, int>> all;
  for (std::size_t f = 0; f < cut.faces.size(); ++f)
    if (cut.cap[f] == 0)
      for (std::size_t k = 0; k < cut.faces[f].size(); ++k) all.insert({cut.faces[f][k], cut.faces[f][(k + 1) % cut.faces[f].size()]});
  std::map<int, int> next;
  for (const auto& [u, v] : all)
    if (!all.count({v, u})) next[u] = v;
  std::vector<std::vector<int>> loops;
  while (!next.empty()) {
    std::vector<int> loop;
    int u = next.begin()->first;
    while (next.count(u)) {
      loop.push_back(u);
      const int v = next[u];
      next.erase(u);
      u = v;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace

J section_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  input_section(pr.scene, out);
  const Plane& h = pr.scene.section[0];
  const SceneBody& b = pr.scene.bodies[0];
  const Polyhedron& body = b.body;
  Section test("section_test", b.name);
  test.value("cut_test_function", "f(P) = " + linear_text(h.a(), h.b(), h.c(), h.d()));
  test.value("kept_side", "f(P) ≤ 0", "f(P) ≤ 0");
  J& tv = test.table("vertex_sides", {"vertex", "point", "f", "class"});
  std::vector<Rational> f;
  for (std::size_t v = 0; v < body.num_vertices(); ++v) {
    f.push_back(h.value(body.vertices()[v]));
    tv.push_back({ix(static_cast<long>(v)), pt(body.vertices()[v]), q(f.back()), side_word(f.back())});
  }
  out["sections"].push_back(test.j);
  // The edges whose ends lie on opposite sides: P(t) = U + t·(V − U), t = f(U) / (f(U) − f(V)).
  Section crossed("crossed_edges", b.name);
  J& ct = crossed.table("edge_crossings", {"edge", "fU", "fV", "t", "point"});
  J crossings = J::array();
  for (const auto& [u, v] : body.edges()) {
    if (!((f[u] < 0 && f[v] > 0) || (f[u] > 0 && f[v] < 0))) continue;
    const Rational t = f[u] / (f[u] - f[v]);
    const Point3 p = body.vertices()[u] + t * (body.vertices()[v] - body.vertices()[u]);
    ct.push_back({ix(u) + "-" + ix(v), q(f[u]), q(f[v]), q(t), pt(p)});
    crossings.push_back(pt(p));
  }
  if (crossings.empty()) crossed.value("note", "the plane crosses no edge", "плоскость не пересекает ни одного ребра");
  out["sections"].push_back(crossed.j);
  // The cap: the cut solid's border on the plane, in order.
  const CutSolid cut = cut_solid(body, {h});
  Section cap("cap", b.name);
  J loops = J::array();
  if (cut.state == CutSolid::State::Whole) {
    cap.value("verdict", "the plane does not cut into the body: it is kept whole, no cap",
              "плоскость не рассекает тело: оно остаётся целым, сечения нет");
  } else if (cut.state == CutSolid::State::Removed) {
    cap.value("verdict", "the whole body lies on the removed side", "всё тело лежит по отсекаемую сторону");
  } else if (cut.open) {
    cap.value("verdict", "the body is open: its faces are cut, it gets no cap", "тело незамкнуто: его грани рассечены, сечения нет");
  } else {
    int n = 0;
    for (const std::vector<int>& loop : cap_loops(cut)) {
      J& lt = cap.table("cap_polygon", {"n_corner", "point", "where"});
      J points = J::array();
      for (int v : loop) {
        const Point3& p = cut.vertices[v];
        // Where the corner comes from: a vertex on the plane or a crossed edge.
        std::string where = "-";
        for (std::size_t k = 0; k < body.num_vertices() && where == "-"; ++k)
          if (body.vertices()[k] == p) where = ix(static_cast<long>(k));
        if (where == "-")
          for (const auto& [u, w] : body.edges())
            if (((f[u] < 0 && f[w] > 0) || (f[u] > 0 && f[w] < 0)) &&
                body.vertices()[u] + (f[u] / (f[u] - f[w])) * (body.vertices()[w] - body.vertices()[u]) == p)
              where = ix(u) + "-" + ix(w);
        lt.push_back({std::to_string(++n), pt(p), where});
        points.push_back(pt(p));
      }
      loops.push_back(points);
    }
    cap.value("loops", std::to_string(loops.size()));
    cap.value("cap_corners", std::to_string(n));
  }
  out["sections"].push_back(cap.j);
  out["result"]["crossings"] = crossings;
  out["result"]["cap"] = loops;
  return out;
}

}  // namespace hlr::explain_parts
