// Exact 128-bit integer helpers (see int128.hpp).
#include "kernel/int128.hpp"

#include <utility>

namespace hlr {
namespace {

struct U256 {
  UInt128 hi, lo;
};

U256 mul(UInt128 a, UInt128 b) {
  const UInt128 m = 0xffffffffffffffffULL;
  UInt128 a0 = a & m, a1 = a >> 64, b0 = b & m, b1 = b >> 64;
  UInt128 p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
  UInt128 mid = (p00 >> 64) + (p01 & m) + (p10 & m);
  return {p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64), (p00 & m) | (mid << 64)};
}

int compare(const U256& x, const U256& y) {
  if (x.hi != y.hi) return x.hi < y.hi ? -1 : 1;
  if (x.lo != y.lo) return x.lo < y.lo ? -1 : 1;
  return 0;
}

// One Euclid step (a large number against a small one is one division), then binary gcd
// (Stein): shifts and subtractions.
std::uint64_t gcd64(std::uint64_t a, std::uint64_t b) {
  if (a > b) std::swap(a, b);
  if (a == 0) return b;
  b %= a;
  if (b == 0) return a;
  const int shift = __builtin_ctzll(a | b);
  a >>= __builtin_ctzll(a);
  while (b) {
    b >>= __builtin_ctzll(b);
    if (a > b) std::swap(a, b);
    b -= a;
  }
  return a << shift;
}

}  // namespace

int bit_length(Int128 v) {
  const UInt128 u = static_cast<UInt128>(abs128(v));
  const auto hi = static_cast<std::uint64_t>(u >> 64), lo = static_cast<std::uint64_t>(u);
  if (hi) return 128 - __builtin_clzll(hi);
  return lo ? 64 - __builtin_clzll(lo) : 0;
}

Int128 gcd128(Int128 a, Int128 b) {
  UInt128 x = static_cast<UInt128>(abs128(a)), y = static_cast<UInt128>(abs128(b));
  while (y) {
    if ((x >> 64) == 0 && (y >> 64) == 0)  // the rest in 64 bits
      return static_cast<Int128>(gcd64(static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(y)));
    UInt128 t = x % y;
    x = y;
    y = t;
  }
  return static_cast<Int128>(x);
}

int compare_products(Int128 a, Int128 b, Int128 c, Int128 d) {
  int sl = (a == 0 || b == 0) ? 0 : ((a < 0) != (b < 0) ? -1 : 1);
  int sr = (c == 0 || d == 0) ? 0 : ((c < 0) != (d < 0) ? -1 : 1);
  if (sl != sr) return sl < sr ? -1 : 1;
  if (sl == 0) return 0;
  int m = compare(mul(static_cast<UInt128>(abs128(a)), static_cast<UInt128>(abs128(b))),
                  mul(static_cast<UInt128>(abs128(c)), static_cast<UInt128>(abs128(d))));
  return sl > 0 ? m : -m;
}

mpz_class to_mpz(Int128 v) {
  if (v >= INT64_MIN && v <= INT64_MAX) return mpz_class(static_cast<long>(v));
  bool neg = v < 0;
  UInt128 u = neg ? static_cast<UInt128>(-v) : static_cast<UInt128>(v);
  mpz_class hi(static_cast<unsigned long>(static_cast<std::uint64_t>(u >> 64)));
  mpz_class lo(static_cast<unsigned long>(static_cast<std::uint64_t>(u)));
  mpz_class r = (hi << 64) + lo;
  return neg ? mpz_class(-r) : r;
}

void set_mpz(mpz_ptr r, Int128 v) {
  if (v >= INT64_MIN && v <= INT64_MAX) return mpz_set_si(r, static_cast<long>(v));
  const bool neg = v < 0;
  const UInt128 u = neg ? static_cast<UInt128>(-v) : static_cast<UInt128>(v);
  mpz_set_ui(r, static_cast<unsigned long>(static_cast<std::uint64_t>(u >> 64)));
  mpz_mul_2exp(r, r, 64);
  mpz_add_ui(r, r, static_cast<unsigned long>(static_cast<std::uint64_t>(u)));
  if (neg) mpz_neg(r, r);
}

bool common_denominator(const Rational* const* qs, int n, std::uint64_t limit, std::uint64_t& L) {
  L = 1;
  for (int i = 0; i < n; ++i) {
    if (!qs[i]->get_den().fits_ulong_p()) return false;
    std::uint64_t d = qs[i]->get_den().get_ui();
    if (d == 1) continue;
    UInt128 l = static_cast<UInt128>(L / gcd64(L, d)) * d;
    if (l >= limit) return false;
    L = static_cast<std::uint64_t>(l);
  }
  return true;
}

bool scaled_integer(const Rational& q, std::uint64_t L, Int128 limit, Int128& out) {
  if (!q.get_num().fits_slong_p()) return false;
  out = static_cast<Int128>(q.get_num().get_si()) * static_cast<Int128>(L / q.get_den().get_ui());
  return abs128(out) < limit;
}

}  // namespace hlr
