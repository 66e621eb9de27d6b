// The priority-list (painter's) algorithm of Newell, Newell and Sancha, exact (course notes
// sections 32-34, part 3.3, "the algorithm using a priority list"): the polygons sorted by their farthest
// depth; the farthest polygon A is painted when no polygon B whose depth range overlaps A's can
// be hidden by it, which the notes decide by five tests in order of cost: (1) the picture boxes
// of A and B are apart in x, (2) in y, (3) A lies wholly on the far side of B's plane (the test
// function f = ax + by + cz + d of B's plane at A's corners has the sign of the side away from
// the eye), (4) B lies wholly on the near side of A's plane, (5) the projections do not
// overlap. When all fail, B goes to the head of the list if the tests with the roles swapped
// allow it, and is marked; a marked polygon that has to move again means a cyclic overlap, and
// A is cut by B's plane (Sutherland–Hodgman, each side cut exactly where the test function
// changes sign), the parts going back into the list. Polygons that pierce each other are cut
// the same way. Every test is exact (rational test functions, exact orientation in the
// picture), so the order painted is never wrong. Faces are the convex polygons of
// scene_polygons.hpp; orthographic and perspective (every body in front of the eye).
#pragma once

#include <cstddef>
#include <vector>

#include "algorithms/model/line_drawing.hpp"
#include "algorithms/picture/scene_polygons.hpp"

namespace hlr {

/// A polygon of the list: a face's convex piece or a part cut from one.
struct PriorityPolygon {
  int body = -1, face = -1, piece = 0;
  int source = -1;               // the polygon of the first list it was cut from (itself if whole)
  std::vector<Point3> corners;   // exact, on the face
  std::vector<Exact2> pts;       // picture, counter-clockwise
  Rational zmin, zmax;           // depth of its farthest and nearest corner (larger is nearer)
};

/// One step, for the exam page (trace on). Polygons are indices into PriorityResult::polygons.
struct PriorityStep {
  enum class Kind { Sort, Tests, Swap, Cycle, Split, Paint };
  Kind kind = Kind::Sort;
  std::vector<int> list;          // Sort: the list, farthest first
  int a = -1, b = -1;             // Tests, Swap, Cycle: the head A and the polygon B; Split: cut, cutter; Paint: a
  /// Tests: the first of the notes' tests 1-5 that answered yes (0: none); with the roles
  /// swapped (B before A) the test 3 or 4 that answered yes, or 0.
  int passed = 0, swapped = 0;
  /// Tests: B's test function at A's corners and A's at B's corners; the sign each takes on the
  /// eye's side (+1 or -1).
  std::vector<Rational> f_b_at_a, f_a_at_b;
  int eye_b = 0, eye_a = 0;
  /// Split: the parts (indices), the cutting plane's function at the cut polygon's corners,
  /// and whether the cut is along the picture outline of the cutter (no plane of the two cuts).
  std::vector<int> parts;
  std::vector<Rational> values;
  bool along_outline = false;
};

struct PriorityOptions {
  bool trace = false;
  /// Refuse to go on once the list has made this many polygons (cuts included).
  std::size_t max_polygons = 4'000'000;
};

struct PriorityResult {
  std::vector<PriorityPolygon> polygons;  // every polygon made: the first list, then the parts
  std::vector<int> order;                 // painted, back to front
  std::vector<PriorityStep> steps;        // trace on
  std::size_t initial = 0;                // polygons in the first list
  std::size_t pairs = 0;                  // pairs put to the tests
  std::size_t passed[6] = {};             // [k]: pairs whose first yes was test k (k = 1..5)
  std::size_t swaps = 0, cycles = 0, splits = 0, outline_splits = 0;
};

/// The painter's list of the scene's faces. `lines` gives the faces' facing (a closed solid's
/// faces turned away are dropped first). Coplanar overlapping faces are painted so that the
/// face toward the viewer, then the lower face number (counting through the bodies), is on
/// top, as visible_surfaces.hpp decides them. Throws std::invalid_argument when a body reaches
/// the eye's plane (perspective) or the polygons grow past max_polygons.
PriorityResult priority_list(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineDrawing& lines,
                             const PriorityOptions& options = {});

}  // namespace hlr
