// Signed integers of exactly N 64-bit limbs in two's complement (docs/design.md, "Number
// paths"): the multi-limb path's hottest constructions when every scaled coordinate lies below
// 2^125 (differences in 128 bits, normals in 256, plane values in 384), without WideInt's
// sign-and-size bookkeeping and its branches. The caller proves that every result fits its
// width (the bounds are stated where it is used); nothing here checks, and a value that did
// not fit would wrap. A value's double and its WideInt are WideInt's own of the same number
// (limbs_to_double), so a construction made here and the generic one give the same bits.
#pragma once

#include <gmp.h>

#include <array>
#include <cstdint>

#include "kernel/int128.hpp"
#include "kernel/wide_int.hpp"

namespace hlr {

template <int N>
struct FixedInt {
  static_assert(N >= 2 && N % 2 == 0, "pairs of limbs");
  std::uint64_t limb[N] = {};  // least significant first; the top bit of limb[N - 1] is the sign

  FixedInt() = default;
  explicit FixedInt(Int128 v) {  // sign-extended
    set(0, static_cast<UInt128>(v));
    for (int i = 1; i < N / 2; ++i) set(i, v < 0 ? ~UInt128{0} : 0);
  }

  /// Limbs 2i and 2i + 1 as one 128-bit word.
  UInt128 pair(int i) const { return static_cast<UInt128>(limb[2 * i + 1]) << 64 | limb[2 * i]; }
  void set(int i, UInt128 v) {
    limb[2 * i] = static_cast<std::uint64_t>(v);
    limb[2 * i + 1] = static_cast<std::uint64_t>(v >> 64);
  }

  bool negative() const { return (limb[N - 1] >> 63) != 0; }
  int sign() const {
    if (negative()) return -1;
    for (int i = 0; i < N; ++i)
      if (limb[i] != 0) return 1;
    return 0;
  }
  /// -x (x is never the most negative value: the callers' bounds keep one bit free).
  FixedInt negated() const { return FixedInt() - *this; }
  FixedInt magnitude() const { return negative() ? negated() : *this; }

  friend FixedInt operator+(const FixedInt& a, const FixedInt& b) {
    FixedInt r;
    UInt128 carry = 0;
    for (int i = 0; i < N / 2; ++i) {
      const UInt128 x = a.pair(i), s = x + b.pair(i), t = s + carry;
      carry = static_cast<UInt128>((s < x) | (t < s));
      r.set(i, t);
    }
    return r;
  }
  friend FixedInt operator-(const FixedInt& a, const FixedInt& b) {
    FixedInt r;
    UInt128 borrow = 0;
    for (int i = 0; i < N / 2; ++i) {
      const UInt128 x = a.pair(i), y = b.pair(i), d = x - y, t = d - borrow;
      borrow = static_cast<UInt128>((x < y) | (d < borrow));
      r.set(i, t);
    }
    return r;
  }

  /// WideInt::to_double of the same value.
  double to_double() const {
    const FixedInt m = magnitude();
    int n = N;
    while (n > 0 && m.limb[n - 1] == 0) --n;
    const double r = limbs_to_double(m.limb, n);
    return negative() ? -r : r;
  }
  /// The same value as a WideInt of M limbs (its magnitude must fit them).
  template <int M>
  WideInt<M> to_wide() const {
    const FixedInt m = magnitude();
    int n = N;
    while (n > 0 && m.limb[n - 1] == 0) --n;
    mpz_t view;
    return WideInt<M>(mpz_roinit_n(view, m.limb, negative() ? -n : n));
  }
};

namespace fixed_detail {
/// The 256-bit product of two unsigned 128-bit words: {low, high}.
inline std::array<UInt128, 2> product(UInt128 a, UInt128 b) {
  const auto a0 = static_cast<std::uint64_t>(a), a1 = static_cast<std::uint64_t>(a >> 64);
  const auto b0 = static_cast<std::uint64_t>(b), b1 = static_cast<std::uint64_t>(b >> 64);
  const UInt128 p00 = static_cast<UInt128>(a0) * b0, p01 = static_cast<UInt128>(a0) * b1;
  const UInt128 p10 = static_cast<UInt128>(a1) * b0, p11 = static_cast<UInt128>(a1) * b1;
  const UInt128 mid = (p00 >> 64) + static_cast<std::uint64_t>(p01) + static_cast<std::uint64_t>(p10);
  return {mid << 64 | static_cast<std::uint64_t>(p00), p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64)};
}
}  // namespace fixed_detail

/// The exact product of an A-limb and a B-limb value in A + B limbs (B = 2): the product of
/// the two bit patterns read as unsigned, less b·2^(64A) when a < 0 and a·2^(64B) when b < 0
/// (two's complement, modulo 2^(64(A + B)); no branch).
template <int A, int B>
inline FixedInt<A + B> mul(const FixedInt<A>& a, const FixedInt<B>& b) {
  static_assert(B == 2 && (A == 2 || A == 4), "the widths the engine uses");
  const UInt128 ub = b.pair(0);
  const UInt128 ma = a.negative() ? ~UInt128{0} : 0, mb = b.negative() ? ~UInt128{0} : 0;
  FixedInt<A + B> r;
  if constexpr (A == 2) {
    const UInt128 ua = a.pair(0);
    const auto p = fixed_detail::product(ua, ub);
    r.set(0, p[0]);
    r.set(1, p[1] - (ub & ma) - (ua & mb));
  } else {
    const UInt128 lo = a.pair(0), hi = a.pair(1);
    const auto p0 = fixed_detail::product(lo, ub), p1 = fixed_detail::product(hi, ub);
    UInt128 mid = p0[1] + p1[0];
    UInt128 top = p1[1] + static_cast<UInt128>(mid < p0[1]);
    const UInt128 s = lo & mb;  // a·2^128 when b < 0: its low word from mid, its high from top
    top -= static_cast<UInt128>(mid < s);
    mid -= s;
    top -= (hi & mb) + (ub & ma);
    r.set(0, p0[0]);
    r.set(1, mid);
    r.set(2, top);
  }
  return r;
}

namespace fixed_detail {
/// a·b for |a|, |b| < 2^126 as hi·2^128 + r1·2^64 + r0: each operand split into a signed high
/// and an unsigned low limb, the four partial products in 128-bit words (the two middle ones
/// below 2^126 each, their sum below 2^127).
struct Signed256 {
  std::uint64_t r0, r1;
  Int128 hi;
};
inline Signed256 product(Int128 a, Int128 b) {
  const auto al = static_cast<std::uint64_t>(a), bl = static_cast<std::uint64_t>(b);
  const auto ah = static_cast<std::int64_t>(a >> 64), bh = static_cast<std::int64_t>(b >> 64);
  const UInt128 low = static_cast<UInt128>(al) * bl;
  const Int128 mid = static_cast<Int128>(ah) * static_cast<Int128>(bl) + static_cast<Int128>(bh) * static_cast<Int128>(al);
  const UInt128 t = (low >> 64) + static_cast<std::uint64_t>(mid);
  return {static_cast<std::uint64_t>(low), static_cast<std::uint64_t>(t), static_cast<Int128>(ah) * bh + (mid >> 64) + static_cast<Int128>(t >> 64)};
}
/// p - q in four limbs.
inline FixedInt<4> difference(const Signed256& p, const Signed256& q) {
  FixedInt<4> r;
  const std::uint64_t b0 = p.r0 < q.r0;
  r.limb[0] = p.r0 - q.r0;
  const UInt128 d1 = static_cast<UInt128>(p.r1) - q.r1 - b0;
  r.limb[1] = static_cast<std::uint64_t>(d1);
  r.set(1, static_cast<UInt128>(p.hi - q.hi - static_cast<Int128>(d1 >> 127)));
  return r;
}
}  // namespace fixed_detail

/// a x b for components below 2^126: products below 2^252, components below 2^253 (4 limbs).
inline std::array<FixedInt<4>, 3> fixed_cross(const std::array<Int128, 3>& a, const std::array<Int128, 3>& b) {
  using fixed_detail::difference, fixed_detail::product;
  return {difference(product(a[1], b[2]), product(a[2], b[1])), difference(product(a[2], b[0]), product(a[0], b[2])),
          difference(product(a[0], b[1]), product(a[1], b[0]))};
}

namespace fixed_detail {
/// d·e for |d| < 2^63 and |e| < 2^126 as hi·2^64 + lo (hi below 2^125): e split into its signed
/// high and unsigned low limb, d·e_high one signed 64 x 64 product, d·e_low the unsigned
/// product of the bit patterns less e_low·2^64 when d < 0 (its value below 2^127).
struct Signed192 {
  std::uint64_t lo;
  Int128 hi;
};
inline Signed192 product(std::int64_t d, Int128 e) {
  const auto el = static_cast<std::uint64_t>(e);
  const auto eh = static_cast<std::int64_t>(e >> 64);
  const UInt128 low = static_cast<UInt128>(static_cast<std::uint64_t>(d)) * el - (d < 0 ? static_cast<UInt128>(el) << 64 : 0);
  return {static_cast<std::uint64_t>(low), static_cast<Int128>(d) * eh + (static_cast<Int128>(low) >> 64)};
}
/// p - q in four limbs (sign-extended).
inline FixedInt<4> difference(const Signed192& p, const Signed192& q) {
  FixedInt<4> r;
  r.limb[0] = p.lo - q.lo;
  const Int128 hi = p.hi - q.hi - static_cast<Int128>(p.lo < q.lo);
  r.limb[1] = static_cast<std::uint64_t>(hi);
  r.limb[2] = static_cast<std::uint64_t>(hi >> 64);
  r.limb[3] = hi < 0 ? ~std::uint64_t{0} : 0;
  return r;
}
}  // namespace fixed_detail

/// d x e for |d_j| < 2^62 (an orthographic direction) and |e_j| < 2^126 (an edge): products
/// below 2^188, components below 2^189, the same values as fixed_cross of the 128-bit d, in
/// 64 x 64-bit products.
inline std::array<FixedInt<4>, 3> fixed_cross(const std::array<std::int64_t, 3>& d, const std::array<Int128, 3>& e) {
  using fixed_detail::difference, fixed_detail::product;
  return {difference(product(d[1], e[2]), product(d[2], e[1])), difference(product(d[2], e[0]), product(d[0], e[2])),
          difference(product(d[0], e[1]), product(d[1], e[0]))};
}

/// n·x for n below 2^253 and x below 2^126: below 3·2^379 < 2^381 (6 limbs). Each term as
/// nh·x·2^128 + nl·x (n's signed high and unsigned low words), nl·x as the unsigned product
/// less nl·2^128 when x < 0; summed in three words with their carries.
inline FixedInt<6> fixed_dot(const std::array<FixedInt<4>, 3>& n, const std::array<Int128, 3>& x) {
  UInt128 lo = 0, mid = 0;
  Int128 hi = 0;
  for (int k = 0; k < 3; ++k) {
    const UInt128 nl = n[k].pair(0);
    const auto u = fixed_detail::product(nl, static_cast<UInt128>(x[k]));
    const fixed_detail::Signed256 p = fixed_detail::product(static_cast<Int128>(n[k].pair(1)), x[k]);
    lo += u[0];
    const UInt128 pl = static_cast<UInt128>(p.r1) << 64 | p.r0, less = x[k] < 0 ? nl : 0;
    Int128 carry = 0;
    for (const UInt128 v : {u[1], pl, static_cast<UInt128>(lo < u[0])}) {
      mid += v;
      carry += mid < v;
    }
    carry -= mid < less;
    mid -= less;
    hi += p.hi + carry;
  }
  FixedInt<6> r;
  r.set(0, lo);
  r.set(1, mid);
  r.set(2, static_cast<UInt128>(hi));
  return r;
}

}  // namespace hlr
