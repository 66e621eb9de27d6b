// The classic floating horizon with per-column arrays (see floating_horizon_classic.hpp).
#include "algorithms/horizon/floating_horizon_classic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace hlr {

HorizonResult floating_horizon_classic(const HeightGrid& g, const Camera& cam, double dx) {
  const std::size_t nx = g.xs.size(), nz = g.zs.size();
  if (nx < 2 || nz < 1 || g.heights() != nx * nz) throw std::invalid_argument("the grid needs at least 2 x samples and one cut");
  if (cam.perspective || cam.direction.z() == 0) throw std::invalid_argument("the floating horizon takes an orthographic view with a z component");
  if (!(dx > 0)) throw std::invalid_argument("the classic method needs a column width dx > 0");
  Vector3 r = cross(cam.up, cam.direction), u = cross(cam.direction, r);
  if (r.y() != 0 || r.x() == 0) throw std::invalid_argument("the cuts must run left to right in the picture");
  // Unit picture axes in doubles (drawing only: this method is approximate by design).
  double rn = std::sqrt(to_double(dot(r, r))), un = std::sqrt(to_double(dot(u, u)));
  auto X = [&](std::size_t i, std::size_t j) { return (to_double(g.xs[i]) * to_double(r.x()) + to_double(g.zs[j]) * to_double(r.z())) / rn; };
  auto Y = [&](std::size_t i, std::size_t j) {
    return (to_double(g.xs[i]) * to_double(u.x()) + to_double(g.y(i, j)) * to_double(u.y()) + to_double(g.zs[j]) * to_double(u.z())) / un;
  };
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
  for (std::size_t j = 0; j < nz; ++j)
    for (std::size_t i : {std::size_t{0}, nx - 1}) x0 = std::min(x0, X(i, j)), x1 = std::max(x1, X(i, j));
  const std::size_t columns = static_cast<std::size_t>(std::ceil((x1 - x0) / dx)) + 1;
  if (columns > 10'000'000) throw std::invalid_argument("the classic method would need over 10 million columns: give a larger dx");
  const double none = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> upper(columns, none), lower(columns, none);
  HorizonResult res;
  for (std::size_t k = 0; k < nz; ++k) res.order.push_back(static_cast<int>(cam.direction.z() > 0 ? nz - 1 - k : k));
  for (int jj : res.order) {
    const std::size_t j = static_cast<std::size_t>(jj);
    // The cut at the columns inside its x range.
    std::vector<double> cx(nx), cy(nx);
    for (std::size_t i = 0; i < nx; ++i) cx[i] = X(i, j), cy[i] = Y(i, j);
    const bool forward = cx[0] < cx[nx - 1];
    auto at = [&](double x) {  // the cut's height at picture x (linear between samples)
      std::size_t lo = 0, hi = nx - 1;
      if (!forward) std::swap(lo, hi);
      for (std::size_t i = 0; i + 1 < nx; ++i) {
        double a = cx[i], b = cx[i + 1];
        if ((a <= x && x <= b) || (b <= x && x <= a)) return a == b ? cy[i] : cy[i] + (cy[i + 1] - cy[i]) * (x - a) / (b - a);
      }
      return x <= cx[lo] ? cy[lo] : cy[hi];
    };
    double xa = std::min(cx[0], cx[nx - 1]), xb = std::max(cx[0], cx[nx - 1]);
    std::size_t c0 = static_cast<std::size_t>(std::ceil((xa - x0) / dx)), c1 = static_cast<std::size_t>(std::floor((xb - x0) / dx));
    std::vector<std::pair<double, double>> runs;  // visible runs in picture x
    auto visible = [&](std::size_t c, double y) {
      return std::isnan(upper[c]) || y >= upper[c] || y <= lower[c];
    };
    double run_start = xa;
    bool in_run = false;
    for (std::size_t c = c0; c <= c1 && c < columns; ++c) {
      double x = x0 + static_cast<double>(c) * dx, y = at(x);
      bool v = visible(c, y);
      if (c == c0) {
        in_run = v;
        run_start = xa;
      } else if (v != in_run) {
        // The notes' crossing: where the cut's chord meets the horizon's chord between columns.
        double xp = x - dx, yp = at(xp);
        const std::vector<double>& h = (!std::isnan(upper[c]) && (v ? y >= upper[c] : yp >= upper[c - 1])) ? upper : lower;
        double hp = std::isnan(h[c - 1]) ? h[c] : h[c - 1], hc = std::isnan(h[c]) ? hp : h[c];
        double denom = (y - yp) - (hc - hp);
        double xc = denom != 0 ? xp + dx * (hp - yp) / denom : x;
        xc = std::clamp(xc, xp, x);
        if (in_run) runs.push_back({run_start, xc});
        else run_start = xc;
        in_run = v;
      }
    }
    if (in_run) runs.push_back({run_start, xb});
    if (c0 > c1) runs.push_back({xa, xb});  // narrower than a column: drawn
    for (std::size_t c = c0; c <= c1 && c < columns; ++c) {
      double y = at(x0 + static_cast<double>(c) * dx);
      upper[c] = std::isnan(upper[c]) ? y : std::max(upper[c], y);
      lower[c] = std::isnan(lower[c]) ? y : std::min(lower[c], y);
    }
    // Runs in picture x to t ranges on each cut segment.
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      double a = cx[i], b = cx[i + 1], lo = std::min(a, b), hi = std::max(a, b);
      for (auto [r0, r1] : runs) {
        double s0 = std::max(lo, r0), s1 = std::min(hi, r1);
        if (!(s0 < s1)) continue;
        double t0 = (s0 - a) / (b - a), t1 = (s1 - a) / (b - a);
        if (t1 < t0) std::swap(t0, t1);
        res.visible.push_back({static_cast<int>(j), static_cast<int>(i), rational_from_double(std::clamp(t0, 0.0, 1.0)),
                               rational_from_double(std::clamp(t1, 0.0, 1.0))});
      }
    }
  }
  sort_visible(res);
  return res;
}

}  // namespace hlr
