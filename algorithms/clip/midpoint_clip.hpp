// 3D clipping by midpoint subdivision (course notes, section 21) against the notes'
// two clippers: a box (6-bit outcodes: left, right, below, above, near, far) and the truncated
// viewing pyramid (the notes' test functions with coefficients alpha1..delta2). Approximate by
// design: every midpoint is computed exactly, every reported end is exactly inside the clipper,
// and each reported end is within `eps` (Euclidean) of the exact clipped end (Cyrus-Beck); see
// MidpointResult for the full bound.
#pragma once

#include <array>
#include <string>
#include <variant>
#include <vector>

#include "kernel/geometry.hpp"

namespace hlr {

/// Outcode bits in the notes' order; bit i set means outside that plane. On a plane is inside.
enum OutcodeBit : unsigned { kLeft = 1, kRight = 2, kBelow = 4, kAbove = 8, kNear = 16, kFar = 32 };

struct BoxWindow {
  Rational xl, xr, yb, yt, zfar, znear;  // viewer on +z: near is z = znear (the larger z)
};

struct FrustumWindow {
  Rational xl, xr, yb, yt, znear, zfar, zcp;  // window at the far plane, centre (0, 0, zcp)
  // The notes' coefficients: x = z·alpha1 + alpha2 on the right plane, and so on.
  Rational alpha1() const { return xr / (zfar - zcp); }
  Rational alpha2() const { return -alpha1() * zcp; }
  Rational beta1() const { return xl / (zfar - zcp); }
  Rational beta2() const { return -beta1() * zcp; }
  Rational gamma1() const { return yt / (zfar - zcp); }
  Rational gamma2() const { return -gamma1() * zcp; }
  Rational delta1() const { return yb / (zfar - zcp); }
  Rational delta2() const { return -delta1() * zcp; }
};

using Window = std::variant<BoxWindow, FrustumWindow>;

/// The outcode of p: one bit per plane, set when p is strictly outside it. For the frustum the
/// side bits are the signs of the notes' test functions f = x - z·alpha1 - alpha2 (> 0: right),
/// and so on, i.e. the true half-spaces of the convex pyramid.
unsigned outcode(const Window& w, const Point3& p);

/// The notes' rule for points behind the centre of projection (z > zcp): the first four bits
/// inverted. Reported for the course's tables; not used for decisions, because it is not a
/// half-space test: a segment from behind the centre that crosses the pyramid can get two
/// codes with a common bit and be rejected wrongly (docs/design.md, test
/// MidpointClip.NotesBehindCentreRuleWouldRejectAVisibleSegment).
unsigned notes_outcode(const Window& w, const Point3& p);

/// "LRBANF" style text: the six bits in the notes' order, e.g. "010010".
std::string outcode_bits(unsigned code);

struct MidpointResult {
  bool visible = false;
  Point3 from, to;              // exact ends, each exactly inside the clipper
  unsigned code1 = 0, code2 = 0;  // the input ends' outcodes
  long subdivisions = 0;        // midpoints computed
  bool trivially_accepted = false, trivially_rejected = false;
  /// The bound: when visible, |from - exact_from| <= eps and |to - exact_to| <= eps, where
  /// exact_* are Cyrus-Beck's ends, and [from, to] lies inside [exact_from, exact_to]. When not
  /// visible, the exact visible part (if any) is shorter than 2·eps.
};

/// One midpoint of the subdivision, for the course's tables (hlr explain): the point, its
/// outcode and which search produced it ("search": looking for an inside point between two
/// outside ends; "end 1" / "end 2": halving toward that end's boundary crossing).
struct MidpointStep {
  std::string phase;
  Point3 point;
  unsigned code = 0;
};

/// Clips P1P2 by midpoint subdivision to tolerance eps > 0. With `trace`, every midpoint is
/// recorded in order.
MidpointResult midpoint_clip(const Window& w, const Point3& p1, const Point3& p2, const Rational& eps,
                             std::vector<MidpointStep>* trace = nullptr);

}  // namespace hlr
