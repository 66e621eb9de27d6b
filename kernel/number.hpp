// Exact numbers: the rational type every exact decision in exact-hlr is made with, and its
// conversion from and to text. `0.1` parses to exactly 1/10, `-3/7` to -3/7, `1e-3` to 1/1000.
// Course notes "Visibility semantics": coordinates keep the exact value of their text.
#pragma once

#include <gmpxx.h>

#include <stdexcept>
#include <string>
#include <string_view>

namespace hlr {

/// The exact rational number type (GMP). Always kept in lowest terms by GMP.
using Rational = mpq_class;

/// num/den in lowest terms. (GMP's mpq_class(num, den) does not canonicalise, and GMP's
/// arithmetic on non-canonical values is wrong: always build fractions through this.)
inline Rational rational(long num, long den) {
  Rational q(num, den);
  q.canonicalize();
  return q;
}

/// A number in text that is not an exact finite rational. `token()` is the offending text.
class NumberError : public std::runtime_error {
 public:
  NumberError(std::string token, const std::string& why);
  const std::string& token() const { return token_; }

 private:
  std::string token_;
};

/// Largest decimal exponent accepted in scientific notation (|e| <= this). Larger ones would
/// make numbers of millions of digits from a few bytes of text.
inline constexpr long kMaxDecimalExponent = 4000;

/// Whether q is in lowest terms with a positive denominator (what GMP's arithmetic needs):
/// decided without a general gcd for a denominator 2^a·r with r of one limb (decimals), and
/// without allocating.
bool in_lowest_terms(const Rational& q);

/// Parses an exact rational from text: integer (`-12`, `+3`), decimal (`0.1`, `.5`, `5.`),
/// scientific (`1e-3`, `2.5E+2`) or fraction of two integers (`-3/7`; a zero denominator is an
/// error). Surrounding whitespace is not accepted. NaN, infinities and anything else throw
/// NumberError naming the token.
Rational parse_rational(std::string_view text);

/// The same into an existing number (its storage reused; on an error it is left unspecified).
void parse_rational_into(std::string_view text, Rational& out);

/// Non-throwing variant: returns false (and leaves `out` untouched) on bad text.
bool try_parse_rational(std::string_view text, Rational& out);

/// Exact rational of a finite double (every double is a dyadic rational). Throws NumberError
/// for NaN or infinity.
Rational rational_from_double(double v);

/// Lowest-terms text: `"2"`, `"-3/4"`.
std::string to_string(const Rational& q);

/// Nearest double (round to nearest), for drawing only.
double to_double(const Rational& q);

}  // namespace hlr
