// Exact viewpoint and double drawing projection (see camera.hpp).
#include "algorithms/model/camera.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>

#include "algorithms/support/parallel.hpp"
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

// floor(log2 |q|) within one, from the sizes of numerator and denominator (q != 0).
long log2_about(const Rational& q) {
  return static_cast<long>(mpz_sizeinbase(q.get_num_mpz_t(), 2)) - static_cast<long>(mpz_sizeinbase(q.get_den_mpz_t(), 2));
}

// A direction as doubles, first scaled exactly by a power of two so that its largest
// component is near 1: a vector of 1e-400 or 1e300 is a direction like any other. For
// ordinary magnitudes the doubles are the same up to that power of two, and unit() removes it.
V3 d3_direction(const Vector3& v) {
  long e = 0;
  bool any = false;
  for (int k = 0; k < 3; ++k)
    if (v[k] != 0) {
      long x = log2_about(v[k]);
      e = any ? std::max(e, x) : x;
      any = true;
    }
  if (!any || (e > -500 && e < 500)) return d3(v);
  Rational s = 1;
  if (e > 0) mpq_div_2exp(s.get_mpq_t(), s.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
  else mpq_mul_2exp(s.get_mpq_t(), s.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
  return d3(s * v);
}

// Default up: +y, or +z when the axis is parallel to y (exact test).
Vector3 choose_up(const Vector3& axis, std::optional<Vector3> up) {
  if (up) {
    if (up->is_zero()) throw std::invalid_argument("the up vector has zero length");
    if (cross(axis, *up).is_zero())
      throw std::invalid_argument("the up vector " + to_string(*up) + " is parallel to the viewing direction " + to_string(axis) +
                                  ": give another up vector (--up X,Y,Z, or up: in the scene's view)");
    return *up;
  }
  Vector3 y(0, 1, 0);
  if (!cross(axis, y).is_zero()) return y;
  return Vector3(0, 0, 1);
}

// The vector times the power of two that brings its largest component into [1, 2) when it lies
// outside [2^-32, 2^32): the same direction, so that a direction's length never matters (a
// view typed as 0,2e60,0 is the view 0,1,0, and its picture's numbers are as short).
Vector3 power_of_two_scaled(const Vector3& v) {
  long most = LONG_MIN;
  for (int k = 0; k < 3; ++k) {
    const Rational& c = v[k];
    if (c == 0) continue;
    const long bits = static_cast<long>(mpz_sizeinbase(c.get_num_mpz_t(), 2)) - static_cast<long>(mpz_sizeinbase(c.get_den_mpz_t(), 2));
    most = std::max(most, bits);
  }
  if (most == LONG_MIN || (most > -32 && most < 32)) return v;
  Rational f = 1;
  if (most > 0) mpq_div_2exp(f.get_mpq_t(), f.get_mpq_t(), static_cast<mp_bitcnt_t>(most));
  else mpq_mul_2exp(f.get_mpq_t(), f.get_mpq_t(), static_cast<mp_bitcnt_t>(-most));
  return Vector3(v.x() * f, v.y() * f, v.z() * f);
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

std::array<int, 2> Camera::eye_plane_signs(const Point3& a, const Point3& b) const {
  const Rational da = depth(a), db = depth(b);
  // (da - db)·(crossing point - E), a positive multiple of the crossing point seen from the eye.
  const Vector3 w = (da - db) * (a - eye) + da * (b - a);
  const Vector3 toward_viewer = eye - target;
  const Vector3 right = cross(up, toward_viewer), screen_up = cross(toward_viewer, right);
  return {sgn(dot(w, right)), sgn(dot(w, screen_up))};
}

Sign Camera::in_front(const Point3& p) const {
  if (!perspective) return Sign::Positive;
  return sign_of_dot(p - eye, target - eye);
}

Camera make_orthographic(const Vector3& direction, std::optional<Vector3> up) {
  if (direction.is_zero()) throw std::invalid_argument("the view direction has zero length");
  Camera c;
  c.direction = power_of_two_scaled(direction);
  c.up = choose_up(c.direction, up && !up->is_zero() ? std::optional<Vector3>(power_of_two_scaled(*up)) : up);
  return c;
}

Camera make_perspective(const Point3& eye, const Point3& target, std::optional<Vector3> up) {
  if (eye == target) throw std::invalid_argument("the eye and the target are the same point");
  Camera c;
  c.perspective = true;
  c.eye = eye;
  c.target = target;
  c.up = choose_up(target - eye, up && !up->is_zero() ? std::optional<Vector3>(power_of_two_scaled(*up)) : up);
  return c;
}

std::array<double, 3> DrawingFrame::to_frame(const Point3& p) const {
  if (identity) {
    // The certified bounds carried by the point are at most one double apart: their midpoint
    // is within one unit in the last place, plenty for drawing and for the widened filters.
    auto mid = [&](int k) { return p.approx(k).lo + (p.approx(k).hi - p.approx(k).lo) / 2; };
    return {mid(0), mid(1), mid(2)};
  }
  return {to_double((p.x() - centre.x()) * scale), to_double((p.y() - centre.y()) * scale),
          to_double((p.z() - centre.z()) * scale)};
}

namespace {

// The certified boxes' hull of points (minima and maxima: the same in any order).
struct Hull {
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, big = 0;
  void add(int k, const Bounds& q) {
    lo[k] = std::min(lo[k], q.lo);
    hi[k] = std::max(hi[k], q.hi);
    big = std::max({big, std::fabs(q.lo), std::fabs(q.hi)});
  }
  void join(const Hull& h) {
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], h.lo[k]), hi[k] = std::max(hi[k], h.hi[k]);
    big = std::max(big, h.big);
  }
};

// Calls add(hull, i) for every i < n on all cores, each worker into its own hull; then joined.
template <class Add>
void add_all(std::size_t n, Hull& out, const Add& add) {
  const ParallelLoop loop;
  PerWorker<Hull> part(loop);
  loop.run(n, 16384, [&](unsigned w, std::size_t b, std::size_t e) {
    Hull h = part[w];  // in registers while the range runs
    for (std::size_t i = b; i < e; ++i) add(h, i);
    part[w] = h;
  });
  for (unsigned w = 0; w < part.size(); ++w) out.join(part[w]);
}

// The frame of points whose bounds make `hull`: the identity unless doubles would lose them,
// else from their exact bounding box (each_point(f) calls f on every exact point).
DrawingFrame frame_of_hull(const Hull& h, const std::function<void(const std::function<void(const Point3&)>&)>& each_point) {
  DrawingFrame f;
  if (!(h.lo[0] <= h.hi[0])) return f;  // no points
  double ext = std::max({h.hi[0] - h.lo[0], h.hi[1] - h.lo[1], h.hi[2] - h.lo[2]});
  if (std::isfinite(h.big) && h.big < 0x1p100 && ext > 0x1p-100 && ext >= h.big * 0x1p-30) return f;
  // The exact bounding box.
  Rational L[3], H[3];
  bool first = true;
  each_point([&](const Point3& p) {
    for (int k = 0; k < 3; ++k) {
      if (first || p[k] < L[k]) L[k] = p[k];
      if (first || p[k] > H[k]) H[k] = p[k];
    }
    first = false;
  });
  Rational side = 0;
  for (int k = 0; k < 3; ++k) side = std::max(side, Rational(H[k] - L[k]));
  if (side == 0) return f;  // a single point: nothing to scale
  f.identity = false;
  f.centre = Point3((L[0] + H[0]) / 2, (L[1] + H[1]) / 2, (L[2] + H[2]) / 2);
  f.scale = 1 / side;
  return f;
}

}  // namespace

DrawingFrame drawing_frame(std::size_t n, const std::function<const Point3&(std::size_t)>& point) { return drawing_frame({}, n, point); }

DrawingFrame drawing_frame(const std::vector<StorePoints>& stores, std::size_t n, const std::function<const Point3&(std::size_t)>& point) {
  Hull h;
  auto taken = [](const StorePoints& s, std::size_t i) { return !s.marks || (i < s.marks->size() && (*s.marks)[i]); };
  for (const StorePoints& s : stores)
    add_all(s.store->size(), h, [&](Hull& hull, std::size_t i) {
      if (taken(s, i))
        for (int k = 0; k < 3; ++k) hull.add(k, s.store->approx(i, k));
    });
  add_all(n, h, [&](Hull& hull, std::size_t i) {
    const Point3& p = point(i);
    for (int k = 0; k < 3; ++k) hull.add(k, p.approx(k));
  });
  return frame_of_hull(h, [&](const std::function<void(const Point3&)>& f) {
    for (const StorePoints& s : stores)
      for (std::size_t i = 0; i < s.store->size(); ++i)
        if (taken(s, i)) f(s.store->points()[i]);
    for (std::size_t i = 0; i < n; ++i) f(point(i));
  });
}

std::array<double, 3> DrawingFrame::to_frame(const PointStore& s, std::size_t i) const {
  if (!identity) return to_frame(s.compact() ? s.point(i) : s.points()[i]);
  auto mid = [&](int k) {
    const Bounds b = s.approx(i, k);
    return b.lo + (b.hi - b.lo) / 2;
  };
  return {mid(0), mid(1), mid(2)};
}

Projector::Projector(const Camera& c, DrawingFrame frame) : perspective_(c.perspective), frame_(std::move(frame)) {
  V3 toward_viewer = c.perspective ? unit(d3_direction(c.eye - c.target)) : unit(d3_direction(c.direction));
  forward_ = {-toward_viewer[0], -toward_viewer[1], -toward_viewer[2]};
  V3 up = d3_direction(c.up);
  right_ = unit(cross3(up, toward_viewer));
  up_ = cross3(toward_viewer, right_);
  eye_ = perspective_ ? (frame_.identity ? V3{to_double(c.eye.x()), to_double(c.eye.y()), to_double(c.eye.z())}
                                         : frame_.to_frame(c.eye))
                      : V3{0, 0, 0};
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
  auto q = frame_.to_frame(p);
  return project(q[0], q[1], q[2]);
}

std::array<double, 3> Projector::project(const PointStore& s, std::size_t i) const {
  auto q = frame_.to_frame(s, i);
  return project(q[0], q[1], q[2]);
}

}  // namespace hlr
