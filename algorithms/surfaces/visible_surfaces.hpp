// Visible surfaces as exact polygons (course notes section 31, after Weiler–Atherton; section 25:
// an object-space method whose result is exact). The visible lines of the exact line drawing
// (every edge and every intersection line) cut the picture into cells; inside a cell the face
// seen does not change, since it can only change across a visible edge or intersection line.
// The cells are an exact planar arrangement (planar_arrangement.hpp); the face seen in each is
// decided by exact ray casting at a point just beside one of its edges (a symbolic offset: no
// epsilon); cells of the same face are merged and lifted into the face's plane. The result is,
// for every face, the part of it that is seen, as polygons with holes with exact rational
// vertices; pieces of different faces do not overlap and together cover the projection.
#pragma once

#include <vector>

#include "algorithms/model/line_drawing.hpp"
#include "algorithms/picture/planar_arrangement.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr {

struct SurfaceOptions {
  unsigned threads = 0;  // 0: all cores
  /// Label every half-edge, not only one per cycle, and count disagreements (tests).
  bool check_cycles = false;
  /// The regions per face (VisibleSurfaces::faces). Off: only the groups' (a drawing that
  /// fills by group needs no more), and stats.polygons stays 0.
  bool faces = true;
  /// Exact picture corners for the groups' polygons; off: their doubles only
  /// (VisiblePolygon::outer_approx), when the arrangement's doubles are in range (a drawing
  /// that fills by group needs no more; the per-face polygons stay exact).
  bool exact_groups = true;
  /// Optional: a group per face (indexed by body, then face), e.g. faces of one colour; the
  /// regions of equal group are merged too (VisibleSurfaces::groups): no seam between faces
  /// that are filled alike.
  std::vector<std::vector<int>> face_group;
  /// Lift the faces' polygons to exact 3D corners (VisiblePolygon::outer, holes); off: the
  /// exact picture corners only. Group polygons are never lifted.
  bool lift = true;
};

/// One visible piece of a face: exact 3D vertices in the face's plane and the same points in
/// the picture (picture_plane.hpp), outer boundary counter-clockwise in the picture, holes
/// clockwise; `area2` is twice its exact area in picture units.
struct VisiblePolygon {
  std::vector<Point3> outer;
  std::vector<std::vector<Point3>> holes;
  std::vector<Exact2> outer_2d;
  std::vector<std::vector<Exact2>> holes_2d;
  /// Groups with SurfaceOptions::exact_groups off: the picture corners as doubles (mpq_get_d
  /// of the exact ones) instead of outer_2d and holes_2d, for drawing only.
  std::vector<std::array<double, 2>> outer_approx;
  std::vector<std::vector<std::array<double, 2>>> holes_approx;
  Rational area2;

  // Moves declared noexcept so that vectors of polygons move them when they grow (mpq_class's
  // move is not noexcept, so the defaulted one would copy every point). It cannot throw: it
  // allocates only in mpq_init, and GMP aborts rather than throw when memory runs out.
  VisiblePolygon() = default;
  VisiblePolygon(const VisiblePolygon&) = default;
  VisiblePolygon& operator=(const VisiblePolygon&) = default;
  VisiblePolygon(VisiblePolygon&&) noexcept = default;
  VisiblePolygon& operator=(VisiblePolygon&&) noexcept = default;
};

struct VisibleFace {
  int body = -1, face = -1;
  bool front = true;  // the side the face's normal points to is toward the viewer
  std::vector<VisiblePolygon> polygons;
};

struct SurfaceStats {
  std::size_t segments = 0;     // visible pieces after the 2D clean-up
  std::size_t edges = 0;        // arrangement edges
  std::size_t cycles = 0;       // arrangement cycles (each labelled once)
  std::size_t crossings = 0, splits = 0, exact_tests = 0;
  std::size_t triangles = 0;    // scene triangles that can be seen (not edge-on)
  std::size_t polygons = 0;     // visible polygons out (per face)
  std::size_t fills = 0;        // polygons per group (VisibleSurfaces::groups)
  std::size_t label_mismatches = 0;  // check_cycles: half-edges whose label differs from their cycle's
  bool weiler_atherton = false;      // made by the Weiler–Atherton route (surfaces_from_pieces)
  std::size_t wa_clips = 0, wa_splits = 0, wa_recursions = 0, wa_cycles = 0;
  double seconds = 0;
  // Stages (wall clock): 2D clean-up, exact picture points, arrangement, the scene's triangles
  // in the picture, probes, merge and lift.
  double seconds_clean = 0, seconds_points = 0, seconds_arrangement = 0, seconds_triangles = 0, seconds_probe = 0,
         seconds_regions = 0;
};

/// A region of faces of one group (SurfaceOptions::face_group), exact picture corners only.
struct VisibleGroup {
  int group = -1;
  std::vector<VisiblePolygon> polygons;
};

struct VisibleSurfaces {
  std::vector<VisibleFace> faces;  // faces with a visible part, in order of body and face
  std::vector<VisibleGroup> groups;  // with SurfaceOptions::face_group, in order of group
  SurfaceStats stats;
};

/// The visible part of every face. `lines` must be the drawing of `bodies` from `camera` with
/// every edge (EdgeSelection::All) and intersection lines. Perspective: every vertex must lie in
/// front of the eye and no drawn piece may be clipped by the near plane (std::invalid_argument).
VisibleSurfaces visible_surfaces(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineDrawing& lines,
                                 const SurfaceOptions& options = {});

/// A convex piece of the picture (counter-clockwise, exact) seen on a face.
struct SurfacePiece {
  int body = -1, face = -1;
  std::vector<Exact2> pts;
};

/// The same result from pieces that do not overlap and cover the visible part of each face (the
/// Weiler–Atherton route, weiler_atherton.hpp): merged per face, and per group when asked,
/// through the same exact arrangement.
VisibleSurfaces surfaces_from_pieces(const std::vector<SurfacePiece>& pieces, const std::vector<const Polyhedron*>& bodies,
                                     const Camera& camera, const SurfaceOptions& options = {});

}  // namespace hlr
