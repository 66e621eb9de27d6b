// Which surface of the user's model each face of a mesh is part of (a B-rep face of a STEP or
// IGES model, a polygon split into triangles), and how two surfaces meet: the edges a drawing
// takes from the model's own topology instead of the crease angle (docs/design.md, "Faces'
// identity").
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "kernel/face.hpp"

namespace hlr {

/// Per face, the surface it belongs to; between surfaces, whether an edge is sharp or tangent.
struct FaceSurfaces {
  /// Per face (empty: none, every edge goes by the crease angle).
  std::vector<int> surface;
  /// Pairs of surfaces (a < b, sorted) that meet tangentially (G1 or smoother, from the B-rep).
  std::vector<std::pair<int, int>> tangent;
  /// True (CAD models): two surfaces meet at a sharp edge unless they are tangent, whatever the
  /// angle. False (a polygon split into triangles): an edge between two surfaces goes by the
  /// crease angle as any mesh edge.
  bool sharp_between = true;

  bool empty() const { return surface.empty(); }
};

/// How the edge between faces f0 and f1 is drawn, by their surfaces: Inside one surface (never
/// a crease; still a silhouette where it is one), Sharp (always a crease), Tangent (a tangent
/// edge, its own line class), or ByAngle (the crease angle decides).
enum class SurfaceEdge { Inside, Sharp, Tangent, ByAngle };
SurfaceEdge surface_edge(const FaceSurfaces& s, int f0, int f1);

/// The smooth surfaces a file marks (its normals, OBJ's smoothing groups): per face and corner
/// a key (a normal's number, a smoothing group); two faces that share an edge are one surface
/// when each end of the edge has the same key in both. Edges between surfaces go by the crease
/// angle (`sharp_between` false): the keys say what is smooth, not what must be drawn.
FaceSurfaces surfaces_from_corner_keys(const std::vector<Face>& faces, const std::vector<std::vector<std::int64_t>>& keys);

/// The surfaces after faces were split or renumbered: new face k is part of old face
/// `part[k]`; a part >= the old face count (a section's cap) gets a surface of its own, one per
/// distinct part number.
FaceSurfaces renumbered_surfaces(const FaceSurfaces& s, const std::vector<int>& part);

}  // namespace hlr
