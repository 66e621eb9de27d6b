// The output options and the step from drawings to files (see drawing_output.hpp).
#include "cli/drawing_output.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <set>

#include "algorithms/support/progress.hpp"
#include "cli/arguments.hpp"
#include "io/writers/json_writer.hpp"
#include "io/writers/plot_output.hpp"

namespace hlr::cli {
namespace {

PageOptions page_options(const OutputArgs& a) {
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

PlotStyle plot_style(const OutputArgs& a) {
  PlotStyle st;
  for (auto& [k, w] : st.weights) w *= a.stroke / 0.35;  // --stroke: the visible edges' width, the rest in proportion
  if (!a.weights.empty()) parse_weights(a.weights, st);
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
    static const std::set<std::string> known = {"visible-silhouette", "visible-boundary", "visible-crease", "visible-intersection",
                                                "visible-edge", "hidden-silhouette", "hidden-boundary", "hidden-crease",
                                                "hidden-intersection", "hidden-edge", "through-silhouette", "through-boundary",
                                                "through-crease", "through-intersection", "through-edge"};
    if (!known.count(item))
      throw std::invalid_argument("--layers: unknown layer '" + item +
                                  "' (visible, through, hidden, visible-silhouette, hidden-crease, ... or numbers)");
    keep.insert(item);
  }
  bool drawn = false;
  for (const Plot& p : plots) {
    drawn = drawn || !p.fills.empty();
    for (const PlotLayer& l : p.layers) drawn = drawn || keep.count(l.name());
  }
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
  std::cerr << "stats: pieces " << t.pieces << ", end-on " << t.zero_length << ", overlap groups " << t.overlap_groups
            << " (duplicate length " << t.duplicate_length << " mm removed), edges " << t.edges << ", paths " << t.path_count
            << " (minimum " << t.min_path_count << "), specks dropped " << t.dropped_short << ", pen-down " << t.pen_down_length
            << " mm, pen-up " << t.pen_up_length << " mm (greedy " << t.pen_up_greedy << ", unordered " << t.pen_up_unordered
            << ")";
  std::cerr.precision(3);
  std::cerr << ", exact tests: points " << t.exact_point_tests << ", lines " << t.exact_line_tests;
  std::cerr << ", clean-up " << t.seconds_dedup << " s, chaining " << t.seconds_chain << " s, ordering " << t.seconds_order << " s\n";
}

// Standard views on one sheet: their names and their cells (third-angle: top above front).
std::vector<std::array<int, 2>> sheet_cells(const std::vector<std::string>& names, bool first_angle) {
  std::vector<std::array<int, 2>> cells;
  for (const std::string& n : names) {
    std::array<int, 2> c{0, 0};
    if (n == "top") c = {0, 1};
    else if (n == "bottom") c = {0, -1};
    else if (n == "right") c = {1, 0};
    else if (n == "left") c = {-1, 0};
    else if (n == "back") c = {2, 0};
    else if (n != "front") c = {1, 1};  // a pictorial view: the free corner
    if (first_angle && n != "back" && n != "front" && (c[0] != 1 || c[1] != 1)) c = {-c[0], -c[1]};
    cells.push_back(c);
  }
  return cells;
}

}  // namespace

void add_output_options(CLI::App* cmd, OutputArgs& a, bool sheets) {
  cmd->add_option("-o", a.output, "Output file (default: standard output); the extension picks the format (.svg .pdf .png .dxf .json)");
  cmd->add_option("--format", a.format, "svg, pdf, png, dxf or json (default: from the output file's extension, else svg)")
      ->check(CLI::IsMember({"svg", "pdf", "png", "dxf", "json"}));
  if (sheets)
    cmd->add_option("--projection", a.projection, "Arrangement of --views: third (top above front; default) or first angle")
        ->check(CLI::IsMember({"first", "third"}));
  cmd->add_option("--hidden", a.hidden, "none, dashed or solid (default none); hidden lines go to their own layers")
      ->check(CLI::IsMember({"none", "dashed", "solid"}));
  cmd->add_option("--dashes", a.dashes, "pattern (stroke-dasharray, continuous along each stroke) or geometry (real dash strokes for plotters)")
      ->check(CLI::IsMember({"pattern", "geometry"}));
  cmd->add_option("--threads", a.threads, "Threads (default: all cores)");
  cmd->add_flag("--stats", a.stats, "Print the 2D stage's numbers (paths, pen-up and pen-down lengths in mm) to standard error");
  cmd->add_flag("--progress", a.progress, "Say what it is doing on standard error (default: when it is a terminal)");
  cmd->add_flag("--quiet", a.quiet, "No progress messages");
  cmd->add_option("--page", a.page, "Page: A0..A5, letter, legal, tabloid or WxHmm (default: the drawing's own size)");
  cmd->add_flag("--landscape", a.landscape, "Turn the page to landscape");
  cmd->add_option("--margin", a.margin, "Margin in millimetres (default 10 on a page)");
  cmd->add_option("--scale", a.scale, "True scale 1:N or N:1 (scene units are millimetres; default: fit the page)");
  cmd->add_option("--width", a.width, "Drawing width in millimetres without --page (default 150)");
  cmd->add_option("--stroke", a.stroke, "Width of visible edges in millimetres (default 0.35; outlines 0.5 and hidden 0.25 in proportion)");
  cmd->add_option("--weights", a.weights, "Line widths per kind in mm, e.g. silhouette=0.7,crease=0.35,hidden=0.18");
  cmd->add_option("--layers", a.layers, "Layers to write: visible, through, hidden, visible-silhouette, through-edge, hidden-crease, ... or their numbers");
  cmd->add_option("--min-length", a.min_length, "Drop strokes shorter than this many millimetres on the page (specks)");
  cmd->add_option("--dpi", a.dpi, "PNG resolution (default 150)");
  cmd->add_flag("--raw", a.raw, "One line per exact piece: no clean-up, chaining or pen order");
}

std::string check_output_args(const OutputArgs& a, bool sheet) {
  if (!(a.width > 0) || !std::isfinite(a.width) || a.width > 1e6) throw std::invalid_argument("--width must be a positive size in millimetres");
  if (!(a.stroke > 0) || !std::isfinite(a.stroke) || a.stroke > 1e3) throw std::invalid_argument("--stroke must be a positive width in millimetres");
  if (!(a.min_length >= 0) || !std::isfinite(a.min_length)) throw std::invalid_argument("--min-length must be a length in millimetres");
  if (!(a.dpi > 0) || a.dpi > 4800) throw std::invalid_argument("--dpi must be between 0 and 4800");
  const std::string format = output_format(a.format, a.output,
                                           {{".svg", "svg"}, {".pdf", "pdf"}, {".png", "png"}, {".dxf", "dxf"}, {".json", "json"}}, "svg");
  if (format == "json" && sheet) throw std::invalid_argument("--views makes a sheet: write svg, pdf, png or dxf (JSON is one view)");
  if ((format == "pdf" || format == "png") && a.output.empty() && isatty(1))
    throw std::invalid_argument("a " + format + " file goes to -o FILE, not to the terminal");
  page_options(a);
  plot_style(a);
  return format;
}

PartText drawing_text(const std::vector<RenderResult>& results, const std::vector<std::string>& view_names, const OutputArgs& a,
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
      plot = make_plot(results[0].drawing, results[0].camera, po);
      PenOrderOptions order;
      order.threads = a.threads;
      order_plot(*plot, {plot->bounds[0], plot->bounds[3]}, order);
    }
    const RenderResult& r0 = results[0];
    SurfacesJson sj;
    if (r0.surfaces) sj = SurfacesJson{&*r0.surfaces, &r0.face_colours, nullptr};
    if (r0.priority) sj = SurfacesJson{nullptr, &r0.face_colours, &*r0.priority};
    if (r0.shadows) sj.shadows = &*r0.shadows, sj.shadow_colours = &r0.shadow_colours;
    if (r0.transparent) sj.transparent = &*r0.transparent, sj.transparent_colours = &r0.transparent_colours;
    text = to_json_text(r0.names, r0.drawing, r0.camera, plot ? &plot->stats : nullptr, sj);
  } else {
    progress("strokes");
    const PlotOptions po = plot_options(a);
    for (const RenderResult& r : results) {
      plots.push_back(make_plot(r.drawing, r.camera, po));
      add_surface_fills(plots.back(), r);
    }
    text.add(plots_text(plots, view_names, a, format, command, results[0].camera.perspective));
  }
  return text;
}

PlotOptions plot_options(const OutputArgs& a) {
  PlotOptions po;
  po.hidden = a.hidden != "none";
  po.dedup = po.chain = !a.raw;
  po.threads = a.threads;
  return po;
}

std::string plots_text(std::vector<Plot>& plots, const std::vector<std::string>& view_names, const OutputArgs& a,
                       const std::string& format, const std::string& command, bool perspective) {
  const PageOptions page = page_options(a);
  const PlotStyle style = plot_style(a);
  std::string text;
  {
    select_layers(a.layers, plots, a.hidden != "none");
    if (perspective && page.scale) throw std::invalid_argument("--scale (true scale) needs an orthographic view");
    std::vector<const Plot*> ptrs;
    for (const Plot& p : plots) ptrs.push_back(&p);
    std::vector<std::string> labels;
    for (const std::string& v : view_names) {
      std::string up = v;
      for (char& c : up) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      labels.push_back(up);
    }
    Sheet sheet = view_names.empty() ? layout_single(plots[0], page)
                                     : layout_views(ptrs, sheet_cells(view_names, a.projection == "first"), labels, page);
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
    text = format == "pdf" ? sheet_to_pdf(sheet, style)
         : format == "png" ? sheet_to_png(sheet, style, a.dpi)
         : format == "dxf" ? sheet_to_dxf(sheet, style)
                           : sheet_to_svg(sheet, style);
    if (a.stats) print_stats(plots, sheet.views[0].scale);
  }
  return text;
}

}  // namespace hlr::cli
