// Floating-point error bounds, in one place: the unit roundoff, the error of a rational's
// double, the range in which a double filter may be used, one ulp up and down, the interval
// type, and the pad of picture boxes. Every filter of the project takes its constants from
// here; the derivations are in docs/design.md ("Filters" and "Orientation of three points").
// Doubles only skip work: a filter that cannot decide hands the question to exact numbers.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>

namespace hlr {

/// u: a rounded double operation errs by at most u times the magnitude of its result.
constexpr double kUnitRoundoff = 0x1p-53;
/// A rational's double (mpq_get_d truncates) is within 2u of it, relative.
constexpr double kToDoubleError = 2 * kUnitRoundoff;
/// The absolute error of an operation whose result underflows.
constexpr double kUnderflowError = 0x1p-1074;
/// Covers the roundings of a bound's own computation (a handful of non-negative terms).
constexpr double kBoundSafety = 1 + 0x1p-40;

/// The range of the double filters: a value that is 0, or of magnitude in [2^-400, 2^400].
/// A product of two such values neither underflows nor overflows. Decides only whether a
/// filter may be tried, never an answer.
inline bool in_filter_range(double v) { return v == 0 || (std::fabs(v) >= 0x1p-400 && std::fabs(v) <= 0x1p400); }

/// A double above v (below, for next_down) with nothing between: std::nextafter's value,
/// with the bits stepped inline (the library call dominated the interval arithmetic), except
/// that 0 steps to ±2^-1022, the smallest normal double (still a bound: a rounded result of 0
/// is within 2^-1075 of the exact value), so that no subnormal, slow on x86, enters.
inline double next_up(double v) {
  if (!(v < INFINITY)) return v;  // +inf, NaN
  if (v == 0) return 0x1p-1022;
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  b += v > 0 ? 1 : -1;
  std::memcpy(&v, &b, sizeof b);
  return v;
}
inline double next_down(double v) { return -next_up(-v); }

/// std::nextafter(v, ±infinity) for a float, bit for bit (0 steps to the smallest subnormal),
/// with the bits stepped inline: the library call was a tenth of the boxes' cost.
inline float next_float_up(float v) {
  if (!(v < INFINITY)) return v;  // +inf, NaN
  if (v == 0) return std::numeric_limits<float>::denorm_min();
  std::uint32_t b;
  std::memcpy(&b, &v, sizeof b);
  b += v > 0 ? 1 : -1;
  std::memcpy(&v, &b, sizeof b);
  return v;
}
inline float next_float_down(float v) { return -next_float_up(-v); }

/// A closed interval [lo, hi] of doubles that certainly contains an exact value.
struct Interval {
  double lo = 0, hi = 0;
};

/// Interval arithmetic: each operation rounds to nearest, then widens one step each way
/// (next_up/next_down), so the result contains the exact value (the rounding error is at most
/// half an ulp of the result, or 2^-1075 when it underflows to 0); a product with an exact
/// zero interval is exact zero.
namespace interval {
inline Interval add(Interval a, Interval b) { return {next_down(a.lo + b.lo), next_up(a.hi + b.hi)}; }
inline Interval sub(Interval a, Interval b) { return {next_down(a.lo - b.hi), next_up(a.hi - b.lo)}; }
inline Interval mul(Interval a, Interval b) {
  if ((a.lo == 0 && a.hi == 0) || (b.lo == 0 && b.hi == 0)) return {0, 0};  // exact
  const double p = a.lo * b.lo, q = a.lo * b.hi, r = a.hi * b.lo, s = a.hi * b.hi;
  return {next_down(std::min(std::min(p, q), std::min(r, s))), next_up(std::max(std::max(p, q), std::max(r, s)))};
}
/// a·x for an exact double x.
inline Interval scale(Interval a, double x) {
  const double p = a.lo * x, q = a.hi * x;
  return {next_down(std::min(p, q)), next_up(std::max(p, q))};
}
inline bool finite(Interval a) { return std::isfinite(a.lo) && std::isfinite(a.hi); }
/// The quotient a / b when b does not contain 0 and the result is finite (else false: undecided).
inline bool divide(Interval a, Interval b, Interval& out) {
  if (!(b.lo > 0 || b.hi < 0)) return false;
  const double p[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  out = {next_down(*std::min_element(p, p + 4)), next_up(*std::max_element(p, p + 4))};
  return finite(out);
}
}  // namespace interval

/// The pad that widens a picture box of doubles so that it holds the exact box: 1e-9 of the
/// box's largest coordinate (far above the few ulps by which its doubles err), and at least
/// 1e-300. A filter's margin, never a tolerance of a decision.
inline double box_pad(std::initializer_list<double> coordinates) {
  // std::max({|c|..., 1e-300})'s order of comparisons, so that a NaN goes where it went.
  double m = 1e-300;
  bool first = true;
  for (double c : coordinates) {
    const double v = std::fabs(c);
    if (first) m = v, first = false;
    else if (m < v) m = v;
  }
  if (first || m < 1e-300) m = 1e-300;
  return 1e-9 * m;
}

}  // namespace hlr
