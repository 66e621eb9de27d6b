// Exact rotations. A rotation is a pair (cos, sin) of rationals with cos^2 + sin^2 = 1
// exactly, so every rotation matrix is exactly orthogonal and lengths and angles stay exact.
// Angles whose sine and cosine are rational (multiples of 90 degrees, and angles given by a
// rational tangent of the half-angle or a Pythagorean pair) are exact. Other angles in degrees
// (30, 45, 17.5...) have irrational sine or cosine: they are replaced by the nearest rational
// rotation found from a continued fraction of tan(angle/2), and the result says so, with a
// bound on the angle error (see docs/design.md "Rotations"). Nothing is rounded silently.
#pragma once

#include <string>

#include "kernel/number.hpp"

namespace hlr {

struct Rotation {
  Rational cos = 1, sin = 0;
  /// True when (cos, sin) is exactly the angle asked for.
  bool exact = true;
  /// When not exact: a proven bound on |realised angle - requested angle|, in degrees.
  double max_error_degrees = 0;
};

/// Bound on the angle error of an inexact rotation_from_degrees, in degrees.
inline constexpr double kRotationErrorBoundDegrees = 1e-11;

/// Rotation by `degrees`. Exact for multiples of 90; otherwise a rational rotation within
/// kRotationErrorBoundDegrees of the angle, with exact = false.
Rotation rotation_from_degrees(const Rational& degrees);

/// The same with the smallest numbers whose angle is within `max_error_degrees` (at least
/// kRotationErrorBoundDegrees) of the one asked for: the first convergent of the continued
/// fraction of tan(angle/2) close enough. Exact for multiples of 90.
Rotation rotation_from_degrees(const Rational& degrees, double max_error_degrees);

/// Exact rotation from the tangent of the half-angle t: cos = (1-t^2)/(1+t^2),
/// sin = 2t/(1+t^2).
Rotation rotation_from_tan_half(const Rational& t);

/// Exact rotation from cos and sin; throws std::invalid_argument unless cos^2 + sin^2 == 1.
Rotation rotation_from_cos_sin(const Rational& c, const Rational& s);

/// Text such as "exact rotation cos=3/5 sin=4/5" for reports.
std::string describe(const Rotation& r);

}  // namespace hlr
