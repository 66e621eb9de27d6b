// Sections in the render pipeline (docs/design.md, "Sections"): the scene's bodies cut by the
// section's half-spaces before any hidden-line or surface route runs (algorithms/sections/
// section_cut.hpp), so that what is removed hides nothing; the cut lines named; the caps
// hatched on the page once the page's scale is known (algorithms/hatching/hatch.hpp), with the
// hatch lines' visibility decided exactly by the per-face route.
#pragma once

#include <string>
#include <vector>

#include "algorithms/hlr/face_occluders.hpp"
#include "io/pipeline/render.hpp"

namespace hlr {

/// Cuts every body that takes cuts (SceneBody::cut) by `planes`: a body wholly removed leaves
/// `bodies` and `names`; a cut one gets its caps and SceneBody::section_part/section_cap; an
/// open one a note (into `notes`, "SOURCE: body 'NAME' is open: ...").
/// With `away` (a cut-away, section_cut.hpp's cut_away), after the cut by `planes`: the region
/// where every plane of `away` is <= 0 is removed too.
void cut_bodies(const std::vector<Plane>& planes, const std::vector<Plane>& away, std::vector<SceneBody*>& bodies, std::vector<DrawingBody>& names,
                std::vector<std::string>& notes);

/// SceneBody::section_cap of a face on the near plane (cut_near's caps).
constexpr int kEyeCap = -2;

/// Filled products of a perspective view with the eye among the bodies: every body (also one
/// that takes no section) cut by `keep` (the near plane, its kept side keep.value <= 0) after any
/// section. A body wholly behind it leaves `bodies` and `names`; the cut ones keep their input
/// face numbers (the cap on the near plane numbered after the input's faces and the section's
/// caps), their section parts and caps, and get caps marked kEyeCap: faces that hide and are
/// filled but are not hatched and draw no line. An open body is cut without a cap.
/// With `parent`: per body kept, per face, the face before the cut it is part of (-1: a cap).
void cut_near(const Plane& keep, std::vector<SceneBody*>& bodies, std::vector<DrawingBody>& names, std::vector<std::vector<int>>* parent = nullptr);

/// The per-face route's hooks that name the cut lines and keep the faces' inner seams undrawn.
void section_hooks(const std::vector<const SceneBody*>& bodies, FaceRouteHooks& hooks);

/// Names the cut lines of a drawing (an edge between a cap face and a face of another part)
/// and drops the edges inside one face of the model (between two pieces of a cut face).
void mark_cut_lines(LineDrawing& drawing, const std::vector<const SceneBody*>& bodies);

/// True when some body of the render has a cap to hatch.
bool has_caps(const RenderResult& r);

/// The visible hatch lines of every cap, for a page at `mm_per_unit` (mm per drawing unit):
/// spacing and angle on the page, `pen_mm` the hatch pen (a solid fill's spacing).
LineDrawing cap_hatching(const RenderResult& r, double mm_per_unit, double pen_mm, unsigned threads);

/// The JSON's "section" member (docs/output-format.md): the planes, each cap's exact border
/// loops per body and plane, and the visible pieces of `hatch` (cap_hatching's, made at
/// `mm_per_unit`). "" when the render has no section.
std::string section_json(const RenderResult& r, const LineDrawing& hatch, double mm_per_unit);

}  // namespace hlr
