// SVG writer (see svg_writer.hpp): formats the 2D stage's polylines, nothing else.
#include "io/writers/svg_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <tuple>

namespace hlr {

// Three decimals (micrometres in the drawing). Integer formatting of the value rounded to
// thousandths: several times faster than printf on million-line drawings, same text except
// for values exactly halfway between two thousandths (rounded away from zero here).
std::string svg_number(double v) {
  if (!(std::fabs(v) < 1e12)) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    return buf;
  }
  long long m = std::llround(v * 1000.0);
  char buf[32];
  char* e = buf + sizeof buf;
  char* p = e;
  bool neg = m < 0;
  unsigned long long u = neg ? static_cast<unsigned long long>(-m) : static_cast<unsigned long long>(m);
  for (int i = 0; i < 3; ++i) *--p = static_cast<char>('0' + u % 10), u /= 10;
  *--p = '.';
  do *--p = static_cast<char>('0' + u % 10), u /= 10;
  while (u);
  if (neg) *--p = '-';
  return std::string(p, e);
}

std::string svg_escape(const std::string& s) {
  std::string e;
  for (char c : s) {
    if (c == '&') e += "&amp;";
    else if (c == '<') e += "&lt;";
    else if (c == '>') e += "&gt;";
    else if (c == '"') e += "&quot;";
    else e += c;
  }
  return e;
}

namespace {
std::string fmt(double v) { return svg_number(v); }
}  // namespace

std::string to_svg(const std::vector<DrawingBody>& bodies, const Drawing2D& d, const SvgOptions& opt) {
  // Group key: (visible 0, through 1 or hidden 2, line kind, body or -1 - body for
  // intersections, second body).
  std::map<std::tuple<int, int, int, int>, std::vector<const Polyline2D*>> groups;
  auto drawn = [&](const Polyline2D& l) { return l.visible || l.through || opt.hidden_dashed; };
  for (const Polyline2D& l : d.lines) {
    if (!drawn(l)) continue;
    groups[{l.visible ? 0 : l.through ? 1 : 2, static_cast<int>(l.kind), l.intersection ? -1 - l.body : l.body, l.intersection ? l.body2 : -1}]
        .push_back(&l);
  }
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const Polyline2D& l : d.lines) {
    if (!drawn(l)) continue;
    for (std::uint32_t k = 0; k < l.count; ++k) {
      const auto& p = d.point(l, k);
      x0 = std::min(x0, p[0]);
      x1 = std::max(x1, p[0]);
      y0 = std::min(y0, p[1]);
      y1 = std::max(y1, p[1]);
    }
  }
  if (!(x1 >= x0)) x0 = y0 = 0, x1 = y1 = 1;
  double w = x1 - x0, h = y1 - y0, m = 0.04 * std::max({w, h, 1e-300});
  if (w == 0 && h == 0) m = 1;
  double k = opt.width_mm / (w + 2 * m);
  double height_mm = (h + 2 * m) * k;
  std::string out;
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + fmt(opt.width_mm) + "mm\" height=\"" + fmt(height_mm) +
         "mm\" viewBox=\"0 0 " + fmt(opt.width_mm) + " " + fmt(height_mm) + "\">\n";
  out += "<title>exact-hlr drawing</title>\n";
  auto X = [&](double x) { return fmt((x - x0 + m) * k); };
  auto Y = [&](double y) { return fmt((y1 - y + m) * k); };
  auto escape = svg_escape;
  for (int vis = 0; vis < 3; ++vis) {
    if (vis == 2 && !opt.hidden_dashed) break;
    if (vis == 1 && std::none_of(groups.begin(), groups.end(), [](const auto& g) { return std::get<0>(g.first) == 1; })) continue;
    const char* id = vis == 0 ? "visible" : vis == 1 ? "through" : "hidden";
    out += std::string("<g id=\"") + id + "\" fill=\"none\" stroke=\"" + (vis == 1 ? "#808080" : "#000") + "\" stroke-width=\"" +
           fmt(vis == 0 ? opt.stroke_mm : opt.stroke_mm / 2) + "\" stroke-linecap=\"round\"" +
           (vis == 2 ? " stroke-dasharray=\"" + fmt(opt.stroke_mm * 4) + " " + fmt(opt.stroke_mm * 3) + "\"" : std::string()) +
           ">\n";
    int open_kind = -1;
    for (const auto& [key, lines] : groups) {
      auto [v, kind, b, b2] = key;
      if (v != vis) continue;
      std::string kid = std::string(id) + "-" + to_string(static_cast<LineKind>(kind));
      if (kind != open_kind) {
        if (open_kind >= 0) out += "  </g>\n";
        out += "  <g id=\"" + kid + "\">\n";
        open_kind = kind;
      }
      std::string gid = b >= 0 ? kid + "-body-" + std::to_string(b)
                               : kid + "-" + std::to_string(-1 - b) + "-" + std::to_string(b2);
      std::string name = b >= 0 && b < static_cast<int>(bodies.size()) ? " data-name=\"" + escape(bodies[b].name) + "\"" : "";
      out += "    <g id=\"" + gid + "\"" + name + ">\n";
      for (const Polyline2D* l : lines)
        for (std::uint32_t k = 0; k + 1 < l->count; ++k) {
          const auto &a = d.point(*l, k), &b = d.point(*l, k + 1);
          out += "      <line x1=\"" + X(a[0]) + "\" y1=\"" + Y(a[1]) + "\" x2=\"" + X(b[0]) + "\" y2=\"" + Y(b[1]) + "\"/>\n";
        }
      out += "    </g>\n";
    }
    if (open_kind >= 0) out += "  </g>\n";
    out += "</g>\n";
  }
  if (!d.labels.empty()) {
    out += "<g id=\"vertex-labels\" font-family=\"sans-serif\" font-size=\"" + fmt(opt.stroke_mm * 9) +
           "\" fill=\"#b00\">\n";
    for (const Label2D& l : d.labels)
      out += "  <text x=\"" + X(l.at[0] + 0) + "\" y=\"" + Y(l.at[1]) + "\" dx=\"" + fmt(opt.stroke_mm * 2) + "\" dy=\"" +
             fmt(-opt.stroke_mm * 2) + "\">" + escape(l.text) + "</text>\n";
    out += "</g>\n";
  }
  out += "</svg>\n";
  return out;
}

std::string to_svg(const std::vector<DrawingBody>& bodies, const LineDrawing& r, const Camera& camera, const SvgOptions& opt) {
  Project2DOptions po;
  po.hidden = opt.hidden_dashed;
  po.vertex_labels = opt.vertex_labels;
  po.label_base = opt.label_base;
  return to_svg(bodies, project_drawing(r, camera, po), opt);
}

}  // namespace hlr
