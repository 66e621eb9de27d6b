// Pen order (see pen_order.hpp).
#include "algorithms/plot/pen_order.hpp"

#include "algorithms/support/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hlr {
namespace {

double dist(const Point2& a, const Point2& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], d = std::sqrt(dx * dx + dy * dy);
  return std::isfinite(d) ? d : std::hypot(dx, dy);  // hypot only where the squares overflow
}

// Points in a uniform grid, for nearest-point queries; entries can be switched off.
class PointGrid {
 public:
  struct Entry {
    Point2 p;
    std::uint32_t stroke, point;
  };
  explicit PointGrid(std::vector<Entry> entries) : entries_(std::move(entries)), removed_(entries_.size(), 0) {
    for (std::uint32_t i = 0; i < entries_.size(); ++i) {
      if (by_stroke_.size() <= entries_[i].stroke) by_stroke_.resize(entries_[i].stroke + 1);
      by_stroke_[entries_[i].stroke].push_back(i);
    }
    build();
  }
  /// Takes a stroke's entries out of the grid. When three quarters of the entries the cells were
  /// built with are gone, the cells are built again, coarser, over the rest: searches never walk
  /// rings of empty cells (the greedy pass's last strokes). Results do not depend on the cells.
  void remove_stroke(std::uint32_t s) {
    if (s >= by_stroke_.size()) return;
    for (std::uint32_t i : by_stroke_[s]) {
      auto& c = cells_[cell(entries_[i].p)];
      auto it = std::find(c.begin(), c.end(), i);
      if (it != c.end()) *it = c.back(), c.pop_back();
      removed_[i] = 1;
      --live_;
    }
    by_stroke_[s].clear();
    if (live_ > 0 && live_ * 4 < built_) build();
  }
  const std::vector<Entry>& entries() const { return entries_; }
  struct Found {
    double d;
    std::uint32_t entry, stroke;
    bool operator<(const Found& o) const { return d < o.d || (d == o.d && entry < o.entry); }
  };
  /// The `k` strokes nearest to `q` among entries with accept(entry) true and distance at most
  /// `max_dist`, each stroke by its nearest entry, in (distance, entry index) order, in one walk
  /// of the rings.
  template <class Accept>
  void nearest_strokes(const Point2& q, std::size_t k, Accept accept, double max_dist, std::vector<Found>& best) const {
    best.clear();
    if (live_ == 0 || k == 0) return;
    int cx = clampc((q[0] - x0_) / size_), cy = clampc((q[1] - y0_) / size_);
    for (int r = 0; r < 2 * g_; ++r) {
      if (best.size() == k && best.back().d < (r - 1) * size_) break;  // every unvisited cell is farther
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
            offer(best, k, Found{d, i, entries_[i].stroke});
          }
          if (r == 0) break;
        }
      }
      if (!any && r > g_) break;
    }
  }
  /// The nearest entry with accept(entry) true, or -1 (ties: the lower index).
  template <class Accept>
  long nearest(const Point2& q, Accept accept, double max_dist = std::numeric_limits<double>::infinity()) const {
    thread_local std::vector<Found> one;
    nearest_strokes(q, 1, accept, max_dist, one);  // the nearest stroke by its nearest entry
    return one.empty() ? -1 : static_cast<long>(one[0].entry);
  }

 private:
  // Keeps `best` the k smallest strokes (each by its smallest entry), sorted.
  static void offer(std::vector<Found>& best, std::size_t k, const Found& f) {
    if (best.size() == k && !(f < best.back())) return;  // beats nothing kept (nor its stroke's own entry)
    auto same = std::find_if(best.begin(), best.end(), [&](const Found& b) { return b.stroke == f.stroke; });
    if (same != best.end()) {
      if (!(f < *same)) return;
      best.erase(same);
    } else if (best.size() == k && !(f < best.back())) {
      return;
    }
    best.insert(std::upper_bound(best.begin(), best.end(), f), f);
    if (best.size() > k) best.pop_back();
  }
  // Cells over the entries still in, about two per cell.
  void build() {
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    live_ = 0;
    for (std::uint32_t i = 0; i < entries_.size(); ++i) {
      if (removed_[i]) continue;
      const Point2& p = entries_[i].p;
      x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
      ++live_;
    }
    if (live_ == 0) x0 = y0 = 0, x1 = y1 = 1;
    built_ = live_;
    x0_ = x0, y0_ = y0;
    g_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(live_) / 2)), 1, 4096);
    size_ = std::max({(x1 - x0) / g_, (y1 - y0) / g_, 1e-300});
    cells_.assign(static_cast<std::size_t>(g_) * g_, {});
    for (std::uint32_t i = 0; i < entries_.size(); ++i)
      if (!removed_[i]) cells_[cell(entries_[i].p)].push_back(i);
  }
  int clampc(double c) const { return std::clamp(static_cast<int>(std::floor(c)), 0, g_ - 1); }
  std::size_t cell(const Point2& p) const {
    return static_cast<std::size_t>(clampc((p[1] - y0_) / size_)) * g_ + clampc((p[0] - x0_) / size_);
  }
  std::vector<Entry> entries_;
  std::vector<std::vector<std::uint32_t>> cells_, by_stroke_;
  std::vector<char> removed_;
  std::size_t live_ = 0, built_ = 0;
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
    if (s[p.stroke].points.empty()) continue;  // nothing to draw, no travel
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

// One 2-opt move from place i: for the pen position before place i (the end of place i - 1),
// try reversing places i..j where place j's last point is one of that position's neighbours, or
// place j+1's first point one of place i's first point's neighbours (the new edge out of the
// reversed run). Only neighbours nearer than the edge they replace can help. Applies the first
// move that shortens the travel; returns its j, or -1.
struct TwoOpt {
  const std::vector<Stroke>& strokes;
  std::vector<Placed>& seq;
  Point2 home;
  const PenOrderOptions& opt;
  PointGrid grid;
  std::vector<std::uint32_t> pos;
  std::size_t budget;  // elements moved by reversals: bounded work, deterministic
  std::vector<std::size_t> js;
  std::vector<PointGrid::Found> found;

  // Per grid entry, its nearest entries of other strokes (2k strokes), found once: a pen
  // position at a stroke end reads its list instead of searching the grid.
  std::vector<std::uint32_t> first_entry;  // per stroke: its first entry (the front)
  std::vector<std::vector<PointGrid::Found>> near;

  TwoOpt(const std::vector<Stroke>& s, std::vector<Placed>& q, Point2 h, const PenOrderOptions& o)
      : strokes(s), seq(q), home(h), opt(o), grid(stroke_entries(s, false)), pos(s.size()), budget(64 * q.size() + 10'000'000) {
    for (std::uint32_t i = 0; i < seq.size(); ++i) pos[seq[i].stroke] = i;
    const auto& entries = grid.entries();
    first_entry.assign(s.size(), kNone);
    near.resize(entries.size());
    for (std::uint32_t e = 0; e < entries.size(); ++e)
      if (first_entry[entries[e].stroke] == kNone) first_entry[entries[e].stroke] = e;
    ParallelLoop(opt.threads).for_each(entries.size(), 256, [&](std::size_t e) {
      const std::uint32_t own = entries[e].stroke;
      grid.nearest_strokes(entries[e].p, 2 * opt.neighbours, [&](const PointGrid::Entry& x) { return x.stroke != own; },
                           std::numeric_limits<double>::infinity(), near[e]);
    });
  }
  static constexpr std::uint32_t kNone = 0xffffffffu;

  // The grid entry at a stroke's end point (first: the point drawn first), or kNone.
  std::uint32_t entry_at(const Placed& p, bool first) const {
    const Stroke& st = strokes[p.stroke];
    const std::uint32_t e = first_entry[p.stroke];
    if (e == kNone) return kNone;
    if (st.closed) return p.start == 0 ? e : kNone;
    const bool front = first != static_cast<bool>(p.reversed);
    return front || st.points.size() < 2 ? e : e + 1;
  }

  // Up to opt.neighbours strokes after place `after`, nearest to the point `at` (the entry `e`
  // when it is one) within `max_dist`: the grid search's answer, from the entry's list when
  // the list holds it.
  void candidates(const Point2& at, std::uint32_t e, std::size_t after, double max_dist) {
    auto later = [&](const PointGrid::Entry& x) { return pos[x.stroke] > after; };
    if (e == kNone) {
      grid.nearest_strokes(at, opt.neighbours, later, max_dist, found);
      return;
    }
    // The list is every stroke nearer than its last one, in the search's order: the later
    // ones in it are the search's answer unless the list runs out first.
    found.clear();
    const auto& list = near[e];
    for (const PointGrid::Found& c : list) {
      if (c.d > max_dist || found.size() == opt.neighbours) return;
      if (pos[c.stroke] > after) found.push_back(c);
    }
    if (list.size() == 2 * opt.neighbours) grid.nearest_strokes(at, opt.neighbours, later, max_dist, found);
  }

  long move_from(std::size_t i) {
    const std::size_t n = seq.size();
    Point2 prev = i == 0 ? home : last_point(strokes, seq[i - 1]);
    Point2 first_i = first_point(strokes, seq[i]);
    double old_in = dist(prev, first_i);
    if (old_in == 0) return -1;
    js.clear();
    for (int family = 0; family < 2; ++family) {
      const Point2 at = family == 0 ? prev : first_i;
      const std::uint32_t e = family == 0 ? (i == 0 ? kNone : entry_at(seq[i - 1], false)) : entry_at(seq[i], true);
      candidates(at, e, i + static_cast<std::size_t>(family), old_in);
      for (const PointGrid::Found& c : found) js.push_back(family == 0 ? pos[c.stroke] : pos[c.stroke] - 1);
    }
    for (std::size_t j : js) {
      if (j < i) continue;
      Point2 last_j = last_point(strokes, seq[j]);
      double old_out = j + 1 < n ? dist(last_j, first_point(strokes, seq[j + 1])) : 0;
      double new_in = dist(prev, last_j);
      double new_out = j + 1 < n ? dist(first_i, first_point(strokes, seq[j + 1])) : 0;
      if (new_in + new_out < old_in + old_out - 1e-12 * (old_in + old_out)) {
        if (budget < j - i + 1) return -2;
        budget -= j - i + 1;
        std::reverse(seq.begin() + static_cast<long>(i), seq.begin() + static_cast<long>(j) + 1);
        for (std::size_t k = i; k <= j; ++k) {
          seq[k].reversed = static_cast<char>(!seq[k].reversed);
          pos[seq[k].stroke] = static_cast<std::uint32_t>(k);
        }
        return static_cast<long>(j);
      }
    }
    return -1;
  }

  // Passes over the places in order, as long as one moves something; after the first, a
  // place is looked at only when a move changed a pen-up edge next to it (don't-look bits),
  // and a quiet pass of that kind is followed by a whole one (a move can open up elsewhere:
  // neighbours' places moved). Ends at a whole pass that moves nothing, or when the work bound
  // (max_passes looks at every place) is spent.
  void run() {
    const std::size_t n = seq.size();
    std::vector<char> dirty(strokes.size(), 1);  // per stroke: the edge into its place changed
    std::size_t evaluations = static_cast<std::size_t>(std::max(opt.max_passes, 1)) * n;
    bool whole = true;
    for (;;) {
      bool moved = false;
      for (std::size_t i = 0; i < n && evaluations > 0; ++i) {
        if (!whole && !dirty[seq[i].stroke]) continue;
        dirty[seq[i].stroke] = 0;
        --evaluations;
        long j = move_from(i);
        if (j == -2) return;
        if (j < 0) continue;
        moved = true;
        const std::size_t jj = static_cast<std::size_t>(j);
        for (std::size_t p : {i - 1, i, i + 1, jj, jj + 1, jj + 2})
          if (p < n) dirty[seq[p].stroke] = 1;
      }
      if (evaluations == 0 || (whole && !moved)) return;
      whole = !moved;
    }
  }
};

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
  if (opt.two_opt) {  // over the strokes with points (the greedy pass put the empty ones last)
    std::vector<Placed> empty;
    while (!seq.empty() && strokes[seq.back().stroke].points.empty()) empty.push_back(seq.back()), seq.pop_back();
    if (seq.size() >= 3) TwoOpt(strokes, seq, home, opt).run();
    seq.insert(seq.end(), empty.rbegin(), empty.rend());
  }
  out.pen_up = travel(strokes, seq, home);
  for (const Placed& p : seq) {
    out.order.push_back(p.stroke);
    out.reversed.push_back(p.reversed);
    out.start.push_back(p.start);
  }
  return out;
}

}  // namespace hlr
