// Exact rational rotations (see rotation.hpp and docs/design.md "Rotations").
#include "kernel/rotation.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace hlr {
namespace {

// Best rational approximation of x by continued fraction convergents with |p/q - x| <= tol.
Rational continued_fraction(long double x, long double tol) {
  mpz_class h0 = 0, h1 = 1, k0 = 1, k1 = 0;  // convergents h/k
  long double r = x;
  for (int i = 0; i < 64; ++i) {
    long double a = std::floor(r);
    mpz_class ai(static_cast<double>(a));  // |a| stays far below 2^53 here
    mpz_class h2 = ai * h1 + h0, k2 = ai * k1 + k0;
    h0 = h1;
    h1 = h2;
    k0 = k1;
    k1 = k2;
    Rational approx(h1, k1);
    approx.canonicalize();
    long double err = std::fabs(static_cast<long double>(approx.get_d()) - x);
    if (err <= tol || r == a) return approx;
    r = 1.0L / (r - a);
  }
  Rational approx(h1, k1);
  approx.canonicalize();
  return approx;
}

}  // namespace

Rotation rotation_from_tan_half(const Rational& t) {
  Rational t2 = t * t, den = 1 + t2;
  return Rotation{(1 - t2) / den, 2 * t / den, true, 0};
}

Rotation rotation_from_cos_sin(const Rational& c, const Rational& s) {
  if (c * c + s * s != 1)
    throw std::invalid_argument("cos^2 + sin^2 = " + to_string(Rational(c * c + s * s)) +
                                ", not 1: not a rotation");
  return Rotation{c, s, true, 0};
}

Rotation rotation_from_degrees(const Rational& degrees) { return rotation_from_degrees(degrees, kRotationErrorBoundDegrees); }

Rotation rotation_from_degrees(const Rational& degrees, double max_error_degrees) {
  if (!(max_error_degrees >= kRotationErrorBoundDegrees)) max_error_degrees = kRotationErrorBoundDegrees;
  // Reduce to (-180, 180].
  mpz_class turns = degrees.get_num() / (degrees.get_den() * 360);
  Rational d = degrees - Rational(turns * 360);
  while (d > 180) d -= 360;
  while (d <= -180) d += 360;
  if (d == 0) return Rotation{1, 0, true, 0};
  if (d == 90) return Rotation{0, 1, true, 0};
  if (d == -90) return Rotation{0, -1, true, 0};
  if (d == 180) return Rotation{-1, 0, true, 0};
  // Rotation by d = rotation by (d -/+ 180) followed by a half turn (cos, sin both negate),
  // so the half-angle stays within 45 degrees and its tangent within [-1, 1].
  bool flip = false;
  if (d > 90) {
    d -= 180;
    flip = true;
  } else if (d < -90) {
    d += 180;
    flip = true;
  }
  // t = tan(d/2) in long double (64-bit mantissa): its error is far below 1e-17. The
  // continued fraction keeps |t_rational - t| <= tol, tol = (bound in radians)/2 less 1e-16
  // for the errors of t and of the check. Since |d atan/dt| <= 1, the realised angle
  // 2·atan(t_rational) is within 2·(tol + 1e-16) rad of d: within the bound (the default's
  // tol = 1e-14 gives 1.2e-12 degrees).
  const long double pi = 3.14159265358979323846264338327950288L;
  long double half = static_cast<long double>(d.get_d()) * (pi / 360.0L);
  const long double tol = max_error_degrees == kRotationErrorBoundDegrees
                              ? 1e-14L
                              : static_cast<long double>(max_error_degrees) * pi / 360.0L - 1e-16L;
  Rational t = continued_fraction(std::tan(half), tol);
  Rotation r = rotation_from_tan_half(t);
  // By Niven's theorem no rational number of degrees other than a multiple of 90 has both a
  // rational sine and a rational cosine, so this rotation is never exactly the one asked for.
  if (flip) {
    r.cos = -r.cos;
    r.sin = -r.sin;
  }
  r.exact = false;
  r.max_error_degrees = max_error_degrees;
  return r;
}

std::string describe(const Rotation& r) {
  std::string s = (r.exact ? "exact rotation" : "rational rotation") + std::string(" cos=") +
                  to_string(r.cos) + " sin=" + to_string(r.sin);
  if (!r.exact) {
    char bound[32];
    std::snprintf(bound, sizeof bound, "%g", r.max_error_degrees);
    s += std::string(" (angle within ") + bound + " degrees of the one asked for)";
  }
  return s;
}

}  // namespace hlr
