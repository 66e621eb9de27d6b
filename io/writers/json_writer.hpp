// JSON writer: the exact drawing in the schema of docs/output-format.md, every coordinate an
// exact rational in lowest terms, world coordinates; one body and one segment per line.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "algorithms/clip/view_pyramid.hpp"
#include "algorithms/model/camera.hpp"
#include "algorithms/model/line_drawing.hpp"
#include "algorithms/plot/plot.hpp"
#include "algorithms/shading/lighting.hpp"
#include "algorithms/surfaces/priority_list.hpp"
#include "algorithms/surfaces/shadows.hpp"
#include "algorithms/surfaces/transparency.hpp"
#include "algorithms/surfaces/visible_surfaces.hpp"
#include "io/writers/atomic_file.hpp"
#include "io/writers/svg_writer.hpp"

namespace hlr {

/// With `plot`, a "plot" object follows "stats": the plotting 2D stage's numbers in vpype's
/// terms (path_count, pen_down_length, pen_up_length, ...; lengths in drawing units).
std::string to_json(const std::vector<DrawingBody>& bodies, const LineDrawing& drawing, const Camera& camera,
                    const PlotStats* plot = nullptr);

/// The visible surfaces of a render: a "surfaces" object after "stats" with the
/// picture's exact axes, one face per line with its side, shade, exact area and visible
/// polygons (exact 3D corners in the face's plane), and the route's counters.
/// The painter's list of a priority render: a "priority" object with one polygon per line in
/// the order painted (its face, whether it is a cut part, exact 3D corners, shade) and the
/// algorithm's counters.
struct SurfacesJson {
  const VisibleSurfaces* surfaces = nullptr;
  const std::vector<std::vector<Rgb>>* colours = nullptr;
  const PriorityResult* priority = nullptr;
  /// Shadows (--shadows): a "shadows" object, one visible face per line with its regions (the
  /// lights that reach each, its shade) and per light the lit and the shadow polygons.
  const Shadows* shadows = nullptr;
  const std::vector<std::vector<Rgb>>* shadow_colours = nullptr;
  /// Transparency: a "transparency" object, one region per line: the faces seen one behind the
  /// other (back to front), the final colour, the exact picture polygon and its area.
  const TransparentPicture* transparent = nullptr;
  const std::vector<Rgb>* transparent_colours = nullptr;
  /// Sections: the "section" object's text (io/pipeline/section.hpp), "" for none.
  std::string section;
  /// A perspective view's picture frame: the view's "frame" (its four exact planes through the
  /// eye, positive inside, and the rectangle the page shows).
  const ViewPyramid* frame = nullptr;
};
std::string to_json(const std::vector<DrawingBody>& bodies, const LineDrawing& drawing, const Camera& camera,
                    const PlotStats* plot, const SurfacesJson& surfaces);
/// The same text, its segments' lines made on all cores as it is written (a 1M-triangle
/// drawing's JSON is 335 MB: it is never all in memory). `drawing` must outlive the text.
PartText to_json_text(const std::vector<DrawingBody>& bodies, const LineDrawing& drawing, const Camera& camera, const PlotStats* plot,
                      const SurfacesJson& surfaces);

/// One piece of a segment as it appears in `segments` of the JSON; also used by `hlr explain`,
/// so both print the same.
nlohmann::ordered_json piece_json(const Segment& segment, const Piece& piece);
/// piece_json(segment, piece).dump(), appended to `out` without building the JSON value (the
/// segments of a 1M-triangle drawing: 1.5 million of them).
void append_piece_json(std::string& out, const Segment& segment, const Piece& piece);

}  // namespace hlr
