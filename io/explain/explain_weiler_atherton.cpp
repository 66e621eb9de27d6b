// Exam mode, the Weiler–Atherton algorithm (see explain_parts.hpp; course notes section 31):
// the polygons in the picture with their planes and nearest depths, then every step in order:
// the preliminary depth sort, each clip against the front polygon into the inside and outside
// lists, each inside polygon removed as hidden or found in front (with the depth comparison at
// its corners), the cut of polygons that pierce each other, the recursive subdivision by the
// polygon that violated the order (and a cyclic overlap when a clipper comes back), the
// polygons displayed; every corner exact. A picture of the visible lines.
#include "algorithms/clip/weiler_atherton.hpp"
#include "algorithms/hlr/face_occluders.hpp"
#include "io/explain/explain_parts.hpp"
#include "io/pipeline/render.hpp"
#include "io/views/view_choice.hpp"
#include "io/writers/svg_writer.hpp"

namespace hlr::explain_parts {

namespace {

std::string corners(const std::vector<Exact2>& p) {
  std::string out;
  for (const Exact2& c : p) out += (out.empty() ? "" : ", ") + std::string("(") + q(c[0]) + ", " + q(c[1]) + ")";
  return out;
}

Rational area_of(const std::vector<Exact2>& p) {
  Rational s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) s += p[i][0] * p[(i + 1) % p.size()][1] - p[i][1] * p[(i + 1) % p.size()][0];
  return s / 2;
}

}  // namespace

J weiler_atherton_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  input_section(pr.scene, out);
  std::vector<const Polyhedron*> polys;
  for (const SceneBody& b : pr.scene.bodies) polys.push_back(&b.body);
  Camera cam = choose_camera({}, &pr.scene.view, polys);
  LineOptions lo;
  lo.edges = EdgeSelection::All;
  LineDrawing lines = face_occluders(polys, cam, lo);
  WeilerAthertonOptions wo;
  wo.trace = true;
  wo.max_polygons = 400;
  WeilerAthertonResult wa = weiler_atherton(polys, cam, lines, wo);
  auto name = [&](const WaPolygon& p) {
    return pr.scene.bodies[p.body].name + "/" + ix(p.face) + (p.piece ? "." + std::to_string(p.piece) : std::string());
  };

  PicturePlane pp(cam);
  Section in("wa_input");
  in.value("view", cam.perspective ? "eye " + pt(cam.eye) + ", target " + pt(cam.target) : vec(cam.direction));
  if (cam.perspective)
    in.value("axes", "X = (P − E)·" + vec(pp.r()) + " / (P − E)·" + vec(pp.d()) + ", Y = (P − E)·" + vec(pp.u()) + " / (P − E)·" + vec(pp.d()));
  else
    in.value("axes", "X = (x, y, z)·" + vec(pp.r()) + ", Y = (x, y, z)·" + vec(pp.u()));
  in.value("depth", cam.perspective ? "−l, with P = E + l·dir(X, Y): larger is nearer" : "s, with P = P0(X, Y) + s·" + vec(cam.direction) + " (P0 the point of the picture plane at (X, Y)): larger is nearer",
           cam.perspective ? "−l, где P = E + l·dir(X, Y): больше — ближе" : "s, где P = P0(X, Y) + s·" + vec(cam.direction) + " (P0 — точка картинной плоскости в (X, Y)): больше — ближе");
  out["sections"].push_back(in.j);

  for (const WaStep& st : wa.steps) {
    const std::string level = std::to_string(st.level);
    switch (st.kind) {
      case WaStep::Kind::Sort: {
        Section s("wa_sort", level);
        J& t = s.table("wa_list", {"order", "polygon", "corners", "nearest_depth"});
        for (std::size_t i = 0; i < st.polygons.size(); ++i)
          t.push_back({std::to_string(i + 1), name(st.polygons[i]), corners(st.polygons[i].pts), q(st.depths[i])});
        out["sections"].push_back(s.j);
        break;
      }
      case WaStep::Kind::Clip: {
        Section s("wa_clip", name(st.polygons[0]));
        s.value("level", level);
        s.value("clipper", corners(st.polygons[0].pts));
        J& ti = s.table("wa_inside", {"polygon", "corners"});
        for (const WaPolygon& p : st.inside) ti.push_back({name(p), corners(p.pts)});
        J& to = s.table("wa_outside", {"polygon", "corners"});
        for (const WaPolygon& p : st.outside) to.push_back({name(p), corners(p.pts)});
        out["sections"].push_back(s.j);
        break;
      }
      case WaStep::Kind::Hidden:
      case WaStep::Kind::Violation:
      case WaStep::Kind::Split: {
        const char* title = st.kind == WaStep::Kind::Hidden ? "wa_hidden" : st.kind == WaStep::Kind::Violation ? "wa_in_front" : "wa_split";
        Section s(title, name(st.subject));
        s.value("level", level);
        if (!st.polygons.empty() && st.kind != WaStep::Kind::Split) s.value("clipper", name(st.polygons[0]));
        J& t = s.table("wa_corners", {"corner", "X", "Y", "nearer_by"});
        for (std::size_t i = 0; i < st.subject.pts.size() && i < st.depths.size(); ++i)
          t.push_back({ix(static_cast<long>(i)), q(st.subject.pts[i][0]), q(st.subject.pts[i][1]), q(st.depths[i])});
        if (st.kind == WaStep::Kind::Split) {
          s.value("front_part", corners(st.polygons[0].pts));
          s.value("back_part", corners(st.polygons[1].pts));
        }
        out["sections"].push_back(s.j);
        break;
      }
      case WaStep::Kind::Cycle: {
        Section s("wa_cycle", name(st.subject));
        s.value("level", level);
        out["sections"].push_back(s.j);
        break;
      }
      case WaStep::Kind::Display: {
        Section s("wa_display", name(st.subject));
        s.value("level", level);
        s.value("corners", corners(st.subject.pts));
        s.value("area", q(area_of(st.subject.pts)));
        out["sections"].push_back(s.j);
        break;
      }
    }
  }
  Section res("wa_result");
  J& vr = res.table("wa_visible", {"polygon", "corners", "area"});
  J visible = J::array();
  Rational total = 0;
  for (const WaPolygon& p : wa.visible) {
    Rational a = area_of(p.pts);
    total += a;
    vr.push_back({name(p), corners(p.pts), q(a)});
    J c = J::array();
    for (const Exact2& x : p.pts) c.push_back(J::array({q(x[0]), q(x[1])}));
    visible.push_back({{"body", p.body}, {"face", p.face}, {"corners", c}});
  }
  res.value("total_area", q(total));
  res.value("counts", std::to_string(wa.clips) + " / " + std::to_string(wa.splits) + " / " + std::to_string(wa.recursions) + " / " +
                          std::to_string(wa.cycles));
  out["sections"].push_back(res.j);
  out["result"]["visible"] = visible;
  out["drawing_svg"] = problem_drawing_svg(pr, lines, cam);
  return out;
}

}  // namespace hlr::explain_parts
