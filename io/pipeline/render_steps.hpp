// Steps of the render pipeline that the methods share (io/pipeline/methods/): which bodies
// are see-through, the transparency regions and their colours, the shadows and theirs. Made in
// render.cpp; used by the methods' polygon steps.
#pragma once

#include <vector>

#include "io/pipeline/render.hpp"

namespace hlr {

/// Per body: its material lets light through (transparency > 0).
std::vector<char> see_through_bodies(const RenderResult& r);
/// The regions of equal face lists behind see-through bodies, each composited back to front
/// (nothing when no body is see-through).
void solve_transparency(RenderResult& r, const std::vector<const Polyhedron*>& polys, const LineDrawing& all);
/// Each light's lit parts laid over the visible surfaces, every region shaded by its lights.
void solve_shadows(RenderResult& r, const std::vector<const Polyhedron*>& polys, const std::vector<Scene>& scenes, const RenderOptions& o,
                   const LineDrawing& all);

}  // namespace hlr
