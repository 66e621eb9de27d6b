// The floating horizon, exactly (course notes section 24): a surface y = f(x, z)
// given on a grid is cut by the planes z = z_j; the cuts are drawn nearest to the viewer first,
// and a point of the next cut is visible where it lies on or above the upper horizon, or on or
// below the lower horizon, of everything in front of it. The horizons are exact piecewise-
// linear functions of the screen x (rational breakpoints), not per-pixel arrays; they are
// updated with the projected strips of the surface between consecutive cuts (the grid split
// into triangles along the diagonal (i, j)-(i+1, j+1)), not only with the cuts, because a strip
// can rise above both of its cuts in the picture when the view turns about the vertical axis.
// Every crossing point is exact, so the result is the general renderer's drawing of the same
// triangulated surface (a test checks it).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "algorithms/model/camera.hpp"
#include "kernel/number.hpp"

namespace hlr {

/// Samples y = f(x, z) at x = xs[i], z = zs[j] (each strictly increasing): ys[j * nx + i].
/// The heights are `ys`, or, when `yd` is not empty, the doubles `yd` taken exactly (an
/// expression's values: no rational per sample until one is asked for; `ys` is then empty).
struct HeightGrid {
  std::vector<Rational> xs, zs, ys;
  std::vector<double> yd;
  std::size_t heights() const { return yd.empty() ? ys.size() : yd.size(); }
  Rational y(std::size_t i, std::size_t j) const { return yd.empty() ? ys[j * xs.size() + i] : Rational(yd[j * xs.size() + i]); }
  Point3 point(std::size_t i, std::size_t j) const { return Point3(xs[i], y(i, j), zs[j]); }
};

/// A visible part of a cut: on curve `curve` (z = zs[curve]), on its segment from sample
/// `segment` to `segment + 1`, the parameter range [t0, t1] (t = 0 at sample `segment`).
struct HorizonPiece {
  int curve = 0, segment = 0;
  Rational t0, t1;
};

struct HorizonResult {
  std::vector<HorizonPiece> visible;  // by curve in drawing order (nearest first), then segment
  /// Only from floating_horizon_filtered(..., flat = false): `visible` left empty and its
  /// pieces kept here, in the same order, in the chunks they were computed in (one vector of a
  /// million GMP numbers costs a serial allocation each; the horizon drawing reads the chunks).
  std::vector<std::vector<HorizonPiece>> visible_chunks;
  std::vector<int> order;             // the curves, nearest to the viewer first
  std::size_t horizon_breakpoints = 0;  // largest size of the upper or lower horizon
  /// The notes' side edges, the edges (i, j)-(i, j+1) at i = 0 and i = nx - 1 (`curve` = i,
  /// `segment` = j). The one on the viewer's side in x has nothing in front: visible whole.
  /// Everything else of the surface lies on the viewer's side of the other one, so it is
  /// hidden exactly where it is strictly inside the envelope of the whole surface (the final
  /// horizons). A view with no x component sees both edge-on: visible whole.
  std::vector<HorizonPiece> side;
};

/// A line of the picture y = s·x + c (exact), as the exam page writes horizon pieces.
struct HorizonLine {
  Rational s, c;
};

/// A piece of a horizon: its line over [x0, x1].
struct HorizonPieceLine {
  Rational x0, x1;
  HorizonLine line;
};

/// One step of the method, for the exam page: a cut, the horizons it is tested against (after
/// the strip in front of it was added), each sample's verdict, and each crossing.
struct HorizonStep {
  int curve = 0;
  std::vector<std::array<Rational, 2>> points;  // the cut's samples in the picture (X, Y)
  std::vector<HorizonPieceLine> upper, lower;   // empty for the first cut
  /// Per sample: "first" (the nearest cut), "free" (nothing in front there), "above", "below",
  /// "on" (touches a horizon: visible),
  /// "between" (hidden).
  std::vector<std::string> verdicts;
  struct Crossing {
    int segment = 0;
    Rational x, y;       // the crossing point in the picture
    HorizonLine cut, horizon;  // x = (c_h − c_s) / (s_s − s_h)
    bool upper = true;   // with the upper horizon (else the lower)
  };
  std::vector<Crossing> crossings;
};

/// Runs the exact floating horizon for an orthographic camera whose view direction has a z
/// component (the cutting planes are not seen edge-on) and whose up vector makes the cuts
/// x-monotone in the picture (up has no x or z component... any up with the picture's x axis
/// not orthogonal to the x axis). Throws std::invalid_argument otherwise or for a bad grid.
/// Without a trace it runs floating_horizon_filtered() (the same result on certified doubles,
/// floating_horizon_filtered.hpp); with one, floating_horizon_exact().
HorizonResult floating_horizon(const HeightGrid& grid, const Camera& camera, std::vector<HorizonStep>* trace = nullptr);

/// What the horizons are made of. Strips: the projected strip of the surface between each cut
/// and the one in front of it (the exact surface; the default and the drawing's rule). Cuts: the
/// cuts alone, as the notes' method grows them (each cut tested against the upper and lower
/// envelopes of the cuts in front of it, then merged into them): where a strip rises above
/// both of its cuts in the picture, it sees a far cut the surface hides (the exam page).
enum class HorizonRule { Strips, Cuts };

/// The same sweep on rationals throughout (the exam page's trace, and the tests' reference).
HorizonResult floating_horizon_exact(const HeightGrid& grid, const Camera& camera, std::vector<HorizonStep>* trace = nullptr,
                                     HorizonRule rule = HorizonRule::Strips);

/// The checks both sweeps make (the grid's shape and order, an orthographic view with a z
/// component, cuts running left to right) and the picture axes r = up × v, u = v × r. Throws
/// std::invalid_argument.
std::array<Vector3, 2> horizon_axes(const HeightGrid& grid, const Camera& camera);

/// Orders `visible` as floating_horizon() returns it: curves nearest first, then segments, then t.
void sort_visible(HorizonResult& result);

/// The second family of cuts, x = xs[i] (a grid with both families; the notes' side edges are
/// its first and last cut): the same method on the grid with x and z exchanged (a reflection of
/// the scene and the view, which changes no visibility; the cells' diagonals stay the same).
/// `curve` is then i and `segment` j (the edge from (i, j) to (i, j+1)). Needs a view with an x
/// component; with none, every x cut lies in a plane through the viewing direction and is seen
/// edge-on: see x_cuts_edge_on().
HorizonResult floating_horizon_x(const HeightGrid& grid, const Camera& camera, unsigned threads = 0, bool flat = true);

/// True when the view has no x component: the x cuts lie in planes through the viewing
/// direction (each is seen as a vertical line). The first and last (the side edges) are then
/// visible whole: their sight rays stay in a plane where the surface has only its boundary.
bool x_cuts_edge_on(const Camera& camera);

}  // namespace hlr
