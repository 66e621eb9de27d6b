// Roberts' hidden-line algorithm for convex polyhedra (course notes, sections 26-28),
// exact. Stage 0: sign-corrected body matrices. Stage 1: non-facing faces from the viewpoint
// (E·[V] < 0, zero: edge-on) and self-hidden edges (both faces non-facing). Stage 2: every
// other edge against every other body: the hidden parameter interval from the inequalities
// h_j = p_j + q_j·t + w_j·a > 0, a > 0, solved exactly by eliminating a (Fourier-Motzkin), so
// the interval ends are exact rationals. Stage 3: intersection lines where two bodies' surfaces
// cross, tested against all bodies like edges.
//
// Semantics (course notes, "Visibility semantics"): a point is hidden when its open sight ray
// (toward the viewer at infinity along v, or the open segment to the eye) meets the interior of
// a body. The viewpoint g = [v 0] (orthographic) or [E 1] (perspective) makes both views the
// same linear problem: for the eye, Q = P + b·(E - P) with b in (0, 1) and the substitution
// a = b / (1 - b) in (0, inf) gives h_j(Q)·(1 + a) = h_j(P) + a·h_j(E).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/model/camera.hpp"
#include "algorithms/model/line_drawing.hpp"
#include "kernel/body_matrix.hpp"

namespace hlr {

/// The open set of t hidden by one body: (lo, hi), each end possibly unbounded.
struct OpenInterval {
  bool empty = true;
  std::optional<Rational> lo, hi;  // nullopt: unbounded
};

/// The t (on the whole line P1 + t·(P2 - P1)) whose sight rays meet the interior of the
/// convex body with inward body matrix V, from viewpoint g. Exact.
OpenInterval hidden_interval(const Point3& p1, const Point3& p2, const BodyMatrixData& V, const RowVector4& g);

/// Roberts' own values beside the drawing.
struct RobertsResult : LineDrawing {
  /// Per body: the course notes' E·[V] per face (E = -g): negative = non-facing,
  /// zero = edge-on, positive = facing.
  std::vector<std::vector<Rational>> ev;
  std::vector<BodyMatrix> matrices;
};

/// The edges of a closed body to draw, in order of their vertex pairs, classified (Feature:
/// silhouettes by `facing` (1 facing, 0 edge-on, -1 non-facing per face), creases over the
/// threshold; edges between coplanar faces left out) and marked self-hidden when both faces are
/// non-facing (Stage 1). Pieces are left to the caller. Counts go to `stats`.
std::vector<Segment> body_edge_segments(const Polyhedron& p, int body, const std::vector<signed char>& facing,
                                        const LineOptions& options, DrawingStats& stats);

/// Runs the algorithm. Bodies must be closed, manifold, oriented, planar, convex solids;
/// throws BodyError naming the first that is not (or holds the eye).
RobertsResult roberts(const std::vector<const Polyhedron*>& bodies, const Camera& camera,
                      const LineOptions& options = {});

}  // namespace hlr
