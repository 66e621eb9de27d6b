// The screen grid (see screen_grid.hpp): counting sort of items into cells, two passes
// (course notes sections 26-28).
#include "algorithms/support/screen_grid.hpp"

#include "algorithms/support/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace hlr {

void ScreenGrid::build(const std::vector<ScreenRect>& rects, const std::vector<char>& always, double items_per_cell,
                       int max_cells, unsigned threads) {
  build_from(
      rects.size(), [&](std::size_t i) { return rects[i]; }, [&](std::size_t i) { return always[i] != 0; }, items_per_cell, max_cells, threads);
}

void ScreenGrid::build(std::size_t n, const std::function<ScreenRect(std::size_t)>& rect, double items_per_cell, int max_cells, unsigned threads) {
  build_from(
      n, rect, [](std::size_t) { return false; }, items_per_cell, max_cells, threads);
}

template <class Rect, class Always>
void ScreenGrid::build_from(std::size_t n, const Rect& rect, const Always& always, double items_per_cell, int max_cells, unsigned threads) {
  // The grid spans the middle 98% of the boxes' finite sides: in perspective a few boxes near
  // the eye project huge and would otherwise squeeze everything else into a few cells. Boxes
  // (and queries) beyond clamp to the edge cells; clamping keeps every overlap, so the grid
  // never loses a candidate. Unbounded sides (occluders reaching the eye plane) clamp too.
  // Large inputs: the span from every k-th box (the grid's extent is a heuristic; any extent
  // keeps every candidate), so that a million boxes cost no four selections over millions.
  std::vector<double> xs, ys;
  std::size_t count = 0;
  const std::size_t every = std::max<std::size_t>(1, n / 65536);
  always_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (always(i)) {
      always_.push_back(static_cast<int>(i));
      continue;
    }
    ++count;
    if (i % every) continue;
    const ScreenRect r = rect(i);
    for (double v : {r.x0, r.x1})
      if (std::isfinite(v)) xs.push_back(v);
    for (double v : {r.y0, r.y1})
      if (std::isfinite(v)) ys.push_back(v);
  }
  auto span = [](std::vector<double>& v, double& lo, double& hi) {
    if (v.empty()) {
      lo = 0, hi = 1;
      return;
    }
    const std::size_t k = v.size() / 100;
    std::nth_element(v.begin(), v.begin() + k, v.end());
    lo = v[k];
    std::nth_element(v.begin(), v.end() - 1 - k, v.end());
    hi = v[v.size() - 1 - k];
  };
  double X0, X1, Y0, Y1;
  span(xs, X0, X1);
  span(ys, Y0, Y1);
  if (!(X1 >= X0) || !(Y1 >= Y0) || !std::isfinite(X1 - X0) || !std::isfinite(Y1 - Y0)) X0 = Y0 = 0, X1 = Y1 = 1;
  n_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(count) / items_per_cell)), 1, max_cells);
  x0_ = X0;
  y0_ = Y0;
  cell_ = std::max({(X1 - X0) / n_, (Y1 - Y0) / n_, 1e-300});
  start_.assign(static_cast<std::size_t>(n_) * n_ + 1, 0);
  // Each item's cell range (worked out again for the second pass: no array of them), the
  // cells' counts and their items, all on all cores: the items land in a cell in any order and
  // each cell is then sorted (by index: the same grid on any number of threads).
  const ParallelLoop loop(threads);
  loop.for_each(n, 8192, [&](std::size_t i) {
    if (always(i)) return;
    auto [cx0, cy0, cx1, cy1] = range(rect(i));
    for (int cy = cy0; cy <= cy1; ++cy)
      for (int cx = cx0; cx <= cx1; ++cx)
        std::atomic_ref<std::uint32_t>(start_[static_cast<std::size_t>(cy) * n_ + cx + 1]).fetch_add(1, std::memory_order_relaxed);
  });
  for (std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
  reserve_touched(items_, start_.back(), loop);
  items_.resize(start_.back());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  loop.for_each(n, 8192, [&](std::size_t i) {
    if (always(i)) return;
    auto [cx0, cy0, cx1, cy1] = range(rect(i));
    for (int cy = cy0; cy <= cy1; ++cy)
      for (int cx = cx0; cx <= cx1; ++cx) {
        const std::size_t cell = static_cast<std::size_t>(cy) * n_ + cx;
        items_[std::atomic_ref<std::uint32_t>(fill[cell]).fetch_add(1, std::memory_order_relaxed)] = static_cast<std::uint32_t>(i);
      }
  });
  loop.for_each(start_.size() - 1, 4096, [&](std::size_t c) {
    if (start_[c + 1] - start_[c] > 1) std::sort(items_.begin() + start_[c], items_.begin() + start_[c + 1]);
  });
}

std::array<int, 4> ScreenGrid::range(const ScreenRect& r) const {
  // NaN (a degenerate projection) clamps to the whole grid: never skips an item.
  auto c = [&](double v, double o, bool low) {
    double k = std::floor((v - o) / cell_);
    if (std::isnan(k)) return low ? 0 : n_ - 1;
    return static_cast<int>(std::clamp(k, 0.0, static_cast<double>(n_ - 1)));
  };
  return {c(r.x0, x0_, true), c(r.y0, y0_, true), c(r.x1, x0_, false), c(r.y1, y0_, false)};
}

}  // namespace hlr
