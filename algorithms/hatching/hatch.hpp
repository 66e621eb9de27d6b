// Hatching (ISO 128-50 for section caps; docs/design.md, "Sections" and "Tone hatching"):
// parallel lines clipped exactly to a planar region in space. Each page line is lifted onto the region's
// plane and its ends snapped exactly onto it, so it is an exact line of the plane; where it is
// inside the region is decided by the exact side of each boundary edge's ends and the exact
// order of the crossing points along it: a hatch line never crosses the region's border.
// Doubles only place the lines (angle and spacing on the page): what is drawn is decided exactly.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "kernel/geometry.hpp"

namespace hlr {

/// How a body's section caps are hatched (ISO 128-50): single lines, crossed lines, a solid fill
/// (lines a pen's width apart) or none; the angle on the page in degrees and the spacing in mm
/// on the page (unset: the defaults, which alternate the angle between cut bodies).
struct HatchStyle {
  enum class Pattern { Single, Cross, Solid, None };
  Pattern pattern = Pattern::Single;
  std::optional<double> angle, spacing;
};

/// A hatch line across a planar region: exact ends on the region's plane with dyadic
/// coordinates (the lines of a scene then share one small denominator, which keeps the
/// per-face route that decides their visibility on small integers), and the parameter
/// intervals of p0 + t·(p1 − p0) inside the closed region, exact.
struct HatchLine {
  Point3 p0, p1;
  std::vector<std::pair<Rational, Rational>> inside;
};

/// A line of a plane by two points near it, in doubles: clip_lines snaps them exactly onto it.
struct ApproxLine {
  std::array<double, 3> a, b;
};

/// The exact lines through `lines`' ends snapped onto `plane` (two coordinates rounded to a
/// power of two 2^-30 of `size`, the third solved from the plane), each with the parameter
/// intervals inside the closed region bounded by `boundary` (directed edges into `pts`, closed
/// loops in `plane`, holes as loops of their own: inside is an odd number of crossings). Only
/// lines that meet the region; a line whose two ends snap to one point is left out.
std::vector<HatchLine> clip_lines(const std::vector<Point3>& pts, const std::vector<std::array<int, 2>>& boundary, const Plane& plane,
                                  const std::vector<ApproxLine>& lines, double size);

/// The same for exact lines of `plane` (p0 p1 of each; `inside` is filled in).
std::vector<HatchLine> clip_exact_lines(const std::vector<Point3>& pts, const std::vector<std::array<int, 2>>& boundary, const Plane& plane,
                                        std::vector<HatchLine> lines);

/// The page lines n·q = c, n = (cos angle, sin angle), c = first, first + step, ... <= last,
/// over the region bounded by `boundary` (directed edges into `pts`, closed loops in `plane`):
/// each line from the page point q0 to q1 across `page_box` (x0, y0, x1, y1 of the region's
/// picture) is lifted by `lift` (a page point to the point of the plane it shows, doubles) and
/// its two ends snapped exactly onto the plane (two coordinates rounded to a power of two
/// 2^-30 of `size`, the third solved from the plane). Only lines that meet the region.
std::vector<HatchLine> hatch_lines(const std::vector<Point3>& pts, const std::vector<std::array<int, 2>>& boundary, const Plane& plane,
                                   const std::function<std::array<double, 3>(double, double)>& lift, double angle_degrees, double first, double step,
                                   double last, const std::array<double, 4>& page_box, double size);

}  // namespace hlr
