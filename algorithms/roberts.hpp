// Roberts' hidden-line algorithm for convex polyhedra (course notes, seed 003 sections 26-28),
// exact. Stage 0: sign-corrected body matrices. Stage 1: non-facing faces from the viewpoint
// (E·[V] < 0, zero: edge-on) and self-hidden edges (both faces non-facing). Stage 2: every
// other edge against every other body: the hidden parameter interval from the inequalities
// h_j = p_j + q_j·t + w_j·a > 0, a > 0, solved exactly by eliminating a (Fourier-Motzkin), so
// the interval ends are exact rationals. Stage 3: junction lines where two bodies' surfaces
// cross, tested against all bodies like edges.
//
// Semantics (course notes, "Visibility semantics"): a point is hidden when its open sight ray
// (toward the viewer at infinity along v, or the open segment to the eye) meets the interior of
// a body. The viewpoint g = [v 0] (orthographic) or [E 1] (perspective) makes both views the
// same linear problem: for the eye, Q = P + b·(E - P) with b in (0, 1) and the substitution
// a = b / (1 - b) in (0, inf) gives h_j(Q)·(1 + a) = h_j(P) + a·h_j(E).
#pragma once

#include <optional>
#include <vector>

#include "algorithms/camera.hpp"
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

enum class EdgeSelection { All, Feature };

struct RobertsOptions {
  EdgeSelection edges = EdgeSelection::Feature;  // Feature: skip edges between coplanar faces
  bool prefilter = true;                          // spatial pre-filter of (edge, body) pairs
};

/// A maximal piece [t0, t1] of a segment, t0 < t1.
struct Piece {
  Rational t0, t1;
  bool visible = true;
  bool behind_eye = false;  // perspective: behind the eye, never drawn
  bool clipped = false;     // outside the clipping volume or nearer than the near plane
  bool same_kind(const Piece& o) const {
    return visible == o.visible && behind_eye == o.behind_eye && clipped == o.clipped;
  }
};

struct Segment {
  enum class Kind { Edge, Intersection };
  Kind kind = Kind::Edge;
  int body = -1;                 // Edge: the body; Intersection: the first body
  int body2 = -1;                // Intersection: the second body
  int v0 = -1, v1 = -1;          // Edge: input vertex indices, from v0 toward v1
  int face0 = -1, face1 = -1;    // Edge: its two faces; Intersection: the facets' faces
  Point3 from, to;               // world coordinates
  bool self_hidden = false;      // Stage 1
  std::vector<Piece> pieces;     // in order of t, covering [0, 1]
  Point3 at(const Rational& t) const;
};

struct RobertsStats {
  std::size_t edges = 0, self_hidden = 0, junction_segments = 0;
  std::size_t pairs_tested = 0, pairs_skipped = 0;
  std::size_t pairs_rational = 0;  // tested on the rational path (the 128-bit path did not fit)
};

struct RobertsResult {
  /// Per body: the course notes' E·[V] per face (E = -g): negative = non-facing,
  /// zero = edge-on, positive = facing.
  std::vector<std::vector<Rational>> ev;
  std::vector<BodyMatrix> matrices;
  std::vector<Segment> segments;
  RobertsStats stats;
};

/// Thrown for a body Roberts' algorithm cannot take (not a valid solid, not convex) or a bad
/// view (eye inside a body); `body()` is its index.
class RobertsError : public std::runtime_error {
 public:
  RobertsError(int body, const std::string& what) : std::runtime_error(what), body_(body) {}
  int body() const { return body_; }

 private:
  int body_;
};

/// Runs the algorithm. Bodies must be closed, manifold, oriented, planar, convex solids.
RobertsResult roberts(const std::vector<const Polyhedron*>& bodies, const Camera& camera,
                      const RobertsOptions& options = {});

}  // namespace hlr
