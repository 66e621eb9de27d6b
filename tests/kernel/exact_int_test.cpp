// The fixed-width exact paths at their bounds (kernel/exact_int.hpp): the same scene
// just inside and just outside each bound gives exactly the same drawing (every path exact),
// and the split-parameter filter never decides on values beyond the double range.
#include <gtest/gtest.h>

#include "algorithms/hlr/face_occluders.hpp"
#include "kernel/exact_int.hpp"

using namespace hlr;

namespace {

std::string pieces_of(const LineDrawing& r) {
  std::string out;
  for (const Segment& s : r.segments) {
    out += std::to_string(s.v0) + "-" + std::to_string(s.v1) + ":";
    for (const Piece& p : s.pieces) out += (p.visible ? " v " : " h ") + to_string(p.t0) + ".." + to_string(p.t1);
    out += "\n";
  }
  return out;
}

// A box and a rod in front of it, scaled by k: the pieces do not depend on k.
std::string scene_at(const Rational& k) {
  Polyhedron cube = make_box(Point3(0, 0, 0), Point3(2 * k, 2 * k, 2 * k));
  Polyhedron rod = make_box(Point3(-k, -k, k / 2), Point3(3 * k, k / 2, k));
  LineOptions o;
  o.edges = EdgeSelection::All;
  return pieces_of(face_occluders({&cube, &rod}, make_perspective(Point3(5 * k, -7 * k, 6 * k), Point3(k, k, k)), o)) +
         pieces_of(face_occluders({&cube, &rod}, make_orthographic(Vector3(1, -2, 3)), o));
}

Rational pow2(int e) {
  Rational r = 1;
  mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
  return r;
}

}  // namespace

// Coordinates reach about 7k: k = 2^26 stays below 2^29 (the 64-bit path), 2^27 and 2^37 are in
// the 128-bit path, 2^38 just inside its 2^40, 2^40 and beyond on GMP.
TEST(ExactInt, EachPathAtItsBoundGivesTheSameDrawing) {
  const std::string unit = scene_at(1);
  ASSERT_NE(unit.find(" h "), std::string::npos);  // something is hidden
  ASSERT_NE(unit.find(" v "), std::string::npos);
  for (int e : {25, 26, 27, 28, 36, 37, 38, 39, 40, 41, 70, 300})
    EXPECT_EQ(scene_at(pow2(e)), unit) << "scaled by 2^" << e;
  // Small scales: denominators instead of large numerators.
  EXPECT_EQ(scene_at(1 / pow2(40)), unit);
  EXPECT_EQ(scene_at(Rational(1, 3)), unit);
}

// GMP ratios beyond the double range: 3·10^400 / 10^300 against 10^101. Dividing the doubles
// (inf / 1e300) would call the first one larger; it is 3·10^100.
TEST(ExactInt, SplitFilterNeverDecidesBeyondTheDoubles) {
  mpz_class big, den, other;
  mpz_ui_pow_ui(big.get_mpz_t(), 10, 400);
  big *= 3;
  mpz_ui_pow_ui(den.get_mpz_t(), 10, 300);
  mpz_ui_pow_ui(other.get_mpz_t(), 10, 101);
  Frac<Big> a{big, den, Big::ratio(big, den)}, b{other, mpz_class(1), Big::ratio(other, mpz_class(1))};
  ComparisonCounters c;
  EXPECT_EQ(compare(a, b, c), -1);
  EXPECT_EQ(compare(b, a, c), 1);
  EXPECT_NEAR(a.x, 3e100, 1e86);
  // Ratios beyond the doubles are left to the exact comparison.
  mpz_class huge;
  mpz_ui_pow_ui(huge.get_mpz_t(), 10, 500);
  Frac<Big> h{huge, mpz_class(1), Big::ratio(huge, mpz_class(1))}, h2{huge + 1, mpz_class(1), Big::ratio(huge + 1, mpz_class(1))};
  std::size_t before = c.exact;
  EXPECT_EQ(compare(h, h2, c), -1);
  EXPECT_EQ(c.exact, before + 1);
}
