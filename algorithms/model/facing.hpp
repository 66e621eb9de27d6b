// Facing and non-facing faces (course notes, section 27, Stage 1: a face is
// non-facing, "нелицевая", when the viewer is on the inner side of its plane). The one
// definition used by every route: the sign of the face's outward plane at the homogeneous
// viewpoint g = [v 0] (orthographic, v toward the viewer) or [E 1] (perspective), i.e. of
// n·v or n·(E - a) for a point a of the face. 1: facing, 0: edge-on (the viewer in the
// plane), -1: non-facing. Roberts' E·[V] (inward columns, E = -g) has the same sign. Lighting
// uses it with the light's position or direction in place of the viewpoint.
#pragma once

#include "algorithms/model/camera.hpp"
#include "kernel/exact_int.hpp"

namespace hlr {

/// Facing of the plane with normal n through point a, under number policy P (exact_int.hpp),
/// from `view`: the eye (perspective) or the direction toward the viewer (orthographic).
template <class P>
int facing_sign(const Vec<P>& n, const Vec<P>& a, const Vec<P>& view, bool perspective) {
  return perspective ? P::sign(dot<P>(n, sub<P>(view, a))) : P::sign(dot<P>(n, view));
}

/// Facing of an outward plane from a camera (exact rationals).
int facing_sign(const Plane& outward, const Camera& camera);

/// Facing of an outward plane from a light: a point light at `position` (w = 1) or a
/// direction toward the light (w = 0), as the homogeneous [x y z w].
int facing_sign(const Plane& outward, const RowVector4& viewpoint);

}  // namespace hlr
