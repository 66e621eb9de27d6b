// Exact 128-bit integer helpers for the fast exact paths (face planes, Roberts' intervals):
// conversions between rationals and 128-bit integers, gcd, and the sign of a 256-bit
// difference of products. Callers check their own bounds and fall back to rationals.
#pragma once

#include <cstdint>

#include "kernel/number.hpp"

namespace hlr {

__extension__ typedef __int128 Int128;            // GCC/Clang extension
__extension__ typedef unsigned __int128 UInt128;

inline Int128 abs128(Int128 v) { return v < 0 ? -v : v; }

/// Number of bits of |v| (0 for 0).
int bit_length(Int128 v);

/// gcd(|a|, |b|); gcd(0, 0) = 0.
Int128 gcd128(Int128 a, Int128 b);

/// Sign of a·b - c·d, exactly, for |a|, |b|, |c|, |d| < 2^127.
int compare_products(Int128 a, Int128 b, Int128 c, Int128 d);

/// Exact conversion to GMP.
mpz_class to_mpz(Int128 v);
/// r = v, into an existing GMP integer (no temporaries).
void set_mpz(mpz_ptr r, Int128 v);

/// Least common multiple of the denominators of `n` rationals, when it is below `limit`.
bool common_denominator(const Rational* const* qs, int n, std::uint64_t limit, std::uint64_t& L);

/// q·L as an integer, when q's denominator divides L and |q·L| < limit.
bool scaled_integer(const Rational& q, std::uint64_t L, Int128 limit, Int128& out);

}  // namespace hlr
