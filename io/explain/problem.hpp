// Problem files for `hlr explain`: a scene file (docs/scene-format.md) with a
// `problem` type and the data of that type. Types: roberts (bodies, view, optional light and
// edges to analyse), cyrus-beck (a convex clipper and segments), midpoint (a box or frustum,
// segments, eps), convexity, decompose, transform (one body), horizon (heights on a grid),
// weiler-atherton (polygons or bodies and a view), section (one body and one plane in
// `section:`). Every number is exact; unknown
// keys and wrong types are errors with file and line. Format: docs/problem-format.md.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/clip/cyrus_beck.hpp"
#include "algorithms/horizon/floating_horizon.hpp"
#include "algorithms/clip/midpoint_clip.hpp"
#include "io/readers/scene.hpp"

namespace hlr {

struct Problem {
  enum class Type { Roberts, CyrusBeck, Midpoint, Convexity, Decompose, Transform, Horizon, WeilerAtherton, Priority, Raster, RayTree, Section };
  Type type = Type::Roberts;
  std::string file;
  std::string title;  // optional `title`
  Scene scene;
  // roberts: the edges to analyse, as (body, vertex, vertex); empty: every edge.
  std::vector<std::array<int, 3>> edges;
  // cyrus-beck, midpoint
  std::optional<ConvexClipper> clipper;
  std::optional<Window> window;  // box or frustum (midpoint needs one)
  std::string clipper_text;      // e.g. "box [0, 2, 0, 2, 0, 2]"
  std::vector<std::pair<Point3, Point3>> segments;
  Rational eps = rational(1, 100);
  // horizon: the heights (row j: the cut z = zs[j]) on x from..to and z from..to
  HeightGrid grid;
  // raster: the pixel grid (size, and the picture window it covers) and the z-buffer's traced pixels
  int raster_width = 8, raster_height = 6;
  std::array<Rational, 4> raster_window{Rational(0), Rational(8), Rational(0), Rational(6)};  // x0, x1, y0, y1
  std::vector<std::array<int, 2>> raster_trace;
  // ray-tree: the primary ray (exact) and the levels of reflected and refracted rays
  Point3 ray_from;
  Vector3 ray_direction{Rational(0), Rational(0), Rational(-1)};
  int ray_depth = 3;
  /// The page numbers faces, vertices and columns from this (0, or 1 as the notes do); the
  /// problem file's own indices and the JSON `result` stay 0-based.
  int index_base = 0;
};

const char* to_string(Problem::Type t);

/// Loads a problem file (YAML or JSON). Throws InputError with file and line.
Problem load_problem(const std::string& path);
Problem load_problem_text(const std::string& text, const std::string& path);

}  // namespace hlr
