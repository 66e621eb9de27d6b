// The scan-line z-buffer (course notes section 34), exact: the frame is filled one row of pixel
// centres at a time. Polygons wait in the y-group list under the first row they may cover; a
// row's active polygon list takes them in and drops them after their last row; each active
// polygon covers one span [X_L, X_R] of the row (a convex polygon meets a line in one segment:
// the largest of its left sides' crossings to the smallest of its right sides', exact), and the
// row's own depth buffer keeps the nearest polygon per centre, compared exactly
// (raster_scene.hpp). The same face at every pixel as the full-frame z-buffer.
#pragma once

#include <optional>

#include "algorithms/raster/raster_scene.hpp"

namespace hlr {

struct ScanlineOptions {
  unsigned threads = 0;  // 0: all cores (bands of rows, each with its own active list)
};

/// Counters of the scan-line run.
struct ScanlineStats {
  std::size_t spans = 0;          // (row, polygon) spans found from the sides' crossings
  std::size_t spans_by_test = 0;  // a nearly horizontal side: the span's centres tested one by one
};

/// The exact span of polygon p on the row at picture height y: X_L <= x <= X_R, and the sides
/// that bound it (side k runs from corner k to k + 1; -1: none); on a row through a corner, the
/// side that continues below the row. Empty when the row misses it.
struct ExactSpan {
  Rational xl, xr;
  int left = -1, right = -1;
};
std::optional<ExactSpan> exact_span(const RasterScene& scene, const RasterPolygon& p, const Rational& y);

/// The face seen at every pixel centre of `scene`'s grid.
FaceIdBuffer scanline(const RasterScene& scene, const ScanlineOptions& options = {}, ScanlineStats* stats = nullptr);

}  // namespace hlr
