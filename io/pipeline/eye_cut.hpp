// Filled products with the eye among the bodies (docs/design.md, "Filled products with the eye
// among the bodies"): the visible surfaces, shadows, Weiler-Atherton, the priority list and the
// rasters project polygons, which needs every corner in front of the eye; so every body is cut
// exactly by a near plane first.
#pragma once

#include <string>
#include <vector>

#include "io/pipeline/render.hpp"

namespace hlr {

/// When some vertex of `polys` lies on the eye's plane or behind it (a perspective view from
/// among the bodies): cuts every body of `editable` (and r.names) by the near plane at `near` of
/// the eye-target distance, or with a frame (r.pyramid) as far out as changes nothing in it;
/// sets r.eye_cut, and with `shadows` r.whole (the lights see the bodies whole); rebuilds
/// `polys`; says so in `notes`. Nothing when every body is in front of the eye.
void cut_at_eye(RenderResult& r, const Rational& near, bool shadows, std::vector<SceneBody*>& editable, std::vector<const Polyhedron*>& polys,
                std::vector<std::string>& notes);

}  // namespace hlr
