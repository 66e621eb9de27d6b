// Convexity test, course notes section 23 (algorithms/solids/convexity.hpp).
#include <gtest/gtest.h>

#include <filesystem>

#include "algorithms/solids/convexity.hpp"
#include "io/readers/mesh_reader.hpp"
#include "kernel/predicates.hpp"

using namespace hlr;

namespace {
const std::string kData = HLR_DATA_DIR;
}

TEST(Convexity, ConvexBodies) {
  for (const char* f : {"/cube.off", "/wedge.off", "/pyramid.off", "/tetra_decimal.obj"})
    EXPECT_TRUE(convexity(load_mesh(kData + f)).convex()) << f;
}

TEST(Convexity, LPrismNamesAFaceWithVerticesOnBothSides) {
  Polyhedron l = load_mesh(kData + "/l_prism.off");
  ConvexityResult r = convexity(l);
  ASSERT_EQ(r.verdict, ConvexityResult::Verdict::NonConvex);
  const Plane& h = l.planes()[r.face];
  EXPECT_EQ(side_of_plane(h, l.vertices()[r.vertex_positive]), Sign::Positive);
  EXPECT_EQ(side_of_plane(h, l.vertices()[r.vertex_negative]), Sign::Negative);
  // Face 4 is the inner wall y = 1 between (2,1) and (1,1): vertex 4 (1,2,0) is on one side,
  // vertex 0 (0,0,0) on the other.
  EXPECT_EQ(r.face, 4);
  EXPECT_NE(describe(r).find("face 4"), std::string::npos);
}

TEST(Convexity, FlatBodyIsDegenerate) {
  std::vector<Point3> vs = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(1, 1, 0), Point3(0, 1, 0)};
  EXPECT_EQ(convexity(Polyhedron(vs, {{0, 1, 2, 3}, {3, 2, 1, 0}})).verdict, ConvexityResult::Verdict::Flat);
}

TEST(Convexity, CoplanarNeighbouringFacesStillConvex) {
  // The cube with its top split into two triangles: vertices on a plane count as "one side".
  Polyhedron cube = load_mesh(kData + "/cube.off");
  std::vector<Face> f = cube.faces();
  Face top = f[5];
  f[5] = {top[0], top[1], top[2]};
  f.push_back({top[0], top[2], top[3]});
  EXPECT_TRUE(convexity(Polyhedron(cube.vertices(), f)).convex());
}

TEST(Convexity, DentByAnUltraSmallAmountIsCaught) {
  // A square pyramid whose base centre is pulled into the body by 1e-30: not convex.
  std::vector<Point3> vs = {Point3(0, 0, 0), Point3(2, 0, 0), Point3(2, 2, 0), Point3(0, 2, 0),
                            Point3(1, 1, 2), Point3(1, 1, parse_rational("1e-30"))};
  std::vector<Face> f = {{0, 5, 1}, {1, 5, 2}, {2, 5, 3}, {3, 5, 0}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  EXPECT_EQ(convexity(Polyhedron(vs, f)).verdict, ConvexityResult::Verdict::NonConvex);
  vs[5] = Point3(1, 1, parse_rational("-1e-30"));  // pushed out instead: convex
  EXPECT_TRUE(convexity(Polyhedron(vs, f)).convex());
}


// The hull method (hull_planes.cpp) on the cases a convex hull treats specially: points on a
// facet that are not hull vertices, repeated points, a vertex no face uses, faces that are not
// hull triangles (quads, another triangulation of a flat side), non-planar faces, a flat body,
// dents of 1e-30 and coordinates beyond the range of doubles. Verdict and witnesses as the
// plain scan's.
TEST(ConvexityHull, SameAsAllPairsWhereHullsAreHard) {
  int cases = 0, convex = 0;
  auto same = [&](const std::vector<Point3>& vs, const std::vector<Face>& faces, const std::string& what) {
    const Polyhedron p(vs, faces);
    const ConvexityResult a = convexity(p, ConvexityMethod::AllPairs), b = convexity(p, ConvexityMethod::Hull);
    EXPECT_EQ(a.verdict, b.verdict) << what;
    EXPECT_EQ(a.face, b.face) << what;
    EXPECT_EQ(a.vertex_positive, b.vertex_positive) << what;
    EXPECT_EQ(a.vertex_negative, b.vertex_negative) << what;
    ++cases;
    convex += a.convex();
  };
  // A cube with its top split at its centre (a vertex on a facet, not a hull vertex), as four
  // triangles or as quads from the centre to the edge midpoints.
  std::vector<Point3> cube = {Point3(0, 0, 0), Point3(2, 0, 0), Point3(2, 2, 0), Point3(0, 2, 0),
                              Point3(0, 0, 2), Point3(2, 0, 2), Point3(2, 2, 2), Point3(0, 2, 2), Point3(1, 1, 2)};
  std::vector<Face> sides = {{3, 2, 1, 0}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::vector<Face> fan = sides;
  for (int k = 0; k < 4; ++k) fan.push_back({4 + k, 4 + (k + 1) % 4, 8});
  same(cube, fan, "cube, top fanned from its centre");
  const Rational tiny = Rational(1) / Rational("1000000000000000000000000000000");
  for (const Rational& dz : std::vector<Rational>{tiny, -tiny}) {
    std::vector<Point3> d = cube;
    d[8] = Point3(1, 1, 2 + dz);  // the centre lifted out (not convex) or pushed in (convex)
    same(d, fan, "cube, top centre moved by 1e-30");
  }
  // The cube's top as one quad and as the other diagonal's two triangles; a repeated corner.
  std::vector<Face> quad = sides;
  quad.push_back({4, 5, 6, 7});
  same(cube, quad, "cube, an unused point on the top");
  std::vector<Face> diag = sides;
  diag.push_back({4, 5, 7}), diag.push_back({5, 6, 7});
  same(cube, diag, "cube, top split along the other diagonal");
  std::vector<Point3> rep = cube;
  rep.push_back(cube[6]);  // vertex 9 = vertex 6
  std::vector<Face> repf = sides;
  repf[2] = {1, 2, 9, 5}, repf.push_back({4, 5, 6, 7});
  same(rep, repf, "cube, a corner repeated");
  // An unused point outside: not convex by the plain test's reading (every vertex counts).
  std::vector<Point3> out = cube;
  out[8] = Point3(1, 1, 3);
  same(out, quad, "cube, an unused point above it");
  // A non-planar quad side (one corner raised by 1/7): its Newell plane passes through none or
  // some of its corners.
  std::vector<Point3> bent = cube;
  bent[6] = Point3(2, 2, 2 + Rational(1) / 7);
  same(bent, quad, "cube, a non-planar top");
  // A flat body, and coordinates far beyond the range of doubles.
  same({Point3(0, 0, 0), Point3(1, 0, 0), Point3(1, 1, 0), Point3(0, 1, 0)}, {{0, 1, 2, 3}, {3, 2, 1, 0}}, "flat square");
  const Rational big = Rational("1" + std::string(400, '0'));
  std::vector<Point3> huge;
  for (const Point3& c : cube) huge.emplace_back(c.x() * big, c.y() * big, c.z() * big);
  same(huge, fan, "cube scaled by 1e400");
  huge[8] = Point3(big, big, 2 * big + 1);
  same(huge, fan, "cube scaled by 1e400, centre lifted by 1");
  EXPECT_EQ(cases, 11);
  EXPECT_GE(convex, 5);
}

namespace hlr {
namespace {

// The tree-pruned test gives the plain test's verdict and witnesses (`hlr info` on
// 100k faces in seconds): every data mesh, CGAL's meshes when extracted, and random convex
// polytopes with one vertex pushed in or out.
TEST(ConvexityTree, SameVerdictAndWitnessesAsAllPairs) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(kData))
    if (e.path().extension() == ".off") files.push_back(e.path().string());
  for (const char* m : {"/fandisk.off", "/cube-meshed.off", "/sphere.off", "/ellipsoid.off", "/cube_quad.off", "/bunny00.off"})
    if (std::filesystem::exists(std::string(HLR_CORPUS_DIR) + m)) files.push_back(std::string(HLR_CORPUS_DIR) + m);
  int convex = 0, nonconvex = 0;
  auto same = [&](const Polyhedron& p, const std::string& what) {
    ConvexityResult a = convexity(p, ConvexityMethod::AllPairs);
    for (ConvexityMethod m : {ConvexityMethod::Tree, ConvexityMethod::Hull}) {
      ConvexityResult b = convexity(p, m);
      EXPECT_EQ(a.verdict, b.verdict) << what;
      EXPECT_EQ(a.face, b.face) << what;
      EXPECT_EQ(a.vertex_positive, b.vertex_positive) << what;
      EXPECT_EQ(a.vertex_negative, b.vertex_negative) << what;
    }
    (a.convex() ? convex : nonconvex)++;
  };
  for (const std::string& f : files) {
    try {
      same(load_mesh(f), f);
    } catch (const std::exception&) {
    }
  }
  // A convex polytope: the points of a fine grid on a sphere-like surface are hard to build
  // exactly; use a prism over a regular-ish convex polygon with many vertices (rational points
  // on the unit circle from Pythagorean parametrisation), then push one cap vertex.
  std::vector<Point3> vs;
  const int n = 200;
  for (int i = 0; i < n; ++i) {
    Rational t(2 * i - n + 1, n);  // tan(theta/2) in (-1, 1): a half circle... use both halves
    Rational x = (1 - t * t) / (1 + t * t), y = 2 * t / (1 + t * t);
    vs.emplace_back(x, y, Rational(0));
  }
  for (int i = 0; i < n; ++i) vs.emplace_back(-vs[i].x(), -vs[i].y(), Rational(0));
  const int m = 2 * n;
  for (int i = 0; i < m; ++i) vs.emplace_back(vs[i].x(), vs[i].y(), Rational(1));
  std::vector<Face> faces;
  Face bottom, top;
  for (int i = m - 1; i >= 0; --i) bottom.push_back(i);
  for (int i = 0; i < m; ++i) top.push_back(m + i);
  faces.push_back(bottom);
  faces.push_back(top);
  for (int i = 0; i < m; ++i) faces.push_back({i, (i + 1) % m, m + (i + 1) % m, m + i});
  Polyhedron prism(vs, faces);
  same(prism, "prism");
  EXPECT_TRUE(convexity(prism, ConvexityMethod::Tree).convex());
  for (int k : {3, 77, 150}) {
    std::vector<Point3> dented = vs;
    dented[k] = Point3(vs[k].x() * Rational(9, 10), vs[k].y() * Rational(9, 10), Rational(0));
    same(Polyhedron(dented, faces), "dented prism");
    EXPECT_FALSE(convexity(Polyhedron(dented, faces), ConvexityMethod::Tree).convex());
  }
  EXPECT_GT(convex, 3);
  EXPECT_GT(nonconvex, 3);
}

}  // namespace
}  // namespace hlr
