// The fixed-width exact paths at their bounds (kernel/exact_int.hpp): the same scene
// just inside and just outside each bound gives exactly the same drawing (every path exact),
// and the split-parameter filter never decides on values beyond the double range.
#include "kernel/exact_int.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "algorithms/hlr/face_occluders.hpp"
#include "kernel/fixed_int.hpp"
#include "support/torus.hpp"

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
// the 128-bit path, 2^38 just inside its 2^40, 2^40 to 2^136 in the multi-limb path (2^136
// just inside its 2^150), 2^137 and beyond on GMP.
TEST(ExactInt, EachPathAtItsBoundGivesTheSameDrawing) {
  const std::string unit = scene_at(1);
  ASSERT_NE(unit.find(" h "), std::string::npos);  // something is hidden
  ASSERT_NE(unit.find(" v "), std::string::npos);
  for (int e : {25, 26, 27, 28, 36, 37, 38, 39, 40, 41, 70, 127, 128, 135, 136, 137, 138, 300})
    EXPECT_EQ(scene_at(pow2(e)), unit) << "scaled by 2^" << e;
  // Small scales: denominators instead of large numerators.
  for (int e : {40, 100, 136, 140}) EXPECT_EQ(scene_at(1 / pow2(e)), unit) << "scaled by 2^-" << e;
  EXPECT_EQ(scene_at(Rational(1, 3)), unit);
  // Mixed: ten digits with noise near 1e-17 (an exporter's %.10g): the multi-limb path.
  EXPECT_EQ(scene_at(Rational(mpz_class("1000000000000000000000000037"), mpz_class("100000000000000000000000000"))), scene_at(1));
}

namespace {

// A random WideInt<4> value of 0-4 limbs (often small, often equal to another) and its mpz.
mpz_class random_value(std::mt19937_64& rng, int max_limbs) {
  mpz_class v = 0;
  const int limbs = static_cast<int>(rng() % static_cast<unsigned>(max_limbs + 1));
  for (int k = 0; k < limbs; ++k) {
    v <<= 64;
    const std::uint64_t w = rng() % 4 == 0 ? ~std::uint64_t(0) : rng();  // all-ones limbs carry
    v += mpz_class(static_cast<unsigned long>(w));
  }
  if (rng() % 2) v = -v;
  return v;
}

}  // namespace

// The fixed-width integers against GMP: sums, differences, products, negation, equality, the
// order of products and the doubles, on random values of every size up to the width
// (carries across all limbs, equal magnitudes, zero); a result beyond the width throws.
TEST(ExactInt, WideIntegersAgreeWithGmp) {
  using W4 = WideInt<4>;
  using W8 = WideInt<8>;
  std::mt19937_64 rng(20261204);
  for (int i = 0; i < 20000; ++i) {
    const mpz_class a = random_value(rng, 3), b = rng() % 8 == 0 ? a : (rng() % 8 == 0 ? mpz_class(-a) : random_value(rng, 3));
    const W4 wa(a.get_mpz_t()), wb(b.get_mpz_t());
    ASSERT_EQ(wa.to_mpz(), a);
    EXPECT_EQ((wa + wb).to_mpz(), a + b) << a << " + " << b;
    EXPECT_EQ((wa - wb).to_mpz(), a - b) << a << " - " << b;
    EXPECT_EQ((-wa).to_mpz(), -a);
    W4 acc = wa;
    acc += wb;
    EXPECT_EQ(acc.to_mpz(), a + b);
    acc = wa;
    acc += acc;
    EXPECT_EQ(acc.to_mpz(), a + a);
    EXPECT_EQ(wa == wb, a == b);
    EXPECT_EQ(wa.sign(), sgn(a));
    // The double within 2^-52 of the value, relative, and exact below 2^53; the bit length.
    const mpq_class err = abs(mpq_class(wa.to_double()) - mpq_class(a)), allowed = mpq_class(abs(a)) / mpq_class(mpz_class(1) << 52);
    EXPECT_LE(err, allowed) << a;
    if (mpz_sizeinbase(a.get_mpz_t(), 2) <= 53) {
      EXPECT_EQ(wa.to_double(), a.get_d());
    }
    EXPECT_EQ(wa.bits(), a == 0 ? 0 : static_cast<int>(mpz_sizeinbase(a.get_mpz_t(), 2)));
    // From 128 bits, both signs.
    const Int128 big = (Int128(static_cast<std::int64_t>(rng() >> 2)) << 62) + static_cast<std::int64_t>(rng() >> 2);
    EXPECT_EQ(W4(big).to_mpz(), to_mpz(big));
    EXPECT_EQ(W4(-big).to_mpz(), -to_mpz(big));
    EXPECT_EQ(W4(-big).to_int128(), -big);
    if (wa.bits() > 127) {
      EXPECT_THROW(wa.to_int128(), std::logic_error);
    }
    const mpz_class c = random_value(rng, 2), d = random_value(rng, 2);
    const W4 wc(c.get_mpz_t()), wd(d.get_mpz_t());
    const W8 pab = W8::product(wa, wb), pcd = W8::product(wc, wd);
    EXPECT_EQ(pab.to_mpz(), a * b);
    const int want = cmp(a * b, c * d);
    EXPECT_EQ(W4::compare_products(wa, wb, wc, wd), (want > 0) - (want < 0));
    EXPECT_EQ(W8::compare_products(pab, W8(1), pcd, W8(1)), (want > 0) - (want < 0));
    EXPECT_EQ(W4::compare_products(wa, wb, wa, wb), 0);
    // Products in line (up to 3 limbs a side) and by mpn_mul (4 limbs).
    const mpz_class e = random_value(rng, 4), f = random_value(rng, 4);
    EXPECT_EQ(W8::product(W4(e.get_mpz_t()), W4(f.get_mpz_t())).to_mpz(), e * f) << e << " * " << f;
  }
  mpz_class top = 1;
  top <<= 255;
  const W4 t(top.get_mpz_t());
  EXPECT_THROW(t + t, std::logic_error);
  EXPECT_THROW(t * W4(2), std::logic_error);
  EXPECT_EQ((t - t).sign(), 0);
  mpz_class five_limbs = 1;
  five_limbs <<= 256;
  EXPECT_THROW(W4(five_limbs.get_mpz_t()), std::logic_error);
}

// Sums, differences and doubles at every width the engine uses: the in-line limb loops (up to
// five limbs), GMP's beyond, carries and borrows through runs of all-ones limbs, and doubles
// of values up to 19 limbs (scaled by the table of powers of two, then beyond the range).
TEST(ExactInt, WideSumsAndDoublesAtEveryWidthAgreeWithGmp) {
  using W20 = WideInt<20>;
  std::mt19937_64 rng(20261205);
  const mpq_class two52 = mpq_class(mpz_class(1) << 52);
  int infinite = 0;
  for (int i = 0; i < 20000; ++i) {
    const int la = 1 + static_cast<int>(rng() % 9), lb = 1 + static_cast<int>(rng() % 9);
    const mpz_class a = random_value(rng, la), b = rng() % 8 == 0 ? mpz_class(-a + 1) : random_value(rng, lb);
    const W20 wa(a.get_mpz_t()), wb(b.get_mpz_t());
    EXPECT_EQ((wa + wb).to_mpz(), a + b) << a << " + " << b;
    EXPECT_EQ((wa - wb).to_mpz(), a - b) << a << " - " << b;
    W20 acc = wa;
    acc += wb;
    EXPECT_EQ(acc.to_mpz(), a + b);
    const mpz_class big = random_value(rng, 19);
    const double d = W20(big.get_mpz_t()).to_double();
    const std::size_t bits = mpz_sizeinbase(big.get_mpz_t(), 2);
    if (std::isinf(d)) {  // beyond the range, or rounded up to 2^1024
      EXPECT_GE(bits, 1024u) << big;
      ++infinite;
    } else {
      EXPECT_LE(bits, 1024u) << big;
      EXPECT_LE(abs(mpq_class(d) - mpq_class(big)), mpq_class(abs(big)) / two52) << big;
    }
  }
  EXPECT_GT(infinite, 100);
  // A carry out of five all-ones limbs into a sixth; a borrow through four zero limbs.
  mpz_class ones = (mpz_class(1) << 320) - 1, one = 1;
  EXPECT_EQ((WideInt<6>(ones.get_mpz_t()) + WideInt<6>(one.get_mpz_t())).to_mpz(), ones + 1);
  const mpz_class power = mpz_class(1) << 256;
  EXPECT_EQ((WideInt<5>(power.get_mpz_t()) - WideInt<5>(one.get_mpz_t())).to_mpz(), power - 1);
}

namespace {

// A value of at most `bits` bits (either sign), often with all-ones or zero runs, or at the
// bound itself.
mpz_class random_bits(std::mt19937_64& rng, int bits) {
  mpz_class v = random_value(rng, (bits + 63) / 64);
  v = abs(v) % (mpz_class(1) << bits);
  if (rng() % 16 == 0) v = (mpz_class(1) << bits) - 1;                             // the largest magnitude
  if (rng() % 16 == 0) v = mpz_class(1) << (rng() % static_cast<unsigned>(bits));  // a power of two
  if (rng() % 2) v = -v;
  return v;
}

template <int N>
mpz_class fixed_value(const FixedInt<N>& x) {
  mpz_class v = 0;
  for (int i = N - 1; i >= 0; --i) v = (v << 64) + mpz_class(static_cast<unsigned long>(x.limb[i]));
  if (x.negative()) v -= mpz_class(1) << (64 * N);
  return v;
}

Int128 to_int128(const mpz_class& v) {
  const mpz_class m = abs(v);
  const auto lo = static_cast<UInt128>(mpz_class(m % (mpz_class(1) << 64)).get_ui());
  const auto hi = static_cast<UInt128>(mpz_class(m >> 64).get_ui());
  const Int128 r = static_cast<Int128>(hi << 64 | lo);
  return v < 0 ? -r : r;
}

}  // namespace

// The two's-complement widths of the multi-limb path's fixed constructions against GMP, at their
// bounds: 128-bit values below 2^126 and their products, 256-bit values below 2^253 times
// 128-bit ones, sums and differences, negation, signs, the doubles (bit for bit WideInt's) and
// the WideInt made from each.
TEST(ExactInt, FixedWidthsAgreeWithGmpAndWideIntAtTheirBounds) {
  std::mt19937_64 rng(20261206);
  for (int i = 0; i < 20000; ++i) {
    const mpz_class a = random_bits(rng, 126), b = random_bits(rng, 126), c = random_bits(rng, 126), d = random_bits(rng, 126);
    const FixedInt<2> fa(to_int128(a)), fb(to_int128(b)), fc(to_int128(c)), fd(to_int128(d));
    ASSERT_EQ(fixed_value(fa), a);
    const FixedInt<4> p = mul(fa, fb) - mul(fc, fd);  // a cross product's component
    ASSERT_EQ(fixed_value(p), a * b - c * d) << a << " " << b << " " << c << " " << d;
    ASSERT_EQ(fixed_value(mul(fa, fb) + mul(fc, fd)), a * b + c * d);
    const mpz_class n = a * b - c * d;
    ASSERT_EQ(fixed_value(p.negated()), -n);
    ASSERT_EQ(p.sign(), sgn(n));
    const mpz_class e = random_bits(rng, 253);
    FixedInt<4> fe;
    {
      const mpz_class m = abs(e);
      for (int k = 0; k < 4; ++k) fe.limb[k] = mpz_class((m >> (64 * k)) % (mpz_class(1) << 64)).get_ui();
      if (e < 0) fe = fe.negated();
    }
    ASSERT_EQ(fixed_value(fe), e);
    const FixedInt<6> q = mul(fe, fa) + mul(p, fb) - mul(fe, fc);  // a plane value
    const mpz_class qv = e * a + n * b - e * c;
    ASSERT_EQ(fixed_value(q), qv) << e << " " << a;
    ASSERT_EQ(q.sign(), sgn(qv));
    // The doubles and the WideInts are WideInt's own of the same numbers.
    EXPECT_EQ(std::bit_cast<std::uint64_t>(p.to_double()), std::bit_cast<std::uint64_t>(WideInt<5>(n.get_mpz_t()).to_double())) << n;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(q.to_double()), std::bit_cast<std::uint64_t>(WideInt<10>(qv.get_mpz_t()).to_double())) << qv;
    EXPECT_EQ(p.to_wide<5>().to_mpz(), n);
    EXPECT_EQ(q.to_wide<10>().to_mpz(), qv);
    // The cross product and the dot product the occluders are made with.
    const std::array<mpz_class, 3> u = {a, b, random_bits(rng, 126)}, w = {c, d, random_bits(rng, 126)};
    const std::array<Int128, 3> ui = {to_int128(u[0]), to_int128(u[1]), to_int128(u[2])}, wi = {to_int128(w[0]), to_int128(w[1]), to_int128(w[2])};
    const std::array<FixedInt<4>, 3> x = fixed_cross(ui, wi);
    const std::array<mpz_class, 3> xv = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(fixed_value(x[k]), xv[k]) << k << ": " << u[0] << " " << u[1] << " " << u[2] << " x " << w[0] << " " << w[1] << " " << w[2];
    const std::array<mpz_class, 3> z = {random_bits(rng, 126), random_bits(rng, 126), random_bits(rng, 126)};
    ASSERT_EQ(fixed_value(fixed_dot(x, {to_int128(z[0]), to_int128(z[1]), to_int128(z[2])})), xv[0] * z[0] + xv[1] * z[1] + xv[2] * z[2]);
    ASSERT_EQ(fixed_dot(x, ui).sign(), 0);  // (u x w)·u
    ASSERT_EQ(fixed_value(fixed_dot({fe, p, fe.negated()}, wi)), e * w[0] + n * w[1] - e * w[2]);
    // An orthographic direction below 2^62 across an edge: the 64-bit factors' cross product.
    const std::array<mpz_class, 3> dv = {random_bits(rng, 62), random_bits(rng, 62), random_bits(rng, 62)};
    const std::array<std::int64_t, 3> di = {dv[0].get_si(), dv[1].get_si(), dv[2].get_si()};
    const std::array<FixedInt<4>, 3> y = fixed_cross(di, wi);
    const std::array<mpz_class, 3> yv = {dv[1] * w[2] - dv[2] * w[1], dv[2] * w[0] - dv[0] * w[2], dv[0] * w[1] - dv[1] * w[0]};
    for (int k = 0; k < 3; ++k) ASSERT_EQ(fixed_value(y[k]), yv[k]) << k << ": " << dv[0] << " " << dv[1] << " " << dv[2] << " x " << w[0];
    ASSERT_EQ(fixed_dot(y, wi).sign(), 0);  // (d x w)·w
  }
  EXPECT_EQ(FixedInt<4>().to_double(), 0.0);
  EXPECT_FALSE(std::signbit(FixedInt<4>().negated().to_double()));  // +0, as WideInt's 0
}

// The 128-bit conversion rounds as the compiler's: to nearest, ties to even, also where the tie
// is decided by a bit far below the top 64 (every lower bit folded into one).
TEST(ExactInt, DoublesOf128BitWordsRoundAsTheCompilers) {
  std::mt19937_64 rng(1205);
  auto check = [](std::uint64_t hi, std::uint64_t lo) {
    const UInt128 v = static_cast<UInt128>(hi) << 64 | lo;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(uint128_to_double(hi, lo)), std::bit_cast<std::uint64_t>(static_cast<double>(v))) << hi << " " << lo;
  };
  for (int i = 0; i < 200000; ++i) {
    const int shift = static_cast<int>(rng() % 64);
    const std::uint64_t hi = (rng() >> shift) | 1;
    std::uint64_t lo = rng();
    switch (rng() % 4) {
      case 0:
        lo = 0;
        break;
      case 1:
        lo = std::uint64_t{1} << (rng() % 64);
        break;  // one bit far below
      case 2:
        lo = ~std::uint64_t{0} >> (rng() % 64);
        break;  // a run of ones
      default:
        break;
    }
    check(hi, lo);
    // Ties at the rounding place of the top 64 bits: 1 then zeros below it, with and without a
    // set bit further down.
    const int s = __builtin_clzll(hi);
    if (s <= 10) {
      const std::uint64_t round = std::uint64_t{1} << (10 - s);
      check((hi & ~((round << 1) - 1)) | round, 0);
      check((hi & ~((round << 1) - 1)) | round, 1);
    }
  }
  check(~std::uint64_t{0}, ~std::uint64_t{0});  // rounds up to 2^128
  check(1, 0);
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

namespace {

// A torus (24 x 12 quads as triangles, corners rounded to 1/1024) and a box through its ring,
// every coordinate times k; drawn orthographic along two directions and in perspective from an
// eye in the hole and one 1/2048 below the box's bottom face, all edges with intersection lines.
std::string curved_at(const Rational& k) {
  const Polyhedron torus = test::torus_mesh(24, 12, 3, 1, [&](double x) -> Rational {
    Rational q(static_cast<long>(std::lround(x * 1024)), 1024);
    q.canonicalize();
    return q * k;
  });
  Polyhedron box = make_box(Point3(Rational(5, 2) * k, Rational(-1, 2) * k, Rational(-2) * k), Point3(Rational(7, 2) * k, Rational(1, 2) * k, 2 * k));
  LineOptions o;
  o.edges = EdgeSelection::All;
  std::string out;
  for (const Camera& cam : {make_orthographic(Vector3(1, 2, 3)), make_orthographic(Vector3(0, 0, 1)),
                            make_perspective(Point3(0, Rational(1, 3) * k, Rational(1, 5) * k), Point3(3 * k, 0, 0)),
                            make_perspective(Point3(3 * k, Rational(1, 7) * k, Rational(-4097, 2048) * k), Point3(3 * k, 0, 0))})
    out += pieces_of(face_occluders({&torus, &box}, cam, o)) + "|";
  return out;
}

// The torus and box of curved_at (the box inside out), one vertex in 16 of the torus moved by
// 3·10^-26 in z (an exporter's near-zero noise, off the grid of 1/1024 that the others keep),
// all times k; drawn
// along two directions and from an eye in the hole on the grid and one off it, every edge and
// the creases over 20 degrees. `integer`: every drawing took an integer path (not GMP).
std::string noisy_at(const Rational& k, bool& integer) {
  const Polyhedron base = test::torus_mesh(24, 12, 3, 1, [](double x) {
    Rational q(static_cast<long>(std::lround(x * 1024)), 1024);
    q.canonicalize();
    return q;
  });
  mpz_class ten26;
  mpz_ui_pow_ui(ten26.get_mpz_t(), 10, 26);
  const Rational noise(mpz_class(3), ten26);
  std::vector<Point3> vs = base.vertices();
  for (std::size_t i = 0; i < vs.size(); ++i) vs[i] = Point3(vs[i][0] * k, vs[i][1] * k, (i % 16 == 5 ? vs[i][2] + noise : vs[i][2]) * k);
  const Polyhedron torus(vs, base.faces());
  const Polyhedron cube =
      make_box(Point3(Rational(5, 2) * k, Rational(-1, 2) * k, Rational(-2) * k), Point3(Rational(7, 2) * k, Rational(1, 2) * k, 2 * k));
  std::vector<Face> inside_out = cube.faces();  // turned by the engine (its normals negated)
  for (Face& f : inside_out) std::reverse(f.begin(), f.end());
  const Polyhedron box(cube.vertices(), inside_out);
  std::string out;
  integer = true;
  for (EdgeSelection edges : {EdgeSelection::All, EdgeSelection::Feature}) {
    LineOptions o;
    o.edges = edges;
    o.crease_degrees = 20;
    for (const Camera& cam : {make_orthographic(Vector3(1, 2, 3)), make_orthographic(Vector3(0, 0, 1)),
                              make_perspective(Point3(0, Rational(1, 4) * k, Rational(1, 8) * k), Point3(3 * k, 0, 0)),
                              make_perspective(Point3(3 * k, Rational(1, 7) * k, Rational(-4097, 2048) * k), Point3(3 * k, 0, 0))}) {
      const LineDrawing r = face_occluders({&torus, &box}, cam, o);
      integer = integer && r.stats.faces && r.stats.faces->integer_path;
      out += pieces_of(r) + "|";
    }
  }
  return out;
}

}  // namespace

// A curved mesh on the multi-limb path with a grid (face_engine.hpp, Prepared::on_grid): the
// noisy corners' faces keep long normals (FaceNormals), the others take normals, side planes
// and crease angles from the grid's small integers. Its drawing equals GMP's without a grid
// (the same scene times 2^-160: no vertex's denominator stays below 2^62) exactly.
TEST(ExactInt, NoisyCurvedMeshOnTheGridDrawsAsOnGmp) {
  bool integer = false, gmp_integer = true;
  const std::string wide = noisy_at(1, integer);
  EXPECT_TRUE(integer);
  ASSERT_NE(wide.find(" h "), std::string::npos);
  EXPECT_EQ(noisy_at(1 / pow2(160), gmp_integer), wide);
  EXPECT_FALSE(gmp_integer);
}

// A curved mesh (many triangles sharing vertices and sides with the segments they hide, the
// multi-limb path's filter cases), interpenetrated by a box: the 64-bit path's drawing equals the
// multi-limb path's (scaled by 2^-70 and 2^-100) and GMP's (2^-160) exactly.
TEST(ExactInt, CurvedMeshDrawsAlikeOnEveryPath) {
  const std::string fast = curved_at(1);
  ASSERT_NE(fast.find(" h "), std::string::npos);
  for (int e : {70, 100, 160}) EXPECT_EQ(curved_at(1 / pow2(e)), fast) << "scaled by 2^-" << e;
}

namespace {

// Two tori in one body, the second inside out (a component the engine turns), and a third
// torus wholly inside out (a solid the engine turns), every coordinate on 1/1024 times k;
// drawn along two directions and from an eye in the first ring, every edge and the creases
// over 20 degrees: the pieces, each face's facing and the notes. Triangles only, so that
// the multi-limb path without a grid keeps only the doubles of the normals (FaceNormals,
// lazy) and makes each exact normal again when a facing or crease test needs it.
std::string turned_tori_at(const Rational& k) {
  auto on_grid = [&](double x) -> Rational {  // (a Rational: not an expression on the local q)
    Rational q(static_cast<long>(std::lround(x * 1024)), 1024);
    q.canonicalize();
    return q * k;
  };
  const Polyhedron a = test::torus_mesh(16, 8, 3, 1, on_grid);
  const Polyhedron b = test::torus_mesh(12, 6, 2, 0.5, on_grid);
  std::vector<Point3> vs = a.vertices();
  std::vector<Face> fs = a.faces();
  const int off = static_cast<int>(vs.size());
  for (const Point3& p : b.vertices()) vs.emplace_back(p[0] + 9 * k, p[1], p[2]);
  for (Face f : b.faces()) {
    std::reverse(f.begin(), f.end());
    for (int& v : f) v += off;
    fs.push_back(f);
  }
  const Polyhedron pair(vs, fs);
  std::vector<Point3> ws;
  for (const Point3& p : a.vertices()) ws.emplace_back(p[0], p[1] + 8 * k, p[2] + k);
  std::vector<Face> turned = a.faces();
  for (Face& f : turned) std::reverse(f.begin(), f.end());
  const Polyhedron inside_out(ws, turned);
  std::string out;
  for (EdgeSelection edges : {EdgeSelection::All, EdgeSelection::Feature}) {
    LineOptions o;
    o.edges = edges;
    o.crease_degrees = 20;
    for (const Camera& cam : {make_orthographic(Vector3(1, 2, 3)), make_orthographic(Vector3(0, -1, 4)),
                              make_perspective(Point3(0, Rational(1, 4) * k, Rational(1, 8) * k), Point3(3 * k, 0, 0))}) {
      const LineDrawing r = face_occluders({&pair, &inside_out}, cam, o);
      out += pieces_of(r);
      for (const auto& body : r.facing)
        for (signed char f : body) out += std::to_string(f);
      for (const BodyNote& n : r.notes) out += std::to_string(n.body) + n.text;
      out += "|";
    }
  }
  return out;
}

}  // namespace

// Turned components and solids on every path: the multi-limb path without a grid (2^-100:
// denominators of 2^110) keeps only its normals' doubles and their turns, and draws as the
// 64-bit path and GMP (2^-160) do, facing, creases and notes alike.
TEST(ExactInt, TurnedBodiesWithLazyNormalsDrawAlikeOnEveryPath) {
  const std::string fast = turned_tori_at(1);
  ASSERT_NE(fast.find(" h "), std::string::npos);
  ASSERT_NE(fast.find("inside-out component"), std::string::npos);
  for (int e : {100, 160}) EXPECT_EQ(turned_tori_at(1 / pow2(e)), fast) << "scaled by 2^-" << e;
}
