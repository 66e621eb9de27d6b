// Tone hatching (see tone_hatch.hpp; docs/design.md, "Tone hatching").
#include "algorithms/hatching/tone_hatch.hpp"

#include <algorithm>
#include <cmath>

namespace hlr {
namespace {

double dot3(const std::array<double, 3>& a, const std::array<double, 3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

double luminance(const std::array<double, 3>& c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

ToneLevel tone_level(double y, const ToneOptions& o) {
  ToneLevel t;
  const int n = std::clamp(o.levels, 2, kToneLevels);
  const double dark = std::clamp(1 - y, 0.0, 1.0);
  t.level = std::clamp(static_cast<int>(std::lround(dark * n)), 0, n - 1);
  if (t.level == 0 || !(o.pen_mm > 0)) return ToneLevel{};
  t.coverage = static_cast<double>(t.level) / n;
  t.families = t.coverage > o.cross_above ? 2 : 1;
  t.spacing_mm = t.families == 1 ? o.pen_mm / t.coverage : o.pen_mm / (1 - std::sqrt(1 - t.coverage));
  return t;
}

std::vector<HatchLine> family_lines(const std::vector<Point3>& pts, const std::vector<std::array<int, 2>>& boundary, const Plane& plane,
                                    const PlaneFamily& f, const std::vector<std::array<double, 3>>& face_points) {
  if (boundary.empty() || face_points.empty() || !(f.step > 0) || !std::isfinite(f.step)) return {};
  const Vector3 n = plane.normal();
  const Vector3 dir = cross(n, f.m);  // along the lines
  if (dir.is_zero()) return {};
  // The region's extent across the planes picks the lines; the face's along them places the ends.
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& e : boundary) {
    const Point3& p = pts[e[0]];
    const double c = dot3(f.m_d, {to_double(p.x()), to_double(p.y()), to_double(p.z())});
    lo = std::min(lo, c), hi = std::max(hi, c);
  }
  const double k0 = std::ceil(lo / f.step - 0.5), k1 = std::floor(hi / f.step - 0.5);
  if (!(k1 >= k0) || k1 - k0 > 1e6) return {};
  const std::array<double, 3> dd = {to_double(dir.x()), to_double(dir.y()), to_double(dir.z())};
  const double dd2 = dot3(dd, dd);
  double alo = INFINITY, ahi = -INFINITY;
  for (const auto& p : face_points) alo = std::min(alo, dot3(dd, p) / dd2), ahi = std::max(ahi, dot3(dd, p) / dd2);
  // Dyadic parameters a little beyond the face: X0 + t·dir covers it for every line.
  const double margin = 0.05 * (ahi - alo) + 1e-300;
  const double q = std::ldexp(1.0, std::ilogb(std::max(std::fabs(alo), std::fabs(ahi)) + margin) - 20);
  const Rational t0(std::floor((alo - margin) / q) * q), t1(std::ceil((ahi + margin) / q) * q);
  // The point of both planes n·X = −d and m·X = c nearest the origin: (−d (m × D) + c (D × n)) / D·D.
  const Vector3 m_x_d = cross(f.m, dir), d_x_n = cross(dir, n);
  const Rational inv = Rational(1) / dot(dir, dir);
  const Rational step(f.step);
  const Vector3 base = Rational(-plane.d() * inv) * m_x_d;
  const Vector3 across = Rational(inv) * d_x_n;
  std::vector<HatchLine> lines;
  for (double k = k0; k <= k1; ++k) {
    const Rational c = Rational(k + 0.5) * step;
    const Point3 x0 = Point3(0, 0, 0) + (base + c * across);
    lines.push_back(HatchLine{x0 + t0 * dir, x0 + t1 * dir, {}});
  }
  return clip_exact_lines(pts, boundary, plane, std::move(lines));
}

}  // namespace hlr
