// Roberts' body matrix (course notes, section 27): [V] is 4 x n, column j holds the
// plane (a_j, b_j, c_j, d_j) of face j, so that [x y z 1]·[V] gives one test value per face.
// Signs are corrected so that an interior point (the average of the vertices) gives a
// positive value for every column. A body transformed by [T] has [VT] = [T]^-1·[V].
#pragma once

#include <stdexcept>
#include <vector>

#include "kernel/polyhedron.hpp"
#include "kernel/transform.hpp"

namespace hlr {

/// Raised when the interior point lies on a face plane (the body is flat or not convex, so
/// no sign correction can make every column positive). `face()` names the plane.
class BodyMatrixError : public std::runtime_error {
 public:
  BodyMatrixError(int face, const std::string& what) : std::runtime_error(what), face_(face) {}
  int face() const { return face_; }

 private:
  int face_;
};

struct BodyMatrix {
  BodyMatrixData V;             // sign-corrected, one column per face
  Point3 interior;              // the average of the vertices, [S] = [x y z 1]
  std::vector<Rational> s_v;    // [S]·[V] before correction, one value per face
  std::vector<bool> negated;    // columns multiplied by -1
};

/// Builds the sign-corrected body matrix from exact face planes. Throws BodyMatrixError when
/// the interior point lies on a face's plane, or when a face plane is degenerate.
BodyMatrix body_matrix(const Polyhedron& body);

/// Body matrix from planes and an interior point directly (for hand-made examples).
BodyMatrix body_matrix(const std::vector<Plane>& planes, const Point3& interior);

/// [VT] = [T]^-1·[V] for a body moved by the non-singular transform T (row-vector
/// convention). Throws std::invalid_argument when T is singular.
BodyMatrixData transformed_body_matrix(const BodyMatrixData& V, const Matrix4& T);

/// [x y z w]·[V]: one test value per face (w = 1 for points, 0 for directions).
std::vector<Rational> row_times_matrix(const RowVector4& row, const BodyMatrixData& V);

}  // namespace hlr
