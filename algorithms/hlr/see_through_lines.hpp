// Lines seen through transparent faces (course notes section 41, what lies behind a
// transparent face stays in the picture). A piece of a line hidden in the full drawing but not
// hidden once the see-through bodies hide nothing is seen only through transparent faces: it
// becomes its own class (Piece::through), drawn thin and grey by the writers, apart from the
// visible and the hidden lines. Both drawings are the per-face route's exact pieces, so every
// piece end is an exact split parameter and the marking is exact.
#pragma once

#include <vector>

#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/model/camera.hpp"
#include "algorithms/model/line_drawing.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr {

/// Marks in `drawing` (a face_occluders() drawing of `bodies` under `options`) the hidden
/// parts that are seen through the bodies with see_through[b] != 0: runs the per-face route
/// once more with those bodies hiding nothing and refines every segment's pieces. Returns the
/// number of pieces marked. Does nothing when no body is see-through.
std::size_t mark_see_through(LineDrawing& drawing, const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineOptions& options,
                             const std::vector<char>& see_through, const FaceRouteHooks& hooks = {});

/// The pieces of `full` refined by `opaque` (the same segment's pieces when only opaque bodies
/// hide): where `full` is hidden and `opaque` visible, the piece is through. Exposed for tests.
std::vector<Piece> refine_through(const PieceList& full, const PieceList& opaque);

}  // namespace hlr
