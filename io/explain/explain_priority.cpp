// Exam mode, the priority-list (painter's) algorithm (see explain_parts.hpp; course notes
// sections 32-34, part 3.3): the polygons with their test functions f = ax + by + cz + d, the
// sign f takes on the eye's side and their depth ranges; the list sorted by z_min, farthest
// first; then every step in order: each pair put to the notes' five tests (each answer, and
// the test functions' values at the corners, so the reader sees why), the tests with the roles
// swapped, each swap with its mark, each cyclic overlap, each cut by a plane with the test
// function at the corners and the exact parts, each polygon painted. A picture of the lines.
#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/surfaces/priority_list.hpp"
#include "io/explain/explain_parts.hpp"
#include "io/views/view_choice.hpp"
#include "io/writers/svg_writer.hpp"

namespace hlr::explain_parts {

namespace {

std::string corners3(const std::vector<Point3>& c) {
  std::string out;
  for (const Point3& p : c) out += (out.empty() ? "" : ", ") + pt(p);
  return out;
}

std::string values_text(const std::vector<Rational>& v) {
  std::string out;
  for (const Rational& x : v) out += (out.empty() ? "" : ", ") + q(x);
  return out;
}

std::string plane_text(const Plane& h) { return "f = " + linear_text(h.a(), h.b(), h.c(), h.d()); }

std::string sign_text(int s) { return s > 0 ? "+" : s < 0 ? "−" : "0"; }

}  // namespace

J priority_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  input_section(pr.scene, out);
  std::vector<const Polyhedron*> polys;
  for (const SceneBody& b : pr.scene.bodies) polys.push_back(&b.body);
  Camera cam = choose_camera({}, &pr.scene.view, polys);
  LineOptions lo;
  lo.edges = EdgeSelection::All;
  LineDrawing lines = face_occluders(polys, cam, lo);
  PriorityOptions po;
  po.trace = true;
  po.max_polygons = 400;
  PriorityResult res = priority_list(polys, cam, lines, po);

  // Names: body/face (#k for a triangle of a face that is not convex); a cut's parts .1 and .2.
  std::vector<std::string> names(res.polygons.size());
  for (std::size_t i = 0; i < res.initial; ++i) {
    const PriorityPolygon& p = res.polygons[i];
    names[i] = pr.scene.bodies[p.body].name + "/" + ix(p.face) + (p.piece ? "#" + std::to_string(p.piece) : std::string());
  }
  for (const PriorityStep& st : res.steps)
    if (st.kind == PriorityStep::Kind::Split)
      for (std::size_t k = 0; k < st.parts.size(); ++k) names[st.parts[k]] = names[st.a] + "." + std::to_string(k + 1);
  auto plane_of = [&](int i) -> const Plane& { return polys[res.polygons[i].body]->planes()[res.polygons[i].face]; };
  auto eye_sign = [&](int i) {
    const Plane& h = plane_of(i);
    return cam.perspective ? sgn(h.value(cam.eye)) : sgn(dot(h.normal(), cam.direction));
  };

  Section in("pl_input");
  in.value("view", cam.perspective ? "eye " + pt(cam.eye) + ", target " + pt(cam.target) : vec(cam.direction));
  in.value("depth", cam.perspective ? "z = −(P − E)·(target − E): larger is nearer" : "z = (x, y, z)·" + vec(cam.direction) + ": larger is nearer",
           cam.perspective ? "z = −(P − E)·(target − E): больше — ближе" : "z = (x, y, z)·" + vec(cam.direction) + ": больше — ближе");
  J& tp = in.table("pl_polygons", {"polygon", "corners3", "test_function", "eye_side", "z_min", "z_max"});
  for (std::size_t i = 0; i < res.initial; ++i) {
    const PriorityPolygon& p = res.polygons[i];
    tp.push_back({names[i], corners3(p.corners), plane_text(plane_of(static_cast<int>(i))), sign_text(eye_sign(static_cast<int>(i))),
                  q(p.zmin), q(p.zmax)});
  }
  out["sections"].push_back(in.j);

  for (const PriorityStep& st : res.steps) {
    switch (st.kind) {
      case PriorityStep::Kind::Sort: {
        Section s("pl_sort");
        J& t = s.table("pl_list", {"order", "polygon", "z_min", "z_max"});
        for (std::size_t k = 0; k < st.list.size(); ++k) {
          const PriorityPolygon& p = res.polygons[st.list[k]];
          t.push_back({std::to_string(k + 1), names[st.list[k]], q(p.zmin), q(p.zmax)});
        }
        out["sections"].push_back(s.j);
        break;
      }
      case PriorityStep::Kind::Tests: {
        Section s("pl_tests", names[st.a] + " / " + names[st.b]);
        s.value("f_b_at_a", values_text(st.f_b_at_a) + " (" + sign_text(st.eye_b) + ")");
        s.value("f_a_at_b", values_text(st.f_a_at_b) + " (" + sign_text(st.eye_a) + ")");
        J& t = s.table("pl_answers", {"test", "question", "answer"});
        for (int k = 1; k <= 5; ++k) {
          std::string ans = st.passed == 0 || k <= st.passed ? (k == st.passed ? "yes" : "no") : "-";
          t.push_back({std::to_string(k), J{{"en", word("pl_q" + std::to_string(k), Lang::En)}, {"ru", word("pl_q" + std::to_string(k), Lang::Ru)}}, ans});
        }
        if (st.passed == 0) {
          t.push_back({"3'", J{{"en", word("pl_q3s", Lang::En)}, {"ru", word("pl_q3s", Lang::Ru)}}, st.swapped == 3 ? "yes" : "no"});
          if (st.swapped != 3) t.push_back({"4'", J{{"en", word("pl_q4s", Lang::En)}, {"ru", word("pl_q4s", Lang::Ru)}}, st.swapped == 4 ? "yes" : "no"});
        }
        if (st.passed)
          s.value("outcome", names[st.a] + " cannot hide " + names[st.b], names[st.a] + " не может закрыть " + names[st.b]);
        else if (st.swapped)
          s.value("outcome", names[st.b] + " must be painted before " + names[st.a], names[st.b] + " надо рисовать раньше " + names[st.a]);
        else
          s.value("outcome", "neither can go first: " + names[st.a] + " crosses the plane of " + names[st.b],
                  "ни один не может идти первым: " + names[st.a] + " пересекает плоскость " + names[st.b]);
        out["sections"].push_back(s.j);
        break;
      }
      case PriorityStep::Kind::Swap: {
        Section s("pl_swap", names[st.b]);
        s.value("head_before", names[st.a]);
        out["sections"].push_back(s.j);
        break;
      }
      case PriorityStep::Kind::Cycle: {
        Section s("pl_cycle", names[st.b]);
        s.value("head_before", names[st.a]);
        out["sections"].push_back(s.j);
        break;
      }
      case PriorityStep::Kind::Split: {
        Section s("pl_split", names[st.a]);
        if (st.along_outline) {
          s.value("cutter", names[st.b] + " (outline)", names[st.b] + " (контур)");
        } else {
          s.value("cutter", names[st.b]);
          s.value("cut_plane", plane_text(plane_of(st.b)));
          s.value("f_at_corners", values_text(st.values));
        }
        J& t = s.table("pl_parts", {"polygon", "corners3", "pl_cut_points"});
        const auto& before = res.polygons[st.a].corners;
        for (int part : st.parts) {
          std::string cuts;
          for (const Point3& c : res.polygons[part].corners)
            if (std::find(before.begin(), before.end(), c) == before.end()) cuts += (cuts.empty() ? "" : ", ") + pt(c);
          t.push_back({names[part], corners3(res.polygons[part].corners), cuts});
        }
        out["sections"].push_back(s.j);
        break;
      }
      case PriorityStep::Kind::Paint: {
        Section s("pl_paint", names[st.a]);
        out["sections"].push_back(s.j);
        break;
      }
    }
  }
  Section r("pl_result");
  J& t = r.table("pl_order", {"order", "polygon", "corners3"});
  J order = J::array();
  for (std::size_t k = 0; k < res.order.size(); ++k) {
    const PriorityPolygon& p = res.polygons[res.order[k]];
    t.push_back({std::to_string(k + 1), names[res.order[k]], corners3(p.corners)});
    J c = J::array();
    for (const Point3& x : p.corners) c.push_back(J::array({q(x.x()), q(x.y()), q(x.z())}));
    order.push_back({{"polygon", names[res.order[k]]}, {"body", p.body}, {"face", p.face}, {"corners", c}});
  }
  r.value("pl_counts", std::to_string(res.pairs) + " / " + std::to_string(res.swaps) + " / " + std::to_string(res.cycles) + " / " +
                           std::to_string(res.splits));
  out["sections"].push_back(r.j);
  out["result"]["order"] = order;
  out["drawing_svg"] = problem_drawing_svg(pr, lines, cam);
  return out;
}

}  // namespace hlr::explain_parts
