// Exact predicates of the picture plane, in one place (course notes section 25; the filters'
// bounds in docs/design.md, "Orientation of three points"): the exact 2D point, orientation
// with one double filter and its exact fallback, the sign of a dot product, and the same
// orientation on intervals. Every algorithm that orients picture points calls these.
#pragma once

#include <array>

#include "kernel/error_bounds.hpp"
#include "kernel/number.hpp"

namespace hlr {

/// An exact point of the picture (x along r, y along u).
using Exact2 = std::array<Rational, 2>;
/// Its doubles (mpq_get_d of each coordinate).
using Double2 = std::array<double, 2>;

/// The one orientation filter: the sign of orient2d of three exact points from their doubles
/// (each within kToDoubleError relative of its coordinate, and in_filter_range, a zero double
/// only for a zero coordinate), or 0 when the doubles cannot tell. The doubles' determinant is
/// within 64·kToDoubleError·Mx·My of the exact one (Mx, My: the largest |x|, |y|).
inline int orient2d_filter(const Double2& a, const Double2& b, const Double2& c, double mx, double my, double factor = 1);
inline int orient2d_filter(const Double2& a, const Double2& b, const Double2& c) {
  const double mx = std::max({std::fabs(a[0]), std::fabs(b[0]), std::fabs(c[0])});
  const double my = std::max({std::fabs(a[1]), std::fabs(b[1]), std::fabs(c[1])});
  return orient2d_filter(a, b, c, mx, my);
}
/// The same with the magnitudes given (mx >= every |x|, my >= every |y|) and the bound
/// multiplied by `factor` (2 when c's doubles are themselves computed and err twice as much).
inline int orient2d_filter(const Double2& a, const Double2& b, const Double2& c, double mx, double my, double factor) {
  const double det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  const double bound = factor * 64 * kToDoubleError * mx * my;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return 0;
}

/// The one comparison filter: the sign of y - x from the doubles of two exact numbers (the
/// difference of the doubles is within 4·kToDoubleError·(|x| + |y|) of the exact one), or 0.
inline int compare_filter(double x, double y) {
  const double d = y - x, bound = 4 * kToDoubleError * (std::fabs(x) + std::fabs(y));
  if (d > bound) return 1;
  if (d < -bound) return -1;
  return 0;
}

/// Whether a rational's double may enter the filters (in_filter_range, and zero only when the
/// rational is: an underflowed 0 or an overflowed infinity turns the filter off).
bool filter_usable(const Rational& q, double d);
/// The same for both coordinates of a point.
bool filter_usable(const Exact2& p, const Double2& d);

/// Orientation of c against the line a -> b: +1 left, -1 right, 0 on it (filter, then exact).
int orient2d(const Exact2& a, const Exact2& b, const Exact2& c);
/// The same with the points' doubles already made (mpq_get_d of each coordinate).
int orient2d(const Exact2& a, const Exact2& b, const Exact2& c, const Double2& da, const Double2& db, const Double2& dc);
/// The same without the double filter (exact integers, no gcd).
int orient2d_exact(const Exact2& a, const Exact2& b, const Exact2& c);
/// Sign of (q - p)·(b - a), exact (integers, no gcd).
int dot_sign_exact(const Exact2& p, const Exact2& q, const Exact2& a, const Exact2& b);

/// A picture point known by certified intervals of its coordinates.
using Interval2 = std::array<Interval, 2>;
/// The sign of orient2d of three points from their intervals, or 2 when they cannot tell.
inline int orient2d_interval(const Interval2& a, const Interval2& b, const Interval2& c) {
  using namespace interval;
  const Interval det = sub(mul(sub(b[0], a[0]), sub(c[1], a[1])), mul(sub(b[1], a[1]), sub(c[0], a[0])));
  if (det.lo > 0) return 1;
  if (det.hi < 0) return -1;
  return 2;
}

}  // namespace hlr
