// Face planes in 128-bit integers (kernel/plane_int128.hpp) against the rational route, the
// 128-bit gcd and bit length against GMP, and the picture plane's depth doubles
// (PicturePlane::depth_doubles) against the exact depth, within their stated bound.
#include "kernel/plane_int128.hpp"

#include <gtest/gtest.h>

#include <random>

#include "algorithms/picture/picture_plane.hpp"
#include "kernel/polyhedron.hpp"

using namespace hlr;

namespace {

Rational ratio(long n, long d) {
  Rational q(n);
  q /= d;
  return q;
}

// A random polygon of 3 to 6 vertices with coordinates n / den, |n| below 2^bits; a few share
// a line (degenerate) or repeat.
std::vector<Point3> polygon(std::mt19937_64& rng, int bits, long den) {
  std::uniform_int_distribution<long> c(-(1L << bits) + 1, (1L << bits) - 1);
  const int n = 3 + static_cast<int>(rng() % 4);
  std::vector<Point3> out;
  for (int i = 0; i < n; ++i) out.emplace_back(ratio(c(rng), den), ratio(c(rng), den), ratio(c(rng), den));
  if (rng() % 8 == 0) out[2] = Point3(out[0].x() * 2 - out[1].x(), out[0].y() * 2 - out[1].y(), out[0].z() * 2 - out[1].z());
  if (n == 3 && rng() % 8 == 0) out[2] = out[0];
  return out;
}

}  // namespace

TEST(PlaneInt128, TheSamePlaneAsTheRationalRoute) {
  std::mt19937_64 rng(17);
  const long dens[] = {1, 2, 10, 1000, 10000000, 3 * 1024, 7 * 125};
  int made = 0, degenerate = 0, wide = 0;
  for (int it = 0; it < 4000; ++it) {
    const int bits = 4 + static_cast<int>(rng() % 36);
    const std::vector<Point3> v = polygon(rng, bits, dens[rng() % 7]);
    std::vector<const Point3*> p;
    for (const Point3& q : v) p.push_back(&q);
    const Plane want = primitive_plane(plane_of_polygon(p.data(), p.size()));
    PlaneInt128 h;
    if (!plane_int128(p.data(), p.size(), h)) continue;
    ++made;
    ASSERT_EQ(to_plane(h), want) << it;
    ASSERT_EQ(h.degenerate(), want.is_degenerate());
    degenerate += h.degenerate();
    const std::array<Bounds, 3> nb = normal_bounds(h);
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(nb[k].lo, want.approx(k).lo) << it;
      ASSERT_EQ(nb[k].hi, want.approx(k).hi) << it;
      wide += !(nb[k].lo == nb[k].hi);
    }
  }
  EXPECT_GT(made, 3000);
  EXPECT_GT(degenerate, 50);
  EXPECT_GT(wide, 100);  // coefficients beyond 2^53 take bounds_of's interval
}

TEST(PlaneInt128, FacePlaneIsThePolyhedronsPlane) {
  Polyhedron box = make_box(Point3(ratio(-1, 3), 0, ratio(1, 7)), Point3(2, ratio(5, 2), 3));
  for (std::size_t f = 0; f < box.num_faces(); ++f) {
    PlaneInt128 h;
    ASSERT_TRUE(face_plane_int128(box, f, h));
    EXPECT_EQ(to_plane(h), box.planes()[f]);
  }
}

TEST(Int128, GcdAndBitLengthAgreeWithGmp) {
  std::mt19937_64 rng(5);
  auto value = [&] {
    const int bits = static_cast<int>(rng() % 127);
    UInt128 u = (static_cast<UInt128>(rng()) << 64) | rng();
    u = bits == 0 ? 0 : u >> (128 - bits);
    u <<= rng() % 4 == 0 ? rng() % 8 : 0;
    u &= (static_cast<UInt128>(1) << 126) - 1;
    const Int128 v = static_cast<Int128>(u);
    return rng() % 2 ? -v : v;
  };
  for (int it = 0; it < 20000; ++it) {
    Int128 a = value(), b = value();
    if (it % 5 == 0) {  // a common factor
      const Int128 k = static_cast<Int128>(1 + rng() % 100000);
      a = (a >> 20) * k, b = (b >> 20) * k;
    }
    mpz_class g;
    mpz_gcd(g.get_mpz_t(), to_mpz(a).get_mpz_t(), to_mpz(b).get_mpz_t());
    ASSERT_EQ(to_mpz(gcd128(a, b)), g) << it;
    const int want = a == 0 ? 0 : static_cast<int>(mpz_sizeinbase(to_mpz(a).get_mpz_t(), 2));
    ASSERT_EQ(bit_length(a), want) << it;
  }
  EXPECT_EQ(gcd128(0, 0), 0);
  EXPECT_EQ(gcd128(0, -12), 12);
}

// The depth's doubles are within 5·kToDoubleError of the exact coefficients, its facing is the
// exact sign of n·v, and the 128-bit form gives the same numbers as the rational plane.
TEST(PicturePlane, DepthDoublesWithinTheirBound) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<long> small(-9, 9);
  int checked = 0, refused = 0, edge_on = 0;
  for (int it = 0; it < 3000; ++it) {
    Vector3 dir(ratio(small(rng), 1 + rng() % 7), ratio(small(rng), 1 + rng() % 5), ratio(1 + rng() % 9, 1 + rng() % 3));
    const PicturePlane pp(make_orthographic(dir));
    const int bits = 2 + static_cast<int>(rng() % 38);
    std::vector<Point3> v = polygon(rng, bits, rng() % 2 ? 1 : 1000);
    v.erase(v.begin() + 3, v.end());
    if (it % 50 == 0) v[2] = Point3(v[0].x() + dir.x(), v[0].y() + dir.y(), v[0].z() + dir.z());  // edge-on
    const Point3* p[3] = {&v[0], &v[1], &v[2]};
    PlaneInt128 hi;
    if (!plane_int128(p, 3, hi) || hi.degenerate()) continue;
    const Plane h = to_plane(hi);
    const PicturePlane::DepthDoubles d = pp.depth_doubles(h), d2 = pp.depth_doubles(hi);
    ASSERT_TRUE(d.integers && d2.integers);
    ASSERT_EQ(d.facing, d2.facing);
    ASSERT_EQ(d.ok, d2.ok);
    ASSERT_EQ(d.c, d2.c);
    const auto ray = pp.ray_parameter(h);
    ASSERT_EQ(d.facing, sgn(ray[1].c0)) << it;
    if (d.facing == 0) {
      ++edge_on;
      continue;
    }
    if (!d.ok) {
      ++refused;
      continue;
    }
    const Rational c[3] = {ray[0].c0 / ray[1].c0, ray[0].cx / ray[1].c0, ray[0].cy / ray[1].c0};
    for (int k = 0; k < 3; ++k) {
      const Rational err = abs(Rational(d.c[k]) - c[k]), bound = Rational(5 * kToDoubleError) * abs(c[k]);
      ASSERT_LE(err, bound) << it << " " << k;
    }
    ++checked;
  }
  EXPECT_GT(checked, 2000);
  EXPECT_GT(edge_on, 20);
  EXPECT_EQ(refused, 0);
  // A plane whose depth doubles would leave [2^-200, 2^200] is refused, never used.
  const PicturePlane pp(make_orthographic(Vector3(1, 2, 3)));
  mpz_class big = mpz_class(1) << 700;
  const Plane far(Rational(1), Rational(2), Rational(5), Rational(big));
  EXPECT_FALSE(pp.depth_doubles(far).ok);
  EXPECT_EQ(pp.depth_doubles(far).facing, 1);
  const PicturePlane persp(make_perspective(Point3(5, 5, 5), Point3(0, 0, 0)));
  EXPECT_FALSE(persp.depth_doubles(far).integers);
}
