// Tiles of the picture (one drawing on many machines; course notes section 20 for the
// projection, 21-22 for clipping by half-planes): the picture is split into a grid of tiles by
// exact vertical and horizontal lines; each point of a segment belongs to exactly one tile, so
// a segment's parameter range [0, 1] splits into the tiles' exact intervals. A tile's drawing is
// the pieces of the whole drawing cut to its intervals; joining the tiles' pieces again gives
// the whole drawing's pieces exactly (pieces are maximal: two touching pieces of one segment
// differ in kind, so a join at a tile border is exactly where the whole drawing has none).
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/model/camera.hpp"
#include "algorithms/model/line_drawing.hpp"
#include "algorithms/picture/picture_plane.hpp"

namespace hlr {

/// A split of the picture into cols x rows tiles, numbered row by row from the top left.
/// Column c (0-based) holds the picture points with xs[c-1] <= X < xs[c] (xs[-1] = -inf,
/// xs[cols-1] = +inf), rows alike from the top: ys[r-1] > Y >= ys[r]. X and Y are the exact
/// picture coordinates of PicturePlane. Perspective: points not strictly in front of the eye
/// (never drawn) belong to tile 0.
struct TileSplit {
  int count = 1, cols = 1, rows = 1;
  std::vector<Rational> xs, ys;      // cols - 1 and rows - 1 exact lines, xs increasing, ys decreasing
  std::vector<double> xd, yd;        // the same lines in drawing coordinates (Projector's), for filters
  std::vector<double> xe, ye;        // bounds on the error of xd and yd
};

/// A point for the filters: drawing coordinates (Projector's) and a bound on their error, from
/// the error of the doubles of the point in the frame (below 2^-52 relative) through the
/// projection's few operations (docs/design.md, "Tiles"); infinite where no bound is known
/// (perspective: not clearly in front of the eye).
struct LocatedPoint {
  double x = 0, y = 0, err = 0;
};
LocatedPoint locate(const Camera& camera, const Projector& projector, const Point3& p);

/// The columns and rows for `count` tiles: cols = the smallest divisor of count that is at
/// least its square root, rows = count / cols (4 -> 2 x 2, 9 -> 3 x 3, 6 -> 3 x 2, 7 -> 7 x 1).
std::array<int, 2> tile_grid(int count);

/// Splits the picture of the `n` points (point(i)) into `count` tiles at quantiles of the
/// points' drawing coordinates (every tile gets about as many points), each line through one
/// of the points (exactly). The same points and camera give the same split on any machine and
/// thread count. Throws std::invalid_argument for count < 1.
TileSplit split_picture(const Camera& camera, const Projector& projector, std::size_t n,
                        const std::function<const Point3&(std::size_t)>& point, int count);

/// The closed parameter intervals of `segment` (in order, of positive length) whose points
/// belong to tile `index`: exact.
std::vector<std::pair<Rational, Rational>> tile_intervals(const Segment& segment, const PicturePlane& picture,
                                                          const Camera& camera, const TileSplit& split, int index);

/// A conservative filter: false only when no point of the segment with ends `a`, `b` can
/// belong to tile `index`.
bool tile_may_hold(const TileSplit& split, int index, const LocatedPoint& a, const LocatedPoint& b);

/// A conservative filter the other way: true only when every point of that segment is in tile
/// `index` (then tile_intervals() is [0, 1]).
bool tile_holds_wholly(const TileSplit& split, int index, const LocatedPoint& a, const LocatedPoint& b);

/// The sides of tile `index` that the point `a` surely lies beyond: bits 1 left, 2 right, 4
/// above, 8 below (a bit only where the error bounds cannot doubt it). Points whose bits share
/// one lie on one side of a tile line, and so does their convex hull (perspective: when all
/// are in front of the eye, which a finite error bound says).
int tile_outside(const TileSplit& split, int index, const LocatedPoint& a);

/// Cuts the segment's pieces to the intervals (tile_intervals()): what tile draws of it.
void cut_to_intervals(Segment& segment, const std::vector<std::pair<Rational, Rational>>& intervals);

/// Joins the pieces of one segment gathered from all tiles (any order): sorted, touching pieces
/// of the same kind joined. Returns an error text when they do not cover [0, 1] exactly once
/// (a tile missing or given twice), else the empty string.
std::string join_tile_pieces(std::vector<Piece>& pieces);

}  // namespace hlr
