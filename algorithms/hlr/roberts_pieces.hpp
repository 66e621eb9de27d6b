// Roberts' algorithm for non-convex solids through their convex pieces (course notes
// sections 23 and 26-28): each non-convex body is split into convex pieces
// (convex_decomposition.hpp) and every original edge is tested against every piece with the
// notes' inequalities (hidden_interval). Only the original edges are drawn, never cut edges.
//
// The trap: points on a cut face lie inside the union, yet on the boundary of both
// pieces, so a sight ray running exactly along a cut plane meets no piece's interior and the
// strict inequalities would call it visible. Such rays are inside the solid. So for every pair
// of pieces with opposite faces in one cut plane seen edge-on, the common part of the two faces
// is added as a "glue" occluder: the same hidden-interval problem on the side planes of both
// faces, for the edges that lie in that plane.
#pragma once

#include "algorithms/hlr/roberts.hpp"

namespace hlr {

/// Like roberts(), for closed solids that need not be convex. Segments: the bodies' edges in
/// order of their vertex pairs, then intersection lines of different bodies; `facing` filled.
LineDrawing roberts_pieces(const std::vector<const Polyhedron*>& bodies, const Camera& camera,
                           const LineOptions& options = {});

}  // namespace hlr
