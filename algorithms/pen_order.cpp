// Pen order (see pen_order.hpp).
#include "algorithms/pen_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hlr {
namespace {

double dist(const Point2& a, const Point2& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

// Points in a uniform grid, for nearest-point queries; entries can be switched off.
class PointGrid {
 public:
  struct Entry {
    Point2 p;
    std::uint32_t stroke, point;
  };
  explicit PointGrid(std::vector<Entry> entries) : entries_(std::move(entries)) {
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    for (const Entry& e : entries_) x0 = std::min(x0, e.p[0]), x1 = std::max(x1, e.p[0]), y0 = std::min(y0, e.p[1]), y1 = std::max(y1, e.p[1]);
    if (entries_.empty()) x0 = y0 = 0, x1 = y1 = 1;
    x0_ = x0, y0_ = y0;
    g_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(entries_.size()) / 2)), 1, 4096);
    size_ = std::max({(x1 - x0) / g_, (y1 - y0) / g_, 1e-300});
    cells_.assign(static_cast<std::size_t>(g_) * g_, {});
    live_ = entries_.size();
    for (std::uint32_t i = 0; i < entries_.size(); ++i) {
      cells_[cell(entries_[i].p)].push_back(i);
      if (by_stroke_.size() <= entries_[i].stroke) by_stroke_.resize(entries_[i].stroke + 1);
      by_stroke_[entries_[i].stroke].push_back(i);
    }
  }
  /// Takes a stroke's entries out of the grid.
  void remove_stroke(std::uint32_t s) {
    if (s >= by_stroke_.size()) return;
    for (std::uint32_t i : by_stroke_[s]) {
      auto& c = cells_[cell(entries_[i].p)];
      auto it = std::find(c.begin(), c.end(), i);
      if (it != c.end()) *it = c.back(), c.pop_back();
      --live_;
    }
    by_stroke_[s].clear();
  }
  const std::vector<Entry>& entries() const { return entries_; }
  /// The nearest entry with accept(entry) true, or -1.
  template <class Accept>
  long nearest(const Point2& q, Accept accept, double max_dist = std::numeric_limits<double>::infinity()) const {
    if (live_ == 0) return -1;
    int cx = clampc((q[0] - x0_) / size_), cy = clampc((q[1] - y0_) / size_);
    long best = -1;
    double bd = std::numeric_limits<double>::infinity();
    for (int r = 0; r < 2 * g_; ++r) {
      if (best >= 0 && bd < (r - 1) * size_) break;  // every unvisited cell is farther
      if ((r - 1) * size_ > max_dist) break;
      bool any = false;
      for (int y = cy - r; y <= cy + r; ++y) {
        if (y < 0 || y >= g_) continue;
        for (int x = cx - r; x <= cx + r; x += (y == cy - r || y == cy + r) ? 1 : 2 * r) {
          if (x < 0 || x >= g_) {
            if (r == 0) break;
            continue;
          }
          any = true;
          for (std::uint32_t i : cells_[static_cast<std::size_t>(y) * g_ + x]) {
            if (!accept(entries_[i])) continue;
            double d = dist(q, entries_[i].p);
            if (d > max_dist) continue;
            if (d < bd || (d == bd && static_cast<long>(i) < best)) bd = d, best = i;
          }
          if (r == 0) break;
        }
      }
      if (!any && r > g_) break;
    }
    return best;
  }

 private:
  int clampc(double c) const { return std::clamp(static_cast<int>(std::floor(c)), 0, g_ - 1); }
  std::size_t cell(const Point2& p) const {
    return static_cast<std::size_t>(clampc((p[1] - y0_) / size_)) * g_ + clampc((p[0] - x0_) / size_);
  }
  std::vector<Entry> entries_;
  std::vector<std::vector<std::uint32_t>> cells_, by_stroke_;
  std::size_t live_ = 0;
  double x0_ = 0, y0_ = 0, size_ = 1;
  int g_ = 1;
};

// Entries of a stroke: both ends of an open one, every point of a closed one.
std::vector<PointGrid::Entry> stroke_entries(const std::vector<Stroke>& strokes, bool all_closed_points) {
  std::vector<PointGrid::Entry> out;
  for (std::uint32_t s = 0; s < strokes.size(); ++s) {
    const auto& pts = strokes[s].points;
    if (pts.empty()) continue;
    if (strokes[s].closed) {
      std::uint32_t n = all_closed_points ? static_cast<std::uint32_t>(pts.size()) : 1;
      for (std::uint32_t k = 0; k < n; ++k) out.push_back({pts[k], s, k});
    } else {
      out.push_back({pts.front(), s, 0});
      if (pts.size() > 1) out.push_back({pts.back(), s, static_cast<std::uint32_t>(pts.size() - 1)});
    }
  }
  return out;
}

struct Placed {
  std::uint32_t stroke;
  char reversed;
  std::uint32_t start;
};

Point2 first_point(const std::vector<Stroke>& s, const Placed& p) {
  const auto& pts = s[p.stroke].points;
  if (s[p.stroke].closed) return pts[p.start];
  return p.reversed ? pts.back() : pts.front();
}
Point2 last_point(const std::vector<Stroke>& s, const Placed& p) {
  const auto& pts = s[p.stroke].points;
  if (s[p.stroke].closed) return pts[p.start];
  return p.reversed ? pts.front() : pts.back();
}

double travel(const std::vector<Stroke>& s, const std::vector<Placed>& seq, Point2 home) {
  double t = 0;
  Point2 at = home;
  for (const Placed& p : seq) {
    t += dist(at, first_point(s, p));
    at = last_point(s, p);
  }
  return t;
}

std::vector<Placed> greedy(const std::vector<Stroke>& strokes, Point2 home) {
  PointGrid grid(stroke_entries(strokes, true));
  std::vector<char> used(strokes.size(), 0);
  std::vector<Placed> seq;
  Point2 at = home;
  for (;;) {
    long e = grid.nearest(at, [&](const PointGrid::Entry& x) { return !used[x.stroke]; });
    if (e < 0) break;
    const PointGrid::Entry& x = grid.entries()[e];
    used[x.stroke] = 1;
    grid.remove_stroke(x.stroke);
    const Stroke& s = strokes[x.stroke];
    Placed p{x.stroke, static_cast<char>(!s.closed && x.point != 0), s.closed ? x.point : 0};
    seq.push_back(p);
    at = last_point(strokes, p);
  }
  for (std::uint32_t s = 0; s < strokes.size(); ++s)  // strokes without points, last
    if (!used[s]) seq.push_back({s, 0, 0});
  return seq;
}

// 2-opt over near neighbours: for the pen position before place i (the end of place i - 1),
// try reversing places i..j where place j's last point is one of that position's neighbours.
void two_opt(const std::vector<Stroke>& strokes, std::vector<Placed>& seq, Point2 home, const PenOrderOptions& opt) {
  const std::size_t n = seq.size();
  if (n < 3) return;
  PointGrid grid(stroke_entries(strokes, false));
  std::vector<std::uint32_t> pos(strokes.size());
  for (std::uint32_t i = 0; i < n; ++i) pos[seq[i].stroke] = i;
  std::size_t budget = 64 * n + 10'000'000;  // elements moved by reversals: bounded work, deterministic
  for (int pass = 0; pass < opt.max_passes; ++pass) {
    bool improved = false;
    for (std::size_t i = 0; i < n; ++i) {
      Point2 prev = i == 0 ? home : last_point(strokes, seq[i - 1]);
      Point2 first_i = first_point(strokes, seq[i]);
      double old_in = dist(prev, first_i);
      if (old_in == 0) continue;
      // Two families of moves, each from a neighbour list: place j's last point near `prev`
      // (the new edge into place i), or place j+1's first point near place i's first point
      // (the new edge out of the reversed run). Only neighbours nearer than the edge they
      // replace can help.
      std::vector<std::size_t> js;
      for (int family = 0; family < 2; ++family) {
        const Point2 at = family == 0 ? prev : first_i;
        std::vector<std::uint32_t> cands;
        for (std::size_t k = 0; k < opt.neighbours; ++k) {
          long e = grid.nearest(at, [&](const PointGrid::Entry& x) {
            return pos[x.stroke] > i + static_cast<std::size_t>(family) && std::find(cands.begin(), cands.end(), x.stroke) == cands.end();
          }, old_in);
          if (e < 0) break;
          cands.push_back(grid.entries()[e].stroke);
        }
        for (std::uint32_t c : cands) js.push_back(family == 0 ? pos[c] : pos[c] - 1);
      }
      for (std::size_t j : js) {
        if (j < i) continue;
        Point2 last_j = last_point(strokes, seq[j]);
        double old_out = j + 1 < n ? dist(last_j, first_point(strokes, seq[j + 1])) : 0;
        double new_in = dist(prev, last_j);
        double new_out = j + 1 < n ? dist(first_i, first_point(strokes, seq[j + 1])) : 0;
        if (new_in + new_out < old_in + old_out - 1e-12 * (old_in + old_out)) {
          if (budget < j - i + 1) return;
          budget -= j - i + 1;
          std::reverse(seq.begin() + static_cast<long>(i), seq.begin() + static_cast<long>(j) + 1);
          for (std::size_t k = i; k <= j; ++k) {
            seq[k].reversed = static_cast<char>(!seq[k].reversed);
            pos[seq[k].stroke] = static_cast<std::uint32_t>(k);
          }
          improved = true;
          break;
        }
      }
    }
    if (!improved) break;
  }
}

}  // namespace

double pen_up_length(const std::vector<Stroke>& strokes, Point2 home) {
  std::vector<Placed> seq;
  for (std::uint32_t s = 0; s < strokes.size(); ++s) seq.push_back({s, 0, 0});
  return travel(strokes, seq, home);
}

PenOrder order_strokes(const std::vector<Stroke>& strokes, Point2 home, const PenOrderOptions& opt) {
  std::vector<Placed> seq = greedy(strokes, home);
  PenOrder out;
  out.pen_up_greedy = travel(strokes, seq, home);
  if (opt.two_opt) two_opt(strokes, seq, home, opt);
  out.pen_up = travel(strokes, seq, home);
  for (const Placed& p : seq) {
    out.order.push_back(p.stroke);
    out.reversed.push_back(p.reversed);
    out.start.push_back(p.start);
  }
  return out;
}

}  // namespace hlr
