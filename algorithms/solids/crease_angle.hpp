// Exact crease test for `--edges feature --crease DEG`: is the angle between two face
// normals greater than DEG degrees? cos(DEG) is irrational for most DEG (Niven's theorem), so
// the comparison n1·n2 < cos(DEG)·|n1|·|n2| is decided exactly: squared into rationals when
// cos²(DEG) is rational (DEG a multiple of 30 or 45 degrees), otherwise against an MPFR
// enclosure of cos²(DEG) whose precision grows until it separates (it always does: a rational
// never equals an irrational). A double filter decides almost every edge first.
#pragma once

#include "kernel/number.hpp"

namespace hlr {

class CreaseAngle {
 public:
  /// DEG in [0, 180]; throws std::invalid_argument otherwise.
  explicit CreaseAngle(const Rational& degrees);

  /// True iff the angle between the (non-zero) normals n1 and n2 exceeds the threshold. With
  /// a threshold of 0: iff the normals are not parallel with the same direction.
  bool exceeds(const mpz_class n1[3], const mpz_class n2[3]) const;
  bool exceeds(const long n1[3], const long n2[3]) const;
  /// The double filter alone, on doubles of the normals (each component within 2^-52 of the
  /// exact one, relative; each normal may be scaled by its own positive factor): 1 or 0 when
  /// it decides, -1 when the exact test must.
  int filter(const double n1[3], const double n2[3]) const;

  const Rational& degrees() const { return degrees_; }

 private:
  bool exceeds_exact(const mpz_class n1[3], const mpz_class n2[3]) const;

  Rational degrees_;
  double cos_ = 1;          // double cos(DEG), for the filter
  bool cos_nonneg_ = true;  // DEG <= 90
  bool rational_cos2_ = false;
  Rational cos2_;  // exact cos²(DEG) when rational
};

}  // namespace hlr
