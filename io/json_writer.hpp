// JSON writer: the exact drawing in the schema of docs/output-format.md, every coordinate an
// exact rational in lowest terms, world coordinates; one body and one segment per line.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "algorithms/line_drawing.hpp"
#include "algorithms/camera.hpp"
#include "io/svg_writer.hpp"

namespace hlr {

std::string to_json(const std::vector<DrawingBody>& bodies, const LineDrawing& drawing, const Camera& camera);

/// One piece of a segment as it appears in `segments` of the JSON; also used by `hlr explain`,
/// so both print the same.
nlohmann::ordered_json piece_json(const Segment& segment, const Piece& piece);

}  // namespace hlr
