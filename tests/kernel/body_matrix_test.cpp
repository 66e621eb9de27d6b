// Roberts' body matrix, course notes section 27 (kernel/body_matrix.hpp).
#include "kernel/body_matrix.hpp"

#include <gtest/gtest.h>

#include "io/readers/mesh_reader.hpp"
#include "support/numbers.hpp"

using namespace hlr;

namespace {
const std::string kData = HLR_DATA_DIR;
using hlr::test::Q;
}  // namespace

// The notes' example: the box [-1, 1]^3, columns left, right, bottom, top, back, front.
TEST(BodyMatrix, CourseNotesCube) {
  Polyhedron cube = load_mesh(kData + "/cube.off");
  BodyMatrix bm = body_matrix(cube);
  const int expected[4][6] = {{1, -1, 0, 0, 0, 0}, {0, 0, 1, -1, 0, 0}, {0, 0, 0, 0, 1, -1}, {1, 1, 1, 1, 1, 1}};
  ASSERT_EQ(bm.V.cols(), 6);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 6; ++j) EXPECT_EQ(bm.V(i, j), expected[i][j]) << i << "," << j;
  EXPECT_EQ(bm.interior, Point3(0, 0, 0));
  // The file's faces are outward, so every column needed the sign correction.
  for (std::size_t j = 0; j < 6; ++j) {
    EXPECT_TRUE(bm.negated[j]);
    EXPECT_EQ(bm.s_v[j], -1);
  }
  // Viewer at +z infinity: E = [0 0 -1 0]; E·V = [0 0 0 0 -1 1]: back face non-facing.
  RowVector4 E;
  E << 0, 0, -1, 0;
  std::vector<Rational> ev = row_times_matrix(E, bm.V);
  const int want[6] = {0, 0, 0, 0, -1, 1};
  for (int j = 0; j < 6; ++j) EXPECT_EQ(ev[j], want[j]);
}

TEST(BodyMatrix, SignCorrectionOnlyWhereNeeded) {
  // Planes as the notes write them first: x+1, x-1, y+1, y-1, z+1, z-1; [S][V] = [1 -1 1 -1 1 -1].
  std::vector<Plane> planes = {Plane(1, 0, 0, 1), Plane(1, 0, 0, -1), Plane(0, 1, 0, 1),
                               Plane(0, 1, 0, -1), Plane(0, 0, 1, 1), Plane(0, 0, 1, -1)};
  BodyMatrix bm = body_matrix(planes, Point3(0, 0, 0));
  const int sv[6] = {1, -1, 1, -1, 1, -1};
  for (int j = 0; j < 6; ++j) {
    EXPECT_EQ(bm.s_v[j], sv[j]);
    EXPECT_EQ(bm.negated[j], sv[j] < 0);
    EXPECT_EQ(bm.V(3, j), 1);  // every d becomes +1
  }
  EXPECT_EQ(bm.V(0, 1), -1);
}

TEST(BodyMatrix, TransformedBodyMatrixIsInverseTimesV) {
  Polyhedron cube = load_mesh(kData + "/cube.off");
  BodyMatrix bm = body_matrix(cube);
  Matrix4 T = compose(scaling(Vector3(2, 1, 1)), translation(Vector3(3, 0, Q("1/2"))));
  BodyMatrixData VT = transformed_body_matrix(bm.V, T);
  // The moved cube is [1, 5] x [-1, 1] x [-1/2, 3/2]; its centre (3, 0, 1/2) is inside every plane.
  RowVector4 centre;
  centre << 3, 0, Q("1/2"), 1;
  for (const Rational& v : row_times_matrix(centre, VT)) EXPECT_GT(v, 0);
  // Transformed vertices lie on their faces' transformed planes (value 0), e.g. vertex 7.
  Point3 v7 = apply(T, cube.vertices()[7]);
  RowVector4 row;
  row << v7.x(), v7.y(), v7.z(), 1;
  std::vector<Rational> vals = row_times_matrix(row, VT);
  EXPECT_EQ(vals[1], 0);  // right
  EXPECT_EQ(vals[3], 0);  // top
  EXPECT_EQ(vals[5], 0);  // front
  EXPECT_GT(vals[0], 0);
  // Column "right" is x = 5 after the move: (-1, 0, 0, 5) up to the positive factor 1/2.
  EXPECT_EQ(VT(0, 1), Q("-1/2"));
  EXPECT_EQ(VT(3, 1), Q("5/2"));
  EXPECT_THROW(transformed_body_matrix(bm.V, scaling(Vector3(1, 0, 1))), std::invalid_argument);
}

TEST(BodyMatrix, InteriorPointOnAFacePlaneIsAnError) {
  // The L-prism's vertex average (5/6, 5/6, 1/2) is not on a face plane, but a flat quad's is.
  std::vector<Point3> vs = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(1, 1, 0), Point3(0, 1, 0)};
  Polyhedron flat(vs, {{0, 1, 2, 3}, {3, 2, 1, 0}});
  try {
    body_matrix(flat);
    FAIL();
  } catch (const BodyMatrixError& e) {
    EXPECT_EQ(e.face(), 0);
  }
}
