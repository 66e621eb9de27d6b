// Convex decomposition of a closed polyhedron (course notes, section 23): split the
// body by the plane of a face at which it is not convex (a face whose plane has vertices on
// both sides, found by the exact convexity test), recursively, until every piece is convex.
// The splits are exact boolean operations (CGAL Nef polyhedra on an exact kernel), so pieces
// are closed convex polyhedra with exact rational coordinates whose volumes add up exactly to
// the body's. Each piece face says whether it lies on the original surface, on a cut, or both
// (an exact boolean merges a cut with an original face in the same plane into one face).
// A second method runs CGAL's own convex_decomposition_3 on the Nef polyhedron.
#pragma once

#include <string>
#include <vector>

#include "kernel/polyhedron.hpp"

namespace hlr {

enum class FaceOrigin { Surface, Cut, Mixed };
const char* to_string(FaceOrigin o);

struct ConvexPiece {
  Polyhedron body;                // closed, convex, outward faces
  std::vector<FaceOrigin> faces;  // per face of `body`
};

enum class DecompositionMethod { FacePlanes, Nef };

struct Decomposition {
  std::vector<ConvexPiece> pieces;
  std::vector<Plane> cuts;  // FacePlanes: the planes split by, in order
};

/// Decomposes a closed, manifold, consistently oriented polyhedron into convex pieces.
/// Throws std::invalid_argument for a body that is not a valid solid. A convex body comes back
/// as one piece.
Decomposition convex_decomposition(const Polyhedron& body, DecompositionMethod method = DecompositionMethod::FacePlanes);

/// Six times the volume of a closed oriented polyhedron, exactly.
Rational six_volume(const Polyhedron& body);

}  // namespace hlr
