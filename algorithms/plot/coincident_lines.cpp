// Lines that coincide on the page drawn once (see coincident_lines.hpp; docs/design.md, "Lines
// that coincide on the page"). Strokes are taken in priority order; for a segment pq and a
// kept segment ab nearly parallel to it, the part of pq covered is where the foot of its point
// falls on ab and its distance to ab's line is at most the tolerance (the distance is linear
// along pq). The kept segments are found in a grid of cells a few tolerances wide and of
// direction classes: a segment looks only at the kept segments in the cells near it whose
// direction lies within the angle of its own, so a drawing denser than the pen costs about the
// same per segment as a sparse one. Strokes are looked at in batches on all cores: each
// segment of a batch first against what the strokes before the batch kept (the grid does not
// change meanwhile), then, stroke by stroke in order, against what the batch's earlier strokes
// kept (the newest entries of the grid's lists, read only where the boxes meet; a long
// stroke's segments on all cores): the same covers as one stroke at a time, on any number of
// cores. What a stroke keeps has its lists found on all cores and is linked in order.
#include "algorithms/plot/coincident_lines.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <utility>

#include "algorithms/support/parallel.hpp"
#include "algorithms/support/parallel_scan.hpp"
#include "algorithms/support/uninitialised.hpp"

namespace hlr {
namespace {

constexpr double kMaxSin = 0.0523;  // 3 degrees
// The direction classes: a pseudo-angle of the direction modulo a half turn, cut in kBins
// classes; a segment looks at the classes of the directions within kReach of its own (the 3
// degrees and a margin for rounding).
constexpr int kBins = 64;
const double kReachCos = std::cos(3.2 * M_PI / 180), kReachSin = std::sin(3.2 * M_PI / 180);

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

double length(const Point2& a, const Point2& b) { return std::hypot(b[0] - a[0], b[1] - a[1]); }

// A stroke's segments (a closed stroke's last one runs back to its first point).
std::size_t segment_count(const Stroke& s) {
  const std::size_t n = s.points.size();
  return n < 2 ? 0 : n - 1 + (s.closed && n > 2 ? 1 : 0);
}
Seg segment(const Stroke& s, std::size_t i) { return {s.points[i], s.points[(i + 1) % s.points.size()]}; }
double length(const Seg& g) { return length(g.a, g.b); }

// The direction class of (dx, dy): the pseudo-angle 1 - dx / (|dx| + dy) of the direction
// turned into the upper half plane grows with the angle from 0 to 2 over a half turn.
int direction_class(double dx, double dy) {
  if (dy < 0 || (dy == 0 && dx < 0)) dx = -dx, dy = -dy;
  const double p = 1 - dx / (std::fabs(dx) + dy);
  return std::clamp(static_cast<int>(p * (kBins / 2)), 0, kBins - 1);
}

// Whether the covers' direction test can be trusted to the class of a direction: its squared
// length neither underflows nor overflows.
bool sound_direction(double len2) { return len2 >= 1e-200 && len2 <= 1e200; }

// The kept segments by cell and direction class. A segment is entered, piece by piece (no
// piece longer than a cell), in the cells its pieces' boxes meet; a look pads the boxes by the
// reach.
class KeptGrid {
 public:
  // (Its arrays' pages are touched on all cores here, not one at a time as the merge fills them.)
  KeptGrid(const std::array<double, 4>& box, double min_cell, std::size_t segments, const ParallelLoop& loop) : x0_(box[0]), y0_(box[1]) {
    const double w = box[2] - box[0], h = box[3] - box[1], n = static_cast<double>(segments + 1);
    cell_ = std::max({min_cell, std::sqrt(w * h / n), std::max(w, h) / n});
    for (;;) {
      nx_ = static_cast<std::size_t>(std::min(w / cell_, 1e9)) + 1, ny_ = static_cast<std::size_t>(std::min(h / cell_, 1e9)) + 1;
      if (nx_ * ny_ * kBins <= 2 * segments + (1u << 20) || !(cell_ < INFINITY)) break;
      cell_ *= 1.25;
    }
    heads_.resize(nx_ * ny_ * kBins);
    loop.for_each(heads_.size(), 1 << 16, [&](std::size_t i) { heads_[i] = kNone; });
    reserve_touched(entries_, segments + segments / 2, loop);  // mostly one entry a segment: no copies as it grows
  }

  // Enters the segments kept[from...], each under its place in `kept` as id: many at once
  // have their lists found on all cores, then are linked in order.
  void add(const std::vector<Seg>& kept, std::size_t from, const ParallelLoop& loop) {
    if (kept.size() >= kNone) throw std::length_error("merge of coincident lines: too many segments");
    const std::size_t n = kept.size() - from;
    if (n < kParallelAdd) {
      for (std::size_t i = from; i < kept.size(); ++i) lists(kept[i], [&](std::size_t l) { link(l, static_cast<std::uint32_t>(i)); });
    } else {
      const std::vector<std::size_t> at = parallel_offsets(
          n,
          [&](std::size_t i) {
            std::size_t c = 0;
            lists(kept[from + i], [&](std::size_t) { ++c; });
            return c;
          },
          loop);
      std::vector<std::size_t> found(at[n]);
      loop.for_each(n, 256, [&](std::size_t i) {
        std::size_t w = at[i];
        lists(kept[from + i], [&](std::size_t l) { found[w++] = l; });
      });
      constexpr std::size_t kAhead = 16;  // the heads linked next fetched ahead (they lie far apart)
      for (std::size_t k = 0; k < std::min(kAhead, found.size()); ++k) __builtin_prefetch(&heads_[found[k]], 1);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = at[i]; k < at[i + 1]; ++k) {
          if (k + kAhead < found.size()) __builtin_prefetch(&heads_[found[k + kAhead]], 1);
          link(found[k], static_cast<std::uint32_t>(from + i));
        }
    }
    if (entries_.size() >= kNone) throw std::length_error("merge of coincident lines: too many segments");
  }

  std::size_t entries() const { return entries_.size(); }

  // f(id) for every kept segment in a cell within `reach` of s whose direction class lies
  // within the reach angle of s's (some more than once), of the entries from `first` on (a
  // list holds its newest entries first), until f returns true.
  template <class F>
  void visit(const Seg& s, double reach, std::size_t first_entry, F&& f) const {
    const double dx = s.b[0] - s.a[0], dy = s.b[1] - s.a[1], len2 = dx * dx + dy * dy;
    if (!(len2 > 0)) return;  // covered by nothing
    int first = 0, last = kBins - 1;
    if (sound_direction(len2)) {
      first = direction_class(dx * kReachCos + dy * kReachSin, dy * kReachCos - dx * kReachSin);
      last = direction_class(dx * kReachCos - dy * kReachSin, dy * kReachCos + dx * kReachSin);
    }
    bool done = false;
    cells(s, reach, [&](std::size_t cell) {
      for (int k = first; !done; k = (k + 1) % kBins) {
        for (std::uint32_t e = heads_[cell * kBins + k]; e != kNone && e >= first_entry && !done; e = entries_[e].next) done = f(entries_[e].id);
        if (k == last) break;
      }
    });
  }

 private:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  static constexpr std::size_t kParallelAdd = 1024;  // segments entered at once on all cores from this many

  // f(list) for every list (cell and direction class) s is entered in.
  template <class F>
  void lists(const Seg& s, F&& f) const {
    const double dx = s.b[0] - s.a[0], dy = s.b[1] - s.a[1], len2 = dx * dx + dy * dy;
    if (!(len2 > 0)) return;  // covers nothing
    const bool sound = sound_direction(len2);
    const int c = sound ? direction_class(dx, dy) : 0;
    cells(s, 0, [&](std::size_t cell) {
      for (int k = sound ? c : 0; k <= (sound ? c : kBins - 1); ++k) f(cell * kBins + static_cast<std::size_t>(k));
    });
  }
  void link(std::size_t list, std::uint32_t id) {
    std::uint32_t& head = heads_[list];
    entries_.push_back({id, head});
    head = static_cast<std::uint32_t>(entries_.size() - 1);
  }
  struct Entry {
    std::uint32_t id, next;
  };
  template <class F>
  void cells(const Seg& s, double pad, F&& f) const {
    const Point2 &a = s.a, &b = s.b;
    // How many pieces: any count finds every kept segment within the pad (each piece's box
    // is padded), so a plain square root will do where the squares do not overflow.
    const double dx = b[0] - a[0], dy = b[1] - a[1], sq = std::sqrt(dx * dx + dy * dy);
    const double len = std::isfinite(sq) ? sq : length(a, b);
    const std::size_t parts = len > cell_ ? static_cast<std::size_t>(std::min(std::ceil(len / cell_), 1e9)) : 1;
    for (std::size_t k = 0; k < parts; ++k) {
      const double t0 = static_cast<double>(k) / static_cast<double>(parts), t1 = static_cast<double>(k + 1) / static_cast<double>(parts);
      const double px = a[0] + t0 * (b[0] - a[0]), py = a[1] + t0 * (b[1] - a[1]);
      const double qx = a[0] + t1 * (b[0] - a[0]), qy = a[1] + t1 * (b[1] - a[1]);
      const std::size_t x0 = key(std::min(px, qx) - pad, x0_, nx_), x1 = key(std::max(px, qx) + pad, x0_, nx_);
      const std::size_t y0 = key(std::min(py, qy) - pad, y0_, ny_), y1 = key(std::max(py, qy) + pad, y0_, ny_);
      for (std::size_t x = x0; x <= x1; ++x)
        for (std::size_t y = y0; y <= y1; ++y) f(x * ny_ + y);
    }
  }
  std::size_t key(double v, double origin, std::size_t n) const {
    const double c = std::floor((v - origin) / cell_);
    if (!(c > 0)) return 0;  // also NaN
    return c >= static_cast<double>(n - 1) ? n - 1 : static_cast<std::size_t>(c);
  }

  double x0_, y0_, cell_ = 1;
  std::size_t nx_ = 1, ny_ = 1;
  RawVector<std::uint32_t> heads_;  // per cell and class: its last entry
  std::vector<Entry> entries_;
};

// The parameter interval of pq within `tol` of ab, alongside it and nearly parallel (empty:
// lo > hi).
std::pair<double, double> covered(const Point2& p, const Point2& q, const Seg& s, double tol) {
  const double dx = q[0] - p[0], dy = q[1] - p[1], len2 = dx * dx + dy * dy;
  const double ex = s.b[0] - s.a[0], ey = s.b[1] - s.a[1], elen2 = ex * ex + ey * ey;
  if (!(len2 > 0) || !(elen2 > 0)) return {1, 0};
  const double cross = dx * ey - dy * ex;
  if (std::fabs(cross) > kMaxSin * std::sqrt(len2 * elen2)) return {1, 0};
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
  // The signed distance of pq's points from ab's line, linear in t. (The two conditions only
  // narrow [lo, hi], in either order: a part too far from ab's line needs no feet.)
  const double elen = std::sqrt(elen2);
  const double d0 = ((p[0] - s.a[0]) * ey - (p[1] - s.a[1]) * ex) / elen, d1 = ((q[0] - s.a[0]) * ey - (q[1] - s.a[1]) * ex) / elen;
  clamp_to(d0, d1, -tol, tol);
  if (lo > hi) return {1, 0};
  // Where the feet of pq's points fall on ab: ab's parameter u(t) is linear in t.
  const double u0 = ((p[0] - s.a[0]) * ex + (p[1] - s.a[1]) * ey) / elen2;
  const double u1 = ((q[0] - s.a[0]) * ex + (q[1] - s.a[1]) * ey) / elen2;
  clamp_to(u0, u1, 0, 1);
  return {lo, hi};
}

// The covered runs of one segment: the union of the covers; a run shorter than the tolerance
// inside the segment is a touch (lines that cross at a small angle), not a line drawn twice.
std::vector<std::pair<double, double>> runs_of(std::vector<std::pair<double, double>>& covers, double len, double tol) {
  std::sort(covers.begin(), covers.end());
  std::vector<std::pair<double, double>> runs;
  for (const auto& c : covers)
    if (!runs.empty() && c.first <= runs.back().second + 1e-12) runs.back().second = std::max(runs.back().second, c.second);
    else runs.push_back(c);
  std::vector<std::pair<double, double>> kept;
  for (const auto& r : runs)
    if (!((r.second - r.first) * len < tol && r.first > 0 && r.second < 1)) kept.push_back(r);
  return kept;
}

// The merge, stroke by stroke in priority order; what a stroke keeps is kept for the strokes
// after it.
class Merge {
 public:
  // The reach: a margin of half the tolerance over it for the covers' rounding (and 1e-12 of the
  // drawing's size, for a tolerance far below it).
  Merge(const std::array<double, 4>& box, std::size_t segments, double tol, const ParallelLoop& loop)
      : tol_(tol),
        reach_(1.5 * tol + 1e-12 * std::max({std::fabs(box[0]), std::fabs(box[1]), std::fabs(box[2]), std::fabs(box[3])})),
        grid_(box, 2 * reach_, segments, loop),
        looked_(loop),
        look_(loop, 0) {
    reserve_touched(kept_, segments, loop);
  }

  // Appends to `out` the strokes each of `batch` leaves drawn (a stroke itself when nothing
  // covers it), in order; what a stroke draws is kept for the strokes after it.
  void batch(std::span<Stroke> batch, std::vector<Stroke>& out, const ParallelLoop& loop) {
    std::vector<std::size_t> at{0};
    std::vector<std::array<double, 4>> boxes;
    for (const Stroke& s : batch) at.push_back(at.back() + segment_count(s)), boxes.push_back(box_of(s));
    // A stroke whose box meets an earlier one's within the reach is looked at again after it.
    std::vector<char> again(batch.size(), 0);
    for (std::size_t j = 1; j < batch.size(); ++j)
      for (std::size_t i = 0; i < j && !again[j]; ++i) again[j] = meet(boxes[i], boxes[j], reach_);
    const std::size_t n = at.back(), first_kept = kept_.size(), first_entry = grid_.entries();
    std::vector<Covers> covers(n);
    auto look = [&](unsigned w, std::size_t begin, std::size_t end) {
      std::vector<std::uint32_t>& looked = looked_[w];
      if (looked.size() < kept_.size()) looked.resize(kept_.size(), 0);
      std::size_t j = static_cast<std::size_t>(std::upper_bound(at.begin(), at.end(), begin) - at.begin()) - 1;
      for (std::size_t i = begin; i < end; ++i) {
        while (i >= at[j + 1]) ++j;
        covers[i] = covers_of(segment(batch[j], i - at[j]), looked, ++look_[w], 0);
        if (!again[j] && !covers[i].empty()) covers[i] = runs_of(covers[i], length(segment(batch[j], i - at[j])), tol_);
      }
    };
    if (n >= kParallelSegments) loop.run(n, 256, look);
    else look(0, 0, n);
    for (std::size_t j = 0; j < batch.size(); ++j) {
      const std::span<Covers> mine(covers.data() + at[j], at[j + 1] - at[j]);
      // Looked at again (on all cores when long): against what the batch's earlier strokes kept.
      const bool more = again[j] && kept_.size() > first_kept;
      auto look_again = [&](unsigned w, std::size_t begin, std::size_t end) {
        std::vector<std::uint32_t>& looked = looked_[w];
        if (more && looked.size() < kept_.size()) looked.resize(kept_.size(), 0);
        for (std::size_t i = begin; i < end; ++i) {
          if (more && !whole(mine[i])) {
            const Covers extra = covers_of(segment(batch[j], i), looked, ++look_[w], first_entry);
            mine[i].insert(mine[i].end(), extra.begin(), extra.end());
          }
          if (!mine[i].empty()) mine[i] = runs_of(mine[i], length(segment(batch[j], i)), tol_);
        }
      };
      if (again[j] && mine.size() >= kParallelSegments) loop.run(mine.size(), 256, look_again);
      else if (again[j]) look_again(0, 0, mine.size());
      keep(std::move(batch[j]), mine, out, loop);
    }
  }
  const CoincidentStats& stats() const { return st_; }

  // A batch: strokes in order up to this many segments (a longer stroke alone) and strokes;
  // one of kParallelSegments or more is looked at on all cores.
  static constexpr std::size_t kBatchSegments = 4096, kBatchStrokes = 64, kParallelSegments = 1024;

 private:
  using Covers = std::vector<std::pair<double, double>>;

  static bool whole(const Covers& c) { return c.size() == 1 && c[0].first == 0 && c[0].second == 1; }
  static std::array<double, 4> box_of(const Stroke& s) {
    std::array<double, 4> b{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (const Point2& p : s.points) b = {std::min(b[0], p[0]), std::min(b[1], p[1]), std::max(b[2], p[0]), std::max(b[3], p[1])};
    return b;
  }
  // Whether two boxes come within `pad` of each other (a box with NaN meets every box).
  static bool meet(const std::array<double, 4>& a, const std::array<double, 4>& b, double pad) {
    return !(a[2] + pad < b[0] || b[2] + pad < a[0] || a[3] + pad < b[1] || b[3] + pad < a[1]);
  }

  // s split by its segments' covered runs, appended to `out`, and what it draws kept.
  void keep(Stroke&& s, std::span<const Covers> covers, std::vector<Stroke>& out, const ParallelLoop& loop) {
    bool touched = false;
    for (std::size_t i = 0; i < covers.size() && !touched; ++i) touched = !covers[i].empty();
    const std::size_t from = out.size();
    if (!touched) out.push_back(std::move(s));
    else
      for (Stroke& o : split(s, covers)) out.push_back(std::move(o));
    const std::size_t first = kept_.size();
    for (std::size_t k = from; k < out.size(); ++k)
      for (std::size_t i = 0; i < segment_count(out[k]); ++i) kept_.push_back(segment(out[k], i));
    grid_.add(kept_, first, loop);
  }

  // The covers of g (unsorted, not joined) by the kept segments of the grid's entries from
  // `first_entry` on; `looked` and `stamp`: the looking worker's marks of the kept segments
  // this look has tried.
  Covers covers_of(const Seg& g, std::vector<std::uint32_t>& looked, std::uint32_t stamp, std::size_t first_entry) const {
    const std::array<double, 4> near{std::min(g.a[0], g.b[0]) - reach_, std::min(g.a[1], g.b[1]) - reach_, std::max(g.a[0], g.b[0]) + reach_,
                                     std::max(g.a[1], g.b[1]) + reach_};
    Covers covers;
    grid_.visit(g, reach_, first_entry, [&](std::uint32_t k) {
      const Seg& e = kept_[k];
      // A cover needs a point of g within the tolerance of e: their boxes meet, padded.
      if (std::max(e.a[0], e.b[0]) < near[0] || std::min(e.a[0], e.b[0]) > near[2] || std::max(e.a[1], e.b[1]) < near[1] ||
          std::min(e.a[1], e.b[1]) > near[3] || looked[k] == stamp)
        return false;
      looked[k] = stamp;
      auto c = covered(g.a, g.b, e, tol_);
      if (!(c.second > c.first)) return false;
      if (c.first <= 0 && c.second >= 1) {  // the whole segment: its one run, whatever else covers it
        covers.assign(1, {0.0, 1.0});
        return true;
      }
      covers.push_back(c);
      return false;
    });
    return covers;
  }

  // The parts of s outside the covered runs, as strokes; parts shorter than the tolerance go.
  std::vector<Stroke> split(const Stroke& s, std::span<const Covers> covers) {
    std::vector<Stroke> out;
    Stroke cur;
    auto flush = [&] {
      // The sum only grows, so once it reaches the tolerance the part stays, its length unused.
      // (A part's points are all finite or its first is not: point(0) of a segment with an end
      // that is not finite is NaN, which no point equals, so it starts a part of its own.)
      double len = 0;
      for (std::size_t i = 1; i < cur.points.size() && !(len >= tol_); ++i) len += length(cur.points[i - 1], cur.points[i]);
      if (cur.points.size() >= 2 && len >= tol_) out.push_back(std::move(cur));
      else if (cur.points.size() >= 2) ++st_.pieces_removed, st_.length_removed += len;
      cur = Stroke{};
    };
    for (std::size_t i = 0; i < covers.size(); ++i) {
      const Seg g = segment(s, i);
      const Point2 &p = g.a, &q = g.b;
      const double len = covers[i].empty() ? 0 : length(p, q);  // (only the runs left out use it)
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
        st_.length_removed += (c1 - std::max(c0, at)) * len;
        ++st_.pieces_removed;
        at = c1;
        flush();
      }
      if (at < 1) keep_part(at, 1);
    }
    flush();
    return out;
  }

  double tol_, reach_;
  KeptGrid grid_;
  std::vector<Seg> kept_;
  PerWorker<std::vector<std::uint32_t>> looked_;  // per worker, per kept segment: the last look that tried it
  PerWorker<std::uint32_t> look_;                 // per worker: its looks so far
  CoincidentStats st_;
};

}  // namespace

CoincidentStats merge_coincident_lines(Plot& plot, double tol) {
  if (!(tol > 0) || !std::isfinite(tol)) return {};
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < plot.layers.size(); ++i)
    if (takes_part(plot.layers[i].kind)) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rank(plot.layers[a]) < rank(plot.layers[b]); });
  std::array<double, 4> box{INFINITY, INFINITY, -INFINITY, -INFINITY};
  std::size_t segments = 0;
  for (std::size_t li : order)
    for (const Stroke& s : plot.layers[li].strokes) {
      segments += segment_count(s);
      for (const Point2& p : s.points) box = {std::min(box[0], p[0]), std::min(box[1], p[1]), std::max(box[2], p[0]), std::max(box[3], p[1])};
    }
  if (!(box[0] <= box[2] && box[1] <= box[3])) box = {0, 0, 0, 0};
  // (The clean-up's freed pages are not given back first: the grid and the kept segments reuse
  // them without their zeroing again; docs/design.md, "Memory on huge pages".)
  const ParallelLoop loop;
  Merge merge(box, segments, tol, loop);
  for (std::size_t li : order) {
    std::vector<Stroke>& strokes = plot.layers[li].strokes;
    std::vector<Stroke> out;
    for (std::size_t b = 0, e = 0; b < strokes.size(); b = e) {
      for (std::size_t n = 0;
           e < strokes.size() && e - b < Merge::kBatchStrokes && (e == b || n + segment_count(strokes[e]) <= Merge::kBatchSegments);)
        n += segment_count(strokes[e++]);
      merge.batch(std::span<Stroke>(strokes.data() + b, e - b), out, loop);
    }
    strokes = std::move(out);
  }
  std::vector<PlotLayer> layers;
  for (PlotLayer& l : plot.layers)
    if (!l.strokes.empty()) layers.push_back(std::move(l));
  plot.layers = std::move(layers);
  return merge.stats();
}

}  // namespace hlr
