// 3D clipping: Cyrus-Beck (algorithms/clip/cyrus_beck.hpp) and midpoint subdivision
// (algorithms/clip/midpoint_clip.hpp), course notes sections 21-22.
#include <gtest/gtest.h>

#include <random>

#include "algorithms/clip/cyrus_beck.hpp"
#include "algorithms/clip/midpoint_clip.hpp"
#include "io/readers/mesh_reader.hpp"
#include "support/numbers.hpp"

using namespace hlr;

namespace {
const std::string kData = HLR_DATA_DIR;
using hlr::test::Q;
Point3 P(const char* x, const char* y, const char* z) { return Point3(Q(x), Q(y), Q(z)); }

ConvexClipper octahedron() {  // |x| + |y| + |z| <= 1
  std::vector<Point3> v = {Point3(1, 0, 0), Point3(-1, 0, 0), Point3(0, 1, 0), Point3(0, -1, 0), Point3(0, 0, 1), Point3(0, 0, -1)};
  std::vector<Face> f = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return make_clipper(Polyhedron(v, f), "octahedron");
}

ConvexClipper tilted_prism() {  // triangle (0,0),(4,0),(0,4) at z = 0, swept by (1, 0, 2)
  std::vector<Point3> v = {Point3(0, 0, 0), Point3(4, 0, 0), Point3(0, 4, 0), Point3(1, 0, 2), Point3(5, 0, 2), Point3(1, 4, 2)};
  std::vector<Face> f = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
  return make_clipper(Polyhedron(v, f), "prism");
}

ConvexClipper frustum() { return frustum_clipper(-4, 4, -4, 4, 1, -3, 5); }  // half-width (5 - z)/2
FrustumWindow frustum_window() { return FrustumWindow{-4, 4, -4, 4, 1, -3, 5}; }
BoxWindow box_window() { return BoxWindow{0, 2, 0, 2, 0, 2}; }

void expect_interval(const CyrusBeckResult& r, const char* lo, const char* hi) {
  ASSERT_EQ(r.status, CyrusBeckResult::Status::Visible);
  EXPECT_EQ(r.t_lower, Q(lo));
  EXPECT_EQ(r.t_upper, Q(hi));
}
}  // namespace

TEST(CyrusBeck, BoxByHand) {
  ConvexClipper box = box_clipper(0, 2, 0, 2, 0, 2);
  expect_interval(cyrus_beck(box, P("-1", "1", "1"), P("3", "1", "1")), "1/4", "3/4");
  expect_interval(cyrus_beck(box, P("1/2", "1/2", "1/2"), P("1", "1", "1")), "0", "1");  // inside
  expect_interval(cyrus_beck(box, P("-1", "-1", "-1"), P("3", "3", "3")), "1/4", "3/4");  // through two vertices
  expect_interval(cyrus_beck(box, P("0", "0", "-1"), P("0", "0", "3")), "1/4", "3/4");  // along an edge
  EXPECT_EQ(cyrus_beck(box, P("3", "3", "3"), P("4", "1", "1")).status, CyrusBeckResult::Status::Outside);
}

TEST(CyrusBeck, TableAsInTheNotes) {
  ConvexClipper box = box_clipper(0, 2, 0, 2, 0, 2);
  CyrusBeckResult r = cyrus_beck(box, P("-1", "1", "1"), P("3", "1", "1"));
  ASSERT_EQ(r.table.size(), 6u);
  // Face 0 is x = 0 (inner normal +x): W·n = -1, D·n = 4, t = 1/4, a lower limit.
  EXPECT_EQ(r.table[0].n, Vector3(1, 0, 0));
  EXPECT_EQ(r.table[0].wn, -1);
  EXPECT_EQ(r.table[0].dn, 4);
  EXPECT_EQ(*r.table[0].t, Q("1/4"));
  EXPECT_EQ(r.table[0].kind, CyrusBeckRow::Kind::Lower);
  EXPECT_EQ(r.table[1].kind, CyrusBeckRow::Kind::Upper);
  EXPECT_EQ(r.table[2].kind, CyrusBeckRow::Kind::ParallelInside);
}

TEST(CyrusBeck, OctahedronByHand) {
  ConvexClipper o = octahedron();
  expect_interval(cyrus_beck(o, P("-2", "0", "0"), P("2", "0", "0")), "1/4", "3/4");   // through two vertices
  expect_interval(cyrus_beck(o, P("-1", "1/2", "0"), P("1", "1/2", "0")), "1/4", "3/4");
  expect_interval(cyrus_beck(o, P("0", "0", "-2"), P("1/2", "1/2", "2")), "1/3", "3/5");
}

TEST(CyrusBeck, TiltedPrismByHand) {
  ConvexClipper p = tilted_prism();
  expect_interval(cyrus_beck(p, P("1", "1", "-1"), P("1", "1", "3")), "1/4", "3/4");   // leaves through an edge
  expect_interval(cyrus_beck(p, P("-1", "1", "1"), P("7", "1", "1")), "3/16", "9/16");
}

TEST(CyrusBeck, FrustumByHand) {
  ConvexClipper f = frustum();
  expect_interval(cyrus_beck(f, P("-6", "0", "-1"), P("6", "0", "-1")), "1/4", "3/4");
  expect_interval(cyrus_beck(f, P("0", "0", "-5"), P("0", "0", "3")), "1/4", "3/4");
}

TEST(CyrusBeckDegenerate, ZeroLengthSegments) {
  ConvexClipper box = box_clipper(0, 2, 0, 2, 0, 2);
  CyrusBeckResult in = cyrus_beck(box, P("1", "1", "1"), P("1", "1", "1"));
  EXPECT_TRUE(in.degenerate_point);
  EXPECT_EQ(in.point_class, CyrusBeckResult::PointClass::Inside);
  EXPECT_EQ(in.status, CyrusBeckResult::Status::Point);
  EXPECT_EQ(cyrus_beck(box, P("2", "1", "1"), P("2", "1", "1")).point_class, CyrusBeckResult::PointClass::OnBoundary);
  CyrusBeckResult out = cyrus_beck(box, P("3", "1", "1"), P("3", "1", "1"));
  EXPECT_EQ(out.point_class, CyrusBeckResult::PointClass::Outside);
  EXPECT_EQ(out.status, CyrusBeckResult::Status::Outside);
}

TEST(CyrusBeckDegenerate, ParallelToAFace) {
  ConvexClipper box = box_clipper(0, 2, 0, 2, 0, 2);
  EXPECT_EQ(cyrus_beck(box, P("-1", "3", "1"), P("3", "3", "1")).status, CyrusBeckResult::Status::Outside);  // outside: rejected
  expect_interval(cyrus_beck(box, P("-1", "1", "1"), P("3", "1", "1")), "1/4", "3/4");             // inside: no constraint
  expect_interval(cyrus_beck(box, P("-1", "2", "1"), P("3", "2", "1")), "1/4", "3/4");             // in the face's plane
}

TEST(CyrusBeckDegenerate, SinglePointIsReportedAndDrawnAsNothing) {
  ConvexClipper box = box_clipper(0, 2, 0, 2, 0, 2);
  CyrusBeckResult r = cyrus_beck(box, P("-1", "1", "1"), P("1", "3", "1"));  // touches the edge x = 0, y = 2
  EXPECT_EQ(r.status, CyrusBeckResult::Status::Point);
  EXPECT_EQ(r.t_lower, Q("1/2"));
  EXPECT_EQ(r.t_upper, Q("1/2"));
  Segment s;
  s.set_ends(P("-1", "1", "1"), P("1", "3", "1"));
  s.pieces = {Piece{0, 1, true, false, false}};
  clip_pieces(s, box);
  ASSERT_EQ(s.pieces.size(), 1u);
  EXPECT_TRUE(s.pieces[0].clipped);
  EXPECT_FALSE(s.pieces[0].visible);
}

TEST(CyrusBeckDegenerate, NonConvexClipperNamesAFace) {
  try {
    make_clipper(load_mesh(kData + "/l_prism.off"), "L");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not convex: face 4"), std::string::npos) << e.what();
  }
}

TEST(CyrusBeck, ClipPiecesKeepsKindsInsideAndCoversTheSegment) {
  ConvexClipper box = box_clipper(0, 2, 0, 2, 0, 2);
  Segment s;
  s.set_ends(P("-2", "1", "1"), P("2", "1", "1"));  // inside for t in [1/2, 1]
  s.pieces = {Piece{0, Q("3/4"), true, false, false}, Piece{Q("3/4"), 1, false, false, false}};
  clip_pieces(s, box);
  ASSERT_EQ(s.pieces.size(), 3u);
  EXPECT_TRUE(s.pieces[0].clipped);
  EXPECT_EQ(s.pieces[0].t1, Q("1/2"));
  EXPECT_TRUE(s.pieces[1].visible);
  EXPECT_EQ(s.pieces[1].t1, Q("3/4"));
  EXPECT_FALSE(s.pieces[2].visible);
  EXPECT_FALSE(s.pieces[2].clipped);
}

TEST(CyrusBeck, IntegerPathEqualsTheTablePath) {
  std::mt19937 rng(12);
  std::uniform_int_distribution<int> c(-30, 30), den(1, 8), big(0, 20);
  std::vector<ConvexClipper> clippers = {octahedron(), tilted_prism(), frustum(), box_clipper(0, 2, 0, 2, 0, 2)};
  for (int i = 0; i < 4000; ++i) {
    const ConvexClipper& cl = clippers[i % clippers.size()];
    auto R = [&] {
      Rational q = rational(c(rng), den(rng));
      if (big(rng) == 0) q += Rational(mpz_class("1000000000000000000000"), 3);
      return q;
    };
    Point3 a(R(), R(), R()), b = i % 50 == 0 ? a : Point3(R(), R(), R());
    CyrusBeckResult x = cyrus_beck(cl, a, b, true), y = cyrus_beck(cl, a, b, false);
    ASSERT_EQ(x.status, y.status);
    ASSERT_EQ(x.degenerate_point, y.degenerate_point);
    if (x.degenerate_point) {
      ASSERT_EQ(x.point_class, y.point_class);
    }
    if (x.status != CyrusBeckResult::Status::Outside) {
      ASSERT_EQ(x.t_lower, y.t_lower);
      ASSERT_EQ(x.t_upper, y.t_upper);
    }
  }
}

TEST(CyrusBeck, AgreesWithBruteForcePointInConvex) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> c(-30, 30), den(1, 8);
  std::vector<ConvexClipper> clippers = {octahedron(), tilted_prism(), frustum(), box_clipper(0, 2, 0, 2, 0, 2)};
  long samples = 0;
  for (int i = 0; i < 2000; ++i) {
    const ConvexClipper& cl = clippers[i % clippers.size()];
    auto R = [&] { return rational(c(rng), den(rng) * 2); };
    Point3 a(R(), R(), R()), b(R(), R(), R());
    CyrusBeckResult r = cyrus_beck(cl, a, b, i % 2 == 0);
    for (int k = 0; k <= 16; ++k) {
      Rational t = rational(k, 16);
      Point3 x = a + t * (b - a);
      // Brute force: inside every face plane through three of its vertices, on the side of the
      // vertex average.
      bool inside = true;
      Point3 centre = cl.planes.interior;
      for (const Face& f : cl.body.faces()) {
        const Point3 &A = cl.body.vertices()[f[0]], &B = cl.body.vertices()[f[1]], &C = cl.body.vertices()[f[2]];
        Vector3 n = cross(B - A, C - A);
        Rational side = dot(n, x - A), ref = dot(n, centre - A);
        if ((ref > 0 && side < 0) || (ref < 0 && side > 0)) inside = false;
      }
      bool in_interval = r.status != CyrusBeckResult::Status::Outside && r.t_lower <= t && t <= r.t_upper;
      ASSERT_EQ(inside, in_interval) << "segment " << a << " " << b << " t " << t;
      ++samples;
    }
  }
  EXPECT_EQ(samples, 2000 * 17);
}

// ---- midpoint subdivision ----

TEST(MidpointClip, BoxCodesAndOnThePlaneIsInside) {
  BoxWindow b = box_window();
  EXPECT_EQ(outcode(b, P("-1", "1", "1")), unsigned(kLeft));
  EXPECT_EQ(outcode(b, P("3", "1", "1")), unsigned(kRight));
  EXPECT_EQ(outcode(b, P("1", "-1", "1")), unsigned(kBelow));
  EXPECT_EQ(outcode(b, P("1", "3", "1")), unsigned(kAbove));
  EXPECT_EQ(outcode(b, P("1", "1", "3")), unsigned(kNear));
  EXPECT_EQ(outcode(b, P("1", "1", "-1")), unsigned(kFar));
  EXPECT_EQ(outcode(b, P("3", "3", "-1")), unsigned(kRight | kAbove | kFar));
  for (const Point3& on : {P("0", "1", "1"), P("2", "1", "1"), P("1", "0", "1"), P("1", "2", "1"), P("1", "1", "0"),
                           P("1", "1", "2"), P("2", "2", "2")})
    EXPECT_EQ(outcode(b, on), 0u) << on;
  EXPECT_EQ(outcode_bits(kRight | kFar), "010001");
}

TEST(MidpointClip, FrustumCoefficientsCodesAndPlanes) {
  FrustumWindow f = frustum_window();
  EXPECT_EQ(f.alpha1(), Q("-1/2"));
  EXPECT_EQ(f.alpha2(), Q("5/2"));
  EXPECT_EQ(f.beta1(), Q("1/2"));
  EXPECT_EQ(f.beta2(), Q("-5/2"));
  // On each plane (inside): right x = (5 - z)/2 at z = -1 is x = 3; near z = 1; far z = -3.
  for (const Point3& on : {P("3", "0", "-1"), P("-3", "0", "-1"), P("0", "3", "-1"), P("0", "-3", "-1"), P("0", "0", "1"),
                           P("0", "0", "-3"), P("4", "4", "-3")})
    EXPECT_EQ(outcode(f, on), 0u) << on;
  EXPECT_EQ(outcode(f, P("7/2", "0", "-1")), unsigned(kRight));
  EXPECT_EQ(outcode(f, P("0", "0", "2")), unsigned(kNear));
  EXPECT_EQ(outcode(f, P("0", "0", "-4")), unsigned(kFar));
  // Behind the centre (z > 5) on the axis: outside all four side half-spaces; the notes' rule
  // inverts those four bits.
  EXPECT_EQ(outcode(f, P("0", "0", "6")), unsigned(kLeft | kRight | kBelow | kAbove | kNear));
  EXPECT_EQ(notes_outcode(f, P("0", "0", "6")), unsigned(kNear));
}

TEST(MidpointClip, NotesBehindCentreRuleWouldRejectAVisibleSegment) {
  FrustumWindow f = frustum_window();
  Point3 a = P("-10", "0", "6"), b = P("10", "0", "-4");  // crosses the pyramid at t = 1/2
  EXPECT_NE(notes_outcode(f, a) & notes_outcode(f, b), 0u);  // the notes' codes: "invisible"
  EXPECT_EQ(outcode(f, a) & outcode(f, b), 0u);              // the half-space codes: not rejected
  EXPECT_TRUE(cyrus_beck(frustum(), a, b).visible());
  EXPECT_TRUE(midpoint_clip(f, a, b, Q("1/1000")).visible);
}

TEST(MidpointClip, TrivialCasesAndSubdivisionCount) {
  BoxWindow b = box_window();
  MidpointResult in = midpoint_clip(b, P("1/2", "1", "1"), P("3/2", "1", "1"), Q("0.01"));
  EXPECT_TRUE(in.trivially_accepted);
  EXPECT_EQ(in.subdivisions, 0);
  EXPECT_TRUE(midpoint_clip(b, P("3", "0", "0"), P("4", "2", "2"), Q("0.01")).trivially_rejected);
  // From (1,1,1) inside to (5,1,1): the crossing x = 2 is found by bisection to within eps.
  MidpointResult r = midpoint_clip(b, P("1", "1", "1"), P("5", "1", "1"), Q("1/64"));
  ASSERT_TRUE(r.visible);
  EXPECT_EQ(r.from, P("1", "1", "1"));
  EXPECT_LE(Q("2") - r.to.x(), Q("1/64"));
  EXPECT_LE(r.to.x(), 2);
  EXPECT_EQ(r.subdivisions, 8);  // 4 -> 1/64 in 8 halvings
}

TEST(MidpointClip, WithinTheStatedBoundOfCyrusBeckOn10000RandomSegments) {
  std::mt19937 rng(2026);
  std::uniform_int_distribution<int> c(-80, 80), den(1, 9);
  const Rational eps = Q("1/100"), eps2 = eps * eps;
  ConvexClipper box = box_clipper(0, 2, 0, 2, 0, 2), fr = frustum();
  long visible = 0, missed_short = 0, subdivisions = 0;
  for (int i = 0; i < 10000; ++i) {
    bool use_box = i % 2 == 0;
    auto R = [&] { return rational(c(rng), den(rng) * 10); };
    Point3 a(R() + (use_box ? 1 : 0), R() + (use_box ? 1 : 0), R() * (use_box ? 1 : 3)), b(R(), R(), R() * (use_box ? 1 : 3));
    Window w = use_box ? Window(box_window()) : Window(frustum_window());
    const ConvexClipper& cl = use_box ? box : fr;
    MidpointResult m = midpoint_clip(w, a, b, eps);
    CyrusBeckResult x = cyrus_beck(cl, a, b);
    subdivisions += m.subdivisions;
    if (m.visible) {
      ++visible;
      ASSERT_NE(x.status, CyrusBeckResult::Status::Outside) << a << " " << b;
      Point3 ea = a + x.t_lower * (b - a), eb = a + x.t_upper * (b - a);
      Vector3 d1 = m.from - ea, d2 = m.to - eb;
      ASSERT_LE(dot(d1, d1), eps2) << a << " " << b;
      ASSERT_LE(dot(d2, d2), eps2) << a << " " << b;
      ASSERT_EQ(outcode(w, m.from), 0u);
      ASSERT_EQ(outcode(w, m.to), 0u);
    } else if (x.status != CyrusBeckResult::Status::Outside) {
      Vector3 d = (x.t_upper - x.t_lower) * (b - a);
      ASSERT_LT(dot(d, d), 4 * eps2) << "missed a visible part longer than 2 eps: " << a << " " << b;
      ++missed_short;
    }
  }
  std::cout << "[midpoint] 10000 segments, " << visible << " visible, " << missed_short
            << " short visible parts below the bound, " << subdivisions << " subdivisions\n";
  EXPECT_GT(visible, 2000);
}
