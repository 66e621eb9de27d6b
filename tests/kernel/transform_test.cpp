// Homogeneous transforms, course notes section 20 (kernel/transform.hpp, kernel/rotation.hpp).
#include "kernel/transform.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/numbers.hpp"

using namespace hlr;

namespace {
using hlr::test::Q;
Point3 P(const char* x, const char* y, const char* z) { return Point3(Q(x), Q(y), Q(z)); }
Vector3 V(const char* x, const char* y, const char* z) { return Vector3(Q(x), Q(y), Q(z)); }
bool same(const Matrix4& a, const Matrix4& b) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (a(i, j) != b(i, j)) return false;
  return true;
}
const Rotation r34 = rotation_from_cos_sin(Rational(3, 5), Rational(4, 5));
}  // namespace

TEST(Transform, TranslationFormula) {
  Matrix4 t = translation(V("1/2", "-2", "0.1"));
  EXPECT_EQ(apply(t, P("1", "2", "3")), P("3/2", "0", "31/10"));
  EXPECT_EQ(t(3, 0), Q("1/2"));  // last row holds dx dy dz (row-vector convention)
}

TEST(Transform, ScalingAboutCentreFormula) {
  // x' = x*kx + (1-kx)*xm, etc.
  Matrix4 s = scaling(V("2", "1/2", "-1"), P("1", "1", "1"));
  Point3 p = P("3", "5", "7");
  EXPECT_EQ(apply(s, p), P("5", "3", "-5"));
  EXPECT_EQ(apply(s, P("1", "1", "1")), P("1", "1", "1"));  // the centre stays
}

TEST(Transform, RotationsAboutCentreMatchSeedFormulas) {
  const Point3 c = P("1", "2", "3"), p = P("4", "-1", "5");
  const Rational cs = r34.cos, sn = r34.sin;
  // OZ: x' = xc + (x-xc)cos - (y-yc)sin ; y' = yc + (x-xc)sin + (y-yc)cos
  EXPECT_EQ(apply(rotation(Axis::Z, r34, c), p),
            Point3(c.x() + (p.x() - c.x()) * cs - (p.y() - c.y()) * sn, c.y() + (p.x() - c.x()) * sn + (p.y() - c.y()) * cs, p.z()));
  // OX: y' = yc + (y-yc)cos - (z-zc)sin ; z' = zc + (z-zc)cos + (y-yc)sin
  EXPECT_EQ(apply(rotation(Axis::X, r34, c), p),
            Point3(p.x(), c.y() + (p.y() - c.y()) * cs - (p.z() - c.z()) * sn, c.z() + (p.z() - c.z()) * cs + (p.y() - c.y()) * sn));
  // OY: x' = xc + (x-xc)cos + (z-zc)sin ; z' = zc + (z-zc)cos - (x-xc)sin
  EXPECT_EQ(apply(rotation(Axis::Y, r34, c), p),
            Point3(c.x() + (p.x() - c.x()) * cs + (p.z() - c.z()) * sn, p.y(), c.z() + (p.z() - c.z()) * cs - (p.x() - c.x()) * sn));
}

TEST(Transform, RotationMatrixLayoutAsInNotes) {
  Matrix4 rz = rotation(Axis::Z, r34);
  EXPECT_EQ(rz(0, 0), Q("3/5"));
  EXPECT_EQ(rz(0, 1), Q("4/5"));
  EXPECT_EQ(rz(1, 0), Q("-4/5"));
  Matrix4 ry = rotation(Axis::Y, r34);
  EXPECT_EQ(ry(0, 2), Q("-4/5"));
  EXPECT_EQ(ry(2, 0), Q("4/5"));
}

TEST(Transform, ReflectionInCoordinatePlanes) {
  EXPECT_EQ(apply(reflection(Axis::X), P("2", "3", "4")), P("-2", "3", "4"));
  EXPECT_EQ(apply(reflection(Axis::Z, P("0", "0", "1")), P("2", "3", "4")), P("2", "3", "-2"));
  EXPECT_EQ(apply(scaling(V("-1", "-1", "-1")), P("2", "3", "4")), P("-2", "-3", "-4"));  // central symmetry
}

TEST(Transform, OnePointPerspective) {
  // Last column -1/C: w = 1 - z/C; with C = 10, z = 5: (x, y, z) / (1/2).
  Matrix4 m = perspective(0, 0, 10);
  EXPECT_EQ(m(2, 3), Q("-1/10"));
  EXPECT_EQ(apply(m, P("1", "2", "5")), P("2", "4", "10"));
  EXPECT_THROW(apply(m, P("1", "2", "10")), std::domain_error);  // the centre plane goes to infinity
  EXPECT_THROW(perspective(0, 0, 0), std::invalid_argument);
}

TEST(Transform, TwoAndThreePointPerspective) {
  Matrix4 m2 = perspective(4, 0, 10);
  EXPECT_EQ(m2(0, 3), Q("-1/4"));
  EXPECT_EQ(m2(2, 3), Q("-1/10"));
  // w = 1 - 2/4 - 5/10 + ... with (2, 1, 5): w = 1 - 1/2 - 1/2 = 0 -> infinity
  EXPECT_THROW(apply(m2, P("2", "1", "5")), std::domain_error);
  Matrix4 m3 = perspective(2, 4, 8);
  EXPECT_EQ(apply(m3, P("1", "1", "1")), P("8", "8", "8"));  // w = 1 - 1/2 - 1/4 - 1/8 = 1/8
}

TEST(Transform, InverseIsExact) {
  Matrix4 m = compose(compose(translation(V("1", "2", "3")), rotation(Axis::X, r34, P("0", "1", "0"))),
                      compose(scaling(V("2", "3", "1/7")), perspective(0, 0, 10)));
  auto inv = inverse(m);
  ASSERT_TRUE(inv);
  EXPECT_TRUE(same(compose(m, *inv), identity_transform()));
  EXPECT_TRUE(same(compose(*inv, m), identity_transform()));
  Point3 p = P("1/3", "-2", "0.25");
  EXPECT_EQ(apply(*inv, apply(m, p)), p);
  Matrix4 singular = scaling(V("1", "0", "1"));
  EXPECT_FALSE(inverse(singular));
}

TEST(Transform, CommutingPairsFromNotes) {
  Matrix4 t1 = translation(V("1", "2", "3")), t2 = translation(V("-5", "1/2", "0"));
  EXPECT_TRUE(same(compose(t1, t2), compose(t2, t1)));
  EXPECT_TRUE(same(compose(t1, t2), translation(V("-4", "5/2", "3"))));  // additive
  Matrix4 s1 = scaling(V("2", "3", "4")), s2 = scaling(V("1/2", "5", "-1"));
  EXPECT_TRUE(same(compose(s1, s2), compose(s2, s1)));
  EXPECT_TRUE(same(compose(s1, s2), scaling(V("1", "15", "-4"))));  // multiplicative
  Matrix4 ra = rotation(Axis::Z, r34), rb = rotation(Axis::Z, rotation_from_tan_half(Rational(1, 3)));
  EXPECT_TRUE(same(compose(ra, rb), compose(rb, ra)));  // rotation-rotation about one axis
  Matrix4 u = scaling(V("3", "3", "3"));
  EXPECT_TRUE(same(compose(u, ra), compose(ra, u)));  // uniform scaling - rotation
}

TEST(Transform, NonCommutingPairs) {
  Matrix4 t = translation(V("1", "0", "0")), r = rotation(Axis::Z, r34), s = scaling(V("2", "1", "1"));
  EXPECT_FALSE(same(compose(t, r), compose(r, t)));
  EXPECT_FALSE(same(compose(s, r), compose(r, s)));  // non-uniform scaling - rotation
  EXPECT_FALSE(same(compose(t, s), compose(s, t)));
  // Rotations about different axes do not commute either (the notes' list means one axis).
  Matrix4 rx = rotation(Axis::X, r34);
  EXPECT_FALSE(same(compose(rx, r), compose(r, rx)));
}

TEST(Rotation, QuarterTurnsAreExact) {
  for (auto [deg, c, s] : {std::tuple{"90", 0, 1}, {"-90", 0, -1}, {"180", -1, 0}, {"450", 0, 1}, {"-270", 0, 1}, {"360", 1, 0}}) {
    Rotation r = rotation_from_degrees(Q(deg));
    EXPECT_TRUE(r.exact) << deg;
    EXPECT_EQ(r.cos, c) << deg;
    EXPECT_EQ(r.sin, s) << deg;
  }
}

TEST(Rotation, OtherAnglesAreExactRotationsWithinTheBound) {
  for (const char* deg : {"30", "45", "-60", "17.5", "100", "-135", "179.9", "1/3"}) {
    Rotation r = rotation_from_degrees(Q(deg));
    EXPECT_FALSE(r.exact) << deg;
    EXPECT_EQ(r.cos * r.cos + r.sin * r.sin, 1) << deg;  // an exact rotation
    long double got = std::atan2(static_cast<long double>(r.sin.get_d()), static_cast<long double>(r.cos.get_d()));
    long double want = static_cast<long double>(Q(deg).get_d()) * 3.14159265358979323846264338327950288L / 180;
    long double diff = std::remainder(got - want, 2 * 3.14159265358979323846264338327950288L);
    EXPECT_LT(std::fabs(diff) * 180 / 3.14159265358979323846264338327950288L, kRotationErrorBoundDegrees) << deg;
    EXPECT_EQ(r.max_error_degrees, kRotationErrorBoundDegrees);
  }
}

TEST(Rotation, TanHalfAndCosSin) {
  Rotation r = rotation_from_tan_half(Rational(1, 2));
  EXPECT_EQ(r.cos, Q("3/5"));
  EXPECT_EQ(r.sin, Q("4/5"));
  EXPECT_THROW(rotation_from_cos_sin(Q("1/2"), Q("1/2")), std::invalid_argument);
}
