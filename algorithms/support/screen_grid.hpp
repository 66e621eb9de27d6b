// The screen grid: a uniform grid over the projected boxes of occluders (faces' triangles in
// the per-face route, whole bodies in Roberts' algorithm, course notes sections 26-28), so
// that a segment is tested only against the occluders whose boxes its own box meets. A filter
// only: it skips work, never decides visibility. Boxes are double screen rectangles widened by
// the caller's margin (exact_int.hpp, bounds::kBoxMargin); items that cannot be bounded
// (perspective, not strictly in front of the eye) are "always" candidates.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace hlr {

/// A screen rectangle (drawing coordinates, the caller's margin included).
struct ScreenRect {
  double x0, y0, x1, y1;
  bool meets(const ScreenRect& o) const { return !(x0 > o.x1 || x1 < o.x0 || y0 > o.y1 || y1 < o.y0); }
};

/// Perspective: opens `r` to infinity on the sides toward which the projection of a convex set
/// runs off where it meets the plane through the eye; `signs` are the screen signs of one of
/// its crossing points (Camera::eye_plane_signs). Doing this for the crossing points of every
/// edge from a point strictly in front of the eye to one that is not, starting from the box of
/// the front points' projections, bounds the projection of the set's part in front of the eye
/// (docs/design.md, "Occluders that reach behind the eye").
template <class R>
void open_toward(R& r, const std::array<int, 2>& signs) {
  using T = decltype(r.x0);
  constexpr T inf = std::numeric_limits<T>::infinity();
  if (signs[0] > 0) r.x1 = inf;
  if (signs[0] < 0) r.x0 = -inf;
  if (signs[1] > 0) r.y1 = inf;
  if (signs[1] < 0) r.y0 = -inf;
}

class ScreenGrid {
 public:
  /// Builds the grid over `rects` (items with always[i] set are skipped and visited always);
  /// about `items_per_cell` items per cell, at most `max_cells` cells a side; on `threads`
  /// cores (0: all; the same grid on any number).
  void build(const std::vector<ScreenRect>& rects, const std::vector<char>& always, double items_per_cell,
             int max_cells, unsigned threads = 0);
  /// The same over n rectangles read as rect(i) (no array of them: a large grid's caller
  /// keeps its own boxes), none always.
  void build(std::size_t n, const std::function<ScreenRect(std::size_t)>& rect, double items_per_cell, int max_cells, unsigned threads = 0);

  /// Calls f(i) for every "always" item and for every item whose cell range meets the query
  /// (items may come more than once: callers deduplicate with stamps).
  template <class F>
  void visit(const ScreenRect& q, F&& f) const {
    for (int i : always_) f(i);
    auto [cx0, cy0, cx1, cy1] = range(q);
    for (int cy = cy0; cy <= cy1; ++cy)
      for (int cx = cx0; cx <= cx1; ++cx) {
        std::size_t id = static_cast<std::size_t>(cy) * n_ + cx;
        for (std::uint32_t k = start_[id]; k < start_[id + 1]; ++k) f(static_cast<int>(items_[k]));
      }
  }

  const std::vector<int>& always() const { return always_; }

 private:
  template <class Rect, class Always>
  void build_from(std::size_t n, const Rect& rect, const Always& always, double items_per_cell, int max_cells, unsigned threads);
  std::array<int, 4> range(const ScreenRect& r) const;

  double x0_ = 0, y0_ = 0, cell_ = 1;
  int n_ = 1;
  std::vector<std::uint32_t> start_, items_;
  std::vector<int> always_;
};

/// Deduplicates item ids met during one query ("stamps"), cheaply across many queries.
class StampSet {
 public:
  void reset(std::size_t n) { stamp_.assign(n, 0), current_ = 0; }
  void next() {
    if (++current_ == 0) {
      std::fill(stamp_.begin(), stamp_.end(), 0);
      current_ = 1;
    }
  }
  /// True the first time `i` is seen since next().
  bool first(int i) {
    if (stamp_[i] == current_) return false;
    stamp_[i] = current_;
    return true;
  }

 private:
  std::vector<std::uint32_t> stamp_;
  std::uint32_t current_ = 0;
};

}  // namespace hlr
