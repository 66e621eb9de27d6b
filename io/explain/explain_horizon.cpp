// Exam mode, the floating horizon (see explain_parts.hpp; course notes section 24): the grid,
// the picture's axes, then for each cut in the order it is drawn (nearest first) its points in
// the picture, the upper and lower horizons it is tested against, each point's verdict, and
// each crossing with a horizon (the notes' X as the meeting of two lines), all exact, by the
// notes' method (the horizons made of the cuts); then where the exact surface's drawing (the
// strips between cuts count too) differs, and its picture.
#include "algorithms/horizon/floating_horizon.hpp"
#include "io/explain/explain_parts.hpp"
#include "io/pipeline/horizon.hpp"
#include "io/writers/svg_writer.hpp"

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

// The visible runs of one cut and segment, as "[t0, t1]" joined; "-" when none.
std::string runs_text(const HorizonResult& r, int curve, int segment) {
  std::string out;
  for (const HorizonPiece& p : r.visible)
    if (p.curve == curve && p.segment == segment) out += (out.empty() ? "" : ", ") + std::string("[") + q(p.t0) + ", " + q(p.t1) + "]";
  return out.empty() ? "-" : out;
}

// The notes' answer beside the exact surface's: every segment where they differ.
Section exact_surface_section(const HeightGrid& g, const HorizonResult& notes, const HorizonResult& exact) {
  Section sec("horizon_exact");
  sec.value("horizon_exact_note",
            "The notes' method tests each cut against the horizons of the cuts in front of it. The surface between two cuts "
            "(its cells, each split along the diagonal (i, j)-(i+1, j+1)) can rise above both of them in the picture (a ridge "
            "across the cells, or a view turned about the vertical axis); the exact drawing (hlr horizon) counts those strips too, so it can hide more "
            "of a far cut. The answer above is the notes'; the segments where the exact surface differs are listed here.",
            "Метод конспекта проверяет каждое сечение по горизонтам сечений перед ним. Поверхность между двумя сечениями "
            "(её ячейки, разбитые диагональю (i, j)-(i+1, j+1)) может на картинке подняться выше обоих (гребень поперёк "
            "ячеек или взгляд, повёрнутый вокруг вертикальной оси); точный рисунок поверхности учитывает и эти полосы, поэтому может скрыть больше от "
            "дальнего сечения. Ответ выше — по конспекту; здесь перечислены отрезки, где точная поверхность даёт другое.");
  J& t = sec.table("horizon_differences", {"cut_no", "segment", "horizon_notes_runs", "horizon_exact_runs"});
  for (int j : notes.order)
    for (std::size_t i = 0; i + 1 < g.xs.size(); ++i) {
      const std::string a = runs_text(notes, j, static_cast<int>(i)), b = runs_text(exact, j, static_cast<int>(i));
      if (a != b) t.push_back({ix(j), ix(static_cast<long>(i)) + "-" + ix(static_cast<long>(i) + 1), a, b});
    }
  if (t.empty()) sec.value("horizon_same", "none: here both give the same drawing", "нет: здесь оба дают один и тот же рисунок");
  return sec;
}

}  // namespace

J horizon_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  const HeightGrid& g = pr.grid;
  const View& v = pr.scene.view;
  if (v.type != View::Type::Orthographic) throw std::invalid_argument("the floating horizon takes an orthographic view (view: {direction: [x, y, z]})");
  Camera cam = make_orthographic(v.direction, v.up_given ? std::optional<Vector3>(v.up) : std::nullopt);
  // The notes' method (each cut against the envelopes of the cuts in front) is the answer; the
  // exact surface's (the strips between cuts count too) is shown beside it where they differ.
  std::vector<HorizonStep> steps;
  HorizonResult h = floating_horizon_exact(g, cam, &steps, HorizonRule::Cuts);
  HorizonResult exact = floating_horizon_exact(g, cam, nullptr, HorizonRule::Strips);

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
  auto runs = [](const HorizonResult& r) {
    J res = J::array();
    for (const HorizonPiece& p : r.visible) res.push_back({{"cut", p.curve}, {"segment", p.segment}, {"t", J::array({q(p.t0), q(p.t1)})}});
    return res;
  };
  out["result"]["visible"] = runs(h);
  out["result"]["visible_exact_surface"] = runs(exact);
  out["sections"].push_back(exact_surface_section(g, h, exact).j);
  RenderResult rr = render_horizon(g, cam, "surface");
  SvgOptions so;
  so.hidden_dashed = true;
  so.width_mm = 120;
  out["drawing_svg"] = to_svg(rr.names, rr.drawing, rr.camera, so);
  return out;
}

}  // namespace hlr::explain_parts
