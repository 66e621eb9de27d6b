// Convexity test, course notes section 23 (algorithms/convexity.hpp).
#include <gtest/gtest.h>

#include "algorithms/convexity.hpp"
#include "io/mesh_reader.hpp"
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
