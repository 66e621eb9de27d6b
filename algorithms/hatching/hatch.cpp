// Hatch lines clipped exactly to a planar region (see hatch.hpp). For a line p0 p1 of the plane
// and w = normal × (p1 − p0), an edge ab crosses it where the signs of w·(a − p0) < 0 and
// w·(b − p0) < 0 differ (the half-open rule: a line through a vertex counts the vertex once, a
// line along an edge counts it on one side), so every line meets the closed loops an even
// number of times; the crossing points, sorted along the line, pair into the inside pieces.
#include "algorithms/hatching/hatch.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace hlr {
namespace {

// The exact point of `plane` with coordinates i, j the doubles' rounded to multiples of q (a
// power of two) and coordinate k solved.
Point3 snap(const std::array<double, 3>& y, const Plane& plane, double q) {
  int k = 0;
  for (int a = 1; a < 3; ++a)
    if (abs(plane[a]) > abs(plane[k])) k = a;
  Rational x[3];
  const Rational quantum(q);
  for (int a = 0; a < 3; ++a)
    if (a != k) x[a] = Rational(std::nearbyint(y[a] / q)) * quantum;
  Rational rest = plane.d();
  for (int a = 0; a < 3; ++a)
    if (a != k) rest += plane[a] * x[a];
  x[k] = -rest / plane[k];
  return Point3(x[0], x[1], x[2]);
}

// Sign of g < 0 for g = w·(x − p0): doubles when |g| is over 1e-9 of the terms' size
// Σ|w|(|x| + |p0|) (each double within 2^-53 of its value, a few roundings more: the error is
// under 8·2^-53 of that size, far below the gap), else exact.
bool left_of(const Vector3& w, const std::array<double, 3>& wd, const Point3& x, const std::array<double, 3>& xd, const Point3& p0,
             const std::array<double, 3>& p0d) {
  double g = 0, size = 0;
  for (int a = 0; a < 3; ++a) {
    g += wd[a] * (xd[a] - p0d[a]);
    size += std::fabs(wd[a]) * (std::fabs(xd[a]) + std::fabs(p0d[a]));
  }
  if (std::isfinite(g) && std::isfinite(size) && std::fabs(g) > 1e-9 * size + 1e-300) return g < 0;
  return dot(w, x - p0) < 0;
}

}  // namespace

std::vector<HatchLine> clip_exact_lines(const std::vector<Point3>& pts, const std::vector<std::array<int, 2>>& boundary, const Plane& plane,
                                        std::vector<HatchLine> lines) {
  std::vector<HatchLine> out;
  if (boundary.empty()) return out;
  const Vector3 normal = plane.normal();
  std::vector<Rational> hits;
  auto d3 = [](const Point3& p) { return std::array<double, 3>{to_double(p.x()), to_double(p.y()), to_double(p.z())}; };
  std::map<int, std::array<double, 3>> corner;  // the border's corners in doubles, each once
  for (const auto& e : boundary)
    for (int v : e) corner.emplace(v, std::array<double, 3>{});
  for (auto& [v, x] : corner) x = d3(pts[v]);
  std::vector<std::array<std::array<double, 3>, 2>> approx;  // per border edge, read by every line
  approx.reserve(boundary.size());
  for (const auto& e : boundary) approx.push_back({corner.at(e[0]), corner.at(e[1])});
  for (HatchLine& line : lines) {
    const Vector3 d = line.p1 - line.p0;
    if (d.is_zero()) continue;
    const Vector3 w = cross(normal, d);  // in the plane, across the line
    const std::array<double, 3> wd = {to_double(w.x()), to_double(w.y()), to_double(w.z())};
    hits.clear();
    const std::array<double, 3> p0d = d3(line.p0);
    for (std::size_t k = 0; k < boundary.size(); ++k) {
      const auto& e = boundary[k];
      const Point3 &pa = pts[e[0]], &pb = pts[e[1]];
      const bool la = left_of(w, wd, pa, approx[k][0], line.p0, p0d), lb = left_of(w, wd, pb, approx[k][1], line.p0, p0d);
      if (la == lb) continue;
      // Where the edge meets the line: t along p0 -> p1 (w·(X − p0) = 0 on the edge).
      const Vector3 ab = pb - pa;
      const Rational ga = dot(w, pa - line.p0), gb = dot(w, pb - line.p0);
      const Point3 x = pa + Rational(ga / (ga - gb)) * ab;
      hits.push_back(Rational(dot(d, x - line.p0) / dot(d, d)));
    }
    if (hits.empty()) continue;
    std::sort(hits.begin(), hits.end());
    line.inside.clear();
    for (std::size_t k = 0; k + 1 < hits.size(); k += 2)
      if (hits[k] < hits[k + 1]) line.inside.emplace_back(hits[k], hits[k + 1]);
    if (!line.inside.empty()) out.push_back(std::move(line));
  }
  return out;
}

std::vector<HatchLine> clip_lines(const std::vector<Point3>& pts, const std::vector<std::array<int, 2>>& boundary, const Plane& plane,
                                  const std::vector<ApproxLine>& lines, double size) {
  if (boundary.empty() || !(size > 0)) return {};
  const double q = std::ldexp(1.0, std::ilogb(size) - 30);
  std::vector<HatchLine> exact;
  exact.reserve(lines.size());
  for (const ApproxLine& a : lines) {
    for (double v : {a.a[0], a.a[1], a.a[2], a.b[0], a.b[1], a.b[2]})
      if (!std::isfinite(v)) throw std::domain_error("hatching: a hatch line's end is not a finite point of the region's plane");
    exact.push_back(HatchLine{snap(a.a, plane, q), snap(a.b, plane, q), {}});
  }
  return clip_exact_lines(pts, boundary, plane, std::move(exact));
}

std::vector<HatchLine> hatch_lines(const std::vector<Point3>& pts, const std::vector<std::array<int, 2>>& boundary, const Plane& plane,
                                   const std::function<std::array<double, 3>(double, double)>& lift, double angle_degrees, double first, double step,
                                   double last, const std::array<double, 4>& page_box, double size) {
  if (boundary.empty() || !(step > 0) || !(size > 0)) return {};
  const double a = angle_degrees * M_PI / 180, n0 = std::cos(a), n1 = std::sin(a), d0 = -n1, d1 = n0;
  double ulo = INFINITY, uhi = -INFINITY;
  for (double x : {page_box[0], page_box[2]})
    for (double y : {page_box[1], page_box[3]}) ulo = std::min(ulo, x * d0 + y * d1), uhi = std::max(uhi, x * d0 + y * d1);
  const double margin = 0.1 * (uhi - ulo) + step;
  ulo -= margin, uhi += margin;
  std::vector<ApproxLine> lines;
  for (double c = first; c <= last; c += step)
    lines.push_back({lift(c * n0 + ulo * d0, c * n1 + ulo * d1), lift(c * n0 + uhi * d0, c * n1 + uhi * d1)});
  return clip_lines(pts, boundary, plane, lines, size);
}

}  // namespace hlr
