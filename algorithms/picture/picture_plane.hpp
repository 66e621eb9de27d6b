// The picture plane in exact numbers (course notes section 20, the projection; section 25 for
// image space against object space): exact rational picture coordinates of a point, the sight
// ray through a picture point, and the point where that ray meets a plane. The axes are the
// unnormalised r = up × v and u = v × r (v: toward the viewer, or eye - target), so every
// coordinate is rational; lengths along them are |r| and |u| times the true picture lengths
// (docs/output-format.md says how areas relate). Perspective keeps straight lines straight, so
// an exact 2D geometry of the picture is a plain rational one in both projections.
#pragma once

#include <array>

#include "algorithms/model/camera.hpp"
#include "kernel/geometry.hpp"
#include "kernel/plane_int128.hpp"
#include "kernel/predicates_2d.hpp"

namespace hlr {

/// A value linear in the picture point: c0 + cx·x + cy·y (exact).
struct PictureLinear {
  Rational c0, cx, cy;
  Rational at(const Exact2& q) const { return c0 + cx * q[0] + cy * q[1]; }
  /// Derivative along the direction d.
  Rational along(const Exact2& d) const { return cx * d[0] + cy * d[1]; }
};

class PicturePlane {
 public:
  explicit PicturePlane(const Camera& c);
  bool perspective() const { return persp_; }
  /// The exact picture point of p (perspective: p must be in front of the eye).
  Exact2 project(const Point3& p) const;
  /// The point of the plane `h` that the sight ray through q meets (h not containing the ray).
  Point3 lift(const Exact2& q, const Plane& h) const { return lift(q, ray_parameter(h)); }
  /// The same with the plane's ray_parameter() computed once.
  Point3 lift(const Exact2& q, const std::array<PictureLinear, 2>& ray) const;
  /// Where the sight ray through q meets the plane h, as a fraction num(q) / den(q) of two
  /// values linear in q: orthographic, the parameter s of base(q) + s·v (larger is nearer the
  /// viewer, den constant); perspective, the parameter l of E + l·dir(q) (smaller is nearer,
  /// positive in front of the eye).
  std::array<PictureLinear, 2> ray_parameter(const Plane& h) const;
  /// Orthographic only, for a plane with integer coefficients (a primitive plane): the sign of
  /// n·v (positive: the face is turned toward the viewer; 0: edge-on) exactly, and doubles of
  /// the depth s(q) = num(q) / den (ray_parameter) as c0 + cx·x + cy·y, each within
  /// 5·kToDoubleError of its coefficient relatively (docs/design.md, "Visible surfaces as
  /// exact polygons"). `ok` is false when a double left [2^-400, 2^400] (then no filter may
  /// use them) or the coefficients are not integers.
  struct DepthDoubles {
    bool integers = false;  // false: the plane's coefficients are not integers, nothing was made
    int facing = 0;
    bool ok = false;
    std::array<double, 3> c{0, 0, 0};
  };
  DepthDoubles depth_doubles(const Plane& h) const;
  /// The same for a plane in 128-bit parts (kernel/plane_int128.hpp); never degenerate.
  DepthDoubles depth_doubles(const PlaneInt128& h) const;
  /// The axes r, u and the viewing vector d (orthographic: v; perspective: target - eye).
  const Vector3& r() const { return r_; }
  const Vector3& u() const { return u_; }
  const Vector3& d() const { return d_; }

 private:
  bool persp_;
  Point3 e_;
  Vector3 r_, u_, d_;
  Rational rr_, uu_, dd_;  // squared lengths
  // r = ri / rden and u = ui / uden with integers (orthographic project() without rationals).
  std::array<mpz_class, 3> ri_, ui_, di_;
  mpz_class rden_, uden_, dden_;
  // depth_doubles: dden, dden / (rden·|r|²), dden / (uden·|u|²) as doubles (each within
  // kToDoubleError relatively).
  std::array<double, 3> depth_k_{0, 0, 0};
  DepthDoubles depth_doubles(mpz_srcptr a, mpz_srcptr b, mpz_srcptr c, mpz_srcptr d) const;
};

/// Drawing coordinates (Projector's, in its DrawingFrame) of exact picture points, without a
/// 3D point: orthographic x = s·(X - c·r) / |r| (c, s: the frame's centre and scale),
/// perspective x = X·|d| / |r| (the frame does not change a perspective picture); y alike.
class PictureToDrawing {
 public:
  PictureToDrawing(const PicturePlane& pp, const DrawingFrame& frame);
  std::array<double, 2> operator()(const Exact2& q) const;
  /// The same from the picture point's doubles (mpq_get_d of an exact point).
  std::array<double, 2> operator()(const std::array<double, 2>& q) const;

 private:
  bool persp_;
  Rational cr_, cu_, scale_;
  Rational rr_, uu_, dd_;
  // Doubles for points in the doubles' comfortable range: x = (X - cr)·fx, y = (Y - cu)·fy.
  bool fast_ = false;
  double crd_ = 0, cud_ = 0, fx_ = 0, fy_ = 0;
};

}  // namespace hlr
