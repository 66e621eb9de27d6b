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

#include <array>
#include <memory>
#include <optional>
#include <string>
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
  EdgeSelection edges = EdgeSelection::Feature;  // Feature: silhouettes and creases only
  Rational crease_degrees = 30;                   // Feature: creases over this angle
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

/// What a drawn line is (issue 4, `--edges feature`): a boundary edge of an open surface, a
/// crease (dihedral angle over the threshold), a silhouette (one face toward the viewer, the
/// other not), an intersection line, or any mesh edge (`--edges all`).
enum class LineKind { Edge, Boundary, Crease, Silhouette, Intersection };
const char* to_string(LineKind k);

struct Segment {
  enum class Kind { Edge, Intersection };
  Kind kind = Kind::Edge;
  LineKind line = LineKind::Edge;
  int body = -1;                 // Edge: the body; Intersection: the first body
  int body2 = -1;                // Intersection: the second body
  int v0 = -1, v1 = -1;          // Edge: input vertex indices, from v0 toward v1
  int face0 = -1, face1 = -1;    // Edge: its two faces; Intersection: the facets' faces
  bool self_hidden = false;      // Stage 1
  std::vector<Piece> pieces;     // in order of t, covering [0, 1]
  Point3 at(const Rational& t) const;

  /// The ends, world coordinates (set before use).
  const Point3& from() const { return *a_; }
  const Point3& to() const { return *b_; }
  /// Ends owned by the segment (shared between copies).
  void set_ends(Point3 a, Point3 b);
  /// Ends borrowed from storage that outlives the segment (a body's vertices): a segment of a
  /// million-edge mesh then costs no exact numbers of its own.
  void borrow_ends(const Point3& a, const Point3& b) {
    own_.reset();
    a_ = &a;
    b_ = &b;
  }

 private:
  std::shared_ptr<const std::array<Point3, 2>> own_;
  const Point3* a_ = nullptr;
  const Point3* b_ = nullptr;
};

struct RobertsStats {
  std::size_t edges = 0, self_hidden = 0, junction_segments = 0;
  std::size_t pairs_tested = 0, pairs_skipped = 0;
  std::size_t pairs_rational = 0;  // tested on the rational path (the 128-bit path did not fit)
  // Per-face occluders (face_occluders.hpp):
  std::string method = "roberts";
  std::size_t occluders = 0;             // triangles used as occluders
  std::size_t comparisons = 0;           // comparisons of split parameters
  std::size_t comparisons_identical = 0; // ... decided as equal by identical fractions
  std::size_t comparisons_exact = 0;     // ... that the double filter could not decide
  bool integer_path = true;              // coordinates fitted the 64/128-bit integer path
  std::size_t intersection_pairs = 0;    // triangle pairs tested exactly for intersection lines
  double setup_seconds = 0, intersections_seconds = 0, visibility_seconds = 0;  // wall clock
};

struct RobertsResult {
  /// Per body: the course notes' E·[V] per face (E = -g): negative = non-facing,
  /// zero = edge-on, positive = facing.
  std::vector<std::vector<Rational>> ev;
  /// Per body and face: sign of facing, 1 facing, 0 edge-on, -1 non-facing (both routes).
  std::vector<std::vector<signed char>> facing;
  std::vector<BodyMatrix> matrices;
  std::vector<Segment> segments;
  RobertsStats stats;
  /// Remarks for the user, each "body N ..." (e.g. a body drawn as an open surface).
  std::vector<std::pair<int, std::string>> notes;
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

/// The pieces of [0, 1] given the hidden open spans (lo < hi, inside [0, 1], any order,
/// overlapping allowed) and, for perspective, the depths (P - E)·(target - E) at t = 0 and 1
/// (the part at depth <= 0 is behind the eye). Touching spans are merged (a single visible
/// point is not a line).
std::vector<Piece> pieces_from_hidden(std::vector<std::pair<Rational, Rational>> hidden,
                                      const std::optional<std::pair<Rational, Rational>>& depth);

/// The edges of a closed body to draw, in order of their vertex pairs, classified (Feature:
/// silhouettes by `facing` (1 facing, 0 edge-on, -1 non-facing per face), creases over the
/// threshold; edges between coplanar faces left out) and marked self-hidden when both faces are
/// non-facing (Stage 1). Pieces are left to the caller. Counts go to `stats`.
std::vector<Segment> body_edge_segments(const Polyhedron& p, int body, const std::vector<signed char>& facing,
                                        const RobertsOptions& options, RobertsStats& stats);

/// Runs the algorithm. Bodies must be closed, manifold, oriented, planar, convex solids.
RobertsResult roberts(const std::vector<const Polyhedron*>& bodies, const Camera& camera,
                      const RobertsOptions& options = {});

}  // namespace hlr
