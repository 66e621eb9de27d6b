// JSON writer: the exact drawing in the schema of docs/output-format.md, every coordinate an
// exact rational in lowest terms, world coordinates; one body and one segment per line.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "algorithms/line_drawing.hpp"
#include "algorithms/camera.hpp"
#include "algorithms/plot.hpp"
#include "io/svg_writer.hpp"

namespace hlr {

/// With `plot`, a "plot" object follows "stats": the plotting 2D stage's numbers in vpype's
/// terms (path_count, pen_down_length, pen_up_length, ...; lengths in drawing units).
std::string to_json(const std::vector<DrawingBody>& bodies, const LineDrawing& drawing, const Camera& camera,
                    const PlotStats* plot = nullptr);

/// One piece of a segment as it appears in `segments` of the JSON; also used by `hlr explain`,
/// so both print the same.
nlohmann::ordered_json piece_json(const Segment& segment, const Piece& piece);

}  // namespace hlr
