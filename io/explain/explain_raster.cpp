// Exam mode, the image-space algorithms on a tiny grid (see explain_parts.hpp; course notes
// sections 29-30 Warnock, 32 z-buffer, 34 the scan-line z-buffer): the polygons with their
// picture corners and depth functions s(x, y) (larger is nearer); a z-buffer trace of chosen
// pixels (every polygon's inside test and depth at the centre, the buffer before, kept or
// not); the scan-line table row by row (the y-group list, the active polygons, each span
// X_L..X_R with ΔX_L, ΔX_R per row, Z_L, ΔZ_x per column and ΔZ_y per row, the columns it
// covers); Warnock's windows with each polygon's type and the decision; the frame, the same
// from all three (checked), every number exact.
#include <map>
#include <stdexcept>

#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/raster/raster_scene.hpp"
#include "algorithms/raster/scanline.hpp"
#include "algorithms/raster/warnock.hpp"
#include "algorithms/raster/zbuffer.hpp"
#include "io/explain/explain_parts.hpp"
#include "io/views/view_choice.hpp"
#include "io/writers/svg_writer.hpp"

namespace hlr::explain_parts {

namespace {

std::string xy(const Exact2& p) { return "(" + q(p[0]) + ", " + q(p[1]) + ")"; }

// The depth toward the viewer s(x, y) = −z(x, y) of an orthographic raster polygon (z smaller nearer).
std::array<Rational, 3> s_coefficients(const RasterScene& s, const RasterPolygon& p) {
  const std::array<Rational, 6>& z = s.depth(p);
  return {-z[0], -z[1], -z[2]};
}
Rational s_at(const RasterScene& s, const RasterPolygon& p, const Rational& x, const Rational& y) {
  auto c = s_coefficients(s, p);
  return c[0] + c[1] * x + c[2] * y;
}

}  // namespace

J raster_solution(const Problem& pr) {
  J out;
  out["sections"] = J::array();
  input_section(pr.scene, out);
  std::vector<const Polyhedron*> polys;
  for (const SceneBody& b : pr.scene.bodies) polys.push_back(&b.body);
  const Camera cam = choose_camera({}, &pr.scene.view, polys);
  LineOptions lo;
  lo.edges = EdgeSelection::All;
  const LineDrawing lines = face_occluders(polys, cam, lo);
  // The problem's grid: the window [x0, x1] x [y0, y1] of the picture in W x H pixels.
  RasterGrid g;
  g.width = pr.raster_width, g.height = pr.raster_height;
  g.x0 = pr.raster_window[0], g.y1 = pr.raster_window[3];
  g.xstep = (pr.raster_window[1] - pr.raster_window[0]) / pr.raster_width;
  g.ystep = (pr.raster_window[3] - pr.raster_window[2]) / pr.raster_height;
  g.dx0 = to_double(g.x0), g.dy1 = to_double(g.y1), g.dxstep = to_double(g.xstep), g.dystep = to_double(g.ystep);
  const RasterScene s = raster_scene(polys, cam, lines, g.width, g.height, 1, &g);
  const int np = static_cast<int>(s.polygons.size());

  // Names (body/face, #k for a triangle of a face that is not convex) and one letter per face.
  std::vector<std::string> names(np);
  std::map<int, std::string> letter;  // global face number -> letter
  std::vector<std::string> letter_of(np);
  for (int p = 0; p < np; ++p) {
    const RasterPolygon& sp = s.polygons[p];
    names[p] = pr.scene.bodies[sp.body].name + "/" + ix(sp.face) + (sp.piece ? "#" + std::to_string(sp.piece) : std::string());
    const int id = s.polygons[p].id;
    if (!letter.count(id)) letter[id] = std::string(1, static_cast<char>('A' + letter.size() % 26));
    letter_of[p] = letter[id];
  }
  auto centre_text = [&](int i, int j) { return xy(g.centre(i, j)); };

  Section in("rs_input");
  in.value("rs_grid", std::to_string(g.width) + " × " + std::to_string(g.height) + ": x = " + q(g.x0) + " + (i + 1/2)·" + q(g.xstep) +
                          ", y = " + q(g.y1) + " − (j + 1/2)·" + q(g.ystep));
  in.value("view", vec(cam.direction));
  in.value("rs_depth", "s(x, y): the sight ray through the picture point (x, y) is base + s·v (v: the view direction, toward the viewer); larger s is nearer",
           "s(x, y): параметр точки вдоль v на луче зрения через точку картины (x, y) (v — направление на наблюдателя); чем больше s, тем ближе");
  J& tp = in.table("rs_polygons", {"rs_label", "polygon", "rs_picture_corners", "rs_depth_function"});
  for (int p = 0; p < np; ++p) {
    std::string corners;
    for (const Exact2& c : s.points(s.polygons[p])) corners += (corners.empty() ? "" : ", ") + xy(c);
    auto c = s_coefficients(s, s.polygons[p]);
    tp.push_back({letter_of[p], names[p], corners, "s = " + linear_text(c[1], c[2], 0, c[0])});
  }
  out["sections"].push_back(in.j);

  // The z-buffer (section 32): the frame starts as background with depth −∞; each polygon in
  // turn writes the pixels whose centres it covers where it is nearer than the buffer.
  std::vector<std::array<int, 2>> traced = pr.raster_trace;
  if (traced.empty())
    for (int i = 0; i < g.width && i < 8; ++i) traced.push_back({i, g.height / 2});
  Section zb("rs_zbuffer");
  J& zt = zb.table("rs_trace", {"rs_pixel", "rs_centre", "polygon", "rs_inside", "s", "rs_buffer_before", "rs_kept"});
  for (auto [i, j] : traced) {
    const Exact2 c = g.centre(i, j);
    int cur = -1;
    for (int p = 0; p < np; ++p) {
      const bool in_p = s.covers(s.polygons[p], i, j);
      J before = cur < 0 ? J{{"en", "background, −∞"}, {"ru", "фон, −∞"}} : J(letter_of[cur] + ", " + q(s_at(s, s.polygons[cur], c[0], c[1])));
      J kept = "no";
      if (in_p && (cur < 0 || s.nearer(s.polygons[p], s.polygons[cur], g.cx(i), g.cy(j)))) {
        const bool tie = cur >= 0 && s.depth_order(s.polygons[p], s.polygons[cur], g.cx(i), g.cy(j)) == 0;
        kept = tie ? J{{"en", "yes (a tie: the rule)"}, {"ru", "да (равная глубина: правило)"}} : J("yes");
        cur = p;
      } else if (in_p && cur >= 0 && s.depth_order(s.polygons[p], s.polygons[cur], g.cx(i), g.cy(j)) == 0) {
        kept = J{{"en", "no (a tie: the rule)"}, {"ru", "нет (равная глубина: правило)"}};
      }
      zt.push_back({"(" + std::to_string(i) + ", " + std::to_string(j) + ")", xy(c), letter_of[p] + " " + names[p], in_p ? "yes" : "no",
                    in_p ? q(s_at(s, s.polygons[p], c[0], c[1])) : "-", before, kept});
    }
  }
  zb.value("rs_tie_rule", "a tie in depth goes to the face toward the viewer, then to the lower face number",
           "при равной глубине выбирается лицевая грань, затем грань с меньшим номером");
  out["sections"].push_back(zb.j);
  const FaceIdBuffer by_z = zbuffer(s, {1});

  // The scan-line z-buffer (section 34).
  Section sl("rs_scanline");
  std::vector<Rational> ytop(np), ybottom(np);
  for (int p = 0; p < np; ++p) {
    ytop[p] = ybottom[p] = s.point(s.polygons[p], 0)[1];
    for (const Exact2& c : s.points(s.polygons[p])) ytop[p] = std::max(ytop[p], c[1]), ybottom[p] = std::min(ybottom[p], c[1]);
  }
  auto row_y = [&](int j) { return Rational(g.y1 - rational(2 * j + 1, 2) * g.ystep); };
  J& yg = sl.table("rs_ygroups", {"rs_row", "y", "rs_added"});
  std::vector<char> entered(np, 0);
  J& st = sl.table("rs_spans", {"rs_row", "polygon", "X_L", "X_R", "ΔX_L", "ΔX_R", "Z_L", "ΔZ_x", "ΔZ_y", "rs_columns"});
  J& rows = sl.table("rs_rows", {"rs_row", "y", "rs_active", "rs_frame_row"});
  std::vector<int> frame(static_cast<std::size_t>(g.width) * g.height, -1);
  for (int j = 0; j < g.height; ++j) {
    const Rational y = row_y(j);
    std::string added, active;
    for (int p = 0; p < np; ++p)
      if (!entered[p] && ytop[p] >= y && ybottom[p] <= y) entered[p] = 1, added += (added.empty() ? "" : ", ") + letter_of[p];
    if (!added.empty()) yg.push_back({std::to_string(j), q(y), added});
    for (int p = 0; p < np; ++p) {
      if (!(ytop[p] >= y && ybottom[p] <= y)) continue;
      active += (active.empty() ? "" : ", ") + letter_of[p];
      auto sp = exact_span(s, s.polygons[p], y);
      if (!sp) continue;
      const std::vector<Exact2> pts = s.points(s.polygons[p]);
      auto dx = [&](int side) -> std::string {  // X(y − ystep) − X(y) along the bounding side: C·ystep / B
        if (side < 0) return "-";
        const Exact2 &a = pts[side], &b = pts[(side + 1) % pts.size()];
        return q((b[0] - a[0]) * g.ystep / (a[1] - b[1]));
      };
      auto c = s_coefficients(s, s.polygons[p]);
      std::string cols;
      for (int i = 0; i < g.width; ++i) {
        const Rational x = g.x0 + rational(2 * i + 1, 2) * g.xstep;
        if (x < sp->xl || x > sp->xr) continue;
        cols += (cols.empty() ? "" : " ") + std::to_string(i);
        int& cur = frame[static_cast<std::size_t>(j) * g.width + i];
        if (cur < 0 || s.nearer(s.polygons[p], s.polygons[cur], g.cx(i), g.cy(j))) cur = p;
      }
      st.push_back({std::to_string(j), letter_of[p], q(sp->xl), q(sp->xr), dx(sp->left), dx(sp->right), q(s_at(s, s.polygons[p], sp->xl, y)),
                    q(c[1] * g.xstep), q(-c[2] * g.ystep), cols.empty() ? "-" : cols});
    }
    std::string line;
    for (int i = 0; i < g.width; ++i) {
      const int p = frame[static_cast<std::size_t>(j) * g.width + i];
      line += (i ? " " : "") + (p < 0 ? std::string(".") : letter_of[p]);
    }
    rows.push_back({std::to_string(j), q(y), active.empty() ? "-" : active, line});
  }
  sl.value("rs_spans_note", "X_L, X_R: where the row meets the polygon's left and right sides; ΔX: their change to the next row down; Z_L: s at X_L; ΔZ_x: the change of s per column, ΔZ_y per row down",
           "X_L, X_R: пересечения строки с левой и правой сторонами многоугольника; ΔX: их приращения на следующую строку вниз; Z_L: s в точке X_L; ΔZ_x: приращение s на столбец, ΔZ_y на строку вниз");
  out["sections"].push_back(sl.j);

  // Warnock (sections 29-30).
  std::vector<WarnockWindow> windows;
  WarnockOptions wo;
  wo.threads = 1;
  wo.trace = &windows;
  const FaceIdBuffer by_w = warnock(s, wo);
  Section wn("rs_warnock");
  J& wt = wn.table("rs_windows", {"rs_window", "rs_level", "rs_types", "rs_decision"});
  for (const WarnockWindow& w : windows) {
    const Rational x0 = g.x0 + rational(2 * w.i0 + 1, 2) * g.xstep, x1 = g.x0 + rational(2 * (w.i1 - 1) + 1, 2) * g.xstep;
    const Rational y1 = row_y(w.j0), y0 = row_y(w.j1 - 1);
    std::string types_en, types_ru;
    for (auto [p, surrounding] : w.polygons) {
      bool inside = true;
      for (const Exact2& c : s.points(s.polygons[p])) inside = inside && c[0] >= x0 && c[0] <= x1 && c[1] >= y0 && c[1] <= y1;
      const char* en = surrounding ? "surrounding" : inside ? "contained" : "intersecting";
      const char* ru = surrounding ? "охватывающий" : inside ? "внутренний" : "пересекающий";
      types_en += (types_en.empty() ? "" : ", ") + letter_of[p] + " " + en;
      types_ru += (types_ru.empty() ? "" : ", ") + letter_of[p] + " " + ru;
    }
    if (types_en.empty()) types_en = "all disjoint", types_ru = "все внешние";
    std::string d_en, d_ru;
    const std::string who = w.polygon >= 0 ? letter_of[w.polygon] : ".";
    switch (w.decision) {
      case WarnockWindow::Decision::Empty: d_en = "background", d_ru = "фон"; break;
      case WarnockWindow::Decision::Surrounded: d_en = "filled with " + who + " (in front of all)", d_ru = "закрашивается " + who + " (ближе всех)"; break;
      case WarnockWindow::Decision::Single: d_en = "one polygon: " + who + " scan-converted", d_ru = "один многоугольник: " + who + " растрируется"; break;
      case WarnockWindow::Decision::Pixel: d_en = "one pixel: " + who + " at its centre", d_ru = "один пиксел: " + who + " в его центре"; break;
      case WarnockWindow::Decision::Split: d_en = "split into four", d_ru = "делится на четыре"; break;
    }
    wt.push_back({"i " + std::to_string(w.i0) + "–" + std::to_string(w.i1 - 1) + ", j " + std::to_string(w.j0) + "–" + std::to_string(w.j1 - 1),
                  std::to_string(w.level), J{{"en", types_en}, {"ru", types_ru}}, J{{"en", d_en}, {"ru", d_ru}}});
  }
  out["sections"].push_back(wn.j);

  // The frame: the three algorithms agree (the scan-line one computed above, exactly).
  for (std::size_t k = 0; k < frame.size(); ++k) {
    const int f = frame[k] < 0 ? -1 : s.polygons[frame[k]].id;
    if (f != by_z.ids[k] || f != by_w.ids[k]) throw std::logic_error("raster explain: the algorithms disagree at a pixel");
  }
  Section res("rs_result");
  J& ft = res.table("rs_frame", {"rs_row", "rs_frame_row"});
  J result_rows = J::array();
  for (int j = 0; j < g.height; ++j) {
    std::string line;
    J ids = J::array();
    for (int i = 0; i < g.width; ++i) {
      const int id = by_z.ids[static_cast<std::size_t>(j) * g.width + i];
      line += (i ? " " : "") + (id < 0 ? std::string(".") : letter[id]);
      ids.push_back(id < 0 ? J(nullptr) : J::array({s.faces[id][0], s.faces[id][1]}));
    }
    ft.push_back({std::to_string(j), line});
    result_rows.push_back(ids);
  }
  J& lt = res.table("rs_legend", {"rs_label", "polygon"});
  for (const auto& [id, l] : letter) lt.push_back({l, pr.scene.bodies[s.faces[id][0]].name + "/" + ix(s.faces[id][1])});
  res.value("rs_agree", "the z-buffer, the scan-line z-buffer and Warnock give this same frame (checked pixel by pixel)",
            "z-буфер, построчный z-буфер и алгоритм Варнока дают один и тот же кадр (проверено по каждому пикселу)");
  out["sections"].push_back(res.j);
  out["result"]["frame"] = result_rows;
  out["drawing_svg"] = problem_drawing_svg(pr, lines, cam);
  return out;
}

}  // namespace hlr::explain_parts
