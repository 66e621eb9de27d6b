// Shading arithmetic in doubles (course notes sections 36-39), after every exact decision: the
// doubles of exact points, face and vertex normals, the flat colour of a face, the default
// lights of a camera, and the world point of a picture point on a face's plane. Colours only:
// nothing here decides what is seen.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "algorithms/model/camera.hpp"
#include "algorithms/shading/lighting.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr {

/// The middle of the certified bounds an exact number carries (within an ulp of the nearest
/// double, without a rational on the way).
inline double mid(const Bounds& b) { return b.lo + (b.hi - b.lo) / 2; }
inline Vec3d d3(const Point3& p) { return {mid(p.approx(0)), mid(p.approx(1)), mid(p.approx(2))}; }
inline Vec3d d3(const Vector3& p) { return {mid(p.approx(0)), mid(p.approx(1)), mid(p.approx(2))}; }
inline double dot3(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
/// a scaled to length 1 (a zero vector stays zero).
inline Vec3d unit(Vec3d a) {
  const double l = std::sqrt(dot3(a, a));
  return l > 0 ? Vec3d{a[0] / l, a[1] / l, a[2] / l} : a;
}
inline Vec3d minus(const Vec3d& a, const Vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3d cross3(const Vec3d& a, const Vec3d& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

/// The unit outward normal of face f in doubles: Newell's sum over its corners' doubles, or,
/// where those cannot hold it, the exact plane's normal scaled by a power of two.
Vec3d face_normal(const Polyhedron& p, std::size_t f);

/// The camera's eye and unit view direction in doubles, once per drawing (each costs exact
/// copies).
struct ViewDoubles {
  Vec3d eye, view;
  explicit ViewDoubles(const Camera& c) : eye(d3(c.eye)), view(unit(d3(c.direction))) {}
};

/// The flat colour of face f of `p` in material `m` under `light`, for the side the viewer sees
/// (back: the back side; `n` the face's unit normal), shaded at the face's centroid.
Rgb flat_face_colour(const Polyhedron& p, std::size_t f, const Material& m, const Lighting& light, bool back, Vec3d n, bool perspective,
                     const ViewDoubles& vd);

/// The default lights of a camera (default_lighting in the viewer's frame), their directions
/// snapped to sixty-fourths so that shadows decide with small exact numbers.
Lighting camera_lighting(const Camera& cam);

/// Doubles of the picture plane, for shading only: the world point of a picture point on a
/// plane, and the direction toward the viewer.
struct Lift {
  bool persp;
  Vec3d e, r, u, d, v;
  double rr, uu, dd;
  explicit Lift(const Camera& cam);
  /// The point of the plane n·X + c = 0 on the sight ray through (x, y).
  Vec3d at(double x, double y, const Vec3d& n, double c) const;
  Vec3d to_viewer(const Vec3d& p) const { return persp ? unit(minus(e, p)) : unit(v); }
};

/// Shading data of one body: unit face normals and the faces around each vertex, for vertex
/// normals that average the faces within the smoothing angle (notes section 39).
struct BodyNormals {
  std::vector<Vec3d> face;
  std::vector<std::vector<int>> around;  // vertex -> faces
};
BodyNormals body_normals(const Polyhedron& p);
/// The normal of vertex v of face f: the faces around v within cos_smooth of f's, averaged.
Vec3d vertex_normal(const BodyNormals& n, int f, int v, double cos_smooth);

/// Barycentric weights of p over the fan triangle (0, k, k + 1) of the polygon's corners that
/// holds it (in the plane of normal n: the dominant axis dropped). Returns the triangle's k.
int fan_weights(const std::vector<Vec3d>& c, const Vec3d& n, const Vec3d& p, double w[3]);

}  // namespace hlr
