// The per-face route (algorithms/hlr/face_occluders.hpp): exact pieces on hand-made
// scenes for each degenerate case by name (axis views, a ray leaving a solid exactly through
// an edge, holes, open surfaces, intersection lines, crease thresholds) and the line kinds.
#include "algorithms/hlr/face_occluders.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>

#include "algorithms/picture/drawing_2d.hpp"
#include "algorithms/solids/crease_angle.hpp"
#include "io/readers/mesh_reader.hpp"
#include "support/compact.hpp"
#include "support/numbers.hpp"
#include "support/torus.hpp"

using namespace hlr;

namespace {
const std::string kData = HLR_DATA_DIR;
using hlr::test::compact_copy;
using hlr::test::Q;
Point3 P(const char* x, const char* y, const char* z) { return Point3(Q(x), Q(y), Q(z)); }

Polyhedron box(const char* x0, const char* y0, const char* z0, const char* x1, const char* y1, const char* z1) {
  return make_box(P(x0, y0, z0), P(x1, y1, z1));
}

LineDrawing run(const std::vector<const Polyhedron*>& bodies, const Camera& c, EdgeSelection e = EdgeSelection::All,
                  const char* crease = "30") {
  LineOptions o;
  o.edges = e;
  o.crease_degrees = Q(crease);
  LineDrawing r = face_occluders(bodies, c, o);
  for (const Segment& s : r.segments) {  // pieces partition [0, 1]
    EXPECT_EQ(s.pieces.front().t0, 0);
    EXPECT_EQ(s.pieces.back().t1, 1);
    for (std::size_t i = 1; i < s.pieces.size(); ++i) EXPECT_EQ(s.pieces[i - 1].t1, s.pieces[i].t0);
  }
  return r;
}

const Segment* find_edge(const LineDrawing& r, int body, int a, int b) {
  for (const Segment& s : r.segments)
    if (s.kind == Segment::Kind::Edge && s.body == body && s.v0 == std::min(a, b) && s.v1 == std::max(a, b)) return &s;
  return nullptr;
}

const Segment& edge(const LineDrawing& r, int body, int a, int b) {
  const Segment* s = find_edge(r, body, a, b);
  if (!s) throw std::runtime_error("no such edge");
  return *s;
}

bool visible_at(const Segment& s, const Rational& t) {
  for (const Piece& p : s.pieces)
    if (p.t0 < t && t < p.t1) return p.visible;
  throw std::runtime_error("t on a piece boundary");
}

// "v h v" style summary of the pieces with their ends.
std::string pieces(const Segment& s) {
  std::string out = "0";
  for (const Piece& p : s.pieces) out += std::string(p.visible ? " v " : " h ") + to_string(p.t1);
  return out;
}

}  // namespace

// Course notes, "Visibility semantics": the cube [0,2]^3 along (1,1,0). Only the vertical edge
// at x = y = 0 is hidden: its rays enter the cube exactly through the front vertical edge. The
// top and bottom back edges stay visible (their rays run along edge-on faces).
TEST(FaceOccluders, CubeAlong110HidesOnlyTheBackVerticalEdge) {
  Polyhedron cube = box("0", "0", "0", "2", "2", "2");
  for (EdgeSelection e : {EdgeSelection::All, EdgeSelection::Feature}) {
    LineDrawing r = run({&cube}, make_orthographic(Vector3(1, 1, 0)), e);
    ASSERT_EQ(r.segments.size(), 12u);
    for (const Segment& s : r.segments) {
      bool back = s.v0 == 0 && s.v1 == 4;  // (0,0,0)-(0,0,2)
      EXPECT_EQ(pieces(s), back ? "0 h 1" : "0 v 1") << s.v0 << "-" << s.v1;
    }
  }
}

// The same with coordinates of ten decimal places (scaled integers above 2^29): the 128-bit
// coordinate path, same exact answer; with a denominator beyond 64 bits: the fixed-width
// multi-limb path; beyond 2^150: the GMP path.
TEST(FaceOccluders, WiderNumberPathsGiveTheSameAnswer) {
  for (const char* hi : {"2.0000000001", "2.00000000000000000001", "2.0000000000000000000000000000000000000000000000001"}) {
    Polyhedron cube = make_box(P("0", "0", "0"), P(hi, hi, "2"));
    LineDrawing r = run({&cube}, make_orthographic(Vector3(1, 1, 0)));
    EXPECT_EQ(r.stats.faces->integer_path, std::string(hi).size() < 30) << hi;
    for (const Segment& s : r.segments) EXPECT_EQ(pieces(s), s.v0 == 0 && s.v1 == 4 ? "0 h 1" : "0 v 1") << hi;
    Polyhedron rod = box("-1", "-1", "1/2", "3", "-1/2", "1");
    LineDrawing q = run({&cube, &rod}, make_orthographic(Vector3(0, -1, 0)));
    EXPECT_EQ(pieces(edge(q, 1, 0, 1)), "0 v 1");  // in front of the cube
    LineDrawing w = run({&cube, &rod}, make_orthographic(Vector3(0, 1, 0)));
    EXPECT_EQ(pieces(edge(w, 1, 4, 5)).substr(0, 6), "0 v 1/");  // behind it from x = 0
  }
}

// A ray that leaves a solid exactly through a concave edge whose other face is seen edge-on:
// the L-prism seen along +y. Behind the concave edge x = 1 the rays pass through the L's lower
// arm, so the rod's vertical edge exactly behind it is hidden (open prisms alone would miss it).
TEST(FaceOccluders, ConcaveEdgeHidesWhatIsExactlyBehindIt) {
  Polyhedron l = load_mesh(kData + "/l_prism.off");
  Polyhedron rod = box("1", "-2", "1/4", "3", "-1", "3/4");
  LineDrawing r = run({&l, &rod}, make_orthographic(Vector3(0, 1, 0)));
  // Rod vertices: bit 0 x, bit 1 y, bit 2 z. Edge 2-6: x = 1, y = -1 (the front left edge).
  EXPECT_EQ(pieces(edge(r, 1, 2, 6)), "0 h 1");
  // Its top front edge 6-7 (x from 1 to 3 at y = -1, z = 3/4): hidden behind the L up to x = 2.
  EXPECT_EQ(pieces(edge(r, 1, 6, 7)), "0 h 1/2 v 1");
  // The L's own concave edge (3-9) faces the viewer: visible.
  EXPECT_EQ(pieces(edge(r, 0, 3, 9)), "0 v 1");
}

// A cube with a cubic hole, seen along z: the rod below shows through the hole only.
TEST(FaceOccluders, CubeWithCubicHoleShowsWhatIsBelowTheHole) {
  Polyhedron frame = load_mesh(kData + "/frame.off");
  Polyhedron rod = box("-1", "7/5", "-2", "4", "8/5", "-1");
  LineDrawing r = run({&frame, &rod}, make_orthographic(Vector3(0, 0, 1)));
  EXPECT_EQ(pieces(edge(r, 1, 4, 5)), "0 v 1/5 h 2/5 v 3/5 h 4/5 v 1");  // x = -1 .. 4 at y = 7/5
  // The inner vertical edges of the hole are seen end-on along the hole's walls: visible.
  EXPECT_EQ(pieces(edge(r, 0, 4, 12)), "0 v 1");
  // Seen from below the rod is in front: it hides the frame's bottom edge x = 0 (y from 0 to 3)
  // where it crosses under it, y in (7/5, 8/5).
  LineDrawing b = run({&frame, &rod}, make_orthographic(Vector3(0, 0, -1)));
  EXPECT_EQ(pieces(edge(b, 0, 0, 3)), "0 v 7/15 h 8/15 v 1");
}

// A torus seen along its axis: the rod below shows through the hole and outside, not under the
// ring. Coordinates are doubles' exact values (denominators 2^52): the multi-limb path runs.
TEST(FaceOccluders, TorusSeenThroughItsHole) {
  const Polyhedron torus = test::torus_mesh(24, 12, 1, 0.4, [](double x) { return rational_from_double(x); });
  Polyhedron rod = box("-2", "-1/20", "-1", "2", "1/20", "-9/10");
  LineDrawing r = run({&torus, &rod}, make_orthographic(Vector3(0, 0, 1)));
  EXPECT_TRUE(r.stats.faces->integer_path);
  const Segment& top = edge(r, 1, 4, 5);  // x from -2 to 2 at y = -1/20, z = -9/10
  auto t_of = [](double x) { return rational_from_double((x + 2) / 4); };
  EXPECT_TRUE(visible_at(top, t_of(0)));      // through the hole
  EXPECT_FALSE(visible_at(top, t_of(1)));     // under the ring
  EXPECT_FALSE(visible_at(top, t_of(-1)));
  EXPECT_TRUE(visible_at(top, t_of(1.8)));    // outside
  EXPECT_TRUE(visible_at(top, t_of(-1.8)));
  EXPECT_EQ(top.pieces.size(), 5u);
}

// Two meshes that interpenetrate get their intersection lines, exactly, once, merged across
// face diagonals: box B pokes out of box A's face x = 2 in the square y, z in [1/2, 3/2].
TEST(FaceOccluders, InterpenetratingMeshesGetTheirIntersectionLines) {
  Polyhedron a = box("0", "0", "0", "2", "2", "2"), b = box("1", "1/2", "1/2", "3", "3/2", "3/2");
  LineDrawing r = run({&a, &b}, make_orthographic(Vector3(1, Q("1.3"), Q("1.7"))), EdgeSelection::Feature);
  std::map<std::pair<std::string, std::string>, std::string> got;
  for (const Segment& s : r.segments)
    if (s.kind == Segment::Kind::Intersection) {
      EXPECT_EQ(s.line, LineKind::Intersection);
      EXPECT_EQ(s.body, 0);
      EXPECT_EQ(s.body2, 1);
      got[{to_string(std::min(s.from(), s.to())), to_string(std::max(s.from(), s.to()))}] = pieces(s);
    }
  // On A's front face x = 2; the two lines on B's back faces (y = 1/2, z = 1/2) are hidden by
  // B itself, whose rays run into B.
  std::map<std::pair<std::string, std::string>, std::string> want = {
      {{"(2, 1/2, 1/2)", "(2, 1/2, 3/2)"}, "0 h 1"}, {{"(2, 1/2, 1/2)", "(2, 3/2, 1/2)"}, "0 h 1"},
      {{"(2, 1/2, 3/2)", "(2, 3/2, 3/2)"}, "0 v 1"}, {{"(2, 3/2, 1/2)", "(2, 3/2, 3/2)"}, "0 v 1"}};
  EXPECT_EQ(got, want);
  // B's front edge 6-7 (x 1..3 at y = z = 3/2) is inside A up to x = 2.
  EXPECT_EQ(pieces(edge(r, 1, 6, 7)), "0 h 1/2 v 1");
}

// A body that crosses itself (one mesh, two interpenetrating boxes) gets its own intersection
// lines, the same as two bodies would.
TEST(FaceOccluders, SelfIntersectionLines) {
  Polyhedron a = box("0", "0", "0", "2", "2", "2"), b = box("1", "1/2", "1/2", "3", "3/2", "3/2");
  std::vector<Point3> vs = a.vertices();
  vs.insert(vs.end(), b.vertices().begin(), b.vertices().end());
  std::vector<Face> fs = a.faces();
  for (Face f : b.faces()) {
    for (int& v : f) v += 8;
    fs.push_back(f);
  }
  Polyhedron one(vs, fs);
  Camera cam = make_orthographic(Vector3(1, Q("1.3"), Q("1.7")));
  LineDrawing r = run({&one}, cam, EdgeSelection::Feature);
  LineDrawing two = run({&a, &b}, cam, EdgeSelection::Feature);
  auto lines = [](const LineDrawing& x) {
    std::set<std::string> out;
    for (const Segment& s : x.segments)
      if (s.kind == Segment::Kind::Intersection)
        out.insert(to_string(std::min(s.from(), s.to())) + " " + to_string(std::max(s.from(), s.to())) + " " + pieces(s));
    return out;
  };
  EXPECT_EQ(lines(r).size(), 4u);
  EXPECT_EQ(lines(r), lines(two));
  for (const Segment& s : r.segments)
    if (s.kind == Segment::Kind::Intersection) EXPECT_EQ(s.body, s.body2);
}

// An open surface (one square) hides what is behind it and is hidden; its edges are boundaries.
TEST(FaceOccluders, OpenSquareHidesAndIsHidden) {
  Polyhedron square({P("1/2", "-1", "3"), P("3/2", "-1", "3"), P("3/2", "3", "3"), P("1/2", "3", "3")}, {{0, 1, 2, 3}});
  Polyhedron cube = box("0", "0", "0", "2", "2", "2");
  for (const Vector3& v : {Vector3(0, 0, 1), Vector3(0, 0, -1)}) {
    LineDrawing r = run({&square, &cube}, make_orthographic(v), EdgeSelection::Feature);
    for (const Segment& s : r.segments)
      if (s.body == 0) EXPECT_EQ(s.line, LineKind::Boundary);
    if (v.z() > 0) {
      EXPECT_EQ(pieces(edge(r, 1, 6, 7)), "0 v 1/4 h 3/4 v 1");  // the cube's top edge y = 2, x 0..2
      EXPECT_EQ(pieces(edge(r, 0, 0, 3)), "0 v 1");             // the square's edge x = 1/2
    } else {
      EXPECT_EQ(pieces(edge(r, 0, 0, 3)), "0 v 1/4 h 3/4 v 1");  // y -1..3: under the cube for y in (0, 2)
    }
  }
  // Seen from its back side the square still hides (open surfaces hide from both sides).
  Polyhedron flipped = square.reversed();
  LineDrawing r = run({&flipped, &cube}, make_orthographic(Vector3(0, 0, 1)));
  EXPECT_EQ(pieces(edge(r, 1, 6, 7)), "0 v 1/4 h 3/4 v 1");
}

// An open hemisphere (the dome z >= 0 of a UV sphere, open at the equator) hides from the
// side and from below, and a rod inside the bowl is seen from below only through the dome.
TEST(FaceOccluders, OpenHemisphereHidesAndIsHidden) {
  const int N = 32, M = 8;  // N around, M rings from the equator to the pole
  std::vector<Point3> vs;
  std::vector<Face> fs;
  auto q = [](double x) { return rational_from_double(std::round(x * 1e6) / 1e6); };
  for (int j = 0; j < M; ++j)
    for (int i = 0; i < N; ++i) {
      double u = 2 * M_PI * i / N, w = M_PI / 2 * j / M;
      vs.emplace_back(q(std::cos(w) * std::cos(u)), q(std::cos(w) * std::sin(u)), q(std::sin(w)));
    }
  vs.emplace_back(0, 0, 1);
  const int pole = N * M;
  for (int j = 0; j < M; ++j)
    for (int i = 0; i < N; ++i) {
      int a = j * N + i, b = j * N + (i + 1) % N;
      if (j + 1 < M) {  // rounded coordinates make quads non-planar (refused): two triangles
        fs.push_back({a, b, b + N});
        fs.push_back({a, b + N, a + N});
      } else {
        fs.push_back({a, b, pole});
      }
    }
  Polyhedron dome(vs, fs);
  Polyhedron side_rod = box("-3", "-2", "1/4", "-2", "2", "1/2");  // behind the dome seen from +x
  LineDrawing r = run({&dome, &side_rod}, make_orthographic(Vector3(1, 0, 0)), EdgeSelection::Feature);
  const Segment& e = edge(r, 1, 5, 7);  // x = -2, z = 1/2, y from -2 to 2
  EXPECT_TRUE(visible_at(e, Q("1/20")));     // y = -1.8: beside the dome
  EXPECT_FALSE(visible_at(e, Q("1/2")));     // y = 0: behind it
  EXPECT_TRUE(visible_at(e, Q("19/20")));
  std::size_t rim = 0;
  for (const Segment& s : r.segments) rim += s.body == 0 && s.line == LineKind::Boundary;
  EXPECT_EQ(rim, static_cast<std::size_t>(N));  // the equator
  // From below, a rod above the dome is hidden where its rays cross the dome.
  Polyhedron above = box("-2", "-1/10", "3", "2", "1/10", "4");
  LineDrawing b = run({&dome, &above}, make_orthographic(Vector3(0, 0, -1)), EdgeSelection::Feature);
  const Segment& f = edge(b, 1, 0, 1);  // z = 3, y = -1/10, x from -2 to 2
  EXPECT_FALSE(visible_at(f, Q("1/2")));
  EXPECT_TRUE(visible_at(f, Q("1/50")));
  // From above the same rod is in front of everything.
  LineDrawing c = run({&dome, &above}, make_orthographic(Vector3(0, 0, 1)), EdgeSelection::Feature);
  EXPECT_EQ(pieces(edge(c, 1, 4, 5)), "0 v 1");
}

// An open box (no top) seen from above shows its inside bottom; closed, it would hide it.
TEST(FaceOccluders, OpenBoxShowsItsInside) {
  Polyhedron closed = box("0", "0", "0", "2", "2", "2");
  std::vector<Face> faces = closed.faces();
  faces.erase(faces.begin() + 5);  // the top (z max) face
  Polyhedron open(closed.vertices(), faces);
  Camera cam = make_orthographic(Vector3(Q("0.2"), Q("0.3"), 1));
  LineDrawing r = run({&open}, cam, EdgeSelection::Feature);
  // Bottom edge y = 0, x 0..2: seen through the opening up to x = 1.6, then behind the wall x = 2.
  EXPECT_EQ(pieces(edge(r, 0, 0, 1)), "0 v 4/5 h 1");
  EXPECT_EQ(edge(r, 0, 4, 5).line, LineKind::Boundary);
  LineDrawing c = run({&closed}, cam, EdgeSelection::Feature);
  EXPECT_EQ(pieces(edge(c, 0, 0, 1)), "0 h 1");
}

// Crease threshold, decided exactly: the roof's faces meet at exactly 45 degrees.
TEST(FaceOccluders, CreaseThresholdIsExact) {
  // Profile in x-z: (0,0) (4,0) (4,1) (3,2) (0,2), extruded along y in [0, 1].
  std::vector<Point3> v;
  for (const char* y : {"0", "1"})
    for (auto [x, z] : std::vector<std::pair<const char*, const char*>>{{"0", "0"}, {"4", "0"}, {"4", "1"}, {"3", "2"}, {"0", "2"}})
      v.push_back(P(x, y, z));
  std::vector<Face> f = {{0, 4, 3, 2, 1}, {5, 6, 7, 8, 9}, {0, 1, 6, 5}, {1, 2, 7, 6}, {2, 3, 8, 7}, {3, 4, 9, 8}, {4, 0, 5, 9}};
  Polyhedron roof(v, orient_faces(v, f));
  Camera cam = make_orthographic(Vector3(Q("0.2"), Q("-1"), Q("3")));  // top, slant and x = 4 all facing
  auto has = [&](const LineDrawing& r, int a, int b) { return find_edge(r, 0, a, b) != nullptr; };
  LineDrawing r45 = run({&roof}, cam, EdgeSelection::Feature, "45");
  EXPECT_FALSE(has(r45, 3, 8));  // top-slant: exactly 45, not over
  EXPECT_FALSE(has(r45, 2, 7));  // slant-side: exactly 45
  EXPECT_TRUE(has(r45, 1, 6));   // side-bottom: 90
  LineDrawing r44 = run({&roof}, cam, EdgeSelection::Feature, "44.999999");
  EXPECT_TRUE(has(r44, 3, 8));
  EXPECT_EQ(edge(r44, 0, 3, 8).line, LineKind::Crease);
  LineDrawing r0 = run({&roof}, cam, EdgeSelection::Feature, "0");
  EXPECT_TRUE(has(r0, 3, 8));
}

// The crease test decides the same for normals of any size: scaled by 2^k (k up to 3000: the
// exact cut points of a section give such normals on the rational path) an angle stays on
// its side of the threshold; the double filter once overflowed to "every edge is a crease".
TEST(FaceOccluders, CreaseTestIndependentOfTheNormalsSize) {
  const CreaseAngle a(Q("30"));
  const long base[][2][3] = {
      {{0, 0, 1}, {0, 1, 1}}, {{0, 0, 1}, {0, 1, 9}}, {{3, 4, 5}, {3, 4, 6}}, {{1, 0, 0}, {1000, 577, 0}}, {{1, 0, 0}, {1000, 578, 0}}};
  for (const auto& n : base)
    for (int k : {0, 100, 500, 1100, 3000})
      for (int j : {0, 7, 1500}) {
        mpz_class x[3], y[3];
        for (int i = 0; i < 3; ++i) {
          x[i] = mpz_class(n[0][i]) << k;
          y[i] = mpz_class(n[1][i]) << j;
        }
        long lx[3] = {n[0][0], n[0][1], n[0][2]}, ly[3] = {n[1][0], n[1][1], n[1][2]};
        EXPECT_EQ(a.exceeds(x, y), a.exceeds(lx, ly)) << k << " " << j;
      }
}

// Silhouette edges are decided exactly from the facing of the two faces.
TEST(FaceOccluders, SilhouetteKinds) {
  Polyhedron cube = box("0", "0", "0", "2", "2", "2");
  LineDrawing r = run({&cube}, make_orthographic(Vector3(1, 2, 3)), EdgeSelection::Feature, "100");
  std::size_t silhouettes = 0;
  for (const Segment& s : r.segments) {
    EXPECT_EQ(s.line, LineKind::Silhouette);  // creases over 100 degrees: none; only silhouettes drawn
    ++silhouettes;
  }
  EXPECT_EQ(silhouettes, 6u);
  CreaseAngle a(Q("30"));
  long n1[3] = {0, 0, 1}, n2[3] = {0, 1, 1};
  EXPECT_TRUE(a.exceeds(n1, n2));  // 45 > 30
  EXPECT_THROW(CreaseAngle(Q("181")), std::invalid_argument);
}

// Intersection lines and their visibility are the same on the 64-bit path (integer segment
// construction, filtered then integer hidden intervals), the 128-bit path, the multi-limb path
// and the GMP path: random soups of triangles on a coarse lattice (k/4: shared vertices,
// coplanar and touching triangles, edges through edges), the same soup with one far, tiny extra
// body whose coordinates force the wider path (ten decimal places: 128-bit; 2^-70: multi-limb;
// 2^-200: GMP). Views along the axes, diagonals and a perspective eye among the triangles.
TEST(FaceOccluders, IntersectionLinesEqualOnEveryNumberPath) {
  std::mt19937 rng(20261130);
  std::uniform_int_distribution<int> coord(0, 8);
  auto q = [&] { return Rational(coord(rng), 4); };
  std::vector<Camera> views = {make_orthographic(Vector3(0, 0, 1)), make_orthographic(Vector3(1, 1, 1)),
                               make_orthographic(Vector3(1, 0, 0)), make_orthographic(Vector3(1, 2, 3)),
                               make_perspective(P("5/4", "3/4", "9/8"), P("0", "1", "1"))};
  std::size_t lines = 0;
  for (int scene = 0; scene < 30; ++scene) {
    std::vector<Point3> vs;
    std::vector<Face> fs;
    for (int t = 0; t < 14; ++t) {
      for (int k = 0; k < 3; ++k) vs.push_back(Point3(q(), q(), q()));
      fs.push_back({3 * t, 3 * t + 1, 3 * t + 2});
    }
    Polyhedron soup(vs, fs);
    auto far = [](const char* eps) {
      Rational e = Q(eps);
      return Polyhedron({Point3(Rational(-40), Rational(-40), Rational(-40)), Point3(Rational(-40) + e, Rational(-40), Rational(-40)),
                         Point3(Rational(-40), Rational(-40) + e, Rational(-40))},
                        {{0, 1, 2}});
    };
    Polyhedron wide = far("0.0000000001"), limbs = far("1/1180591620717411303424"),    // 2^-70
        big = far("1/1606938044258990275541962092341162602522202993782792835301376");  // 2^-200
    // GMP integers with the soup off the grid: 4,000 far points (in no face) in 3^-38 steps
    // make 3^38 the grid (the soup's quarters are too rare to join it), the 2^-200 triangle
    // puts the scene on GMP integers: the soup's pairs take the doubles' orientation filter
    // and the exact fallback on the scaled points.
    std::vector<Point3> far_pts = big.vertices();
    const Rational step(mpz_class(1), mpz_class("1350851717672992089"));  // 3^-38
    for (int j = 1; j <= 4000; ++j) far_pts.push_back(Point3(Rational(-60) + step * j, Rational(-60), Rational(-60)));
    Polyhedron off_grid(far_pts, {{0, 1, 2}});
    for (const Camera& cam : views) {
      LineDrawing fast = run({&soup}, cam);
      ASSERT_TRUE(fast.stats.faces->integer_path);
      for (const Polyhedron* extra : {&wide, &limbs, &big, &off_grid}) {
        LineDrawing other = run({&soup, extra}, cam);
        EXPECT_EQ(other.stats.faces->integer_path, extra != &big && extra != &off_grid);
        std::vector<const Segment*> a, b;
        for (const Segment& s : fast.segments)
          if (s.kind == Segment::Kind::Intersection) a.push_back(&s);
        for (const Segment& s : other.segments)
          if (s.kind == Segment::Kind::Intersection) b.push_back(&s);
        ASSERT_EQ(a.size(), b.size()) << "scene " << scene;
        for (std::size_t i = 0; i < a.size(); ++i) {
          EXPECT_TRUE(a[i]->from() == b[i]->from() && a[i]->to() == b[i]->to()) << "scene " << scene << " line " << i;
          EXPECT_EQ(pieces(*a[i]), pieces(*b[i])) << "scene " << scene << " line " << i;
        }
        // The soup's own edges: the same pieces too (the extra body hides nothing of them).
        for (const Segment& s : fast.segments)
          if (s.kind == Segment::Kind::Edge) EXPECT_EQ(pieces(s), pieces(edge(other, 0, s.v0, s.v1))) << "scene " << scene;
      }
      lines += std::count_if(fast.segments.begin(), fast.segments.end(),
                             [](const Segment& s) { return s.kind == Segment::Kind::Intersection; });
    }
  }
  EXPECT_GT(lines, 300u);  // the soups do interpenetrate
}

// Feature lines of a mesh with many more triangles than drawn segments take only the
// occluders near those segments (Engine::near_segments, a filter). Every feature segment must
// get the same pieces as the same edge in the drawing of all edges, where every front
// triangle is an occluder: bumpy closed spheres (jagged outlines, parts of the outline hidden
// by bumps in front), a second body through them (intersection lines), several views.
TEST(FaceOccluders, FeatureLinesTakeTheOccludersAllEdgesTake) {
  std::mt19937 rng(20261130);
  std::uniform_real_distribution<double> phase(0, 6.28);
  auto bumpy_sphere = [&](int n, int m, const Rational& cx) {
    std::vector<Point3> vs;
    std::vector<Face> fs;
    const double p1 = phase(rng), p2 = phase(rng);
    auto at = [&](double lat, double lon) {  // smooth bumps: few creases, outlines hidden by bumps
      Rational r = Rational(1) + Rational(std::lround(400 * 0.08 * std::sin(5 * lat + p1) * std::cos(7 * lon + p2)), 400);
      auto q = [](double v) { return Rational(static_cast<long>(std::lround(v * 4096)), 4096); };
      vs.push_back(Point3(cx + r * q(std::cos(lat) * std::cos(lon)), r * q(std::cos(lat) * std::sin(lon)), r * q(std::sin(lat))));
    };
    at(-M_PI / 2, 0);
    for (int i = 1; i < n; ++i)
      for (int j = 0; j < m; ++j) at(-M_PI / 2 + M_PI * i / n, 2 * M_PI * j / m);
    at(M_PI / 2, 0);
    const int top = static_cast<int>(vs.size()) - 1;
    auto id = [&](int i, int j) { return 1 + (i - 1) * m + (j % m); };
    for (int j = 0; j < m; ++j) fs.push_back({0, id(1, j + 1), id(1, j)});
    for (int i = 1; i + 1 < n; ++i)
      for (int j = 0; j < m; ++j) {
        fs.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
        fs.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
      }
    for (int j = 0; j < m; ++j) fs.push_back({top, id(n - 1, j), id(n - 1, j + 1)});
    return Polyhedron(vs, fs);
  };
  const std::vector<Camera> views = {make_orthographic(Vector3(1, Q("1.3"), Q("1.7"))), make_orthographic(Vector3(0, 0, 1)),
                                     make_orthographic(Vector3(1, 0, 0)), make_orthographic(Vector3(Q("-0.3"), 1, Q("0.2")))};
  std::size_t compared = 0, crossings = 0, hidden = 0;
  for (int scene = 0; scene < 3; ++scene) {
    Polyhedron a = bumpy_sphere(60, 120, 0), b = bumpy_sphere(10, 20, Rational(3, 2));
    const std::size_t tris = a.num_faces() + b.num_faces();
    for (const Camera& cam : views) {
      LineOptions fo;
      fo.edges = EdgeSelection::Feature;
      fo.crease_degrees = 40;
      LineDrawing feat = face_occluders({&a, &b}, cam, fo);
      LineOptions ao = fo;
      ao.edges = EdgeSelection::All;
      ao.classify_all = true;
      LineDrawing all = face_occluders({&a, &b}, cam, ao);
      ASSERT_LT(feat.segments.size() * 8, tris) << "the filter must apply";
      std::vector<const Segment*> fx, ax;
      for (const Segment& s : feat.segments) {
        if (s.kind == Segment::Kind::Intersection) {
          fx.push_back(&s);
          continue;
        }
        EXPECT_EQ(pieces(s), pieces(edge(all, s.body, s.v0, s.v1))) << "scene " << scene << " edge " << s.v0 << "-" << s.v1;
        ++compared;
        if (!s.self_hidden)
          for (const Piece& p : s.pieces) hidden += !p.visible;
      }
      for (const Segment& s : all.segments)
        if (s.kind == Segment::Kind::Intersection) ax.push_back(&s);
      ASSERT_EQ(fx.size(), ax.size());
      for (std::size_t i = 0; i < fx.size(); ++i) EXPECT_EQ(pieces(*fx[i]), pieces(*ax[i])) << "scene " << scene << " line " << i;
      crossings += fx.size();
    }
  }
  EXPECT_GT(compared, 1000u);
  EXPECT_GT(crossings, 50u);
  EXPECT_GT(hidden, 100u);  // outlines hidden by bumps and by the other body: occluders at work
}

// The wide (Int128) path's volume sum passes Int128: 128 coincident copies of the cube
// [-2^39, 2^39]^3, one body, six times the volume 6·2^120 each, 3·2^128 in all. A sum kept in
// Int128 wraps to exactly 0 (the body would be "zero volume", a surface); the carried sum is
// positive: a closed solid, no note.
TEST(FaceOccluders, VolumeSumCarriesPastInt128OnTheWidePath) {
  const Rational h(mpz_class(1) << 39);
  const Polyhedron cube = make_box(Point3(-h, -h, -h), Point3(h, h, h));
  std::vector<Point3> vs;
  std::vector<Face> fs;
  for (int copy = 0; copy < 128; ++copy) {
    const int o = static_cast<int>(vs.size());
    for (std::size_t v = 0; v < cube.num_vertices(); ++v) vs.push_back(cube.vertices()[v]);
    for (const Face& f : cube.faces()) {
      Face g = f;
      for (int& i : g) i += o;
      fs.push_back(g);
    }
  }
  const Polyhedron body(std::move(vs), std::move(fs));
  LineDrawing r = run({&body}, make_orthographic(Vector3(1, 2, 3)));
  for (const auto& n : r.notes) EXPECT_EQ(n.text.find("zero volume"), std::string::npos) << n.text;
  EXPECT_TRUE(r.notes.empty());
  EXPECT_EQ(r.segments.size(), 128u * 12u);  // every edge of every copy
}

// The volume's sign on the multi-limb and GMP paths comes from doubles with a proven bound
// (Engine::volume_filter) or, when the bound does not decide, from the exact sum. A closed
// pillow of zero thickness (a convex 120-gon on a tilted plane, its top a fan from one corner,
// its bottom a fan from another, vertices far from the origin in sevenths that do not round
// exactly) has volume 0 exactly while the doubles' sum is not 0: only a bound that holds
// leaves it to the exact sum, which calls the body a surface. A small box as far away has a
// volume far below its monomials: the filter cannot decide, the exact sum finds a solid (no
// note). Each with an extra far, tiny body that puts the scene on the multi-limb path (2^-70)
// and on GMP integers (2^-200).
TEST(FaceOccluders, VolumeSignOfFarFlatAndSmallBodiesOnTheWiderPaths) {
  const Rational far(1000003);
  auto at = [&](const Rational& x, const Rational& y) { return Point3(far + x, far + y, far + x / 3 + y / 5); };
  const int n = 120;
  std::vector<Point3> vs;
  std::vector<Face> fs;
  for (int i = 0; i < n; ++i) vs.push_back(at(Rational(i, 7), Rational(i * i, 49)));  // on a parabola: convex
  for (int i = 1; i + 1 < n; ++i) fs.push_back({0, i, i + 1});
  for (int i = 0; i + 2 < n; ++i) fs.push_back({n - 1, i + 1, i});
  const Polyhedron pillow(vs, fs);
  const Polyhedron small = make_box(at(Rational(1, 7), Rational(2, 7)), at(Rational(3, 7), Rational(5, 7)) + Vector3(0, 0, Rational(1, 7)));
  auto tiny = [](const char* eps) {
    const Rational e = Q(eps);
    return Polyhedron({Point3(Rational(-40), Rational(-40), Rational(-40)), Point3(Rational(-40) + e, Rational(-40), Rational(-40)),
                       Point3(Rational(-40), Rational(-40) + e, Rational(-40))},
                      {{0, 1, 2}});
  };
  const Polyhedron limbs = tiny("1/1180591620717411303424"), big = tiny("1/1606938044258990275541962092341162602522202993782792835301376");
  for (const Polyhedron* extra : {&limbs, &big}) {
    LineDrawing r = run({&pillow, &small, extra}, make_orthographic(Vector3(1, 2, 3)));
    EXPECT_EQ(r.stats.faces->integer_path, extra == &limbs);
    std::set<int> zero_volume;
    for (const auto& n : r.notes)
      if (n.text.find("zero volume") != std::string::npos) zero_volume.insert(n.body);
    EXPECT_EQ(zero_volume, std::set<int>{0}) << (extra == &big ? "GMP" : "multi-limb");
    bool small_noted = false;
    for (const auto& n : r.notes) small_noted = small_noted || n.body == 1;
    EXPECT_FALSE(small_noted);
  }
}

// A polyhedron whose vertices are in a compact store (kernel/point_store.hpp) draws exactly
// as the same polyhedron with exact points: the same segments and pieces, the same 2D
// drawing to the bit, on every number path's scale, in orthographic views (general, along an
// axis, every edge and feature lines) and in perspective, alone and interpenetrating a body
// with exact points. Alone in an orthographic view its exact points are never made (the
// memory a large mesh saves).
namespace {
void expect_same_drawing(const LineDrawing& a, const LineDrawing& b, const Camera& cam) {
  ASSERT_EQ(a.segments.size(), b.segments.size());
  for (std::size_t i = 0; i < a.segments.size(); ++i) {
    const Segment &s = a.segments[i], &t = b.segments[i];
    ASSERT_EQ(s.kind, t.kind);
    ASSERT_EQ(s.line, t.line);
    ASSERT_EQ(s.v0, t.v0);
    ASSERT_EQ(s.v1, t.v1);
    ASSERT_EQ(pieces(s), pieces(t)) << i;
  }
  const Drawing2D da = project_drawing(a, cam), db = project_drawing(b, cam);
  EXPECT_EQ(da.points, db.points);
}
}  // namespace

TEST(FaceOccluders, CompactVerticesDrawTheSameWithoutMakingThePoints) {
  const Polyhedron exact = load_mesh(kData + "/sphere2000.off");
  ASSERT_FALSE(exact.vertex_store().compact());
  for (const Camera& cam : {make_orthographic(Vector3(Q("1"), Q("1.3"), Q("1.7"))), make_orthographic(Vector3(0, 0, 1))})
    for (EdgeSelection e : {EdgeSelection::All, EdgeSelection::Feature}) {
      const Polyhedron compact = *compact_copy(exact);
      ASSERT_TRUE(compact.vertex_store().compact());
      expect_same_drawing(run({&compact}, cam, e, "10"), run({&exact}, cam, e, "10"), cam);
      EXPECT_FALSE(compact.vertex_store().points_made());
    }
  const Polyhedron compact = *compact_copy(exact);
  const Polyhedron rod = box("-0.25", "-0.25", "-2", "0.25", "0.25", "0.5");
  for (const Camera& cam : {make_orthographic(Vector3(Q("1"), Q("1.3"), Q("1.7"))), make_perspective(P("3", "2.5", "4"), P("0", "0", "0"))}) {
    expect_same_drawing(run({&compact, &rod}, cam), run({&exact, &rod}, cam), cam);
    expect_same_drawing(run({&compact}, cam, EdgeSelection::All), run({&exact}, cam, EdgeSelection::All), cam);
  }
}

// A drawing without hidden lines leaves out the edges a body's own faces hide wholly
// (FaceRouteHooks::back_edges off): every other segment the same, in order, with the same
// pieces; the same statistics; the same frame and so the same 2D drawing of what is seen, far
// from the origin (where the frame is not the identity and the back's vertices reach beyond
// the ends the front keeps) too. A see-through body keeps its back edges, and a perspective
// view keeps every one (clipping at the eye moves their ends).
namespace {
bool wholly_hidden_back(const Segment& s) {
  return s.kind == Segment::Kind::Edge && s.self_hidden && s.pieces.size() == 1 && !s.pieces.front().visible;
}

LineDrawing run_hooks(const std::vector<const Polyhedron*>& bodies, const Camera& c, const FaceRouteHooks& hooks) {
  LineOptions o;
  o.edges = EdgeSelection::All;
  return face_occluders(bodies, c, o, hooks);
}
}  // namespace

TEST(FaceOccluders, BackEdgesLeftOutChangeNoDrawnLineNorTheFrame) {
  const Polyhedron sphere = load_mesh(kData + "/sphere2000.off");
  const Rational far = Rational(mpz_class(1) << 120);
  std::vector<Point3> moved;
  for (const Point3& v : sphere.vertices()) moved.push_back(Point3(v.x() + far, v.y() - far, v.z() * 3 + far));
  const Polyhedron far_sphere(moved, sphere.faces());
  const Polyhedron rod = box("-0.25", "-0.25", "-2", "0.25", "0.25", "0.5");
  struct Case {
    std::vector<const Polyhedron*> bodies;
    Camera cam;
    std::vector<char> see_through;
    bool identity;
  };
  const std::vector<Case> cases = {
      {{&sphere, &rod}, make_orthographic(Vector3(Q("1"), Q("1.3"), Q("1.7"))), {}, true},
      {{&sphere}, make_orthographic(Vector3(0, 0, 1)), {}, true},
      {{&far_sphere}, make_orthographic(Vector3(Q("1"), Q("-1.3"), Q("0.2"))), {}, false},
      {{&sphere, &rod}, make_orthographic(Vector3(Q("1"), Q("1.3"), Q("1.7"))), {0, 1}, true},  // the rod of glass
      {{&sphere, &rod}, make_perspective(P("3", "2.5", "4"), P("0", "0", "0")), {}, true},
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const Case& c = cases[k];
    FaceRouteHooks all, front;
    all.see_through = front.see_through = c.see_through;
    front.back_edges = false;
    const LineDrawing a = run_hooks(c.bodies, c.cam, all), f = run_hooks(c.bodies, c.cam, front);
    std::size_t left = 0, j = 0;
    for (const Segment& s : a.segments) {
      const bool glass = s.body >= 0 && static_cast<std::size_t>(s.body) < c.see_through.size() && c.see_through[s.body];
      if (!c.cam.perspective && !glass && wholly_hidden_back(s)) {
        ++left;
        continue;
      }
      ASSERT_LT(j, f.segments.size()) << k;
      const Segment& t = f.segments[j++];
      ASSERT_EQ(s.kind, t.kind) << k;
      ASSERT_EQ(s.line, t.line) << k;
      ASSERT_EQ(s.body, t.body) << k;
      ASSERT_EQ(s.v0, t.v0) << k;
      ASSERT_EQ(s.v1, t.v1) << k;
      ASSERT_EQ(pieces(s), pieces(t)) << k << " segment " << j;
    }
    EXPECT_EQ(j, f.segments.size()) << k;
    EXPECT_EQ(left > 0, !c.cam.perspective) << k;  // (every view has a body that hides)
    EXPECT_EQ(a.stats.edges, f.stats.edges) << k;
    EXPECT_EQ(a.stats.self_hidden, f.stats.self_hidden) << k;
    EXPECT_EQ(a.stats.pairs_tested, f.stats.pairs_tested) << k;
    const DrawingFrame fa = drawing_projector(a, c.cam).frame(), ff = drawing_projector(f, c.cam).frame();
    EXPECT_EQ(fa.identity, c.identity) << k;
    EXPECT_EQ(ff.identity, fa.identity) << k;
    EXPECT_EQ(ff.centre, fa.centre) << k;
    EXPECT_EQ(ff.scale, fa.scale) << k;
    Project2DOptions seen;
    seen.hidden = false;
    const Drawing2D da = project_drawing(a, c.cam, seen), df = project_drawing(f, c.cam, seen);
    EXPECT_EQ(da.points, df.points) << k;
    EXPECT_EQ(da.lines.size(), df.lines.size()) << k;
  }
}
