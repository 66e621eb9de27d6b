// The Weiler–Atherton hidden-surface algorithm (course notes section 31), exact: (1) a
// preliminary sort by the nearest depth of each polygon; (2) every polygon clipped by the front
// polygon into an inside list and an outside list; (3) inside polygons that the clipper hides
// everywhere are removed; (4) when an inside polygon is in front of the clipper somewhere, the
// plane is subdivided again with that polygon (its copy before clipping) as the clipper, a list
// of the clippers used so far catching cyclic overlaps; polygons that pierce each other are
// split along the line where their planes meet (the notes: "one of them must be cut in two by
// their intersection line"). The picture's polygons are convex pieces (faces are triangulated
// when not convex, clipping is Sutherland–Hodgman by each side of the convex clipper, the part
// outside is cut into convex pieces), so every polygon and every cut point is exact. Meant for
// exam-sized scenes: the work grows with the square of the polygons; visible_surfaces.hpp is the
// fast route, and the tests check the two give the same visible part of every face.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "algorithms/model/line_drawing.hpp"
#include "algorithms/picture/picture_plane.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr {

/// A convex polygon of the picture (counter-clockwise, exact) lying on a face of the scene.
struct WaPolygon {
  int body = -1, face = -1;
  int piece = 0;  // which convex piece of the face (faces that are not convex are triangulated)
  std::vector<Exact2> pts;
  /// The preliminary sort's key once computed (a polygon that no clip changed keeps it).
  std::optional<Rational> nearest;
};

/// One step of the algorithm, for the exam page (trace on).
struct WaStep {
  enum class Kind { Sort, Clip, Hidden, Violation, Cycle, Split, Display };
  Kind kind = Kind::Sort;
  int level = 0;                        // recursion depth
  std::vector<WaPolygon> polygons;      // Sort: the list in order; Clip: the clipper; Split: the two parts
  std::vector<WaPolygon> inside, outside;  // Clip: the two lists
  std::vector<Rational> depths;         // Sort: each polygon's nearest depth; Hidden/Violation: the clipper's and the polygon's depth at each corner
  WaPolygon subject;                    // Hidden, Violation, Split, Display: the polygon concerned
};

struct WeilerAthertonOptions {
  bool trace = false;
  std::size_t max_polygons = 20000;  // refuse scenes whose lists would grow past this (not exam-sized)
};

struct WeilerAthertonResult {
  std::vector<WaPolygon> visible;  // convex visible pieces, in the order displayed
  std::vector<WaStep> steps;       // trace on
  std::size_t clips = 0, splits = 0, recursions = 0, cycles = 0;
};

/// The visible pieces of every face. `lines` gives the faces' facing (a closed solid's faces
/// turned away are dropped first, as in the notes' first step of Roberts' algorithm); perspective
/// needs every body in front of the eye. Throws std::invalid_argument for a scene over
/// `max_polygons`.
WeilerAthertonResult weiler_atherton(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineDrawing& lines,
                                     const WeilerAthertonOptions& options = {});

/// The nearest depth of a polygon's corners on its face, as the preliminary sort uses it: the
/// largest P·v (orthographic) or the smallest (P - E)·(target - E) (perspective) over its
/// corners lifted into the face's plane, returned so that larger is nearer.
Rational wa_nearest_depth(const WaPolygon& p, const std::vector<const Polyhedron*>& bodies, const Camera& camera);

}  // namespace hlr
