// Writers for Roberts' results: SVG (visible lines solid, hidden lines optionally dashed, a
// group per body, viewBox fitted with a margin, size in millimetres, fixed number formatting)
// and exact JSON (the schema in docs/output-format.md: every coordinate an exact rational in
// lowest terms, world coordinates).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "algorithms/roberts.hpp"

namespace hlr {

struct DrawingBody {
  std::string name, source;
};

struct SvgOptions {
  bool hidden_dashed = false;
  double width_mm = 150;
  double stroke_mm = 0.35;
};

std::string to_svg(const std::vector<DrawingBody>& bodies, const RobertsResult& result, const Camera& camera,
                   const SvgOptions& options);

std::string to_json(const std::vector<DrawingBody>& bodies, const RobertsResult& result, const Camera& camera);

/// One piece of a segment as it appears in `segments` of the JSON (docs/output-format.md);
/// also used by `hlr explain`, so both print the same.
nlohmann::ordered_json piece_json(const Segment& segment, const Piece& piece);

}  // namespace hlr
