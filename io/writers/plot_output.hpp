// Drawings to plot and print: the plotting 2D stage's layers (algorithms/plot/plot.hpp)
// placed on a page (size, margins, true scale 1:N or fit, several views at one scale in first-
// or third-angle arrangement) and written as SVG with Inkscape layers, PDF and PNG (cairo) or
// DXF (dxflib) with layers and linetypes. Line weights follow ISO 128 (extra wide 0.7 mm for
// cut lines, wide 0.5 for visible edges, narrow 0.25 for hatching, tangent edges and, dashed,
// for hidden lines; all settable). The table below is the "kinds" set (outlines 0.5, other
// visible edges 0.35); io/output's plot_style makes every visible edge wide by default.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/plot/plot.hpp"

namespace hlr {

/// A view placed on the sheet: page point (mm, y down) = (ox + scale·x, oy − scale·y).
struct SheetView {
  const Plot* plot = nullptr;
  double scale = 1;  // mm per drawing unit
  double ox = 0, oy = 0;
  std::string label;  // printed under the view when not empty
  Point2 page(const Point2& p) const { return {ox + scale * p[0], oy - scale * p[1]}; }
};

struct Sheet {
  double width_mm = 0, height_mm = 0;
  std::vector<SheetView> views;
  std::string caption;  // bottom right ("scale 1:2"), when not empty
  std::vector<std::string> notes;  // for the user (a drawing larger than the page at its scale)
};

/// A text of the sheet in page mm (y down): its baseline's point (`anchor` 0: where it starts,
/// 0.5: its middle, 1: where it ends) and its height.
struct SheetText {
  Point2 at{0, 0};
  std::string text;
  double size_mm = 3.5, anchor = 0.5;
};

/// Every text of the sheet, as the writers put them in the layer "labels": each view's label
/// under it, the views' own texts (Plot::texts, centred on their point) and the caption.
std::vector<SheetText> sheet_texts(const Sheet& sheet);

struct PageOptions {
  std::optional<std::array<double, 2>> page;  // mm, portrait as named; none: the drawing's own size
  bool landscape = false;
  std::optional<double> margin_mm;            // default 10 on a page, 4% of the drawing without
  std::optional<double> scale;                // mm per drawing unit (1:N -> 1/N); none: fit
  double width_mm = 150;                      // without a page and a scale: the drawing's width
  double gap_mm = 15;                         // between views on a sheet
};

/// "A4", "a3", "letter", "420x297mm", "420x297": width and height in mm (portrait for names).
std::array<double, 2> parse_page_size(const std::string& text);
/// "1:2", "2:1", "1": mm per drawing unit. Throws std::invalid_argument.
double parse_scale(const std::string& text);

/// One view on its page, centred.
Sheet layout_single(const Plot& plot, const PageOptions& options);

/// Several views at one common scale: `grid` gives each view's (column, row) cell, row +1 above
/// (third-angle: top above front, right to the right; first-angle: the opposite). Rows share
/// their vertical placement and columns their horizontal one, so views stay aligned as
/// projections.
Sheet layout_views(const std::vector<const Plot*>& plots, const std::vector<std::array<int, 2>>& grid,
                   const std::vector<std::string>& labels, const PageOptions& options);

enum class DashMode { Pattern, Geometry };

/// The colour of lines seen through transparent faces (PlotLayer::through): a second pen.
inline constexpr const char* kThroughGrey = "#808080";

struct PlotStyle {
  /// Width in mm per layer key: "cut", "silhouette", "boundary", "crease", "intersection", "edge", "hatch",
  /// "overhead", "section-line", "section-mark", "polyline", "tone" (every tone level), "hidden" (all hidden layers),
  /// "through" (all layers seen through transparent faces).
  std::map<std::string, double> weights = {{"cut", 0.7},      {"silhouette", 0.5},    {"boundary", 0.5},      {"crease", 0.35},   {"tangent", 0.25},
                                           {"hatch", 0.25},   {"overhead", 0.25},     {"intersection", 0.35}, {"edge", 0.35},     {"hidden", 0.25},
                                           {"through", 0.25}, {"section-line", 0.35}, {"section-mark", 0.7},  {"polyline", 0.35}, {"tone", 0.25}};
  /// The number each layer is written with ("2 hidden-crease"; AxiDraw plots by number), by
  /// layer name: a pen map's (several layers may share a pen) or the drawing's order before a
  /// selection of layers. Empty: the order of the layers written.
  std::map<std::string, int> layer_numbers;
  /// Strokes shorter than this on the page (mm) are not written: specks, and the remnants that
  /// cutting dashes leaves (applied after the dashes are cut).
  double min_length_mm = 0;
  DashMode dashes = DashMode::Pattern;
  bool hidden_dashed = true;     // false: hidden lines solid (thin)
  bool numbered_layers = true;   // AxiDraw-style "1 visible-silhouette"
  double weight(const PlotLayer& l) const;
  /// Drawn with the dash pattern (hidden lines, dashed, not cut into dash strokes).
  /// Dashed: hidden lines (unless drawn solid) and a plan's overhead lines.
  bool dashed(const PlotLayer& l) const { return (!l.visible && !l.through && hidden_dashed) || l.kind == LineKind::Overhead; }
  bool pattern_dashed(const PlotLayer& l) const { return dashed(l) && dashes == DashMode::Pattern; }
  /// ISO 128 dashed narrow line: dash 12 d, gap 3 d (d: line width).
  std::array<double, 2> dash_pattern(const PlotLayer& l) const;
};

/// Parses "silhouette=0.7,hidden=0.18" into the style's weights. Throws std::invalid_argument.
void parse_weights(const std::string& text, PlotStyle& style);

/// The layer's strokes in page mm, dashes cut when the style says geometry.
std::vector<std::vector<Point2>> page_strokes(const SheetView& view, const PlotLayer& layer, const PlotStyle& style,
                                              std::vector<char>* closed = nullptr);

std::string sheet_to_svg(const Sheet& sheet, const PlotStyle& style);
/// PDF and PNG through cairo; `dpi` for PNG.
std::string sheet_to_pdf(const Sheet& sheet, const PlotStyle& style);
std::string sheet_to_png(const Sheet& sheet, const PlotStyle& style, double dpi = 150);
/// DXF (AutoCAD 2000, dxflib): one layer per visibility and kind, hidden layers with the
/// DASHED linetype (or cut dashes), lineweights, coordinates in mm with y up.
std::string sheet_to_dxf(const Sheet& sheet, const PlotStyle& style);

/// All layer names of the sheet in drawing order (visible first), for `--layers` and tests.
std::vector<std::string> sheet_layer_names(const Sheet& sheet);

/// A line layer of the sheet as the writers show it: its name, its label (AxiDraw's number
/// first when the style numbers layers) and one of the views' layers of that name (they share
/// kind and visibility, so width, colour and dashes).
struct SheetLayer {
  std::string name, label;
  const PlotLayer* layer = nullptr;
};
std::vector<SheetLayer> sheet_layers(const Sheet& sheet, const PlotStyle& style);

}  // namespace hlr
