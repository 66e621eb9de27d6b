// Roberts' algorithm (algorithms/hlr/roberts.hpp): hand-computed exact cases, degenerate cases by
// name, and the invariants of the pieces.
#include "algorithms/hlr/roberts.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "io/readers/mesh_reader.hpp"
#include "io/readers/scene.hpp"
#include "support/numbers.hpp"

using namespace hlr;

namespace {
const std::string kData = HLR_DATA_DIR;
using hlr::test::Q;
Point3 P(const char* x, const char* y, const char* z) { return Point3(Q(x), Q(y), Q(z)); }
Vector3 V(const char* x, const char* y, const char* z) { return Vector3(Q(x), Q(y), Q(z)); }

Polyhedron box(const char* x0, const char* y0, const char* z0, const char* x1, const char* y1, const char* z1) {
  return make_box(P(x0, y0, z0), P(x1, y1, z1));
}

// Invariants: pieces partition [0, 1] in order, t0 < t1, neighbours differ.
void check_invariants(const RobertsResult& r) {
  for (const Segment& s : r.segments) {
    ASSERT_FALSE(s.pieces.empty());
    EXPECT_EQ(s.pieces.front().t0, 0);
    EXPECT_EQ(s.pieces.back().t1, 1);
    for (std::size_t i = 0; i < s.pieces.size(); ++i) {
      EXPECT_LT(s.pieces[i].t0, s.pieces[i].t1);
      if (i > 0) {
        EXPECT_EQ(s.pieces[i - 1].t1, s.pieces[i].t0);
        EXPECT_FALSE(s.pieces[i - 1].same_kind(s.pieces[i]));
      }
    }
  }
}

const Segment& edge(const RobertsResult& r, int body, int v0, int v1) {
  for (const Segment& s : r.segments)
    if (s.kind == Segment::Kind::Edge && s.body == body && s.v0 == v0 && s.v1 == v1) return s;
  throw std::runtime_error("no such edge");
}

// The edge of a box between two corners given by index bits (0: min, 1: max per axis).
const Segment& box_edge(const RobertsResult& r, int body, int a, int b) { return edge(r, body, std::min(a, b), std::max(a, b)); }

bool fully(const Segment& s, bool visible) { return s.pieces.size() == 1 && s.pieces[0].visible == visible; }

RobertsResult run(const std::vector<const Polyhedron*>& bodies, const Camera& c, EdgeSelection e = EdgeSelection::Feature) {
  LineOptions o;
  o.edges = e;
  RobertsResult r = roberts(bodies, c, o);
  check_invariants(r);
  return r;
}
}  // namespace

// Course notes section 27: the box [-1,1]^3 from +z: side faces edge-on, back non-facing, no
// self-hidden edges, every edge visible (back edges run along edge-on faces).
TEST(Roberts, CubeAloneDefaultView) {
  Polyhedron cube = load_mesh(kData + "/cube.off");
  RobertsResult r = run({&cube}, make_orthographic(V("0", "0", "1")));
  std::vector<Rational> want = {0, 0, 0, 0, -1, 1};
  EXPECT_EQ(r.ev[0], want);
  EXPECT_EQ(r.stats.self_hidden, 0u);
  EXPECT_EQ(r.segments.size(), 12u);
  for (const Segment& s : r.segments) EXPECT_TRUE(fully(s, true));
}

TEST(Roberts, CubeAloneGeneralViewHidesTheThreeEdgesAtTheBackCorner) {
  Polyhedron cube = load_mesh(kData + "/cube.off");
  RobertsResult r = run({&cube}, make_orthographic(V("1", "1.3", "1.7")));
  std::set<std::pair<int, int>> hidden;
  for (const Segment& s : r.segments) {
    ASSERT_EQ(s.pieces.size(), 1u);
    if (!s.pieces[0].visible) hidden.insert({s.v0, s.v1});
  }
  EXPECT_EQ(hidden, (std::set<std::pair<int, int>>{{0, 1}, {0, 2}, {0, 4}}));  // vertex 0 = (-1,-1,-1)
  EXPECT_EQ(r.stats.self_hidden, 3u);
}

// Course notes: the cube [0,2]^3 along (1,1,0): only the vertical edge x = y = 0 is hidden.
TEST(Roberts, CubeAlongDiagonalHidesOnlyTheEdgeBehindTheFrontEdge) {
  Polyhedron c = box("0", "0", "0", "2", "2", "2");
  RobertsResult r = run({&c}, make_orthographic(V("1", "1", "0")));
  for (const Segment& s : r.segments) {
    bool back_vertical = s.v0 == 0 && s.v1 == 4;  // (0,0,0)-(0,0,2)
    EXPECT_TRUE(fully(s, !back_vertical)) << s.v0 << "-" << s.v1;
  }
}

TEST(Roberts, EdgePartlyBehindABoxHasItsExactInterval) {
  // The hidden interval straight from the inequalities: segment x in [-1, 3] at y = 1, z = -1
  // behind the box [0,2]^3 seen from +z: hidden for x in (0, 2), t in (1/4, 3/4).
  Polyhedron front = box("0", "0", "0", "2", "2", "2");
  BodyMatrix bm = body_matrix(front);
  RowVector4 g;
  g << 0, 0, 1, 0;
  OpenInterval iv = hidden_interval(P("-1", "1", "-1"), P("3", "1", "-1"), bm.V, g);
  ASSERT_FALSE(iv.empty);
  EXPECT_EQ(*iv.lo, Q("1/4"));
  EXPECT_EQ(*iv.hi, Q("3/4"));
  // The same through the whole algorithm: the back box's top edge at y = 1, z = -1.
  Polyhedron back = box("-1", "1/2", "-2", "3", "1", "-1");
  RobertsResult r = run({&front, &back}, make_orthographic(V("0", "0", "1")));
  const Segment& s = box_edge(r, 1, 2 | 4, 1 | 2 | 4);  // (-1,1,-1)-(3,1,-1)
  ASSERT_EQ(s.pieces.size(), 3u);
  EXPECT_TRUE(s.pieces[0].visible);
  EXPECT_EQ(s.pieces[0].t1, Q("1/4"));
  EXPECT_FALSE(s.pieces[1].visible);
  EXPECT_EQ(s.pieces[1].t1, Q("3/4"));
  EXPECT_TRUE(s.pieces[2].visible);
  EXPECT_EQ(s.at(s.pieces[1].t0), P("0", "1", "-1"));
}

TEST(Roberts, PenetratingBarHasItsJunctionRectangles) {
  Scene s = load_scene(kData + "/two_boxes.yaml");  // block [0,4]x[0,2]x[0,2], bar [1,2]x[-1,3]x[1/2,3/2]
  RobertsResult r = run({&s.bodies[0].body, &s.bodies[1].body}, make_orthographic(V("1", "1.3", "1.7")));
  std::set<std::pair<Point3, Point3>> got;
  for (const Segment& seg : r.segments)
    if (seg.kind == Segment::Kind::Intersection) {
      EXPECT_EQ(seg.body, 0);
      EXPECT_EQ(seg.body2, 1);
      got.insert({std::min(seg.from(), seg.to()), std::max(seg.from(), seg.to())});
    }
  std::set<std::pair<Point3, Point3>> want;
  for (const char* y : {"0", "2"}) {
    want.insert({P("1", y, "1/2"), P("2", y, "1/2")});
    want.insert({P("1", y, "3/2"), P("2", y, "3/2")});
    want.insert({P("1", y, "1/2"), P("1", y, "3/2")});
    want.insert({P("2", y, "1/2"), P("2", y, "3/2")});
  }
  EXPECT_EQ(got, want);
  // Seen from (1, 1.3, 1.7) the face y = 2 faces the viewer, y = 0 does not: the y = 0
  // rectangle is hidden by the block; on y = 2 the bar hides the far-side pieces of its own
  // junction (rays enter the bar) except the edges nearest the viewer.
  for (const Segment& seg : r.segments)
    if (seg.kind == Segment::Kind::Intersection && seg.from().y() == 0) {
      EXPECT_TRUE(fully(seg, false));
    }
  int visible_on_y2 = 0;
  for (const Segment& seg : r.segments)
    if (seg.kind == Segment::Kind::Intersection && seg.from().y() == 2) visible_on_y2 += fully(seg, true);
  EXPECT_EQ(visible_on_y2, 2);  // x = 2 and z = 3/2 sides: the bar does not cover them
  // The bar's top right edge (2,-1,3/2)-(2,3,3/2) is hidden inside the block (y in (0, 2)) and
  // before it, where its rays still enter the block's face y = 0 below the block's top z = 2:
  // from y = -(1/2)·(1.3/1.7) = -13/34, i.e. t = (1 - 13/34)/4 = 21/136, up to y = 2 (t = 3/4).
  const Segment& bar_edge = box_edge(r, 1, 1 | 4, 1 | 2 | 4);
  ASSERT_EQ(bar_edge.pieces.size(), 3u);
  EXPECT_EQ(bar_edge.pieces[1].t0, Q("21/136"));
  EXPECT_EQ(bar_edge.pieces[1].t1, Q("3/4"));
  EXPECT_FALSE(bar_edge.pieces[1].visible);
}

TEST(Roberts, PerspectiveCubeShowsOnlyItsFrontFace) {
  Polyhedron cube = load_mesh(kData + "/cube.off");
  RobertsResult r = run({&cube}, make_perspective(P("0", "0", "5"), P("0", "0", "0")));
  // From (0,0,5) the side planes x = +-1, y = +-1 have the eye on their inner side.
  std::vector<Rational> want = {-1, -1, -1, -1, -6, 4};
  EXPECT_EQ(r.ev[0], want);
  EXPECT_EQ(r.stats.self_hidden, 8u);
  int visible = 0;
  for (const Segment& s : r.segments) visible += fully(s, true);
  EXPECT_EQ(visible, 4);
}

TEST(Roberts, PerspectiveHiddenIntervalByHand) {
  // Eye (0,0,10); box [-1,1]^2 x [0,1]; segment x in [-5, 5] at y = 0, z = -10. The ray from
  // (x,0,-10) to the eye is at x·(10-z)/20 at height z: inside for some z in (0,1) iff
  // |x| < 20/9, so t = (x+5)/10 is hidden in (5/18, 13/18).
  Polyhedron occluder = box("-1", "-1", "0", "1", "1", "1");
  Polyhedron back = box("-5", "-1", "-11", "5", "0", "-10");  // its top-front edge y = 0, z = -10
  RobertsResult r = run({&occluder, &back}, make_perspective(P("0", "0", "10"), P("0", "0", "0")));
  const Segment& s = box_edge(r, 1, 2 | 4, 1 | 2 | 4);
  ASSERT_EQ(s.pieces.size(), 3u);
  EXPECT_EQ(s.pieces[1].t0, Q("5/18"));
  EXPECT_EQ(s.pieces[1].t1, Q("13/18"));
  EXPECT_FALSE(s.pieces[1].visible);
}

TEST(Roberts, PerspectiveNeverDrawsBehindTheEye) {
  // A long edge passing beside the eye: the part behind the eye plane is marked, not drawn.
  Polyhedron bar = box("2", "0", "-10", "3", "1", "10");
  RobertsResult r = run({&bar}, make_perspective(P("0", "0", "0"), P("0", "0", "-1")));
  const Segment& s = box_edge(r, 0, 0, 4);  // (2,0,-10)-(2,0,10)
  ASSERT_EQ(s.pieces.size(), 2u);
  EXPECT_EQ(s.pieces[0].t1, Q("1/2"));  // z = 0: the eye plane
  EXPECT_FALSE(s.pieces[0].behind_eye);
  EXPECT_TRUE(s.pieces[1].behind_eye);
  EXPECT_FALSE(s.pieces[1].visible);
}

TEST(Roberts, EyeInsideABodyIsAnError) {
  Polyhedron cube = load_mesh(kData + "/cube.off");
  EXPECT_THROW(run({&cube}, make_perspective(P("0", "0", "1/2"), P("0", "0", "-1"))), BodyError);
}

TEST(Roberts, NonConvexBodyRefusedNamingAFace) {
  Polyhedron l = load_mesh(kData + "/l_prism.off");
  try {
    run({&l}, make_orthographic(V("0", "0", "1")));
    FAIL();
  } catch (const BodyError& e) {
    EXPECT_NE(std::string(e.what()).find("not convex: face 4"), std::string::npos) << e.what();
  }
}

// ---- degenerate cases, one each ----

TEST(RobertsDegenerate, EdgeLyingInAnotherBodysFacePlaneTouchingFaceToFace) {
  // A's right face x = 0 lies against B's left face; A's edge (x = 0, y = 1) runs in B's face
  // plane through the edge-on face. Grazing only: visible, and no junction lines.
  Polyhedron b = box("0", "0", "0", "2", "2", "2");
  Polyhedron a = box("-1", "1/2", "-1", "0", "1", "3");
  RobertsResult r = run({&b, &a}, make_orthographic(V("0", "0", "1")));
  EXPECT_TRUE(fully(box_edge(r, 1, 1 | 2, 1 | 2 | 4), true));
  EXPECT_EQ(r.stats.intersection_segments, 0u);
}

TEST(RobertsDegenerate, TwoBoxesTouchingFaceToFaceGiveNoJunctionAndHideNothingOfEachOther) {
  Polyhedron a = box("0", "0", "0", "1", "1", "1");
  Polyhedron b = box("1", "0", "0", "2", "1", "1");
  RobertsResult r = run({&a, &b}, make_orthographic(V("1", "1.3", "1.7")));
  EXPECT_EQ(r.stats.intersection_segments, 0u);
  // Seen from +x+y+z, a's edge x = 1, y = 1 (top right) lies in b's left face: visible.
  EXPECT_TRUE(fully(box_edge(r, 0, 1 | 2, 1 | 2 | 4), true));
  // b's left bottom-front edges are in contact with a; a's right face is hidden behind b? No:
  // b is at larger x, toward the viewer, so b's hidden left face edges stay hidden (own body).
  EXPECT_TRUE(fully(box_edge(r, 1, 0, 4), false));
}

TEST(RobertsDegenerate, EdgeGrazingASilhouetteEdge) {
  // View (0,1,1); B = [0,2]^3; B's silhouette edge is y = 2, z = 0. Sight rays from the line
  // y = 1, z = -1 pass exactly through it: touching only, visible. From y = 9/10 they enter.
  Polyhedron b = box("0", "0", "0", "2", "2", "2");
  Polyhedron grazing = box("-1", "0", "-2", "3", "1", "-1");  // top-front edge y = 1, z = -1
  Polyhedron lower = box("-1", "0", "-2", "3", "9/10", "-1");
  Camera c = make_orthographic(V("0", "1", "1"));
  RobertsResult r1 = run({&b, &grazing}, c);
  EXPECT_TRUE(fully(box_edge(r1, 1, 2 | 4, 1 | 2 | 4), true));
  RobertsResult r2 = run({&b, &lower}, c);
  const Segment& s = box_edge(r2, 1, 2 | 4, 1 | 2 | 4);
  ASSERT_EQ(s.pieces.size(), 3u);
  EXPECT_EQ(s.pieces[1].t0, Q("1/4"));
  EXPECT_EQ(s.pieces[1].t1, Q("3/4"));
}

TEST(RobertsDegenerate, EdgeGrazingAVertex) {
  // View +z; B = [0,2]^3. A vertical line of sight through B's vertex (2,2,z): a segment behind
  // B that crosses below that vertex at one point only touches B there: all visible.
  Polyhedron b = box("0", "0", "0", "2", "2", "2");
  Polyhedron a = box("2", "2", "-2", "3", "3", "-1");  // its corner (2,2,-1) is under B's corner
  RobertsResult r = run({&b, &a}, make_orthographic(V("0", "0", "1")));
  for (const Segment& s : r.segments)
    if (s.body == 1) {
      EXPECT_TRUE(fully(s, true));
    }
}

TEST(RobertsDegenerate, EdgeExactlyBehindAnotherBodysEdge) {
  // Along (1,1,0), A's edge x = y = -1 is exactly behind B's back edge x = y = 0 and its rays
  // then cross B's interior: hidden. (A back edge behind an edge of two front faces.)
  Polyhedron b = box("0", "0", "0", "2", "2", "2");
  Polyhedron a = box("-3", "-3", "0", "-1", "-1", "2");
  RobertsResult r = run({&b, &a}, make_orthographic(V("1", "1", "0")));
  EXPECT_TRUE(fully(box_edge(r, 1, 1 | 2, 1 | 2 | 4), false));  // (-1,-1,0)-(-1,-1,2)
  // A's edges at x = -1 on the top and bottom faces: only their end at (-1,-1) is behind B.
  const Segment& top = box_edge(r, 1, 1 | 4, 1 | 2 | 4);  // (-1,-3,2)-(-1,-1,2)
  EXPECT_TRUE(top.pieces.back().visible);  // rays along the plane z = 2 of B's top face
}

TEST(RobertsDegenerate, FaceExactlyEdgeOn) {
  Polyhedron w = load_mesh(kData + "/wedge.off");
  RobertsResult r = run({&w}, make_orthographic(V("0", "1", "0")));
  // The wedge's bottom (z = 0) and back (x = 0) faces are edge-on from +y.
  EXPECT_EQ(r.ev[0][0], 0);
  EXPECT_EQ(r.ev[0][1], 0);
  EXPECT_LT(r.ev[0][2], 0);  // front y = 0: non-facing
}

TEST(RobertsDegenerate, EdgesBetweenCoplanarFacesOnlyWithAll) {
  // The cube with its front face split into two triangles: the diagonal is not a feature.
  Polyhedron cube = load_mesh(kData + "/cube.off");
  std::vector<Face> f = cube.faces();
  Face front = f[5];
  f[5] = {front[0], front[1], front[2]};
  f.push_back({front[0], front[2], front[3]});
  Polyhedron split(cube.vertices(), f);
  EXPECT_EQ(run({&split}, make_orthographic(V("0", "0", "1"))).segments.size(), 12u);
  EXPECT_EQ(run({&split}, make_orthographic(V("0", "0", "1")), EdgeSelection::All).segments.size(), 13u);
}

TEST(Roberts, PrefilterSkipsFarBodiesAndChangesNothing) {
  std::vector<Polyhedron> boxes;
  for (int i = 0; i < 30; ++i)
    boxes.push_back(make_box(Point3(3 * i, 0, i % 3), Point3(3 * i + 2, 2, i % 3 + 2)));
  std::vector<const Polyhedron*> ptrs;
  for (auto& b : boxes) ptrs.push_back(&b);
  Camera c = make_orthographic(V("1", "1.3", "1.7"));
  LineOptions with, without;
  without.prefilter = false;
  RobertsResult a = roberts(ptrs, c, with), b = roberts(ptrs, c, without);
  EXPECT_GT(a.stats.pairs_skipped, a.stats.pairs_tested);
  ASSERT_EQ(a.segments.size(), b.segments.size());
  for (std::size_t i = 0; i < a.segments.size(); ++i) {
    ASSERT_EQ(a.segments[i].pieces.size(), b.segments[i].pieces.size());
    for (std::size_t k = 0; k < a.segments[i].pieces.size(); ++k) {
      EXPECT_EQ(a.segments[i].pieces[k].t0, b.segments[i].pieces[k].t0);
      EXPECT_EQ(a.segments[i].pieces[k].visible, b.segments[i].pieces[k].visible);
    }
  }
}

#include "algorithms/hlr/int128_interval.hpp"

TEST(RobertsFastPath, AgreesWithTheRationalPathAndFallsBackWhenTooBig) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> c(-40, 40), den(1, 12), big(0, 9);
  int fast = 0, fallback = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    auto R = [&] {
      Rational q = rational(c(rng), den(rng));
      if (big(rng) == 0) q += Rational(mpz_class("123456789012345678901"), 7);  // too big for 128 bits
      q.canonicalize();
      return q;
    };
    Polyhedron b = make_box(Point3(rational(c(rng) - 60, den(rng)), rational(c(rng) - 60, den(rng)), rational(c(rng) - 60, den(rng))),
                            Point3(rational(c(rng) + 60, den(rng)), rational(c(rng) + 60, den(rng)), rational(c(rng) + 60, den(rng))));
    BodyMatrix bm = body_matrix(b);
    RowVector4 g;
    if (trial % 2)
      g << rational(c(rng), den(rng)), rational(c(rng), den(rng)), rational(c(rng), den(rng)), 0;
    else
      g << rational(c(rng) * 5, den(rng)), rational(c(rng) * 5, den(rng)), 300, 1;
    if (g(0) == 0 && g(1) == 0 && g(2) == 0) continue;
    Point3 p1(R(), R(), R()), p2(R(), R(), R());
    if (p1 == p2) continue;
    OpenInterval slow = hidden_interval(p1, p2, bm.V, g);
    auto quick = fast_hidden_interval(p1, p2, prepare_fast_body(bm.V, g));
    if (!quick) {
      ++fallback;
      continue;
    }
    ++fast;
    ASSERT_EQ(quick->empty, slow.empty);
    if (slow.empty) continue;
    ASSERT_EQ(quick->lo.has_value(), slow.lo.has_value());
    ASSERT_EQ(quick->hi.has_value(), slow.hi.has_value());
    if (slow.lo) {
      EXPECT_EQ(*quick->lo, *slow.lo);
    }
    if (slow.hi) {
      EXPECT_EQ(*quick->hi, *slow.hi);
    }
  }
  EXPECT_GT(fast, 1000);
  EXPECT_GT(fallback, 100);
}
