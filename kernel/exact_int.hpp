// Exactness in one address: the fixed-width integer number paths, their bounds with the
// derivation of each, and the error bounds of the double filters in front of them (course
// notes, "Visibility semantics": every decision exact; doubles only where a proven bound says
// the filter cannot be wrong). A path whose bound is exceeded is never taken: callers check
// the bound on the input and fall back to the next wider path, the last one GMP.
//
// Integer coordinates: a scene's rational coordinates times the common denominator L of all
// of them (decimal text has one). With |x| < 2^B for every scaled coordinate:
//   differences            < 2^(B+1)
//   cross products         < 2·2^(B+1)·2^(B+1) = 2^(2B+3)   (face normals, side planes)
//   plane values n·X - c   < 3·2^(2B+3)·2^(B+1) + |c|  <  2^(3B+7)
// so B = 29 keeps cross products in 64 bits (2^61) and plane values in 128 bits (2^94), and
// B = 40 keeps both in 128 bits (2^83 and 2^127). Split parameters are fractions of two plane
// values; two of them are ordered by comparing products of 128-bit values in 256 bits.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "kernel/int128.hpp"
#include "kernel/wide_int.hpp"

namespace hlr {

namespace bounds {
/// Scaled coordinates below 2^29: cross products in int64 (< 2^61), plane values in Int128.
inline constexpr int kFastCoordinateBits = 29;
/// Scaled coordinates below 2^40 (decimals with up to 10 places, as scanned meshes write
/// them): cross products < 2^83 and plane values < 2^127 in Int128. The same bound serves the
/// other 128-bit paths: face planes of polygons with up to 1024 vertices (Newell sums of
/// 1024 products < 2^83, then d = -n·v < 3·2^93), Cyrus-Beck's table-free clip (W·L, D·L
/// < 2^83) and Roberts' 128-bit interval (p, q, w < 2^62 checked on the way).
inline constexpr int kWideCoordinateBits = 40;
inline constexpr Int128 kWideCoordinateLimit = static_cast<Int128>(1) << kWideCoordinateBits;
/// Scaled coordinates below 2^150 (the Wide policy: a common denominator of any size, such as
/// 10^26 for ten significant digits with noise near 1e-17, 10^37 for numpy's %.18e, or 2^106
/// for a double's): cross products < 2^(2·150+3) = 2^303 in 5 limbs; plane values
/// < 2^(3·150+7) = 2^457, a triangle's six volumes summed over fewer than 2^31 triangles
/// < 2^485, and a normal dotted with a cross product of differences (the eye on a face's
/// edges) < 3·2^303·2^303 < 2^608, all in 10 limbs; products of two plane values in 20.
inline constexpr int kWideIntegerBits = 150;
/// Common denominators are kept below 2^62 so that L fits std::uint64_t with a bit to spare.
inline constexpr int kDenominatorBits = 62;

/// The split-parameter filter: a fraction n/d of two exact integers is approximated by
/// fl(fl(n)/fl(d)) (or, for GMP integers, from their mantissas and exponents: Big::ratio);
/// each rounding is within 2^-53 relative, so the approximation is within 4·2^-53 < 4.5e-16
/// relative of n/d. Two approximations x, y decide the order of their
/// fractions when |x - y| > kSplitFilter·(|x| + |y|): the exact difference then has the same
/// sign, since the two errors together are below 4.5e-16·(|x| + |y|)·(1 + 1e-15).
inline constexpr double kSplitFilter = 1e-12;
/// The smallest gap the filter decides on: below it (values that underflowed to subnormals or
/// zero, whose absolute error is below 2^-1022) the exact comparison decides. Infinite values
/// (a ratio beyond the double range) are never decided by the filter either.
inline constexpr double kSplitFilterFloor = 1e-300;

/// Screen-space boxes of projected geometry (grid and depth pruning): the double projection of
/// a point is within a few ulps of the exact one, i.e. below 1e-15 of the scene's extent; boxes
/// are widened by kBoxMargin of the extent, orders of magnitude more. The boxes only skip
/// work; no visibility decision is taken on them.
inline constexpr double kBoxMargin = 1e-6;
/// Roberts' body boxes, the same argument with a wider margin.
inline constexpr double kBodyBoxMargin = 1e-7;

/// Intersection-line filter: a crossing parameter s/(s - t) of exact integer plane values is
/// within 4 ulps in doubles and each interpolated coordinate within 8 ulps of the largest
/// coordinate; extents farther apart than kExtentUlps ulps of that are disjoint for sure.
inline constexpr double kExtentUlps = 64;
}  // namespace bounds

/// Number policy for scaled coordinates below 2^29: int64 coordinates and cross products,
/// Int128 plane values, 256-bit comparison of products.
struct Fast {
  using C = std::int64_t;
  using V = Int128;
  static constexpr int kBits = bounds::kFastCoordinateBits;
  static V mul(C a, C b) { return static_cast<V>(a) * b; }
  static int sign(const V& v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }
  static double dbl(const V& v) { return static_cast<double>(v); }
  static double cdbl(C v) { return static_cast<double>(v); }
  /// n/d for the split-parameter filter: both below 2^127, finite doubles, 3 roundings.
  static double ratio(const V& n, const V& d) { return dbl(n) / dbl(d); }
  static int compare(const V& a, const V& b, const V& c, const V& d) { return compare_products(a, b, c, d); }
  static mpz_class z(const V& v) { return to_mpz(v); }
  static mpz_class zc(C v) { return mpz_class(static_cast<long>(v)); }
};

/// Number policy for scaled coordinates below 2^40: everything in Int128.
struct Fast40 {
  using C = Int128;
  using V = Int128;
  static constexpr int kBits = bounds::kWideCoordinateBits;
  static V mul(C a, C b) { return a * b; }
  static int sign(const V& v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }
  static double dbl(const V& v) { return static_cast<double>(v); }
  static double cdbl(const C& v) { return static_cast<double>(v); }
  static double ratio(const V& n, const V& d) { return dbl(n) / dbl(d); }
  static int compare(const V& a, const V& b, const V& c, const V& d) { return compare_products(a, b, c, d); }
  static mpz_class z(const V& v) { return to_mpz(v); }
  static mpz_class zc(C v) { return to_mpz(v); }
};

/// Number policy for scaled coordinates below 2^150: fixed-width integers of 5 limbs
/// (coordinates, cross products) and 10 limbs (plane values), no allocation (wide_int.hpp).
struct Wide {
  using C = WideInt<5>;
  using V = WideInt<10>;
  static constexpr int kBits = bounds::kWideIntegerBits;
  static V mul(const C& a, const C& b) { return V::product(a, b); }
  template <int N>
  static int sign(const WideInt<N>& v) {
    return v.sign();
  }
  template <int N>
  static double dbl(const WideInt<N>& v) {
    return v.to_double();
  }
  static double cdbl(const C& v) { return v.to_double(); }
  /// As Big::ratio, on a read-only GMP view of the limbs.
  static double ratio(const V& n, const V& d) {
    mpz_t a, b;
    long en = 0, ed = 0;
    const double mn = mpz_get_d_2exp(&en, n.view(a)), md = mpz_get_d_2exp(&ed, d.view(b));
    return std::ldexp(mn / md, static_cast<int>(std::clamp<long>(en - ed, -2000, 2000)));
  }
  static int compare(const V& a, const V& b, const V& c, const V& d) { return V::compare_products(a, b, c, d); }
  static mpz_class z(const V& v) { return v.to_mpz(); }
  static mpz_class zc(const C& v) { return v.to_mpz(); }
};

/// Number policy without bounds: GMP integers.
struct Big {
  using C = mpz_class;
  using V = mpz_class;
  static V mul(const C& a, const C& b) { return a * b; }
  static int sign(const V& v) { return sgn(v); }
  static double dbl(const V& v) { return v.get_d(); }
  static double cdbl(const C& v) { return v.get_d(); }
  /// n/d for the filter without overflow: GMP integers reach far beyond the doubles (a
  /// coordinate with a 150-digit denominator gives plane values of 450 digits), so the two
  /// are taken as mantissa·2^exponent and divided, then scaled back (mpz_get_d_2exp truncates:
  /// each mantissa within 2^-52 relative; with the division and ldexp the ratio stays within
  /// 4·2^-53 < 4.5e-16 relative, inside the filter's bound). Ratios beyond the double range
  /// become 0 or inf, which the filter's floor and its NaN test leave to the exact comparison.
  static double ratio(const V& n, const V& d) {
    long en = 0, ed = 0;
    double mn = mpz_get_d_2exp(&en, n.get_mpz_t()), md = mpz_get_d_2exp(&ed, d.get_mpz_t());
    return std::ldexp(mn / md, static_cast<int>(std::clamp<long>(en - ed, -2000, 2000)));
  }
  static int compare(const V& a, const V& b, const V& c, const V& d) {
    mpz_class l = a * b, r = c * d;
    return cmp(l, r) < 0 ? -1 : (cmp(l, r) > 0 ? 1 : 0);
  }
  static const mpz_class& z(const V& v) { return v; }
  static const mpz_class& zc(const C& v) { return v; }
};

/// An integer point or vector under policy P.
template <class P>
using Vec = std::array<typename P::C, 3>;

template <class P>
Vec<P> sub(const Vec<P>& a, const Vec<P>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class P>
Vec<P> cross(const Vec<P>& a, const Vec<P>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class P>
typename P::V dot(const Vec<P>& a, const Vec<P>& b) {
  return P::mul(a[0], b[0]) + P::mul(a[1], b[1]) + P::mul(a[2], b[2]);
}
template <class P>
Vec<P> neg(const Vec<P>& a) {
  return {-a[0], -a[1], -a[2]};
}

/// A split parameter num/den (den > 0) with its double approximation for the filter.
template <class P>
struct Frac {
  typename P::V n, d;
  double x;
};

/// How comparisons of split parameters were decided (JSON stats).
struct ComparisonCounters {
  std::size_t comparisons = 0, exact = 0, identical = 0;
};

/// Exact order of two split parameters (-1, 0, 1): identical fractions first (neighbouring
/// occluders share side planes, so this is common), then the filter of bounds::kSplitFilter,
/// then exact products.
template <class P>
int compare(const Frac<P>& a, const Frac<P>& b, ComparisonCounters& c) {
  ++c.comparisons;
  if (a.n == b.n && a.d == b.d) {
    ++c.identical;
    return 0;
  }
  double diff = a.x - b.x, scale = std::fabs(a.x) + std::fabs(b.x);
  if (std::isfinite(scale) && std::fabs(diff) > bounds::kSplitFilter * scale + bounds::kSplitFilterFloor)
    return diff < 0 ? -1 : 1;
  ++c.exact;
  return P::compare(a.n, b.d, b.n, a.d);
}

}  // namespace hlr
