// The 2D stage for drawings people plot and print: the projected pieces
// (drawing_2d.hpp) cleaned up exactly (line_dedup.hpp: same points, end-on edges, overlaps),
// chained into the fewest strokes per layer (path_chaining.hpp), specks dropped, and put in
// pen order (pen_order.hpp). A layer is one visibility and one line kind, so a plotter can
// change pens between layers. Coordinates are the drawing's (scene units or, in perspective,
// the picture plane at unit distance); the page layout scales them.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "algorithms/picture/drawing_2d.hpp"
#include "algorithms/picture/line_dedup.hpp"
#include "algorithms/plot/pen_order.hpp"

namespace hlr {

struct PlotLayer {
  bool visible = true;
  bool through = false;         // seen through transparent faces (not visible, not hidden)
  LineKind kind = LineKind::Edge;
  std::vector<Stroke> strokes;  // in pen order once ordered, each in drawing direction
  std::string name() const;     // "visible-silhouette", "through-edge", "hidden-crease", ...
};

/// What the 2D stage did, in vpype's terms where they exist (lengths in drawing units; the
/// writers report them in millimetres on the page).
struct PlotStats {
  std::size_t pieces = 0;             // drawn pieces in
  std::size_t zero_length = 0;        // seen end-on, not drawn
  std::size_t overlap_groups = 0, overlapped_pieces = 0;
  double duplicate_length = 0;        // drawn more than once before the clean-up
  std::size_t edges = 0;              // picture edges after the clean-up
  std::size_t path_count = 0;         // strokes
  std::size_t min_path_count = 0;     // the Euler lower bound for these edges
  std::size_t dropped_short = 0;      // strokes under the minimum length
  double pen_down_length = 0, pen_up_length = 0, pen_up_greedy = 0, pen_up_unordered = 0;
  std::size_t exact_point_tests = 0, exact_line_tests = 0;
  double seconds_dedup = 0, seconds_chain = 0, seconds_order = 0;
};

/// A filled region (visible surfaces): rings in drawing coordinates (outer
/// counter-clockwise, holes clockwise; fill by the even-odd rule) and its colour.
struct PlotFill {
  std::vector<std::vector<Point2>> rings;
  std::array<double, 3> colour{1, 1, 1};
  /// Edged in its own colour this wide (page mm), against antialiasing seams; a painter's
  /// fill is edged wider: its cut parts meet inside one face with nothing drawn over the cut.
  double edge_mm = 0.08;
};

/// A word on the drawing that is not a line (a section line's letter): centred on `at`
/// (drawing coordinates), `height_mm` high on the page.
struct PlotText {
  Point2 at{0, 0};
  std::string text;
  double height_mm = 5;
};

struct Plot {
  std::vector<PlotFill> fills;    // drawn first, under the lines (none for a line drawing)
  std::vector<PlotLayer> layers;  // visible layers first, then seen-through, then hidden; only non-empty ones
  std::vector<PlotText> texts;    // written with the sheet's labels
  PlotStats stats;
  std::array<double, 4> bounds{0, 0, 0, 0};  // x0, y0, x1, y1 of everything drawn
  bool empty() const;
};

struct PlotOptions {
  bool hidden = false;  // include hidden lines (their own layers)
  bool dedup = true;    // exact clean-up (off: every piece as it is)
  bool chain = true;    // join pieces into strokes
  unsigned threads = 0; // 0: all cores
};

/// Projects, cleans up and chains (not yet ordered: see order_plot).
Plot make_plot(const LineDrawing& lines, const Camera& camera, const PlotOptions& options = {});

/// make_plot()'s last step: the cleaned drawing's layers and chains (`seconds_dedup`: for the
/// statistics).
Plot plot_from_clean(const CleanDrawing& clean, const PlotOptions& options, double seconds_dedup = 0);

/// Drops strokes shorter than `min_length` (drawing units).
void drop_short_strokes(Plot& plot, double min_length);

/// Orders every layer's strokes from `home` (drawing coordinates); fills the pen statistics.
void order_plot(Plot& plot, Point2 home, const PenOrderOptions& options = {});

/// Length of a stroke (closed: with the closing edge).
double stroke_length(const Stroke& s);

}  // namespace hlr
