// The user's own 3D lines hidden by the bodies (docs/design.md, "Your own lines"): every
// segment of every polyline is an extra line of the per-face route (face_occluders.hpp, lines
// that lie on no face), so its hidden parts are decided exactly as the bodies' edges are, by
// whatever route drew the bodies. Lines behind glass are seen through (their own class).
#pragma once

#include <vector>

#include "io/pipeline/render.hpp"
#include "io/readers/polyline_file.hpp"

namespace hlr {

/// The polylines' segments with their visibility among `r`'s bodies, as LineKind::Polyline
/// segments of no body (-1), appended to r.drawing (before the drawing's clipping).
void add_polylines(RenderResult& r, const std::vector<Polyline3>& lines, const RenderOptions& o);

}  // namespace hlr
