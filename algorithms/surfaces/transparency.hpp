// Transparency, exactly per region (course notes section 41): the picture is
// cut into regions where the ordered list of faces seen one behind the other is the same, and
// each region gets one final colour, I = (1 − τ)·I1 + τ·I2 applied from the back to the front
// (notes: "if the polygons are written to the frame buffer in priority order (Newell–Sancha),
// I2 is the value in the buffer and I1 the current surface"). The order is the exact priority
// list (priority_list.hpp) with the faces turned away kept for see-through bodies; the regions
// are the cells of the exact arrangement of its polygons, each labelled by the polygons over a
// point beside one of its edges (a symbolic offset: no epsilon), trimmed to what lies in front
// of the nearest opaque face, and merged per list. Colours are the caller's (doubles, after
// every decision).
#pragma once

#include <vector>

#include "algorithms/surfaces/priority_list.hpp"
#include "algorithms/surfaces/visible_surfaces.hpp"

namespace hlr {

struct TransparentRegion {
  /// The faces seen here, back to front, from the nearest opaque one (or the farthest face when
  /// none is opaque): (body, face).
  std::vector<std::pair<int, int>> faces;
  VisiblePolygon polygon;  // exact picture corners (no 3D corners: a region spans faces)
};

struct TransparentPicture {
  std::vector<TransparentRegion> regions;
  std::size_t painted = 0, cuts = 0;
};

/// `see_through[b]`: body b lets light through (its faces turned away are kept); `lines` gives
/// the facing (as for priority_list). Orthographic and perspective (every body in front of the eye).
TransparentPicture transparent_regions(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineDrawing& lines,
                                       const std::vector<char>& see_through);

}  // namespace hlr
