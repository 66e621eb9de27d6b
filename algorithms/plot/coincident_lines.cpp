// Lines that coincide on the page drawn once (see coincident_lines.hpp). A uniform grid of the
// kept segments' boxes finds the candidates; for a segment pq and a kept segment ab nearly
// parallel to it, the part of pq covered is where the foot of its point falls on ab and its
// distance to ab's line is at most the tolerance (the distance is linear along pq).
#include "algorithms/plot/coincident_lines.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

namespace hlr {
namespace {

constexpr double kMaxSin = 0.0523;  // 3 degrees

bool takes_part(LineKind k) {
  return !is_tone(k) && k != LineKind::Hatch && k != LineKind::SectionLine && k != LineKind::SectionMark && k != LineKind::Overhead;
}

// The order layers are kept in: visible, seen-through, hidden; in each, the kinds' order.
int rank(const PlotLayer& l) {
  int k = 0;
  for (std::size_t i = 0; i < std::size(kLayerKinds); ++i)
    if (kLayerKinds[i] == l.kind) k = static_cast<int>(i);
  const int seen = l.visible && !l.through ? 0 : (l.through ? 1 : 2);
  return seen * 100 + k;
}

struct Seg {
  Point2 a, b;
};

class Grid {
 public:
  explicit Grid(double cell) : cell_(cell) {}
  template <class F>
  void visit(const Point2& a, const Point2& b, double pad, F&& f) const {
    const long x0 = key(std::min(a[0], b[0]) - pad), x1 = key(std::max(a[0], b[0]) + pad);
    const long y0 = key(std::min(a[1], b[1]) - pad), y1 = key(std::max(a[1], b[1]) + pad);
    for (long x = x0; x <= x1; ++x)
      for (long y = y0; y <= y1; ++y) {
        auto it = cells_.find(pack(x, y));
        if (it != cells_.end())
          for (std::size_t i : it->second) f(i);
      }
  }
  void add(const Point2& a, const Point2& b, double pad, std::size_t id) {
    const long x0 = key(std::min(a[0], b[0]) - pad), x1 = key(std::max(a[0], b[0]) + pad);
    const long y0 = key(std::min(a[1], b[1]) - pad), y1 = key(std::max(a[1], b[1]) + pad);
    for (long x = x0; x <= x1; ++x)
      for (long y = y0; y <= y1; ++y) cells_[pack(x, y)].push_back(id);
  }

 private:
  long key(double v) const { return static_cast<long>(std::floor(v / cell_)); }
  static long long pack(long x, long y) { return (static_cast<long long>(x) << 32) ^ static_cast<long long>(static_cast<std::uint32_t>(y)); }
  double cell_;
  std::unordered_map<long long, std::vector<std::size_t>> cells_;
};

// The parameter interval of pq within `tol` of ab, alongside it and nearly parallel (empty:
// lo > hi).
std::pair<double, double> covered(const Point2& p, const Point2& q, const Seg& s, double tol) {
  const double dx = q[0] - p[0], dy = q[1] - p[1], len2 = dx * dx + dy * dy;
  const double ex = s.b[0] - s.a[0], ey = s.b[1] - s.a[1], elen2 = ex * ex + ey * ey;
  if (!(len2 > 0) || !(elen2 > 0)) return {1, 0};
  const double cross = dx * ey - dy * ex;
  if (std::fabs(cross) > kMaxSin * std::sqrt(len2 * elen2)) return {1, 0};
  // Where the feet of pq's points fall on ab: ab's parameter u(t) is linear in t.
  const double u0 = ((p[0] - s.a[0]) * ex + (p[1] - s.a[1]) * ey) / elen2;
  const double u1 = ((q[0] - s.a[0]) * ex + (q[1] - s.a[1]) * ey) / elen2;
  double lo = 0, hi = 1;
  auto clamp_to = [&](double f0, double f1, double low, double high) {  // keep t with low <= f(t) <= high, f linear
    const double df = f1 - f0;
    if (df == 0) {
      if (f0 < low || f0 > high) lo = 1, hi = 0;
      return;
    }
    double t0 = (low - f0) / df, t1 = (high - f0) / df;
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0), hi = std::min(hi, t1);
  };
  clamp_to(u0, u1, 0, 1);
  // The signed distance of pq's points from ab's line, linear in t.
  const double elen = std::sqrt(elen2);
  const double d0 = ((p[0] - s.a[0]) * ey - (p[1] - s.a[1]) * ex) / elen, d1 = ((q[0] - s.a[0]) * ey - (q[1] - s.a[1]) * ex) / elen;
  clamp_to(d0, d1, -tol, tol);
  return {lo, hi};
}

}  // namespace

CoincidentStats merge_coincident_lines(Plot& plot, double tol) {
  CoincidentStats st;
  if (!(tol > 0) || !std::isfinite(tol)) return st;
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < plot.layers.size(); ++i)
    if (takes_part(plot.layers[i].kind)) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rank(plot.layers[a]) < rank(plot.layers[b]); });
  const double extent = std::max(plot.bounds[2] - plot.bounds[0], plot.bounds[3] - plot.bounds[1]);
  Grid grid(std::max(8 * tol, extent / 4096));
  std::vector<Seg> kept;
  for (std::size_t li : order) {
    PlotLayer& layer = plot.layers[li];
    std::vector<Stroke> out;
    for (const Stroke& s : layer.strokes) {
      std::vector<Point2> pts = s.points;
      if (s.closed && pts.size() > 2) pts.push_back(pts.front());
      const std::size_t first_out = out.size();
      std::vector<std::vector<std::pair<double, double>>> covers(pts.size() > 1 ? pts.size() - 1 : 0);
      bool touched = false;
      for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const Point2 &p = pts[i], &q = pts[i + 1];
        const double len = std::hypot(q[0] - p[0], q[1] - p[1]);
        grid.visit(p, q, tol, [&](std::size_t k) {
          auto c = covered(p, q, kept[k], tol);
          if (c.second > c.first) covers[i].push_back(c);
        });
        // The covered runs: the union of the covers; a run shorter than the tolerance inside
        // the segment is a touch (lines that cross at a small angle), not a line drawn twice.
        std::sort(covers[i].begin(), covers[i].end());
        std::vector<std::pair<double, double>> runs;
        for (const auto& c : covers[i])
          if (!runs.empty() && c.first <= runs.back().second + 1e-12) runs.back().second = std::max(runs.back().second, c.second);
          else runs.push_back(c);
        std::vector<std::pair<double, double>> kept_runs;
        for (const auto& r : runs)
          if (!((r.second - r.first) * len < tol && r.first > 0 && r.second < 1)) kept_runs.push_back(r);
        covers[i] = std::move(kept_runs);
        touched = touched || !covers[i].empty();
      }
      if (!touched) {
        out.push_back(s);
      } else {
        Stroke cur;
        auto flush = [&] {
          double len = 0;
          for (std::size_t i = 1; i < cur.points.size(); ++i)
            len += std::hypot(cur.points[i][0] - cur.points[i - 1][0], cur.points[i][1] - cur.points[i - 1][1]);
          if (cur.points.size() >= 2 && len >= tol) out.push_back(std::move(cur));
          else if (cur.points.size() >= 2) ++st.pieces_removed, st.length_removed += len;
          cur = Stroke{};
        };
        for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
          const Point2 &p = pts[i], &q = pts[i + 1];
          const double len = std::hypot(q[0] - p[0], q[1] - p[1]);
          auto point = [&](double t) { return Point2{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])}; };
          auto keep_part = [&](double t0, double t1) {
            if (cur.points.empty() || cur.points.back() != point(t0)) {
              flush();
              cur.points.push_back(point(t0));
            }
            cur.points.push_back(point(t1));
          };
          double at = 0;
          for (const auto& [c0, c1] : covers[i]) {
            if (c1 <= at) continue;
            if (c0 > at) keep_part(at, c0);
            st.length_removed += (c1 - std::max(c0, at)) * len;
            ++st.pieces_removed;
            at = c1;
            flush();
          }
          if (at < 1) keep_part(at, 1);
        }
        flush();
      }
      for (std::size_t o = first_out; o < out.size(); ++o) {  // what is drawn is kept for the strokes after it
        std::vector<Point2> q = out[o].points;
        if (out[o].closed && q.size() > 2) q.push_back(q.front());
        for (std::size_t k = 0; k + 1 < q.size(); ++k) {
          kept.push_back({q[k], q[k + 1]});
          grid.add(q[k], q[k + 1], tol, kept.size() - 1);
        }
      }
    }
    layer.strokes = std::move(out);
  }
  std::vector<PlotLayer> layers;
  for (PlotLayer& l : plot.layers)
    if (!l.strokes.empty()) layers.push_back(std::move(l));
  plot.layers = std::move(layers);
  return st;
}

}  // namespace hlr
