// Lines that coincide on the page drawn once (docs/design.md, "Lines that coincide on the
// page"; ISO 128-20's priority where lines coincide: visible over seen-through over hidden, then
// the stronger kind). A drawing decision on the page, made after every exact decision: two
// pieces of the exact drawing that are not exactly collinear (so the exact clean-up keeps both)
// may still lie closer than a pen's width, and a pen then draws one line twice. The part of a
// stroke that runs within `tolerance` of a stroke kept before it, nearly parallel (within 3
// degrees) and alongside it (its points' feet fall on the kept segment), is not drawn. Hatching,
// tone hatching and section marks take no part. The exact JSON is not touched.
#pragma once

#include <cstddef>

#include "algorithms/plot/plot.hpp"

namespace hlr {

struct CoincidentStats {
  std::size_t pieces_removed = 0;  // stroke parts left out
  double length_removed = 0;       // their length, drawing units
};

/// Leaves out of `plot`'s strokes what runs within `tolerance` (drawing units) of a stroke of
/// higher or equal priority kept before it; strokes are split where parts go, parts shorter
/// than `tolerance` are dropped.
CoincidentStats merge_coincident_lines(Plot& plot, double tolerance);

}  // namespace hlr
