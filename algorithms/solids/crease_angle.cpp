// Exact crease test (see crease_angle.hpp).
#include "algorithms/solids/crease_angle.hpp"

#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hlr {
namespace {

// Sign of r - cos²(deg·π/180) for a rational r, with cos² irrational: enclose cos² in MPFR at
// growing precision. Error of cos(x̃) with x̃ = deg·π/180 rounded: |x̃ - x| <= 2^(4-p)·(1+|x|),
// cos is 1-Lipschitz, squaring at most doubles it: |c̃ - cos²x| <= 2^(8-p) for x <= π.
int compare_with_cos2(const Rational& r, const Rational& degrees) {
  for (mpfr_prec_t p = 128; p <= 1 << 16; p *= 2) {
    mpfr_t x, pi, c, q, err;
    mpfr_inits2(p, x, pi, c, q, err, static_cast<mpfr_ptr>(nullptr));
    mpfr_const_pi(pi, MPFR_RNDN);
    mpfr_set_q(x, degrees.get_mpq_t(), MPFR_RNDN);
    mpfr_mul(x, x, pi, MPFR_RNDN);
    mpfr_div_ui(x, x, 180, MPFR_RNDN);
    mpfr_cos(c, x, MPFR_RNDN);
    mpfr_sqr(c, c, MPFR_RNDN);
    mpfr_set_q(q, r.get_mpq_t(), MPFR_RNDN);  // |q - r| <= 2^-p·|r|, r <= 1
    mpfr_sub(q, q, c, MPFR_RNDN);
    mpfr_set_ui_2exp(err, 1, 10 - p, MPFR_RNDU);
    int s = 0;
    if (mpfr_cmpabs(q, err) > 0) s = mpfr_sgn(q);
    mpfr_clears(x, pi, c, q, err, static_cast<mpfr_ptr>(nullptr));
    if (s != 0) return s;
  }
  throw std::runtime_error("crease angle: cannot separate cos² from a rational (precision limit)");
}

}  // namespace

CreaseAngle::CreaseAngle(const Rational& degrees) : degrees_(degrees) {
  if (degrees < 0 || degrees > 180) throw std::invalid_argument("--crease must be an angle in degrees from 0 to 180");
  cos_ = std::cos(to_double(degrees) * M_PI / 180.0);
  cos_nonneg_ = degrees <= 90;
  // cos²(D) = (1 + cos 2D)/2 is rational iff cos 2D is, iff 2D is a multiple of 60 or 90 degrees.
  Rational twice = 2 * degrees;
  if (twice.get_den() == 1) {
    long a = twice.get_num().get_si() % 360;
    switch (a) {
      case 0: cos2_ = 1; rational_cos2_ = true; break;
      case 60: case 300: cos2_ = rational(3, 4); rational_cos2_ = true; break;
      case 90: case 270: cos2_ = rational(1, 2); rational_cos2_ = true; break;
      case 120: case 240: cos2_ = rational(1, 4); rational_cos2_ = true; break;
      case 180: cos2_ = 0; rational_cos2_ = true; break;
      default: break;
    }
  }
}

bool CreaseAngle::exceeds(const long n1[3], const long n2[3]) const {
  double a[3], b[3];
  for (int k = 0; k < 3; ++k) a[k] = static_cast<double>(n1[k]), b[k] = static_cast<double>(n2[k]);
  if (const int f = filter(a, b); f >= 0) return f == 1;
  mpz_class x[3], y[3];
  for (int k = 0; k < 3; ++k) x[k] = n1[k], y[k] = n2[k];
  return exceeds_exact(x, y);
}

bool CreaseAngle::exceeds(const mpz_class n1[3], const mpz_class n2[3]) const {
  // Normals of any size (exact cut points make them huge) as doubles with their exponents
  // kept apart, so that none overflows to infinity; filter() scales each by a power of two.
  double a[3], b[3];
  auto doubles = [](const mpz_class n[3], double out[3]) {
    std::size_t bits = 0;
    for (int k = 0; k < 3; ++k) bits = std::max(bits, mpz_sizeinbase(n[k].get_mpz_t(), 2));
    const long shift = static_cast<long>(bits) - 60;
    for (int k = 0; k < 3; ++k) {
      long e = 0;
      const double m = mpz_get_d_2exp(&e, n[k].get_mpz_t());
      out[k] = std::ldexp(m, static_cast<int>(e - shift));
    }
  };
  doubles(n1, a);
  doubles(n2, b);
  if (const int f = filter(a, b); f >= 0) return f == 1;
  return exceeds_exact(n1, n2);
}

int CreaseAngle::filter(const double n1[3], const double n2[3]) const {
  // Each normal is scaled by a power of two (exact; the angle does not change by it) so that
  // its largest component lies in [1, 2): no product below overflows or underflows. Each
  // input is within 2^-52 (relative), the dot product, norms, square root and division add a
  // few roundings more, so the computed cosine is within about 1e-15 of the exact one (and
  // cos_ within 1e-16 of cos(DEG)); a gap over 1e-9 decides, anything closer goes to the exact
  // test. A component so small against the largest that it underflows only errs by 2^-1074.
  double a[3], b[3];
  auto unit = [](const double n[3], double out[3]) {
    const double big = std::max({std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2])});
    if (!(big > 0) || !std::isfinite(big)) return false;
    int e = 0;
    std::frexp(big, &e);
    for (int k = 0; k < 3; ++k) out[k] = std::ldexp(n[k], 1 - e);
    return true;
  };
  if (!unit(n1, a) || !unit(n2, b)) return -1;
  const double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const double l = std::sqrt((a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
  const double c = d / l;
  if (std::isfinite(c) && std::fabs(c - cos_) > 1e-9) return c < cos_ ? 1 : 0;
  return -1;
}

bool CreaseAngle::exceeds_exact(const mpz_class n1[3], const mpz_class n2[3]) const {
  mpz_class d = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
  mpz_class l1 = n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2];
  mpz_class l2 = n2[0] * n2[0] + n2[1] * n2[1] + n2[2] * n2[2];
  int sd = sgn(d);
  // angle > DEG  <=>  cos(angle) < cos(DEG).
  if (cos_nonneg_) {
    if (sd < 0) return true;
    if (sd == 0) return degrees_ < 90;
  } else if (sd >= 0) {
    return false;
  }
  Rational r(mpz_class(d * d), mpz_class(l1 * l2));
  r.canonicalize();
  int s = rational_cos2_ ? (r < cos2_ ? -1 : r > cos2_ ? 1 : 0) : compare_with_cos2(r, degrees_);
  // cos >= 0 branch: cos(angle) < cos(DEG) <=> r < cos²; cos < 0 branch: <=> r > cos².
  return cos_nonneg_ ? s < 0 : s > 0;
}

}  // namespace hlr
