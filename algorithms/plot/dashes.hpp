// Dashed lines as geometry: a plotter draws what is in the file, not
// `stroke-dasharray`, so hidden lines can be cut into real dash strokes. The pattern runs on
// along the whole stroke, across its corners (it does not restart at every piece).
#pragma once

#include <vector>

#include "algorithms/plot/pen_order.hpp"

namespace hlr {

/// Cuts a polyline (closed: back to its first point) into dashes `dash` long with `gap`
/// between them, the pattern continuous along the polyline, starting with a dash.
std::vector<std::vector<Point2>> cut_dashes(const std::vector<Point2>& points, bool closed, double dash, double gap);

}  // namespace hlr
