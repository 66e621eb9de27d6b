// The picture frame and the viewing pyramid (see view_pyramid.hpp; course notes 21-22).
#include "algorithms/clip/view_pyramid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "algorithms/picture/picture_plane.hpp"

namespace hlr {
namespace {

double half_tan(double degrees) { return std::tan(degrees * M_PI / 360); }

void check_angle(const char* option, const std::optional<double>& a) {
  if (a && !(*a > 0 && *a < 180)) throw std::invalid_argument(std::string(option) + " must be an angle in degrees between 0 and 180");
}

}  // namespace

void check_frame_request(const FrameRequest& f) {
  check_angle("--fov", f.fov);
  check_angle("--fov-v", f.fov_v);
  const int ways = (f.fov || f.fov_v ? 1 : 0) + (f.frame ? 1 : 0) + (f.focal ? 1 : 0);
  if (ways > 1) throw std::invalid_argument("give one of --fov/--fov-v, --frame and --focal: each sets the whole frame");
  if (f.frame && !((*f.frame)[0] > 0 && (*f.frame)[1] > 0)) throw std::invalid_argument("--frame needs a positive width and height");
  if (f.focal && !(*f.focal > 0 && std::isfinite(*f.focal))) throw std::invalid_argument("--focal must be a positive length in mm");
  if (!(f.sensor[0] > 0 && f.sensor[1] > 0 && std::isfinite(f.sensor[0]) && std::isfinite(f.sensor[1])))
    throw std::invalid_argument("--sensor needs a positive width and height in mm");
  if (f.aspect && !(*f.aspect > 0 && std::isfinite(*f.aspect))) throw std::invalid_argument("--aspect must be a positive ratio W:H");
  if (f.aspect && f.fov && f.fov_v) throw std::invalid_argument("--aspect is for one angle: --fov and --fov-v give the frame's shape");
}

std::array<double, 2> frame_tangents(const FrameRequest& f, const Camera& camera) {
  const double aspect = f.aspect ? *f.aspect : f.sensor[0] / f.sensor[1];
  if (f.focal) return {f.sensor[0] / (2 * *f.focal), f.sensor[1] / (2 * *f.focal)};
  if (f.frame) {
    const Vector3 d = camera.target - camera.eye;
    const double distance = std::sqrt(to_double(dot(d, d)));
    return {to_double((*f.frame)[0]) / (2 * distance), to_double((*f.frame)[1]) / (2 * distance)};
  }
  if (f.fov && f.fov_v) return {half_tan(*f.fov), half_tan(*f.fov_v)};
  if (f.fov) return {half_tan(*f.fov), half_tan(*f.fov) / aspect};
  return {half_tan(*f.fov_v) * aspect, half_tan(*f.fov_v)};
}

ViewPyramid view_pyramid(const Camera& camera, const std::array<double, 2>& tangents) {
  if (!camera.perspective) throw std::invalid_argument("a picture frame (--fov, --frame, --focal) needs a perspective view (--eye)");
  // Drawing x = X·|d|/|r| with the exact picture coordinate X = ((P - E)·r) / ((P - E)·d): the
  // side |x| <= t is |X| <= t·|r|/|d|, a slope rounded once to a rational s, exactly a plane.
  const PicturePlane pp(camera);
  const double rd = std::sqrt(to_double(dot(pp.r(), pp.r())) / to_double(dot(pp.d(), pp.d())));
  const double ud = std::sqrt(to_double(dot(pp.u(), pp.u())) / to_double(dot(pp.d(), pp.d())));
  const Rational sx = rational_from_double(tangents[0] * rd), sy = rational_from_double(tangents[1] * ud);
  const Vector3 e = camera.eye - Point3();
  auto through_eye = [&](const Vector3& n) { return Plane(n.x(), n.y(), n.z(), -dot(n, e)); };
  ViewPyramid p;
  const Rational minus = -1;
  p.sides = {through_eye(sx * pp.d() + minus * pp.r()), through_eye(sx * pp.d() + pp.r()), through_eye(sy * pp.d() + minus * pp.u()),
             through_eye(sy * pp.d() + pp.u())};
  const double hx = to_double(sx) / rd, hy = to_double(sy) / ud;
  p.rect = {-hx, -hy, hx, hy};
  p.half_x = sx, p.half_y = sy;
  return p;
}

std::optional<std::array<Exact2, 2>> clip_to_frame(const ViewPyramid& p, const Exact2& a, const Exact2& b) {
  // Liang-Barsky on the box |X| <= half_x, |Y| <= half_y, in rationals.
  Rational lo = 0, hi = 1;
  for (int k = 0; k < 2; ++k) {
    const Rational& h = k == 0 ? p.half_x : p.half_y;
    const Rational d = b[k] - a[k];
    for (int s : {1, -1}) {  // s·(a + t·d) <= h
      const Rational num = h - s * a[k], den = s * d;
      if (den == 0) {
        if (num < 0) return std::nullopt;
      } else if (den > 0) {
        hi = std::min(hi, Rational(num / den));
      } else {
        lo = std::max(lo, Rational(num / den));
      }
    }
  }
  if (!(lo < hi)) return std::nullopt;
  auto at = [&](const Rational& t) { return Exact2{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])}; };
  return std::array<Exact2, 2>{at(lo), at(hi)};
}

}  // namespace hlr
