// Exact parsing of numbers from text into GMP rationals (see number.hpp).
#include "kernel/number.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "kernel/int128.hpp"

namespace hlr {

NumberError::NumberError(std::string token, const std::string& why)
    : std::runtime_error("bad number '" + token + "': " + why), token_(std::move(token)) {}

namespace {

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

// Parses [+-]digits into an mpz. Returns false on bad text.
bool parse_integer(std::string_view s, mpz_class& out) {
  bool neg = false;
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
    neg = s[0] == '-';
    s.remove_prefix(1);
  }
  if (!all_digits(s)) return false;
  out.set_str(std::string(s), 10);
  if (neg) out = -out;
  return true;
}

// Eight ASCII digits from p (little-endian words; eight readable bytes): true and their value,
// the first digit the most significant, when all eight are digits. A byte is a digit when its
// high nibble is 3 and stays 3 after adding 6 (0x3A-0x3F reach 4); a carry out of a byte comes
// only from one that fails the test itself. Then pairs, then fours, then eight in one word:
// each step multiplies by the place values (10, 100, 10^4) with no carry between the fields.
bool eight_digits(const char* p, std::uint64_t& value) {
  if constexpr (std::endian::native != std::endian::little) {
    return false;
  } else {
    std::uint64_t w;
    std::memcpy(&w, p, 8);
    constexpr std::uint64_t kHigh = 0xF0F0F0F0F0F0F0F0ull;
    if (((w & kHigh) | (((w + 0x0606060606060606ull) & kHigh) >> 4)) != 0x3333333333333333ull) return false;
    w -= 0x3030303030303030ull;  // byte k: digit k
    w = w * 10 + (w >> 8);       // byte 2k: digits 2k, 2k + 1 (at most 99)
    constexpr std::uint64_t kPairs = 0x000000FF000000FFull;
    constexpr std::uint64_t kHundreds = 100 + (1000000ull << 32), kOnes = 1 + (10000ull << 32);
    value = ((w & kPairs) * kHundreds + ((w >> 16) & kPairs) * kOnes) >> 32;
    return true;
  }
}

// 5^k for k <= 27 (the largest below 2^64).
constexpr std::array<std::uint64_t, 28> kPowersOfFive = [] {
  std::array<std::uint64_t, 28> p{};
  p[0] = 1;
  for (std::size_t k = 1; k < p.size(); ++k) p[k] = p[k - 1] * 5;
  return p;
}();

// Fast path for the common decimal forms ("-0.0378297", "12", "3.5", an exporter's
// "6.123233995736766e-17" or numpy's "1.234567890123456789e-01"): at most 19 digits and an
// exponent of at most three digits. The value is an integer times a power of ten, reduced by
// its factors of 2 and 5 (the only ones it can share with a power of ten), so no general gcd
// and no string copies. False: not this form (the general parser decides, with its messages).
bool parse_decimal(std::string_view t, Rational& out) {
  std::size_t i = 0;
  bool neg = false;
  if (i < t.size() && (t[i] == '-' || t[i] == '+')) neg = t[i++] == '-';
  unsigned long long n = 0;  // at most 19 digits: below 10^19 < 2^64
  int digits = 0, frac = -1;
  // A run of digits: eight at a time while eight are left (and the 19 allow it), then one by one.
  auto run = [&](bool fraction) {
    for (std::uint64_t eight = 0; digits <= 11 && t.size() - i >= 8 && eight_digits(t.data() + i, eight); i += 8) {
      n = n * 100000000ull + eight;
      digits += 8;
      if (fraction) frac += 8;
    }
    for (; i < t.size() && t[i] >= '0' && t[i] <= '9'; ++i) {
      if (++digits > 19) return false;
      n = n * 10 + static_cast<unsigned long long>(t[i] - '0');
      if (fraction) ++frac;
    }
    return true;
  };
  if (!run(false)) return false;
  if (i < t.size() && t[i] == '.') {
    ++i;
    frac = 0;
    if (!run(true)) return false;
  }
  if (i < t.size() && t[i] != 'e' && t[i] != 'E') return false;
  if (digits == 0) return false;
  long e = 0;
  if (i < t.size()) {  // an exponent
    ++i;
    bool eneg = false;
    if (i < t.size() && (t[i] == '-' || t[i] == '+')) eneg = t[i++] == '-';
    int ed = 0;
    for (; i < t.size(); ++i, ++ed) {
      if (t[i] < '0' || t[i] > '9' || ed == 3) return false;
      e = e * 10 + (t[i] - '0');
    }
    if (ed == 0) return false;
    if (eneg) e = -e;
  }
  if (n == 0) {
    out = 0;
    return true;
  }
  const long p = e - (frac > 0 ? frac : 0);  // the value is n·10^p
  mpz_ptr num = out.get_num_mpz_t(), den = out.get_den_mpz_t();
  if (p >= 0) {
    mpz_ui_pow_ui(num, 10, static_cast<unsigned long>(p));
    mpz_mul_ui(num, num, n);
    mpz_set_ui(den, 1);
  } else {
    long twos = -p, fives = -p;
    const long z = std::min<long>(__builtin_ctzll(n), twos);
    n >>= z;
    twos -= z;
    while (fives > 0 && n % 5 == 0) n /= 5, --fives;
    mpz_set_ui(num, n);
    if (fives <= 27 && twos <= 63 - 2 * fives - fives / 3) {  // 5^fives·2^twos below 2^64
      mpz_set_ui(den, kPowersOfFive[static_cast<std::size_t>(fives)] << twos);
    } else if (fives <= 54 && twos <= 126 - 2 * fives - fives / 3) {  // below 2^128: two limbs (numpy's 10^23)
      const long low = std::min<long>(fives, 27);
      unsigned __int128 d =
          static_cast<unsigned __int128>(kPowersOfFive[static_cast<std::size_t>(low)]) * kPowersOfFive[static_cast<std::size_t>(fives - low)];
      d <<= twos;
      mp_limb_t* limbs = mpz_limbs_write(den, 2);
      limbs[0] = static_cast<mp_limb_t>(d), limbs[1] = static_cast<mp_limb_t>(d >> 64);
      mpz_limbs_finish(den, limbs[1] != 0 ? 2 : 1);
    } else {
      mpz_ui_pow_ui(den, 5, static_cast<unsigned long>(fives));
      mpz_mul_2exp(den, den, static_cast<mp_bitcnt_t>(twos));
    }
  }
  if (neg) mpz_neg(num, num);
  return true;
}

std::string parse_impl(std::string_view text, Rational& out) {
  if (text.empty()) return "empty";
  if (parse_decimal(text, out)) return {};
  {
    std::string low;
    for (char c : text.substr(0, 12)) low += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!low.empty() && (low[0] == '+' || low[0] == '-')) low.erase(0, 1);
    if (low == "nan" || low == "inf" || low == "infinity" || low.rfind("nan(", 0) == 0)
      return "not a finite number (NaN and infinities are not accepted)";
  }
  if (auto slash = text.find('/'); slash != std::string_view::npos) {
    mpz_class num, den;
    if (!parse_integer(text.substr(0, slash), num)) return "numerator is not an integer";
    std::string_view d = text.substr(slash + 1);
    if (d.empty() || d[0] == '+' || d[0] == '-' || !parse_integer(d, den))
      return "denominator is not a positive integer";
    if (den == 0) return "zero denominator";
    out = Rational(num, den);
    out.canonicalize();
    return {};
  }
  std::string_view s = text;
  bool neg = false;
  if (s[0] == '+' || s[0] == '-') {
    neg = s[0] == '-';
    s.remove_prefix(1);
  }
  std::string_view mant = s, expo;
  if (auto e = s.find_first_of("eE"); e != std::string_view::npos) {
    mant = s.substr(0, e);
    expo = s.substr(e + 1);
    if (expo.empty()) return "missing exponent";
  }
  std::string_view ip = mant, fp;
  if (auto dot = mant.find('.'); dot != std::string_view::npos) {
    ip = mant.substr(0, dot);
    fp = mant.substr(dot + 1);
  }
  if (ip.empty() && fp.empty()) return "no digits";
  if ((!ip.empty() && !all_digits(ip)) || (!fp.empty() && !all_digits(fp)))
    return "not a number (expected integer, decimal, scientific or fraction)";
  long e10 = 0;
  if (!expo.empty()) {
    std::string_view ed = expo;
    bool eneg = false;
    if (ed[0] == '+' || ed[0] == '-') {
      eneg = ed[0] == '-';
      ed.remove_prefix(1);
    }
    if (!all_digits(ed)) return "bad exponent";
    while (ed.size() > 1 && ed[0] == '0') ed.remove_prefix(1);
    if (ed.size() > 6) return "exponent out of range";
    e10 = std::stol(std::string(ed));
    if (e10 > kMaxDecimalExponent) return "exponent out of range";
    if (eneg) e10 = -e10;
  }
  mpz_class num;
  num.set_str(std::string(ip) + std::string(fp), 10);
  e10 -= static_cast<long>(fp.size());
  mpz_class pow10;
  mpz_ui_pow_ui(pow10.get_mpz_t(), 10, static_cast<unsigned long>(e10 < 0 ? -e10 : e10));
  if (e10 >= 0) {
    out = Rational(num * pow10);
  } else {
    out = Rational(num, pow10);
    out.canonicalize();
  }
  if (neg) out = -out;
  return {};
}

}  // namespace

static_assert(GMP_NUMB_BITS == 64, "limbs of 64 bits");

bool in_lowest_terms(const Rational& q) {
  mpz_srcptr n = q.get_num_mpz_t(), d = q.get_den_mpz_t();
  if (mpz_sgn(d) <= 0) return false;
  if (mpz_cmp_ui(d, 1) == 0) return true;
  if (mpz_sgn(n) == 0) return false;         // 0 is 0/1
  const mp_bitcnt_t twos = mpz_scan1(d, 0);  // d = 2^twos·r, r odd
  if (twos > 0 && mpz_even_p(n)) return false;
  if (mpz_sizeinbase(d, 2) - twos > 64) {  // r is long: GMP's gcd
    thread_local mpz_class g;
    mpz_gcd(g.get_mpz_t(), n, d);
    return mpz_cmp_ui(g.get_mpz_t(), 1) == 0;
  }
  const mp_size_t k = static_cast<mp_size_t>(twos / 64);  // r = d >> twos, from d's limbs k and k + 1
  const unsigned b = static_cast<unsigned>(twos % 64);
  const std::uint64_t r = b == 0 ? mpz_getlimbn(d, k) : (mpz_getlimbn(d, k) >> b) | (mpz_getlimbn(d, k + 1) << (64 - b));
  if (r == 1) return true;
  std::uint64_t f = r;  // a power of five (decimals): only 5 to test
  while (f % 5 == 0) f /= 5;
  if (f == 1) return !mpz_divisible_ui_p(n, 5);
  if (mpz_size(n) == 1) return gcd128(static_cast<Int128>(mpz_getlimbn(n, 0)), static_cast<Int128>(r)) == 1;  // binary gcd
  return mpz_gcd_ui(nullptr, n, r) == 1;
}

Rational parse_rational(std::string_view text) {
  Rational q;
  std::string why = parse_impl(text, q);
  if (!why.empty()) throw NumberError(std::string(text.substr(0, 64)), why);
  return q;
}

void parse_rational_into(std::string_view text, Rational& out) {
  std::string why = parse_impl(text, out);
  if (!why.empty()) throw NumberError(std::string(text.substr(0, 64)), why);
}

bool try_parse_rational(std::string_view text, Rational& out) {
  Rational q;
  if (!parse_impl(text, q).empty()) return false;
  out = q;
  return true;
}

Rational rational_from_double(double v) {
  if (!std::isfinite(v)) throw NumberError(std::isnan(v) ? "nan" : "inf", "not a finite number");
  return Rational(v);  // GMP converts a double exactly
}

std::string to_string(const Rational& q) { return q.get_str(10); }

namespace {

// to_double by one integer division: |q| = n/d; a = n·2^s / d truncated has 55 or 56 bits, its
// lowest bit or'ed with "remainder != 0" (sticky), so converting it to double rounds exactly
// as rounding n/d to 53 bits would; an exact tie (zero remainder, dropped bits 10..0) is
// truncated, toward zero, as the slow path decides ties. Then 2^-s scales exactly when the
// result is a normal double. False when it is not (subnormal or overflow): the slow path.
bool to_double_by_division(const Rational& q, double& out) {
  mpz_srcptr n = q.get_num_mpz_t(), d = q.get_den_mpz_t();
  if (mpz_sgn(n) == 0) return out = 0, true;
  const long nb = static_cast<long>(mpz_sizeinbase(n, 2)), db = static_cast<long>(mpz_sizeinbase(d, 2));
  if (nb <= 53 && db <= 53) return out = mpz_get_d(n) / mpz_get_d(d), true;  // both exact, one IEEE rounding
  const long s = 55 - nb + db;  // n·2^s / d lies in [2^54, 2^56)
  if (s > 1000 || s < -1000) return false;  // far outside the normal range
  mpz_class a, b, quo, rem;
  mpz_abs(a.get_mpz_t(), n);
  b = mpz_class(d);
  if (s >= 0) mpz_mul_2exp(a.get_mpz_t(), a.get_mpz_t(), static_cast<unsigned long>(s));
  else mpz_mul_2exp(b.get_mpz_t(), b.get_mpz_t(), static_cast<unsigned long>(-s));
  mpz_tdiv_qr(quo.get_mpz_t(), rem.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  std::uint64_t m = mpz_get_ui(quo.get_mpz_t());  // below 2^56
  const int drop = m >= (std::uint64_t{1} << 55) ? 3 : 2;  // bits below the 53 kept
  const std::uint64_t low = m & ((std::uint64_t{1} << drop) - 1);
  if (mpz_sgn(rem.get_mpz_t()) != 0) m |= 1;
  else if (low == std::uint64_t{1} << (drop - 1)) m -= low;  // an exact tie goes toward zero, as the slow path
  const double v = std::ldexp(static_cast<double>(m), static_cast<int>(-s));
  if (!(std::fabs(v) >= 0x1p-1022) || !std::isfinite(v)) return false;
  out = mpz_sgn(n) < 0 ? -v : v;
  return true;
}

}  // namespace

double to_double(const Rational& q) {
  double fast;
  if (to_double_by_division(q, fast)) return fast;
  // mpq_get_d truncates; round to nearest via the two neighbours' exact comparison.
  double d = q.get_d();
  if (!std::isfinite(d)) return d;
  double up = std::nextafter(d, HUGE_VAL), down = std::nextafter(d, -HUGE_VAL);
  Rational best(d), err = abs(q - best);
  for (double c : {up, down}) {
    if (!std::isfinite(c)) continue;
    Rational e = abs(q - Rational(c));
    if (e < err) {
      err = e;
      d = c;
    }
  }
  return d;
}

}  // namespace hlr
