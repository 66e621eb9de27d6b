// Cutting planes that remove material (docs/design.md, "Sections"; course notes sections 21-22:
// the plane's test function at each vertex decides its side, as in clipping, here applied to a
// solid). A body is cut by half-spaces exactly: each face keeps its part where every plane's
// test function is negative (closed: the points on the plane that bound it), split points are
// exact rationals on the edges, and each plane closes the cut solid with its cap, the exact
// region where the plane meets the body's interior, triangulated without new points.
#pragma once

#include <vector>

#include "kernel/polyhedron.hpp"

namespace hlr {

/// A body after the cut: what is left where every plane's test function is <= 0.
struct CutSolid {
  enum class State { Whole, Cut, Removed };
  /// Whole: no plane reaches into the body (the input is unchanged and not copied here);
  /// Removed: nothing of it is kept.
  State state = State::Whole;
  std::vector<Point3> vertices;
  std::vector<Face> faces;
  /// Per face: the input face it is part of, or the number of input faces + k for the cap on
  /// plane k. An edge between two faces of one part lies inside that face.
  std::vector<int> part;
  /// Per face: the plane whose cap it is part of, or -1.
  std::vector<int> cap;
  /// The input is not a closed, oriented solid: its faces are cut, it gets no cap (its inside
  /// is not known).
  bool open = false;
};

/// Cuts `body` by the half-spaces plane.value(p) <= 0 of `planes` (their intersection is
/// kept; a plane's normal points toward the material it removes, which is the side its cap
/// faces). A face lying in a plane stays when its outward normal points the plane's way (it
/// bounds what is kept) and goes otherwise. Exact.
CutSolid cut_solid(const Polyhedron& body, const std::vector<Plane>& planes);

/// The opposite: removes the convex region where every plane's test function is <= 0 (a
/// cut-away; two planes make the half section of a part) and keeps the rest, closed by caps
/// that face into the removed region (cap k on plane k, part number of input faces + k). Built
/// from the pieces {h_0 <= 0 .. h_{i-1} <= 0, h_i >= 0} of cut_solid, whose shared faces are
/// left out and whose seams are joined exactly. Exact.
CutSolid cut_away(const Polyhedron& body, const std::vector<Plane>& planes);

}  // namespace hlr
