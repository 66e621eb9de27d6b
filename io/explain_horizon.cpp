// Exam mode, the floating horizon (see explain_parts.hpp; course notes section 24): the grid,
// the picture's axes, then for each cut in the order it is drawn (nearest first) its points in
// the picture, the upper and lower horizons it is tested against, each point's verdict, and
// each crossing with a horizon (the notes' X as the meeting of two lines), all exact; a picture.
#include "algorithms/floating_horizon.hpp"
#include "io/explain_parts.hpp"
#include "io/horizon.hpp"
#include "io/svg_writer.hpp"

namespace hlr::explain_parts {

namespace {

// "Y = 3/2·X − 4", signs written once.
std::string line_text(const HorizonLine& l) {
  std::string out = "Y = ";
  if (l.s != 0) out += (l.s == 1 ? "" : l.s == -1 ? "−" : l.s < 0 ? "−" + q(-l.s) + "·" : q(l.s) + "·") + std::string("X");
  if (l.c != 0 || l.s == 0) {
    if (l.s == 0) out += q(l.c);
    else out += (l.c < 0 ? " − " + q(-l.c) : " + " + q(l.c));
  }
  return out;
}

// A horizon as its pieces: "[X0, X1]: Y = s·X + c".
std::string horizon_text(const std::vector<HorizonPieceLine>& h) {
  std::string out;
  for (const HorizonPieceLine& p : h) out += (out.empty() ? "" : "; ") + std::string("[") + q(p.x0) + ", " + q(p.x1) + "]: " + line_text(p.line);
  return out.empty() ? "-" : out;
}

}  // namespace

J horizon_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  const HeightGrid& g = pr.grid;
  const View& v = pr.scene.view;
  if (v.type != View::Type::Orthographic) throw std::invalid_argument("the floating horizon takes an orthographic view (view: {direction: [x, y, z]})");
  Camera cam = make_orthographic(v.direction, v.up_given ? std::optional<Vector3>(v.up) : std::nullopt);
  std::vector<HorizonStep> steps;
  HorizonResult h = floating_horizon(g, cam, &steps);

  Section in("horizon_input");
  J& grid = in.table("heights", {"cut_no", "z", "y"});
  for (std::size_t j = 0; j < g.zs.size(); ++j) {
    std::string ys;
    for (std::size_t i = 0; i < g.xs.size(); ++i) ys += (i ? ", " : "") + q(g.y(i, j));
    grid.push_back({ix(static_cast<long>(j)), q(g.zs[j]), ys});
  }
  std::string xs;
  for (const Rational& x : g.xs) xs += (xs.empty() ? "" : ", ") + q(x);
  in.value("x_samples", xs);
  Vector3 r = cross(cam.up, cam.direction), u = cross(cam.direction, r);
  in.value("view", vec(cam.direction));
  in.value("axes", "X = (x, y, z)·" + vec(r) + ", Y = (x, y, z)·" + vec(u));
  std::string order;
  for (int j : h.order) order += (order.empty() ? "" : ", ") + ix(j);
  in.value("cut_order", order);
  out["sections"].push_back(in.j);

  for (const HorizonStep& st : steps) {
    Section sec("horizon_cut", ix(st.curve));
    sec.value("upper_horizon", horizon_text(st.upper));
    sec.value("lower_horizon", horizon_text(st.lower));
    J& pts = sec.table("cut_points", {"point", "x", "X", "Y", "verdict"});
    for (std::size_t i = 0; i < st.points.size(); ++i)
      pts.push_back({ix(static_cast<long>(i)), q(g.xs[i]), q(st.points[i][0]), q(st.points[i][1]), st.verdicts[i]});
    J& cr = sec.table("crossings", {"segment", "with", "cut_line", "horizon_line", "X", "Y"});
    for (const auto& c : st.crossings)
      cr.push_back({ix(c.segment) + "-" + ix(c.segment + 1), c.upper ? "upper" : "lower", line_text(c.cut), line_text(c.horizon),
                    "(" + q(c.horizon.c) + " − (" + q(c.cut.c) + ")) / (" + q(c.cut.s) + " − (" + q(c.horizon.s) + ")) = " + q(c.x), q(c.y)});
    J& vis = sec.table("visible_runs", {"segment", "t"});
    for (const HorizonPiece& p : h.visible)
      if (p.curve == st.curve) vis.push_back({ix(p.segment) + "-" + ix(p.segment + 1), "[" + q(p.t0) + ", " + q(p.t1) + "]"});
    out["sections"].push_back(sec.j);
  }
  J res = J::array();
  for (const HorizonPiece& p : h.visible) res.push_back({{"cut", p.curve}, {"segment", p.segment}, {"t", J::array({q(p.t0), q(p.t1)})}});
  out["result"]["visible"] = res;
  RenderResult rr = render_horizon(g, cam, "surface");
  SvgOptions so;
  so.hidden_dashed = true;
  so.width_mm = 120;
  out["drawing_svg"] = to_svg(rr.names, rr.drawing, rr.camera, so);
  return out;
}

}  // namespace hlr::explain_parts
