// Pages, scales, sheets of views and line styles (see plot_output.hpp).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "algorithms/plot/dashes.hpp"
#include "io/writers/plot_output.hpp"

namespace hlr {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

double positive_number(const std::string& t, const std::string& what) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(t, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != t.size() || !(v > 0) || !std::isfinite(v) || v > 1e7)
    throw std::invalid_argument(what + ": '" + t + "' is not a positive number");
  return v;
}

}  // namespace

std::array<double, 2> parse_page_size(const std::string& text) {
  std::string t = lower(text);
  static const std::map<std::string, std::array<double, 2>> named = {
      {"a0", {841, 1189}}, {"a1", {594, 841}}, {"a2", {420, 594}}, {"a3", {297, 420}}, {"a4", {210, 297}},
      {"a5", {148, 210}},  {"letter", {215.9, 279.4}}, {"legal", {215.9, 355.6}}, {"tabloid", {279.4, 431.8}}};
  if (auto it = named.find(t); it != named.end()) return it->second;
  if (t.size() > 2 && t.substr(t.size() - 2) == "mm") t.resize(t.size() - 2);
  auto x = t.find('x');
  if (x == std::string::npos)
    throw std::invalid_argument("--page: '" + text + "' is not a page (A0..A5, letter, legal, tabloid or WxHmm)");
  return {positive_number(t.substr(0, x), "--page"), positive_number(t.substr(x + 1), "--page")};
}

double parse_scale(const std::string& text) {
  auto colon = text.find(':');
  if (colon == std::string::npos) return positive_number(text, "--scale");
  return positive_number(text.substr(0, colon), "--scale") / positive_number(text.substr(colon + 1), "--scale");
}

Sheet layout_single(const Plot& plot, const PageOptions& o) {
  return layout_views({&plot}, {{0, 0}}, {""}, o);
}

Sheet layout_views(const std::vector<const Plot*>& plots, const std::vector<std::array<int, 2>>& grid,
                   const std::vector<std::string>& labels, const PageOptions& o) {
  Sheet sheet;
  // Columns and rows: the union of their views' extents (drawing units).
  std::map<int, std::array<double, 2>> cols, rows;  // [lo, hi]
  const double inf = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < plots.size(); ++i) {
    const auto& b = plots[i]->bounds;
    auto& c = cols.try_emplace(grid[i][0], std::array<double, 2>{inf, -inf}).first->second;
    auto& r = rows.try_emplace(grid[i][1], std::array<double, 2>{inf, -inf}).first->second;
    if (plots[i]->empty()) continue;
    c = {std::min(c[0], b[0]), std::max(c[1], b[2])};
    r = {std::min(r[0], b[1]), std::max(r[1], b[3])};
  }
  for (auto* m : {&cols, &rows})
    for (auto& [k, v] : *m)
      if (v[0] > v[1]) v = {0, 0};
  double sum_w = 0, sum_h = 0;
  for (auto& [k, v] : cols) sum_w += v[1] - v[0];
  for (auto& [k, v] : rows) sum_h += v[1] - v[0];
  const double gaps_w = o.gap_mm * static_cast<double>(cols.size() - 1), gaps_h = o.gap_mm * static_cast<double>(rows.size() - 1);
  const bool labelled = std::any_of(labels.begin(), labels.end(), [](const std::string& s) { return !s.empty(); });
  const double label_room = labelled ? 8.0 : 0.0;  // mm under each row for its labels
  const double labels_h = label_room * static_cast<double>(rows.size());
  double k = 1, margin = 0, W = 0, H = 0;
  if (o.page) {
    W = (*o.page)[0], H = (*o.page)[1];
    if (o.landscape != (W > H) && W != H) std::swap(W, H);
    margin = o.margin_mm.value_or(10);
    double aw = W - 2 * margin - gaps_w, ah = H - 2 * margin - gaps_h - labels_h;
    if (aw <= 0 || ah <= 0) throw std::invalid_argument("the margins leave no room on the page");
    k = o.scale ? *o.scale : std::min(sum_w > 0 ? aw / sum_w : inf, sum_h > 0 ? ah / sum_h : inf);
    if (!std::isfinite(k)) k = 1;
    if (o.scale && (sum_w * k > aw * (1 + 1e-9) || sum_h * k > ah * (1 + 1e-9)))
      sheet.notes.push_back("the drawing at this scale is larger than the page's drawing area");
  } else {
    double size = std::max({sum_w, sum_h, 1e-300});
    if (o.scale) {
      k = *o.scale;
      margin = o.margin_mm.value_or(10);
    } else {
      // The old look: a 4% margin of the drawing's size around it, the width given.
      double m_units = o.margin_mm ? 0 : 0.04 * size;
      if (sum_w == 0 && sum_h == 0) m_units = 1;
      double fixed = o.margin_mm ? 2 * *o.margin_mm + gaps_w : gaps_w;
      k = (o.width_mm - fixed) / (sum_w + 2 * m_units);
      if (!(k > 0)) throw std::invalid_argument("--width leaves no room for the drawing");
      margin = o.margin_mm ? *o.margin_mm : m_units * k;
    }
    W = sum_w * k + gaps_w + 2 * margin;
    H = sum_h * k + gaps_h + labels_h + 2 * margin;
  }
  sheet.width_mm = W, sheet.height_mm = H;
  // Centre the block of views; columns left to right, rows top (highest index) to bottom.
  const double block_w = sum_w * k + gaps_w, block_h = sum_h * k + gaps_h + labels_h;
  double x = (W - block_w) / 2;
  std::map<int, double> col_ox, row_oy, row_bottom;
  for (auto& [c, v] : cols) {
    col_ox[c] = x - k * v[0];
    x += (v[1] - v[0]) * k + o.gap_mm;
  }
  double y = (H - block_h) / 2;
  for (auto it = rows.rbegin(); it != rows.rend(); ++it) {
    row_oy[it->first] = y + k * it->second[1];
    y += (it->second[1] - it->second[0]) * k;
    row_bottom[it->first] = y;
    y += label_room + o.gap_mm;
  }
  for (std::size_t i = 0; i < plots.size(); ++i) {
    SheetView v;
    v.plot = plots[i];
    v.scale = k;
    v.ox = col_ox[grid[i][0]];
    v.oy = row_oy[grid[i][1]];
    v.label = i < labels.size() ? labels[i] : "";
    sheet.views.push_back(v);
  }
  if (o.scale) {
    double s = *o.scale;
    char buf[64];
    if (s >= 1) std::snprintf(buf, sizeof buf, "scale %g:1", s);
    else std::snprintf(buf, sizeof buf, "scale 1:%g", 1 / s);
    sheet.caption = buf;
  }
  return sheet;
}

std::vector<SheetText> sheet_texts(const Sheet& sheet) {
  std::vector<SheetText> out;
  for (const SheetView& v : sheet.views) {
    if (v.plot->empty()) continue;
    const auto& b = v.plot->bounds;
    Point2 label = v.page({(b[0] + b[2]) / 2, b[1]});
    label[1] += 6;
    for (const PlotText& t : v.plot->texts) {
      const Point2 at = v.page(t.at);  // the baseline a third of the height under the centre
      out.push_back({{at[0], at[1] + t.height_mm / 3}, t.text, t.height_mm, 0.5});
      label[1] = std::max(label[1], at[1] + t.height_mm / 3 + 6);  // the label under the view's letters
    }
    if (!v.label.empty()) out.push_back({label, v.label, 3.5, 0.5});
  }
  if (!sheet.caption.empty()) out.push_back({{sheet.width_mm - 5, sheet.height_mm - 5}, sheet.caption, 3.5, 1});
  return out;
}

double PlotStyle::weight(const PlotLayer& l) const {
  auto it = weights.find(l.visible ? (is_tone(l.kind) ? "tone" : to_string(l.kind)) : l.through ? "through" : "hidden");
  return it != weights.end() ? it->second : 0.35;
}

std::array<double, 2> PlotStyle::dash_pattern(const PlotLayer& l) const {
  double d = weight(l);
  return {12 * d, 3 * d};
}

void parse_weights(const std::string& text, PlotStyle& style) {
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t comma = text.find(',', at);
    std::string item = text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    at = comma == std::string::npos ? text.size() : comma + 1;
    auto eq = item.find('=');
    std::string key = lower(item.substr(0, eq));
    if (eq == std::string::npos || !style.weights.count(key))
      throw std::invalid_argument("--weights: '" + item +
                                  "' is not KIND=MM (kinds: cut, silhouette, boundary, crease, intersection, edge, hatch, overhead, section-line, "
                                  "section-mark, polyline, tone, hidden, through)");
    style.weights[key] = positive_number(item.substr(eq + 1), "--weights");
  }
}

namespace {

double polyline_length(const std::vector<Point2>& p, bool closed) {
  double t = 0;
  for (std::size_t i = 1; i < p.size(); ++i) t += std::hypot(p[i][0] - p[i - 1][0], p[i][1] - p[i - 1][1]);
  if (closed && p.size() > 2) t += std::hypot(p.back()[0] - p[0][0], p.back()[1] - p[0][1]);
  return t;
}

}  // namespace

std::vector<std::vector<Point2>> page_strokes(const SheetView& view, const PlotLayer& layer, const PlotStyle& style,
                                              std::vector<char>* closed) {
  std::vector<std::vector<Point2>> out;
  if (closed) closed->clear();
  const bool cut = style.dashed(layer) && style.dashes == DashMode::Geometry;
  auto pattern = style.dash_pattern(layer);
  for (const Stroke& s : layer.strokes) {
    std::vector<Point2> pts;
    pts.reserve(s.points.size());
    for (const Point2& p : s.points) pts.push_back(view.page(p));
    if (cut) {
      for (auto& d : cut_dashes(pts, s.closed, pattern[0], pattern[1])) {
        if (style.min_length_mm > 0 && polyline_length(d, false) < style.min_length_mm) continue;  // a remnant of the cut
        out.push_back(std::move(d));
        if (closed) closed->push_back(0);
      }
    } else {
      out.push_back(std::move(pts));
      if (closed) closed->push_back(s.closed);
    }
  }
  return out;
}

std::vector<std::string> sheet_layer_names(const Sheet& sheet) {
  std::vector<std::string> names;
  for (int seen : {0, 1, 2})  // visible, through, hidden
    for (LineKind k : kLayerKinds)
      for (const SheetView& v : sheet.views) {
        bool found = false;
        for (const PlotLayer& l : v.plot->layers)
          if (l.visible == (seen == 0) && l.through == (seen == 1) && l.kind == k && !l.strokes.empty()) found = true;
        if (found) {
          names.push_back(std::string(seen == 0 ? "visible-" : seen == 1 ? "through-" : "hidden-") + to_string(k));
          break;
        }
      }
  return names;
}

std::vector<SheetLayer> sheet_layers(const Sheet& sheet, const PlotStyle& style) {
  std::vector<SheetLayer> out;
  const std::vector<std::string> names = sheet_layer_names(sheet);
  for (std::size_t n = 0; n < names.size(); ++n) {
    const auto number = style.layer_numbers.find(names[n]);
    const int k = number != style.layer_numbers.end() ? number->second : static_cast<int>(n + 1);
    SheetLayer l{names[n], style.numbered_layers ? std::to_string(k) + " " + names[n] : names[n], nullptr};
    for (const SheetView& v : sheet.views)
      for (const PlotLayer& p : v.plot->layers)
        if (!l.layer && p.name() == names[n]) l.layer = &p;
    out.push_back(std::move(l));
  }
  return out;
}

}  // namespace hlr
