// The output stage of every drawing (docs/design.md, "The render pipeline, one screen"): from
// exact line drawings (RenderResult) to the text or bytes written — the plotting 2D stage,
// layers, the page layout, specks, pen order and the SVG, PDF, PNG or DXF writer; or the exact
// JSON. `hlr render`, `hlr horizon` and Python's Drawing.svg()/plot() all write through it, so
// the same drawing gives the same bytes from each.
#pragma once

#include <string>
#include <vector>

#include "algorithms/plot/plot.hpp"
#include "io/pipeline/render.hpp"
#include "io/writers/atomic_file.hpp"
#include "io/writers/json_writer.hpp"

namespace hlr {

/// What the drawing looks like on the page (the defaults are the CLI's).
struct OutputOptions {
  std::string format;                         ///< as asked (the CLI resolves it from -o)
  std::string hidden = "none";                ///< none, dashed or solid
  std::string dashes = "pattern";             ///< pattern or geometry
  std::string page, margin, scale, weights;   ///< empty: the drawing's own size, 10 mm, fit, defaults
  std::string layers;                         ///< empty: all; else names or numbers, comma-separated
  std::string pens;                           ///< a pen map "visible=1,hidden=2,tone=3": layer numbers (empty: drawing order)
  std::string projection = "third";           ///< a sheet of standard views: first or third angle
  bool landscape = false, raw = false, stats = false;
  /// Tone hatching instead of fills (a surfaces render: io/output/tone_hatching.hpp): the
  /// number of tone levels, the angle in degrees or "contour", the pen's width in mm (0: the
  /// "tone" weight).
  bool hatch = false;
  int hatch_levels = 5;
  std::string hatch_angle = "45";
  double hatch_pen = 0;
  /// Line widths: "iso" (ISO 128: one wide width for every visible edge, narrow hidden, tangent
  /// and hatch lines) or "kinds" (outlines wider than the other visible edges).
  std::string line_widths = "iso";
  /// The visible edges' width in mm, the other widths in proportion; 0: the default (0.5 iso,
  /// 0.35 kinds).
  double width = 150, stroke = 0, min_length = 0, dpi = 150;
  /// Lines closer than this on the page (mm), nearly parallel, are drawn once, the higher class
  /// kept (algorithms/plot/coincident_lines.hpp; a drawing decision after every exact one). 0:
  /// only the exact clean-up; negative: a quarter of the thinnest pen drawn.
  double merge_tolerance = -1;
  unsigned threads = 0;
};

/// The filled products of a render for the JSON writer (surfaces or the priority list,
/// shadows, transparency), pointing into `r`.
SurfacesJson surfaces_json(const RenderResult& r);

/// The JSON's "section" member for a render with a section ("" without): the hatch lines
/// those of the page `a` gives (section.hpp's section_json).
std::string section_text(const RenderResult& r, const OutputOptions& a);
/// Checks the numbers, the page and the line weights (before any long work).
void check_output_options(const OutputOptions& a);

/// The file's content, in parts (the JSON's segments made as they are written: `results` must
/// outlive the text): JSON of the first drawing (with the 2D stage's numbers), or the sheet of
/// all drawings (`view_names` label them and place them as standard views when not empty).
/// `format`: svg, pdf, png, dxf or json; `command` names the caller in notes.
PartText drawing_text(const std::vector<const RenderResult*>& results, const std::vector<std::string>& view_names,
                      const OutputOptions& a, const std::string& format, const std::string& command);
PartText drawing_text(const std::vector<RenderResult>& results, const std::vector<std::string>& view_names, const OutputOptions& a,
                      const std::string& format, const std::string& command);
/// One drawing.
PartText drawing_text(const RenderResult& result, const OutputOptions& a, const std::string& format, const std::string& command);

/// The plotting options of `a` (hidden layers, clean-up and chaining unless raw, threads).
PlotOptions plot_options(const OutputOptions& a);

/// drawing_text()'s picture formats from plots already made (make_plot() or a faster route):
/// layers, page layout, specks, pen order, the writer.
std::string plots_text(std::vector<Plot>& plots, const std::vector<std::string>& view_names, const OutputOptions& a,
                       const std::string& format, const std::string& command, bool perspective = false);

}  // namespace hlr
