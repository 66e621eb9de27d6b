// A signed integer of at most N 64-bit limbs kept in place (docs/design.md, "Number paths"):
// GMP's own limb routines (mpn) on a fixed array, so that the exact values of scenes whose
// coordinates need more than 128 bits after scaling (ten-digit decimals with 1e-17 noise,
// %.17g, float32 and float64 files) cost no allocation. Sign and magnitude as in mpz: `size_`
// is the number of used limbs, negative for a negative value, and the top used limb is never
// 0. The policy that uses it (exact_int.hpp, Wide) proves that no value reaches N limbs; a
// result that would is a logic error and throws, never wraps.
#pragma once

#include <gmp.h>
#include <gmpxx.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "kernel/int128.hpp"

namespace hlr {

/// hi·2^64 + lo (hi != 0) rounded to the nearest double, ties to even: static_cast<double> of
/// the 128-bit integer without libgcc's generic conversion. The top 64 bits are converted with
/// every lower bit that is set folded into their last bit: that bit lies ten places below the
/// rounding place, so it changes no rounding but a tie's (a tie with more set bits below is
/// no tie); then times 2^(64 - s), exact.
inline double uint128_to_double(std::uint64_t hi, std::uint64_t lo) {
  const int s = __builtin_clzll(hi);
  const std::uint64_t top = s == 0 ? hi : (hi << s) | (lo >> (64 - s));
  const std::uint64_t rest = lo << s;
  const double scale = std::bit_cast<double>(static_cast<std::uint64_t>(1023 + 64 - s) << 52);
  return static_cast<double>(top | (rest != 0 ? 1 : 0)) * scale;
}

/// The magnitude of n limbs (least significant first, the top one non-zero) as a double: the
/// top two limbs rounded once, times 2^(64 (n - 2)) (exact, a power of two, as ldexp; 2^960
/// the last below the range). The limbs below weigh under 2^-64 of the value, so the double is
/// within 2^-52 relative; infinite beyond the range.
inline double limbs_to_double(const mp_limb_t* limb, int n) {
  if (n == 0) return 0;
  const double top = n == 1 ? static_cast<double>(limb[0]) : uint128_to_double(limb[n - 1], limb[n - 2]);
  static constexpr double kScale[] = {1.0,     0x1p64,  0x1p128, 0x1p192, 0x1p256, 0x1p320, 0x1p384, 0x1p448,
                                      0x1p512, 0x1p576, 0x1p640, 0x1p704, 0x1p768, 0x1p832, 0x1p896, 0x1p960};
  return n <= 2 ? top : n - 2 < 16 ? top * kScale[n - 2] : std::ldexp(top, 64 * (n - 2));
}

template <int N>
class WideInt {
 public:
  static constexpr int kLimbs = N;

  WideInt() = default;  // 0; limbs beyond |size_| are never read, nor copied
  WideInt(const WideInt& o) : size_(o.size_) { copy_limbs(o.limb_, std::abs(size_)); }
  WideInt& operator=(const WideInt& o) {
    size_ = o.size_;
    copy_limbs(o.limb_, std::abs(size_));
    return *this;
  }
  WideInt(long v) {  // NOLINT(google-explicit-constructor): integer constants like V(0), V(1)
    if (v == 0) return;
    limb_[0] = v < 0 ? 0UL - static_cast<unsigned long>(v) : static_cast<unsigned long>(v);
    size_ = v < 0 ? -1 : 1;
  }
  WideInt(int v) : WideInt(static_cast<long>(v)) {}  // NOLINT(google-explicit-constructor)
  /// From a 128-bit integer (N >= 2).
  explicit WideInt(Int128 v) {
    static_assert(N >= 2, "two limbs");
    const UInt128 u = v < 0 ? 0 - static_cast<UInt128>(v) : static_cast<UInt128>(v);
    limb_[0] = static_cast<mp_limb_t>(u);
    limb_[1] = static_cast<mp_limb_t>(u >> 64);
    const int n = limb_[1] != 0 ? 2 : (limb_[0] != 0 ? 1 : 0);
    size_ = v < 0 ? -n : n;
  }
  /// From a GMP integer of at most N limbs.
  explicit WideInt(mpz_srcptr z) {
    const int n = std::abs(z->_mp_size);
    check(n);
    std::memcpy(limb_, z->_mp_d, sizeof(mp_limb_t) * static_cast<std::size_t>(n));
    size_ = z->_mp_size;
  }
  /// From a narrower (or equal) width.
  template <int M>
  explicit WideInt(const WideInt<M>& o) {
    const int n = std::abs(o.size_);
    check(n);
    copy_limbs(o.limb_, n);
    size_ = o.size_;
  }

  int sign() const { return (size_ > 0) - (size_ < 0); }
  /// The value as a 128-bit integer; |value| must be below 2^127.
  Int128 to_int128() const {
    const int n = std::abs(size_);
    if (n > 2 || (n == 2 && (limb_[1] >> 63) != 0)) throw std::logic_error("WideInt: not a 128-bit value");
    const UInt128 u = n == 0 ? 0 : (n == 1 ? limb_[0] : (static_cast<UInt128>(limb_[1]) << 64) | limb_[0]);
    return size_ < 0 ? -static_cast<Int128>(u) : static_cast<Int128>(u);
  }
  /// The bit length of |value| (0 for 0).
  int bits() const {
    const int n = std::abs(size_);
    return n == 0 ? 0 : 64 * n - __builtin_clzl(limb_[n - 1]);
  }
  /// A read-only GMP view of the value (valid while this object lives, unchanged).
  mpz_srcptr view(mpz_t scratch) const { return mpz_roinit_n(scratch, limb_, size_); }
  mpz_class to_mpz() const {
    mpz_t t;
    return mpz_class(view(t));
  }
  /// The double of the top two limbs (rounded once) times a power of two: the limbs below
  /// weigh under 2^-64 of the value, so within 2^-52 relative; infinite beyond the range.
  double to_double() const {
    const double r = limbs_to_double(limb_, std::abs(size_));
    return size_ < 0 ? -r : r;
  }

  friend WideInt operator-(WideInt a) {
    a.size_ = -a.size_;
    return a;
  }
  friend WideInt operator+(const WideInt& a, const WideInt& b) {  // r is fresh: no aliasing
    WideInt r;
    r.add(a.limb_, a.size_, b.limb_, b.size_);
    return r;
  }
  friend WideInt operator-(const WideInt& a, const WideInt& b) {
    WideInt r;
    r.add(a.limb_, a.size_, b.limb_, -b.size_);
    return r;
  }
  WideInt& operator+=(const WideInt& b) {
    const WideInt a = *this;
    if (&b == this) return *this = a + a;
    add(a.limb_, a.size_, b.limb_, b.size_);
    return *this;
  }
  friend WideInt operator*(const WideInt& a, const WideInt& b) { return product(a, b); }
  /// a·b into this width (a and b of any widths whose product fits).
  template <int A, int B>
  static WideInt product(const WideInt<A>& a, const WideInt<B>& b) {
    WideInt r;
    if (a.size_ == 0 || b.size_ == 0) return r;
    const int an = std::abs(a.size_), bn = std::abs(b.size_);
    if (an > A || bn > B) __builtin_unreachable();  // sizes never exceed the widths
    int n = an + bn;
    if (n <= N) {  // straight into the result
      multiply(r.limb_, a.limb_, an, b.limb_, bn);
      if (r.limb_[n - 1] == 0) --n;
    } else {
      mp_limb_t t[A + B];
      multiply(t, a.limb_, an, b.limb_, bn);
      if (t[n - 1] == 0) --n;
      check(n);
      std::memcpy(r.limb_, t, sizeof(mp_limb_t) * static_cast<std::size_t>(n));
    }
    r.size_ = (a.size_ < 0) != (b.size_ < 0) ? -n : n;
    return r;
  }
  friend bool operator==(const WideInt& a, const WideInt& b) {
    return a.size_ == b.size_ && (a.size_ == 0 || mpn_cmp(a.limb_, b.limb_, std::abs(a.size_)) == 0);
  }
  friend bool operator!=(const WideInt& a, const WideInt& b) { return !(a == b); }

  /// Sign of a·b - c·d, exactly.
  static int compare_products(const WideInt& a, const WideInt& b, const WideInt& c, const WideInt& d) {
    const int l = a.sign() * b.sign(), r = c.sign() * d.sign();
    if (l != r || l == 0) return l > r ? 1 : (l < r ? -1 : 0);
    const WideInt<2 *N> p = WideInt<2 * N>::product(a, b), q = WideInt<2 * N>::product(c, d);
    const int m = compare_magnitudes(p.limb_, std::abs(p.size_), q.limb_, std::abs(q.size_));
    return l > 0 ? m : -m;
  }

 private:
  template <int M>
  friend class WideInt;

  // r[0, an + bn) = a·b (an, bn >= 1; r apart from both). Up to 3 limbs a side, schoolbook
  // rows of 64 x 64 -> 128-bit products in line (mpn_mul's call and dispatch cost more than
  // the work at these sizes); beyond, mpn_mul.
  static void multiply(mp_limb_t* r, const mp_limb_t* a, int an, const mp_limb_t* b, int bn) {
    static_assert(sizeof(mp_limb_t) == 8, "64-bit limbs");
    if (an > 3 || bn > 3) {
      if (an >= bn) mpn_mul(r, a, an, b, bn);
      else mpn_mul(r, b, bn, a, an);
      return;
    }
    using U = UInt128;
    for (int j = 0; j < bn; ++j) {
      mp_limb_t carry = 0;
      for (int i = 0; i < an; ++i) {  // at most (2^64 - 1)^2 + 2 (2^64 - 1) = 2^128 - 1: no overflow
        const U t = static_cast<U>(a[i]) * b[j] + (j == 0 ? 0 : r[i + j]) + carry;
        r[i + j] = static_cast<mp_limb_t>(t);
        carry = static_cast<mp_limb_t>(t >> 64);
      }
      r[an + j] = carry;
    }
  }
  // n <= N limbs from p (p may be these limbs themselves); unrolled in line up to ten limbs (a
  // library call costs more than the copy at these sizes).
  void copy_limbs(const mp_limb_t* p, int n) {
    if constexpr (N <= 10) {
      for (int i = 0; i < N; ++i)
        if (i < n) limb_[i] = p[i];
    } else {
      std::memmove(limb_, p, sizeof(mp_limb_t) * static_cast<std::size_t>(n));
    }
  }
  static void check(int n) {
    if (n > N) throw std::logic_error("WideInt: a value exceeds its proven bound");
  }
  static int compare_magnitudes(const mp_limb_t* a, int an, const mp_limb_t* b, int bn) {
    if (an != bn) return an < bn ? -1 : 1;
    if (an == 0) return 0;
    const int c = mpn_cmp(a, b, an);
    return (c > 0) - (c < 0);
  }
  // *this = a + b (signed sizes); a and b must not be this object's limbs (mpn_add and mpn_sub
  // allow the result to coincide with the first operand only, and the operands may swap).
  void add(const mp_limb_t* a, int as, const mp_limb_t* b, int bs) {
    if (bs == 0) return set(a, as);
    if (as == 0) return set(b, bs);
    int an = std::abs(as), bn = std::abs(bs);
    if (N >= 3 && an <= 2 && bn <= 2) return add128(a, as, b, bs);
    if ((as < 0) == (bs < 0)) {
      if (an < bn) std::swap(a, b), std::swap(an, bn), std::swap(as, bs);
      if (an < N) {  // room for the carry
        limb_[an] = add_limbs(limb_, a, an, b, bn);
        const int n = an + (limb_[an] != 0);
        size_ = as < 0 ? -n : n;
        return;
      }
      mp_limb_t t[N + 1];
      t[an] = add_limbs(t, a, an, b, bn);
      const int n = an + (t[an] != 0);
      check(n);
      std::memcpy(limb_, t, sizeof(mp_limb_t) * static_cast<std::size_t>(n));
      size_ = as < 0 ? -n : n;
      return;
    }
    const int c = compare_magnitudes(a, an, b, bn);
    if (c == 0) {
      size_ = 0;
      return;
    }
    if (c < 0) std::swap(a, b), std::swap(an, bn), std::swap(as, bs);
    sub_limbs(limb_, a, an, b, bn);
    int n = an;
    while (n > 0 && limb_[n - 1] == 0) --n;
    size_ = as < 0 ? -n : n;
  }
  // r = a + b (an >= bn >= 1), returning the carry out; r may be a or b. Up to 5 limbs in
  // line (mpn's call and dispatch cost more than the work at these sizes); beyond, mpn_add.
  static mp_limb_t add_limbs(mp_limb_t* r, const mp_limb_t* a, int an, const mp_limb_t* b, int bn) {
    if (an > 5) return mpn_add(r, a, an, b, bn);
    bool carry = false;
    int i = 0;
    for (; i < bn; ++i) {
      mp_limb_t t;
      const bool c1 = __builtin_add_overflow(a[i], b[i], &t);
      carry = c1 | __builtin_add_overflow(t, static_cast<mp_limb_t>(carry), &r[i]);
    }
    for (; i < an; ++i) carry = __builtin_add_overflow(a[i], static_cast<mp_limb_t>(carry), &r[i]);
    return carry;
  }
  // r = a - b for |a| > |b| (an >= bn >= 1, no borrow out); r may be a or b. As add_limbs.
  static void sub_limbs(mp_limb_t* r, const mp_limb_t* a, int an, const mp_limb_t* b, int bn) {
    if (an > 5) {
      mpn_sub(r, a, an, b, bn);
      return;
    }
    bool borrow = false;
    int i = 0;
    for (; i < bn; ++i) {
      mp_limb_t t;
      const bool b1 = __builtin_sub_overflow(a[i], b[i], &t);
      borrow = b1 | __builtin_sub_overflow(t, static_cast<mp_limb_t>(borrow), &r[i]);
    }
    for (; i < an; ++i) borrow = __builtin_sub_overflow(a[i], static_cast<mp_limb_t>(borrow), &r[i]);
  }
  // add's case of two non-zero values of at most two limbs each (N >= 3: room for the carry),
  // in 128-bit words.
  void add128(const mp_limb_t* a, int as, const mp_limb_t* b, int bs) {
    const UInt128 x = std::abs(as) == 2 ? (static_cast<UInt128>(a[1]) << 64) | a[0] : a[0];
    const UInt128 y = std::abs(bs) == 2 ? (static_cast<UInt128>(b[1]) << 64) | b[0] : b[0];
    int n = 0;
    bool negative = false;
    if ((as < 0) == (bs < 0)) {
      const UInt128 s = x + y;
      const bool carry = s < x;
      limb_[0] = static_cast<mp_limb_t>(s);
      limb_[1] = static_cast<mp_limb_t>(s >> 64);
      if (carry) limb_[std::min(2, N - 1)] = 1;
      n = carry ? 3 : (limb_[1] != 0 ? 2 : 1);
      negative = as < 0;
    } else {
      if (x == y) {
        size_ = 0;
        return;
      }
      const UInt128 d = x > y ? x - y : y - x;
      limb_[0] = static_cast<mp_limb_t>(d);
      limb_[1] = static_cast<mp_limb_t>(d >> 64);
      n = limb_[1] != 0 ? 2 : 1;
      negative = x > y ? as < 0 : bs < 0;
    }
    size_ = negative ? -n : n;
  }
  void set(const mp_limb_t* p, int s) {
    const int n = std::abs(s);
    check(n);
    copy_limbs(p, n);
    size_ = s;
  }

  int size_ = 0;
  mp_limb_t limb_[N];
};

}  // namespace hlr
