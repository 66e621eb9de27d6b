// Section views and section lines on a sheet (see section_views.hpp; ISO 128-40, ISO 128-44).
#include "io/output/section_views.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "algorithms/picture/drawing_2d.hpp"
#include "io/views/standard_views.hpp"

namespace hlr {
namespace {

// The section line's sizes on the page, mm (ISO 128-44 leaves them to the drawing; these read
// well from 1:1 to 1:100 on A4 to A0).
constexpr double kOvershoot = 6;                      // the line's ends beyond the scene's box
constexpr double kWideEnd = 8;                        // each wide end, from the line's end inward
constexpr double kDash = 12, kGap = 1.5, kDot = 0.5;  // the narrow chain between the wide ends
constexpr double kArrowAt = 3;                        // the arrow's tip, from the line's end
constexpr double kArrow = 7, kHead = 3, kHeadHalfWidth = 1;
constexpr double kLetter = 5;       // the letters' height
constexpr double kLetterGap = 3.5;  // from the arrow's tail to the letter's centre

bool same_direction(const Vector3& a, const Vector3& b) {
  const Vector3 c = cross(a, b);
  return c.x() == 0 && c.y() == 0 && c.z() == 0 && dot(a, b) > 0;
}

using V2 = std::array<double, 2>;
V2 add(const V2& p, const V2& u, double s) { return {p[0] + s * u[0], p[1] + s * u[1]}; }

// The exact bounding box of the bodies' vertices; false when there are none.
bool box_of(const std::vector<const SceneBody*>& bodies, std::array<Rational, 3>& lo, std::array<Rational, 3>& hi) {
  bool any = false;
  for (const SceneBody* b : bodies)
    for (const Point3& p : b->body.vertices()) {
      for (int k = 0; k < 3; ++k) {
        if (!any || p[k] < lo[k]) lo[k] = p[k];
        if (!any || p[k] > hi[k]) hi[k] = p[k];
      }
      any = true;
    }
  return any;
}

// Where the plane meets the box's edges (and corners), exactly.
std::vector<Point3> plane_in_box(const Plane& h, const std::array<Rational, 3>& lo, const std::array<Rational, 3>& hi) {
  std::vector<Point3> corners;
  for (int m = 0; m < 8; ++m) corners.emplace_back(m & 1 ? hi[0] : lo[0], m & 2 ? hi[1] : lo[1], m & 4 ? hi[2] : lo[2]);
  std::vector<Rational> v;
  for (const Point3& c : corners) v.push_back(h.value(c));
  std::vector<Point3> out;
  for (int m = 0; m < 8; ++m) {
    if (v[m] == 0) out.push_back(corners[m]);
    for (int bit : {1, 2, 4}) {
      const int n = m | bit;
      if (n == m || (v[m] < 0) == (v[n] < 0) || v[m] == 0 || v[n] == 0) continue;
      out.push_back(corners[m] + (v[m] / (v[m] - v[n])) * (corners[n] - corners[m]));
    }
  }
  return out;
}

PlotLayer& layer_of(Plot& plot, LineKind kind) {
  for (PlotLayer& l : plot.layers)
    if (l.visible && !l.through && l.kind == kind) return l;
  PlotLayer l;
  l.kind = kind;
  plot.layers.push_back(std::move(l));
  return plot.layers.back();
}

void add_stroke(PlotLayer& layer, std::vector<V2> points, bool closed = false) {
  Stroke s;
  s.points = std::move(points);
  s.closed = closed;
  layer.strokes.push_back(std::move(s));
}

// One section line in a view: the trace from p0 to p1 (drawing units), `v` the viewing
// direction on the page (unit), `mm` drawing units per page mm.
void draw_section_line(Plot& plot, V2 p0, V2 p1, const V2& v, double mm, const std::string& letter) {
  V2 u{p1[0] - p0[0], p1[1] - p0[1]};
  double len = std::hypot(u[0], u[1]);
  if (len == 0) u = {-v[1], v[0]}, len = 1;
  u = {u[0] / len, u[1] / len};
  const V2 e0 = add(p0, u, -kOvershoot * mm), e1 = add(p1, u, kOvershoot * mm);
  PlotLayer& marks = layer_of(plot, LineKind::SectionMark);
  add_stroke(marks, {e0, add(e0, u, kWideEnd * mm)});
  add_stroke(marks, {add(e1, u, -kWideEnd * mm), e1});
  for (const auto& [end, out] : {std::pair{e0, -1.0}, std::pair{e1, 1.0}}) {
    const V2 tip = add(end, u, -out * kArrowAt * mm), base = add(tip, v, -kHead * mm);
    add_stroke(marks, {add(tip, v, -kArrow * mm), base});
    add_stroke(marks, {tip, add(base, u, kHeadHalfWidth * mm), add(base, u, -kHeadHalfWidth * mm)}, true);
    plot.texts.push_back({add(tip, v, -(kArrow + kLetterGap) * mm), letter, kLetter});
  }
  // The narrow chain between the wide ends: long dashes and dots.
  PlotLayer& chain = layer_of(plot, LineKind::SectionLine);
  const double from = kWideEnd * mm, to = len + 2 * kOvershoot * mm - kWideEnd * mm;
  for (double at = from + kGap * mm; at < to;) {
    const double dash_end = std::min(to, at + kDash * mm);
    add_stroke(chain, {add(e0, u, at), add(e0, u, dash_end)});
    at = dash_end + kGap * mm;
    if (at + kDot * mm + kGap * mm >= to) break;
    add_stroke(chain, {add(e0, u, at), add(e0, u, at + kDot * mm)});
    at += (kDot + kGap) * mm;
  }
}

// The section line of `s` in view `r` (orthographic, seeing the plane edge-on).
void add_one(Plot& plot, const RenderResult& r, const NamedSection& s, double mm_per_unit) {
  std::array<Rational, 3> lo, hi;
  if (!box_of(r.bodies, lo, hi)) return;
  const std::vector<Point3> trace = plane_in_box(s.plane, lo, hi);
  if (trace.empty()) return;
  const Projector proj = drawing_projector(r.drawing, r.camera);
  std::vector<V2> pts;
  for (const Point3& p : trace) {
    const auto q = proj.project(p);
    pts.push_back({q[0], q[1]});
  }
  // The viewing direction on the page: against the normal (the normal points to what is removed).
  const auto axes = proj.axes();
  Rational big = 0;
  for (int k = 0; k < 3; ++k)
    if (abs(s.plane[k]) > big) big = abs(s.plane[k]);
  double n3[3];
  for (int k = 0; k < 3; ++k) n3[k] = to_double(s.plane[k] / big);
  V2 v{0, 0};
  for (int k = 0; k < 3; ++k) v[0] -= n3[k] * axes[0][k], v[1] -= n3[k] * axes[1][k];
  const double vl = std::hypot(v[0], v[1]);
  if (!(vl > 0)) return;
  v = {v[0] / vl, v[1] / vl};
  // The trace's two ends: the extremes along the line (perpendicular to v).
  auto along = [&](const V2& p) { return -v[1] * p[0] + v[0] * p[1]; };
  auto [a, b] = std::minmax_element(pts.begin(), pts.end(), [&](const V2& x, const V2& y) { return along(x) < along(y); });
  draw_section_line(plot, *a, *b, v, 1 / mm_per_unit, s.name);
}

}  // namespace

NamedSection named_section(std::string name, Plane plane, bool z_up) {
  if (name.empty()) throw std::invalid_argument("a section view needs a name (a letter: A=PLANE)");
  if (plane.is_degenerate()) throw std::invalid_argument("section view " + name + ": the plane has no normal");
  NamedSection s{std::move(name), std::move(plane), ""};
  for (const char* n : {"front", "top", "right", "left", "bottom", "back"})
    if (same_direction(s.plane.normal(), standard_view(n, z_up)->direction)) s.standard = n;
  return s;
}

ViewRequest section_view_request(const NamedSection& s, bool z_up) {
  ViewRequest v;
  v.direction = s.plane.normal();
  if (!s.standard.empty()) v.up = standard_view(s.standard, z_up)->up;
  else v.up = z_up ? Vector3(0, 0, 1) : Vector3(0, 1, 0);
  return v;
}

std::string section_view_label(const NamedSection& s) { return s.name + "\u2013" + s.name; }

std::string section_view_name(const std::string& name) { return "section:" + name; }

std::string section_of_view_name(const std::string& v) { return v.rfind("section:", 0) == 0 ? v.substr(8) : ""; }

void add_section_lines(std::vector<Plot>& plots, const std::vector<const RenderResult*>& results, const Sheet& sheet) {
  for (const RenderResult* s : results) {
    if (!s->section_view) continue;
    for (std::size_t i = 0; i < results.size(); ++i) {
      const RenderResult& r = *results[i];
      if (r.camera.perspective || dot(s->section_view->plane.normal(), r.camera.direction) != 0) continue;
      add_one(plots[i], r, *s->section_view, sheet.views[i].scale);
    }
  }
}

}  // namespace hlr
