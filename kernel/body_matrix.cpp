// Roberts' body matrix with the course notes' sign correction (see body_matrix.hpp).
#include "kernel/body_matrix.hpp"

namespace hlr {

BodyMatrix body_matrix(const std::vector<Plane>& planes, const Point3& interior) {
  BodyMatrix bm;
  bm.interior = interior;
  const int n = static_cast<int>(planes.size());
  bm.V.resize(4, n);
  for (int j = 0; j < n; ++j) {
    const Plane& h = planes[j];
    if (h.is_degenerate())
      throw BodyMatrixError(j, "face " + std::to_string(j) + " has zero area: it has no plane");
    Rational s = h.value(interior);
    bm.s_v.push_back(s);
    if (s == 0)
      throw BodyMatrixError(j, "the interior point " + to_string(interior) +
                                   " lies on the plane of face " + std::to_string(j) +
                                   ": the body is flat or not convex");
    bool neg = s < 0;
    bm.negated.push_back(neg);
    for (int i = 0; i < 4; ++i) bm.V(i, j) = neg ? Rational(-h[i]) : h[i];
  }
  return bm;
}

BodyMatrix body_matrix(const Polyhedron& body) {
  std::vector<const Point3*> pts;
  for (const Point3& p : body.vertices()) pts.push_back(&p);
  if (pts.empty()) throw BodyMatrixError(-1, "the body has no vertices");
  return body_matrix(body.planes(), centroid_of_vertices(pts.data(), pts.size()));
}

BodyMatrixData transformed_body_matrix(const BodyMatrixData& V, const Matrix4& T) {
  auto inv = inverse(T);
  if (!inv) throw std::invalid_argument("the transform is singular: it has no inverse");
  BodyMatrixData out(4, V.cols());
  for (int j = 0; j < V.cols(); ++j)
    for (int i = 0; i < 4; ++i) {
      Rational s = 0;
      for (int k = 0; k < 4; ++k) s += (*inv)(i, k) * V(k, j);
      out(i, j) = s;
    }
  return out;
}

std::vector<Rational> row_times_matrix(const RowVector4& row, const BodyMatrixData& V) {
  std::vector<Rational> out(V.cols());
  for (int j = 0; j < V.cols(); ++j) {
    Rational s = 0;
    for (int k = 0; k < 4; ++k) s += row(k) * V(k, j);
    out[j] = s;
  }
  return out;
}

}  // namespace hlr
