// Hatching (ISO 128-50 for section caps; docs/design.md, "Sections"): parallel lines on the
// page clipped exactly to a planar region in space. A page line is the trace of a plane (the
// plane through the line and the eye in perspective, the plane along the view direction in
// orthographic), so the lines of one family are exact segments on the region's plane, found
// by the exact side of each boundary edge's ends and ordered along the line by exact keys:
// a hatch line never crosses the region's border. Doubles only place the family (its angle
// and spacing on the page): what is drawn is decided exactly.
#pragma once

#include <array>
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

/// The planes of a family of parallel page lines n·q = c (q the page point in drawing units).
/// Orthographic: plane c is m·X = c·k + o; perspective: (m − c·f)·(X − eye) = 0, where m is
/// n in space (n₀·right + n₁·up), f the viewing axis.
struct HatchFamily {
  bool perspective = false;
  Vector3 m, f;
  Point3 eye;
  Rational k = 1, o = 0;  // orthographic: the drawing frame's scale and offset
  /// The values of c drawn: first + i·step, i = 0, 1, ... while c <= last.
  Rational first, step, last;
};

/// The hatch segments of the region whose boundary is the directed edges `boundary` (indices
/// into `pts`, closed loops, all in one plane with normal `normal`), every line of `family`.
/// Each segment is an exact piece of a line inside the closed region, in order along it.
std::vector<std::array<Point3, 2>> hatch_region(const std::vector<Point3>& pts, const std::vector<std::array<int, 2>>& boundary,
                                                const Vector3& normal, const HatchFamily& family);

}  // namespace hlr
