// The exact scan-line z-buffer (course notes section 34). See scanline.hpp.
#include "algorithms/raster/scanline.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "algorithms/support/parallel.hpp"
#include "algorithms/raster/zbuffer.hpp"

namespace hlr {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
double up(double v) { return next_up(v); }

// The span of polygon p on the row at y (an exact double): [L, R] as intervals containing the
// exact ends (L = -inf, R = +inf when no side bounds them). False when a side's slope has no
// certain sign (a nearly horizontal side): the caller tests centres one by one.
bool span(const RasterScene& scene, const RasterPolygon& p, double y, Interval& L, Interval& R) {
  L = {-kInf, -kInf}, R = {kInf, kInf};
  for (int k = 0; k < p.count; ++k) {
    const FilteredLinear& s = scene.side(p, k);  // A + B·x + C·y >= 0, each within [m, m + r]
    const Interval A{s.m[0], up(s.m[0] + s.r[0])}, B{s.m[1], up(s.m[1] + s.r[1])}, C{s.m[2], up(s.m[2] + s.r[2])};
    const Interval sum = interval::add(A, interval::scale(C, y));
    const Interval rhs{-sum.hi, -sum.lo};  // -(A + C·y)
    Interval x;
    if (!interval::divide(rhs, B, x)) return false;  // B's sign uncertain, or x not finite
    if (B.lo > 0) L = {std::max(L.lo, x.lo), std::max(L.hi, x.hi)};  // x >= bound
    else R = {std::min(R.lo, x.lo), std::min(R.hi, x.hi)};           // x <= bound
  }
  return true;
}

}  // namespace

std::optional<ExactSpan> exact_span(const RasterScene& s, const RasterPolygon& p, const Rational& y) {
  const std::vector<Exact2> pts = s.points(p);
  ExactSpan out;
  bool has_l = false, has_r = false;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const Exact2 &a = pts[k], &b = pts[(k + 1) % pts.size()];
    // orient(a, b, q) = A + B·x + C·y >= 0 inside.
    const Rational B = a[1] - b[1], C = b[0] - a[0];
    const Rational A = (b[1] - a[1]) * a[0] - (b[0] - a[0]) * a[1];
    const Rational rest = A + C * y;
    if (B == 0) {
      if (rest < 0) return std::nullopt;  // the row lies outside this side
      continue;
    }
    const Rational x = -rest / B;
    // A row through a corner meets both sides there: the bound is the side that continues
    // below the row (its ΔX is the change to the next row down).
    const bool below = std::min(a[1], b[1]) < y;
    if (B > 0 && (!has_l || x > out.xl || (x == out.xl && below))) out.xl = x, out.left = static_cast<int>(k), has_l = true;
    if (B < 0 && (!has_r || x < out.xr || (x == out.xr && below))) out.xr = x, out.right = static_cast<int>(k), has_r = true;
  }
  if (!has_l || !has_r || out.xl > out.xr) return std::nullopt;
  return out;
}

FaceIdBuffer scanline(const RasterScene& s, const ScanlineOptions& o, ScanlineStats* stats) {
  const RasterGrid& g = s.grid;
  std::vector<int> frame(static_cast<std::size_t>(g.width) * g.height, -1);
  std::vector<std::array<int, 2>> rows(s.polygons.size());
  for (std::size_t p = 0; p < s.polygons.size(); ++p) rows[p] = g.rows(s.polygons[p].box[1], s.polygons[p].box[3]);
  constexpr int kBand = 32;
  const int bands = (g.height + kBand - 1) / kBand;
  std::atomic<std::size_t> spans{0}, by_test{0};
  ParallelLoop(o.threads).for_each(bands, 1, [&](std::size_t band) {
    const int j0 = static_cast<int>(band) * kBand, j1 = std::min(g.height, j0 + kBand);
    // The y-group list: polygons under the first row of this band they may cover.
    std::vector<std::vector<int>> ygroup(j1 - j0);
    for (std::size_t p = 0; p < s.polygons.size(); ++p)
      if (rows[p][0] < j1 && rows[p][1] > j0) ygroup[std::max(rows[p][0], j0) - j0].push_back(static_cast<int>(p));
    std::vector<int> active;
    std::size_t n_spans = 0, n_test = 0;
    for (int j = j0; j < j1; ++j) {
      for (int p : ygroup[j - j0]) active.push_back(p);
      active.erase(std::remove_if(active.begin(), active.end(), [&](int p) { return rows[p][1] <= j; }), active.end());
      const double y = g.cy(j);
      int* row = &frame[static_cast<std::size_t>(j) * g.width];
      for (int p : active) {
        const RasterPolygon& poly = s.polygons[p];
        if (y < poly.box[1] || y > poly.box[3]) continue;
        Interval L, R;
        const bool ok = span(s, poly, y, L, R);
        ++n_spans;
        n_test += !ok;
        auto cols = ok ? g.columns(std::max(L.lo, poly.box[0]), std::min(R.hi, poly.box[2])) : g.columns(poly.box[0], poly.box[2]);
        for (int i = cols[0]; i < cols[1]; ++i) {
          const double x = g.cx(i);
          bool in;
          if (ok && x >= L.hi && x <= R.lo) in = true;
          else if (ok && (x < L.lo || x > R.hi)) in = false;
          else in = s.covers(poly, i, j);
          if (!in) continue;
          if (row[i] < 0 || s.nearer(poly, s.polygons[row[i]], x, y)) row[i] = p;
        }
      }
    }
    spans += n_spans;
    by_test += n_test;
  });
  if (stats) stats->spans = spans, stats->spans_by_test = by_test;
  return face_ids(s, frame);
}

}  // namespace hlr
