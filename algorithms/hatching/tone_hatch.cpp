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

namespace {

// One crossing of a border edge with a plane of the family: the plane, the exact point and its
// coordinate along the line (the axis where the line's direction is largest).
struct Crossing {
  long k;
  Point3 at;
};

// Whether m·X − c < 0: doubles when the value is clear of its error bound (the doubles of X
// within 2^-53 of theirs, a few roundings more: under 16·2^-53 of Σ|m_i X_i| + |c|), else exact.
bool below(const PlaneFamily& f, const Point3& x, const std::array<double, 3>& xd, long k) {
  const double c = (static_cast<double>(k) + 0.5) * f.step;
  double g = -c, size = std::fabs(c);
  for (int i = 0; i < 3; ++i) g += f.m_d[i] * xd[i], size += std::fabs(f.m_d[i] * xd[i]);
  if (std::isfinite(g) && std::isfinite(size) && std::fabs(g) > 1e-14 * size + 1e-300) return g < 0;
  const Rational exact_c = Rational(static_cast<double>(k) + 0.5) * Rational(f.step);
  return dot(f.m, x - Point3(Rational(0), Rational(0), Rational(0))) < exact_c;
}

}  // namespace

std::vector<std::array<Point3, 2>> family_pieces(const std::vector<std::array<const Point3*, 2>>& edges, const Vector3& normal,
                                                 const PlaneFamily& f) {
  std::vector<std::array<Point3, 2>> out;
  if (edges.empty() || !(f.step > 0) || !std::isfinite(f.step)) return out;
  const Vector3 dir = cross(normal, f.m);  // along the lines
  if (dir.is_zero()) return out;
  int axis = 0;  // where the line's direction is largest, exactly (any non-zero one orders the points)
  for (int i = 1; i < 3; ++i)
    if (abs(dir[i]) > abs(dir[axis])) axis = i;
  auto d3 = [](const Point3& p) { return std::array<double, 3>{to_double(p.x()), to_double(p.y()), to_double(p.z())}; };
  std::vector<Crossing> hits;
  for (const auto& e : edges) {
    const Point3 &a = *e[0], &b = *e[1];
    const std::array<double, 3> ad = d3(a), bd = d3(b);
    const double va = dot3(f.m_d, ad), vb = dot3(f.m_d, bd);
    // The planes between the ends' values, one more each side for the doubles' error.
    const double lo = std::min(va, vb) / f.step - 0.5, hi = std::max(va, vb) / f.step - 0.5;
    if (!std::isfinite(lo) || !std::isfinite(hi) || hi - lo > 1e6) continue;
    for (long k = static_cast<long>(std::floor(lo)) - 1; k <= static_cast<long>(std::ceil(hi)) + 1; ++k) {
      if (below(f, a, ad, k) == below(f, b, bd, k)) continue;
      const Rational c = Rational(static_cast<double>(k) + 0.5) * Rational(f.step);
      const Vector3 ab = b - a;
      const Rational ma = dot(f.m, a - Point3(Rational(0), Rational(0), Rational(0)));
      const Rational s = (c - ma) / dot(f.m, ab);
      hits.push_back({k, a + s * ab});
    }
  }
  std::sort(hits.begin(), hits.end(), [axis](const Crossing& p, const Crossing& q) { return p.k != q.k ? p.k < q.k : p.at[axis] < q.at[axis]; });
  for (std::size_t i = 0; i + 1 < hits.size();) {
    std::size_t j = i;
    while (j < hits.size() && hits[j].k == hits[i].k) ++j;
    for (std::size_t p = i; p + 1 < j; p += 2)
      if (hits[p].at != hits[p + 1].at) out.push_back({hits[p].at, hits[p + 1].at});
    i = j;
  }
  return out;
}

namespace {

struct PictureCrossing {
  long k;
  Exact2 at;
};

bool below_2d(const PictureFamily& f, const Exact2& q, const std::array<double, 2>& qd, long k) {
  const double c = (static_cast<double>(k) + 0.5) * f.step;
  const double g = f.alpha * qd[0] + f.beta * qd[1] - c;
  const double size = std::fabs(f.alpha * qd[0]) + std::fabs(f.beta * qd[1]) + std::fabs(c);
  if (std::isfinite(g) && std::isfinite(size) && std::fabs(g) > 1e-14 * size + 1e-300) return g < 0;
  return Rational(f.alpha) * q[0] + Rational(f.beta) * q[1] < Rational(static_cast<double>(k) + 0.5) * Rational(f.step);
}

}  // namespace

std::vector<std::array<Exact2, 2>> picture_family_pieces(const std::vector<std::array<const Exact2*, 2>>& edges, const PictureFamily& f) {
  std::vector<std::array<Exact2, 2>> out;
  if (edges.empty() || !(f.step > 0) || !std::isfinite(f.step) || (f.alpha == 0 && f.beta == 0)) return out;
  const int axis = std::fabs(f.beta) >= std::fabs(f.alpha) ? 0 : 1;  // along the lines (−β, α)
  const Rational alpha(f.alpha), beta(f.beta), step(f.step);
  std::vector<PictureCrossing> hits;
  for (const auto& e : edges) {
    const Exact2 &a = *e[0], &b = *e[1];
    const std::array<double, 2> ad{a[0].get_d(), a[1].get_d()}, bd{b[0].get_d(), b[1].get_d()};
    const double va = f.alpha * ad[0] + f.beta * ad[1], vb = f.alpha * bd[0] + f.beta * bd[1];
    const double lo = std::min(va, vb) / f.step - 0.5, hi = std::max(va, vb) / f.step - 0.5;
    if (!std::isfinite(lo) || !std::isfinite(hi) || hi - lo > 1e6) continue;
    bool have = false;
    Rational ga, gab;
    for (long k = static_cast<long>(std::floor(lo)) - 1; k <= static_cast<long>(std::ceil(hi)) + 1; ++k) {
      if (below_2d(f, a, ad, k) == below_2d(f, b, bd, k)) continue;
      if (!have) ga = alpha * a[0] + beta * a[1], gab = alpha * (b[0] - a[0]) + beta * (b[1] - a[1]), have = true;
      const Rational s = (Rational(static_cast<double>(k) + 0.5) * step - ga) / gab;
      hits.push_back({k, Exact2{Rational(a[0] + s * (b[0] - a[0])), Rational(a[1] + s * (b[1] - a[1]))}});
    }
  }
  std::sort(hits.begin(), hits.end(),
            [axis](const PictureCrossing& p, const PictureCrossing& q) { return p.k != q.k ? p.k < q.k : p.at[axis] < q.at[axis]; });
  for (std::size_t i = 0; i + 1 < hits.size();) {
    std::size_t j = i;
    while (j < hits.size() && hits[j].k == hits[i].k) ++j;
    for (std::size_t p = i; p + 1 < j; p += 2)
      if (hits[p].at != hits[p + 1].at) out.push_back({hits[p].at, hits[p + 1].at});
    i = j;
  }
  return out;
}

}  // namespace hlr
