// Exact viewpoint and double drawing projection (see camera.hpp).
#include "algorithms/camera.hpp"

#include <cmath>
#include <stdexcept>

#include "kernel/predicates.hpp"

namespace hlr {
namespace {

using V3 = std::array<double, 3>;
V3 d3(const Vector3& v) { return {to_double(v.x()), to_double(v.y()), to_double(v.z())}; }
V3 cross3(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
V3 unit(V3 a) {
  double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return {a[0] / l, a[1] / l, a[2] / l};
}
double dot3(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Default up: +y, or +z when the axis is parallel to y (exact test).
Vector3 choose_up(const Vector3& axis, std::optional<Vector3> up) {
  if (up) {
    if (up->is_zero()) throw std::invalid_argument("the up vector has zero length");
    if (cross(axis, *up).is_zero()) throw std::invalid_argument("the up vector is parallel to the viewing direction");
    return *up;
  }
  Vector3 y(0, 1, 0);
  if (!cross(axis, y).is_zero()) return y;
  return Vector3(0, 0, 1);
}

}  // namespace

RowVector4 Camera::viewpoint() const {
  RowVector4 g;
  if (perspective)
    g << eye.x(), eye.y(), eye.z(), 1;
  else
    g << direction.x(), direction.y(), direction.z(), 0;
  return g;
}

Rational Camera::depth(const Point3& p) const { return dot(p - eye, target - eye); }

Sign Camera::in_front(const Point3& p) const {
  if (!perspective) return Sign::Positive;
  return sign_of_dot(p - eye, target - eye);
}

Camera make_orthographic(const Vector3& direction, std::optional<Vector3> up) {
  if (direction.is_zero()) throw std::invalid_argument("the view direction has zero length");
  Camera c;
  c.direction = direction;
  c.up = choose_up(direction, up);
  return c;
}

Camera make_perspective(const Point3& eye, const Point3& target, std::optional<Vector3> up) {
  if (eye == target) throw std::invalid_argument("the eye and the target are the same point");
  Camera c;
  c.perspective = true;
  c.eye = eye;
  c.target = target;
  c.up = choose_up(target - eye, up);
  return c;
}

Projector::Projector(const Camera& c) : perspective_(c.perspective) {
  V3 toward_viewer = c.perspective ? unit(d3(c.eye - c.target)) : unit(d3(c.direction));
  forward_ = {-toward_viewer[0], -toward_viewer[1], -toward_viewer[2]};
  V3 up = d3(c.up);
  right_ = unit(cross3(up, toward_viewer));
  up_ = cross3(toward_viewer, right_);
  eye_ = perspective_ ? V3{to_double(c.eye.x()), to_double(c.eye.y()), to_double(c.eye.z())} : V3{0, 0, 0};
}

std::array<double, 3> Projector::project(double x, double y, double z) const {
  V3 p = {x - eye_[0], y - eye_[1], z - eye_[2]};
  double depth = dot3(p, forward_);
  double sx = dot3(p, right_), sy = dot3(p, up_);
  if (perspective_) {
    if (depth > 0) return {sx / depth, sy / depth, depth};
    return {sx, sy, depth};
  }
  return {sx, sy, depth};
}

std::array<double, 3> Projector::project(const Point3& p) const {
  // The certified bounds carried by the point are at most one double apart: their midpoint is
  // within one unit in the last place, plenty for drawing and for the widened pre-filter.
  auto mid = [&](int k) { return p.approx(k).lo + (p.approx(k).hi - p.approx(k).lo) / 2; };
  return project(mid(0), mid(1), mid(2));
}

}  // namespace hlr
