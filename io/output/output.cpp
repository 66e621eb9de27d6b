// The output stage: from exact line drawings to the text or bytes written (the plotting 2D
// stage, the page layout, the writers; or the exact JSON). See output.hpp and docs/design.md,
// "The render pipeline, one screen".
#include "io/output/output.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <set>

#include "algorithms/plot/coincident_lines.hpp"
#include "algorithms/support/progress.hpp"
#include "io/output/section_views.hpp"
#include "io/output/tone_hatching.hpp"
#include "io/pipeline/section.hpp"
#include "io/writers/json_writer.hpp"
#include "io/writers/plot_output.hpp"

namespace hlr {
namespace {

PageOptions page_options(const OutputOptions& a) {
  PageOptions p;
  if (!a.page.empty()) p.page = parse_page_size(a.page);
  p.landscape = a.landscape;
  if (!a.margin.empty()) {
    double m = -1;
    std::size_t used = 0;
    try {
      m = std::stod(a.margin, &used);
    } catch (const std::exception&) {
      m = -1;
    }
    if (used != a.margin.size() || !(m >= 0) || m > 1e4)
      throw std::invalid_argument("--margin must be a size in millimetres from 0 to 10000 (got '" + a.margin + "')");
    p.margin_mm = m;
  }
  if (!a.scale.empty()) p.scale = parse_scale(a.scale);
  p.width_mm = a.width;
  return p;
}

PlotStyle plot_style(const OutputOptions& a) {
  PlotStyle st;
  // ISO 128: every visible edge the wide line (the table's outlines' 0.5 mm).
  const bool iso = a.line_widths != "kinds";
  if (iso)
    for (const char* k : {"crease", "intersection", "edge"}) st.weights[k] = st.weights["silhouette"];
  const double visible = iso ? st.weights["silhouette"] : st.weights["crease"];
  if (a.stroke > 0)
    for (auto& [k, w] : st.weights) w *= a.stroke / visible;  // --stroke: the visible edges' width, the rest in proportion
  if (!a.weights.empty()) parse_weights(a.weights, st);
  if (a.hatch_pen > 0) st.weights["tone"] = a.hatch_pen;
  st.dashes = a.dashes == "geometry" ? DashMode::Geometry : DashMode::Pattern;
  st.hidden_dashed = a.hidden != "solid";
  return st;
}

// Keeps the layers named (or numbered, from 1 in the order the writers use) in --layers.
// A selection that keeps nothing to draw is an error naming the drawing's layers (an empty
// drawing with exit 0 looks like a drawing of nothing).
void select_layers(const std::string& list, std::vector<Plot>& plots, bool hidden_drawn) {
  if (list.empty()) return;
  std::vector<std::string> names;
  {
    Sheet all;
    for (const Plot& p : plots) all.views.push_back(SheetView{&p, 1, 0, 0, ""});
    names = sheet_layer_names(all);
  }
  auto layer_list = [&] {
    std::string have;
    for (std::size_t k = 0; k < names.size(); ++k) have += (k ? ", " : "") + std::to_string(k + 1) + " " + names[k];
    return have;
  };
  std::set<std::string> keep;
  bool asked_hidden = false;
  std::size_t at = 0;
  while (at <= list.size()) {
    std::size_t comma = list.find(',', at);
    std::string item = list.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    at = comma == std::string::npos ? list.size() + 1 : comma + 1;
    if (item.empty()) continue;
    bool number = std::all_of(item.begin(), item.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (number) {
      const std::size_t digits = item.find_first_not_of('0');
      const std::size_t n = digits == std::string::npos || item.size() - digits > 9 ? 0 : std::stoul(item);
      if (n < 1 || n > names.size())
        throw std::invalid_argument("--layers: there is no layer " + item + "; this drawing has " + std::to_string(names.size()) + " layers" +
                                    (names.empty() ? "" : ": " + layer_list()));
      keep.insert(names[n - 1]);
      continue;
    }
    asked_hidden = asked_hidden || item.rfind("hidden", 0) == 0;
    if (item == "visible" || item == "through" || item == "hidden") {
      for (const std::string& n : names)
        if (n.rfind(item + "-", 0) == 0) keep.insert(n);
      continue;
    }
    std::set<std::string> known;
    for (const char* seen : {"visible-", "hidden-", "through-"})
      for (LineKind k : kLayerKinds) known.insert(seen + std::string(to_string(k)));
    if (item == "tone") {  // every tone level
      for (const std::string& n : names)
        if (n.find("-tone-") != std::string::npos) keep.insert(n);
      continue;
    }
    if (!known.count(item))
      throw std::invalid_argument("--layers: unknown layer '" + item +
                                  "' (visible, through, hidden, tone, visible-silhouette, hidden-crease, visible-tone-2, ... or numbers)");
    keep.insert(item);
  }
  bool drawn = false;
  for (const Plot& p : plots)  // fills alone are not what a selection of layers asks for
    for (const PlotLayer& l : p.layers) drawn = drawn || keep.count(l.name());
  if (!drawn)
    throw std::invalid_argument("--layers " + list + ": none of this drawing's layers" + (names.empty() ? std::string() : " (" + layer_list() + ")") +
                                (asked_hidden && !hidden_drawn ? "; hidden lines are drawn with --hidden dashed or --hidden solid" : ""));
  for (Plot& p : plots) {
    std::vector<PlotLayer> kept;
    for (PlotLayer& l : p.layers)
      if (keep.count(l.name())) kept.push_back(std::move(l));
    p.layers = std::move(kept);
  }
}

// The layer numbers of a pen map "visible=1,hidden=2,hatch=3" for the layers `names`: a key is
// a layer's name, its kind (both visibilities; "tone": every tone level) or its visibility;
// the most particular key wins. A layer no key names is an error (a pen map is the plotter's
// whole setup).
std::map<std::string, int> pen_numbers(const std::string& map, const std::vector<std::string>& names) {
  std::map<std::string, int> keys;
  std::size_t at = 0;
  while (at < map.size()) {
    std::size_t comma = map.find(',', at);
    const std::string item = map.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    at = comma == std::string::npos ? map.size() : comma + 1;
    const std::size_t eq = item.find('=');
    int pen = 0;
    std::size_t used = 0;
    try {
      pen = eq == std::string::npos ? 0 : std::stoi(item.substr(eq + 1), &used);
    } catch (const std::exception&) {
      pen = 0;
    }
    if (eq == std::string::npos || eq == 0 || used != item.size() - eq - 1 || pen < 1 || pen > 999)
      throw std::invalid_argument("--pens: '" + item + "' is not LAYER=PEN with a pen number from 1 to 999 (e.g. visible=1,hidden=2,tone=3)");
    keys[item.substr(0, eq)] = pen;
  }
  std::map<std::string, int> out;
  std::string missing;
  for (const std::string& n : names) {
    const std::size_t dash = n.find('-');
    const std::string seen = n.substr(0, dash), kind = n.substr(dash + 1);
    int best = -1, pen = 0;
    auto consider = [&](const std::string& key, int rank) {
      auto it = keys.find(key);
      if (it != keys.end() && rank > best) best = rank, pen = it->second;
    };
    consider(seen, 0);
    if (kind.rfind("tone-", 0) == 0) consider("tone", 1);
    consider(kind, 2);
    consider(n, 3);
    if (best < 0) missing += (missing.empty() ? "" : ", ") + n;
    else out[n] = pen;
  }
  if (!missing.empty())
    throw std::invalid_argument("--pens: no pen for the layers " + missing + " (name them, their kind or visible/hidden/through)");
  return out;
}

// What the file holds, per layer: its strokes (dashes cut, specks dropped) and their length on
// the page.
void print_layer_stats(const Sheet& sheet, const PlotStyle& style) {
  std::size_t strokes = 0;
  double length = 0;
  for (const SheetLayer& l : sheet_layers(sheet, style)) {
    std::size_t n = 0;
    double len = 0;
    for (const SheetView& v : sheet.views)
      for (const PlotLayer& pl : v.plot->layers) {
        if (pl.name() != l.name) continue;
        std::vector<char> closed;
        const auto st = page_strokes(v, pl, style, &closed);
        for (std::size_t k = 0; k < st.size(); ++k) {
          const auto& p = st[k];
          for (std::size_t i = 1; i < p.size(); ++i) len += std::hypot(p[i][0] - p[i - 1][0], p[i][1] - p[i - 1][1]);
          if (closed[k] && p.size() > 2) len += std::hypot(p.back()[0] - p[0][0], p.back()[1] - p[0][1]);
        }
        n += st.size();
      }
    std::cerr << "stats: layer " << l.label << ": " << n << " strokes, pen-down " << len << " mm\n";
    strokes += n, length += len;
  }
  std::cerr << "stats: the file holds " << strokes << " strokes, pen-down " << length << " mm\n";
}

void print_stats(const std::vector<Plot>& plots, double scale) {
  PlotStats t;
  for (const Plot& p : plots) {
    const PlotStats& s = p.stats;
    t.pieces += s.pieces, t.zero_length += s.zero_length, t.overlap_groups += s.overlap_groups;
    t.duplicate_length += s.duplicate_length * scale, t.edges += s.edges, t.path_count += s.path_count;
    t.min_path_count += s.min_path_count, t.dropped_short += s.dropped_short;
    t.pen_down_length += s.pen_down_length * scale, t.pen_up_length += s.pen_up_length * scale;
    t.pen_up_greedy += s.pen_up_greedy * scale, t.pen_up_unordered += s.pen_up_unordered * scale;
    t.exact_point_tests += s.exact_point_tests, t.exact_line_tests += s.exact_line_tests;
    t.seconds_dedup += s.seconds_dedup, t.seconds_chain += s.seconds_chain, t.seconds_order += s.seconds_order;
  }
  std::cerr << std::fixed;
  std::cerr.precision(1);
  std::cerr << "stats: pieces " << t.pieces << ", end-on " << t.zero_length << ", overlap groups " << t.overlap_groups << " (duplicate length "
            << t.duplicate_length << " mm removed), edges " << t.edges << ", paths " << t.path_count << " (minimum " << t.min_path_count
            << "), specks dropped " << t.dropped_short << ", pen-down " << t.pen_down_length << " mm, pen-up " << t.pen_up_length << " mm (greedy "
            << t.pen_up_greedy << ", unordered " << t.pen_up_unordered << ")";
  std::cerr.precision(3);
  std::cerr << ", exact tests: points " << t.exact_point_tests << ", lines " << t.exact_line_tests;
  std::cerr << ", clean-up " << t.seconds_dedup << " s, chaining " << t.seconds_chain << " s, ordering " << t.seconds_order << " s\n";
}

// Standard views on one sheet: their names and their cells (third-angle: top above front).
std::array<int, 2> standard_cell(const std::string& n, bool first_angle) {
  std::array<int, 2> c{0, 0};
  if (n == "top") c = {0, 1};
  else if (n == "bottom") c = {0, -1};
  else if (n == "right") c = {1, 0};
  else if (n == "left") c = {-1, 0};
  else if (n == "back") c = {2, 0};
  else if (n != "front") c = {1, 1};  // a pictorial view: the free corner
  if (first_angle && n != "back" && n != "front" && (c[0] != 1 || c[1] != 1)) c = {-c[0], -c[1]};
  return c;
}

// A sheet's views: each one's cell and label. A section view takes its standard view's place
// when no other view has it, else a place right of the middle row; it is labelled "A–A".
struct SheetPlan {
  std::vector<std::array<int, 2>> cells;
  std::vector<std::string> labels;
};

SheetPlan sheet_plan(const std::vector<std::string>& names, const std::vector<const RenderResult*>& results, bool first_angle) {
  SheetPlan plan;
  std::vector<std::size_t> homeless;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const NamedSection* s = i < results.size() && results[i]->section_view ? &*results[i]->section_view : nullptr;
    std::string up = names[i];
    for (char& c : up) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    plan.labels.push_back(s ? section_view_label(*s) : up);
    plan.cells.push_back(standard_cell(s ? s->standard : names[i], first_angle));
    if (s) homeless.push_back(i);
  }
  for (std::size_t i : homeless) {
    const NamedSection& s = *results[i]->section_view;
    bool taken = s.standard.empty();
    for (std::size_t j = 0; j < names.size() && !taken; ++j) taken = j != i && plan.cells[j] == plan.cells[i] && (!results[j]->section_view || j < i);
    if (!taken) continue;
    int right = 0;
    for (std::size_t j = 0; j < names.size(); ++j)
      if (j != i && plan.cells[j][1] == 0) right = std::max(right, plan.cells[j][0] + 1);
    plan.cells[i] = {right, 0};
  }
  return plan;
}

Sheet layout_sheet(const std::vector<Plot>& plots, const std::vector<std::string>& view_names, const SheetPlan& plan, const PageOptions& page) {
  if (view_names.empty()) return layout_single(plots[0], page);
  std::vector<const Plot*> ptrs;
  for (const Plot& p : plots) ptrs.push_back(&p);
  return layout_views(ptrs, plan.cells, plan.labels, page);
}

std::string write_plots(std::vector<Plot>& plots, const std::vector<std::string>& view_names, const SheetPlan& plan, const PageOptions& page,
                        const OutputOptions& a, const std::string& format, const std::string& command, bool perspective);

// The page of a sheet: with section views and no margin given, a margin of 12 mm holds the
// section lines' arrows and letters (they stand up to 11 mm beyond the scene).
PageOptions sheet_page(const OutputOptions& a, const std::vector<const RenderResult*>& results) {
  PageOptions page = page_options(a);
  bool sections = false;
  for (const RenderResult* r : results) sections = sections || r->section_view;
  if (sections && !page.margin_mm) page.margin_mm = 12;
  // A picture frame is the picture's edge: no margin around it without a page.
  if (!page.page && !page.margin_mm && results.size() == 1 && results[0]->pyramid) page.margin_mm = 0;
  return page;
}

// A ring cut to the half-plane where side·(p - at) >= 0 along axis k (Sutherland-Hodgman).
std::vector<Point2> crop_ring(const std::vector<Point2>& ring, int k, double at, double side) {
  std::vector<Point2> out;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point2 &p = ring[i], &q = ring[(i + 1) % ring.size()];
    const double dp = side * (p[k] - at), dq = side * (q[k] - at);
    if (dp >= 0) out.push_back(p);
    if ((dp < 0) != (dq < 0)) {
      const double t = dp / (dp - dq);
      out.push_back(Point2{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
    }
  }
  return out;
}

// The fills cut to the picture frame: a page decision in drawing doubles, after the exact
// visibility (the JSON keeps the whole exact polygons). Each ring on its own: the frame is
// convex, so what lies inside it is filled as before.
void crop_fills(Plot& plot, const std::array<double, 4>& rect) {
  std::vector<PlotFill> kept;
  for (PlotFill& f : plot.fills) {
    std::vector<std::vector<Point2>> rings;
    for (std::vector<Point2>& ring : f.rings) {
      for (int k = 0; k < 2 && ring.size() >= 3; ++k) ring = crop_ring(crop_ring(ring, k, rect[k], 1), k, rect[k + 2], -1);
      if (ring.size() >= 3) rings.push_back(std::move(ring));
    }
    if (rings.empty()) continue;
    f.rings = std::move(rings);
    kept.push_back(std::move(f));
  }
  plot.fills = std::move(kept);
}

// The caps' hatch lines, on the page's scale (the layout is made once without them: they lie
// inside the caps, so the drawing's bounds and scale do not change by them).
void add_hatching(std::vector<Plot>& plots, const std::vector<const RenderResult*>& results, const Sheet& sheet, const OutputOptions& a) {
  bool any = false;
  for (const RenderResult* r : results) any = any || has_caps(*r);
  if (!any) return;
  progress("hatching");
  const double pen = plot_style(a).weights.at("hatch");
  PlotOptions po = plot_options(a);
  po.hidden = false;
  for (std::size_t i = 0; i < results.size(); ++i) {
    LineDrawing h = cap_hatching(*results[i], sheet.views[i].scale, pen, a.threads);
    if (results[i]->pyramid)
      for (Segment& s : h.segments)
        for (const Plane& side : results[i]->pyramid->sides) clip_near(s, side);
    if (h.segments.empty()) continue;
    Plot hp = make_plot(h, results[i]->camera, po);
    for (PlotLayer& l : hp.layers) plots[i].layers.push_back(std::move(l));
  }
}

// The tone hatching options of `a` (the pen: the "tone" weight).
ToneHatchOptions tone_options(const OutputOptions& a) {
  ToneHatchOptions o;
  if (a.hatch_levels < 2 || a.hatch_levels > kMaxToneLevels)
    throw std::invalid_argument("--hatch-levels must be from 2 to " + std::to_string(kMaxToneLevels) + " (got " + std::to_string(a.hatch_levels) +
                                ")");
  o.tone.levels = a.hatch_levels;
  o.tone.pen_mm = plot_style(a).weights.at("tone");
  o.threads = a.threads;
  if (a.hatch_angle == "contour") {
    o.contour = true;
  } else {
    std::size_t used = 0;
    double deg = NAN;
    try {
      deg = std::stod(a.hatch_angle, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != a.hatch_angle.size() || !std::isfinite(deg) || std::fabs(deg) > 360)
      throw std::invalid_argument("--hatch-angle must be an angle in degrees (-360 to 360) or 'contour' (got '" + a.hatch_angle + "')");
    o.angle = deg;
  }
  return o;
}

// The visible faces' tone hatching, on the page's scale (the fills it replaces set the bounds).
void add_tone_hatching(std::vector<Plot>& plots, const std::vector<const RenderResult*>& results, const Sheet& sheet, const OutputOptions& a) {
  if (!a.hatch) return;
  progress("tone hatching");
  const ToneHatchOptions o = tone_options(a);
  PlotOptions po = plot_options(a);
  po.hidden = false;
  for (std::size_t i = 0; i < results.size(); ++i) {
    std::vector<TonePiece> h = tone_hatching(*results[i], sheet.views[i].scale, o);
    if (const auto& frame = results[i]->pyramid) {  // exactly inside the picture frame
      std::vector<TonePiece> kept;
      for (TonePiece& t : h)
        if (auto e = clip_to_frame(*frame, t.ends[0], t.ends[1])) t.ends = *e, kept.push_back(std::move(t));
      h = std::move(kept);
    }
    if (h.empty()) continue;
    Plot hp = tone_plot(h, *results[i], po);
    for (PlotLayer& l : hp.layers) plots[i].layers.push_back(std::move(l));
  }
}

std::string write_plots(std::vector<Plot>& plots, const std::vector<std::string>& view_names, const SheetPlan& plan, const PageOptions& page,
                        const OutputOptions& a, const std::string& format, const std::string& command, bool perspective) {
  PlotStyle style = plot_style(a);
  {  // layer numbers: the pen map's, else the drawing's order before a selection
    Sheet all;
    for (const Plot& p : plots) all.views.push_back(SheetView{&p, 1, 0, 0, ""});
    const std::vector<std::string> names = sheet_layer_names(all);
    if (!a.pens.empty()) style.layer_numbers = pen_numbers(a.pens, names);
    else
      for (std::size_t k = 0; k < names.size(); ++k) style.layer_numbers[names[k]] = static_cast<int>(k + 1);
  }
  select_layers(a.layers, plots, a.hidden != "none");
  if (perspective && page.scale) throw std::invalid_argument("--scale (true scale) needs an orthographic view");
  Sheet sheet = layout_sheet(plots, view_names, plan, page);
  style.min_length_mm = a.min_length;  // specks go once the dashes are cut (the writers)
  // Lines that coincide on the page are drawn once (after every exact decision).
  CoincidentStats merged;
  if (!a.raw && a.merge_tolerance != 0) {
    double tol = a.merge_tolerance;
    if (tol < 0) {
      double thinnest = INFINITY;
      for (const Plot& p : plots)
        for (const PlotLayer& l : p.layers) thinnest = std::min(thinnest, style.weight(l));
      tol = std::isfinite(thinnest) ? thinnest / 4 : 0;
    }
    for (Plot& p : plots) {
      const CoincidentStats m = merge_coincident_lines(p, tol / sheet.views[0].scale);
      merged.pieces_removed += m.pieces_removed, merged.length_removed += m.length_removed * sheet.views[0].scale;
    }
  }
  // Specks and pen order need the page's scale; the layout does not change by them.
  progress("pen order");
  for (Plot& p : plots) {
    drop_short_strokes(p, a.min_length / sheet.views[0].scale);
    // A shaded picture is not plotted: its lines keep their chained order.
    PenOrderOptions order;
    order.threads = a.threads;
    if (!a.raw && p.fills.empty()) order_plot(p, {p.bounds[0], p.bounds[3]}, order);
  }
  for (const std::string& note : sheet.notes) std::cerr << "hlr " << command << ": note: " << note << "\n";
  progress("writing");
  std::string text = format == "pdf"   ? sheet_to_pdf(sheet, style)
                     : format == "png" ? sheet_to_png(sheet, style, a.dpi)
                     : format == "dxf" ? sheet_to_dxf(sheet, style)
                                       : sheet_to_svg(sheet, style);
  if (a.stats) {
    print_stats(plots, sheet.views[0].scale);
    std::cerr << "stats: coincident on the page: " << merged.pieces_removed << " parts, " << merged.length_removed << " mm left out\n";
    print_layer_stats(sheet, style);
  }
  return text;
}

}  // namespace

SurfacesJson surfaces_json(const RenderResult& r) {
  SurfacesJson sj;
  if (r.surfaces) sj = SurfacesJson{&*r.surfaces, &r.face_colours, nullptr};
  if (r.priority) sj = SurfacesJson{nullptr, &r.face_colours, &*r.priority};
  if (r.shadows) sj.shadows = &*r.shadows, sj.shadow_colours = &r.shadow_colours;
  if (r.transparent) sj.transparent = &*r.transparent, sj.transparent_colours = &r.transparent_colours;
  return sj;
}

void check_output_options(const OutputOptions& a) {
  if (!(a.width > 0) || !std::isfinite(a.width) || a.width > 1e6) throw std::invalid_argument("--width must be a positive size in millimetres");
  if (!(a.stroke >= 0) || !std::isfinite(a.stroke) || a.stroke > 1e3) throw std::invalid_argument("--stroke must be a positive width in millimetres");
  if (a.line_widths != "iso" && a.line_widths != "kinds") throw std::invalid_argument("--line-widths must be iso or kinds");
  if (!(a.min_length >= 0) || !std::isfinite(a.min_length)) throw std::invalid_argument("--min-length must be a length in millimetres");
  if (!std::isfinite(a.merge_tolerance) || a.merge_tolerance > 10)
    throw std::invalid_argument("--merge-tolerance must be a distance in millimetres (0: off)");
  if (!(a.dpi > 0) || a.dpi > 4800) throw std::invalid_argument("--dpi must be between 0 and 4800");
  page_options(a);
  plot_style(a);
  if (!(a.hatch_pen >= 0) || !std::isfinite(a.hatch_pen) || a.hatch_pen > 10)
    throw std::invalid_argument("--hatch-pen must be a pen width in millimetres");
  tone_options(a);
}

PartText drawing_text(const std::vector<const RenderResult*>& results, const std::vector<std::string>& view_names, const OutputOptions& a,
                      const std::string& format, const std::string& command) {
  PartText text;
  std::vector<Plot> plots;
  if (format == "json") {
    // The exact pieces, and the numbers of the 2D stage a plotter would get (drawing units).
    std::optional<Plot> plot;
    if (!a.raw) {
      PlotOptions po;
      po.hidden = a.hidden != "none";
      po.threads = a.threads;
      plot = make_plot(results[0]->drawing, results[0]->camera, po);
      PenOrderOptions order;
      order.threads = a.threads;
      order_plot(*plot, {plot->bounds[0], plot->bounds[3]}, order);
    }
    const RenderResult& r0 = *results[0];
    SurfacesJson sj = surfaces_json(r0);
    sj.section = section_text(r0, a);
    if (r0.pyramid) sj.frame = &*r0.pyramid;
    text = to_json_text(r0.names, r0.drawing, r0.camera, plot ? &plot->stats : nullptr, sj);
  } else {
    progress("strokes");
    const PlotOptions po = plot_options(a);
    for (const RenderResult* r : results) {
      plots.push_back(make_plot(r->drawing, r->camera, po));
      add_surface_fills(plots.back(), *r);
      if (r->pyramid) {  // the page shows the picture's frame; the fills are cropped to it there
        plots.back().bounds = r->pyramid->rect;
        crop_fills(plots.back(), r->pyramid->rect);
      }
      if (a.hatch) plots.back().fills.clear();  // a pen draws the shade as hatching (the fills set the bounds)
    }
    // Hatching and section lines are sized on the page: the layout is made once without them
    // (they do not change the drawing's bounds, so neither the scale nor the places).
    const SheetPlan plan = sheet_plan(view_names, results, a.projection == "first");
    const PageOptions page = sheet_page(a, results);
    const Sheet sheet = layout_sheet(plots, view_names, plan, page);
    add_hatching(plots, results, sheet, a);
    add_tone_hatching(plots, results, sheet, a);
    if (!view_names.empty()) add_section_lines(plots, results, sheet);
    text.add(write_plots(plots, view_names, plan, page, a, format, command, results[0]->camera.perspective));
  }
  return text;
}

PartText drawing_text(const std::vector<RenderResult>& results, const std::vector<std::string>& view_names, const OutputOptions& a,
                      const std::string& format, const std::string& command) {
  std::vector<const RenderResult*> ptrs;
  for (const RenderResult& r : results) ptrs.push_back(&r);
  return drawing_text(ptrs, view_names, a, format, command);
}

PartText drawing_text(const RenderResult& result, const OutputOptions& a, const std::string& format, const std::string& command) {
  return drawing_text(std::vector<const RenderResult*>{&result}, {}, a, format, command);
}

std::string section_text(const RenderResult& r, const OutputOptions& a) {
  if (r.section_planes.empty()) return "";
  // The hatch lines of the page the same options give the SVG.
  const Plot lines = make_plot(r.drawing, r.camera, plot_options(a));
  const double scale = layout_single(lines, page_options(a)).views[0].scale;
  return section_json(r, cap_hatching(r, scale, plot_style(a).weights.at("hatch"), a.threads), scale);
}

PlotOptions plot_options(const OutputOptions& a) {
  PlotOptions po;
  po.hidden = a.hidden != "none";
  po.dedup = po.chain = !a.raw;
  po.threads = a.threads;
  return po;
}

std::string plots_text(std::vector<Plot>& plots, const std::vector<std::string>& view_names, const OutputOptions& a, const std::string& format,
                       const std::string& command, bool perspective) {
  return write_plots(plots, view_names, sheet_plan(view_names, {}, a.projection == "first"), page_options(a), a, format, command, perspective);
}

}  // namespace hlr
