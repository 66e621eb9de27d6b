// Tone hatching (docs/design.md, "Tone hatching"; the shading of course notes section 41 drawn
// with a pen): each visible region of a face is hatched by parallel lines whose spacing gives
// its shade's darkness as ink on the page. A region's darkness 1 − Y (Y the shade's luminance)
// is rounded to one of N tone levels with coverage k/N (k = 0 .. N − 1; level 0, paper white,
// is not hatched). A pen of width p drawing lines s apart covers p/s of the paper, so a level
// of coverage c is hatched at s = p/c; above `cross_above` it is cross-hatched, two families at
// right angles, each at s = p/(1 − √(1 − c)) (together they cover 1 − (1 − p/s)² = c).
// A tone's lines are the faces' intersections with one family of parallel planes in space:
// parallel in 3D on each face (a perspective foreshortens them), the same on every region of a
// face, and continuous from face to face across their shared edges; each line is exact and
// clipped exactly to the region (hatch.hpp). Doubles place the planes; what is drawn and where
// it stops is exact.
#pragma once

#include <array>
#include <vector>

#include "algorithms/hatching/hatch.hpp"
#include "kernel/predicates_2d.hpp"

namespace hlr {

/// The most tone levels (the line drawing's kinds Tone1..Tone8).
inline constexpr int kToneLevels = 8;

struct ToneOptions {
  int levels = 5;            ///< tone levels N, 2..kToneLevels
  double pen_mm = 0.25;      ///< the pen's width on the page
  double cross_above = 0.5;  ///< coverage above which a level is cross-hatched
};

/// A tone level and how it is hatched (families 0: not hatched).
struct ToneLevel {
  int level = 0;
  int families = 0;
  double coverage = 0;    ///< k/N
  double spacing_mm = 0;  ///< between the lines of one family, on the page
};

/// Rec. 709 luminance of a colour (0..1 per channel).
double luminance(const std::array<double, 3>& rgb);

/// The level of a shade of luminance `y` (0 black .. 1 white).
ToneLevel tone_level(double y, const ToneOptions& options);

/// A family of parallel planes m·X = (k + ½)·step for whole k (m exact; `m_d` its doubles):
/// the scene's hatch lines of one tone are the faces' intersections with them.
struct PlaneFamily {
  Vector3 m;
  std::array<double, 3> m_d{0, 0, 0};
  double step = 0;
};

/// The family's pieces inside the region bounded by `edges` (directed edges, their ends as
/// pointers, closed loops in the plane of normal `normal`; holes as loops of their own), exact:
/// each piece is a pair of exact points of the region's border on one plane of the family.
/// An edge crosses plane k where the signs of m·X − c_k < 0 at its ends differ (half-open: a
/// plane through a corner counts it once, a plane along an edge crosses neither it nor, by that
/// edge, the region), at X = A + s·(B − A), s = (c_k − m·A)/(m·(B − A)); the crossings of one
/// plane, sorted exactly along its line, pair into the pieces. Where the region's edge is an edge
/// the face shares with another face, both faces' pieces end at the same exact point, so their
/// strokes join. None when the region's plane is parallel to the family.
std::vector<std::array<Point3, 2>> family_pieces(const std::vector<std::array<const Point3*, 2>>& edges, const Vector3& normal,
                                                 const PlaneFamily& family);

/// A family of parallel lines of an orthographic picture, α·x + β·y = (k + ½)·step (α, β and
/// step doubles, taken exactly): the picture of a family of planes that contain the viewing
/// direction (m = α·r + β·u for the picture plane's axes r and u), so a face's hatch lines are
/// found in the picture, from the exact picture corners of its visible region.
struct PictureFamily {
  double alpha = 0, beta = 0, step = 0;
};

/// The family's pieces inside the picture region bounded by `edges` (directed edges of exact
/// picture points, closed loops, holes as loops of their own), exact, by the rules of
/// family_pieces.
std::vector<std::array<Exact2, 2>> picture_family_pieces(const std::vector<std::array<const Exact2*, 2>>& edges, const PictureFamily& family);

}  // namespace hlr
