// The 2D stage's exact clean-up (see line_dedup.hpp; course notes section 20).
#include "algorithms/line_dedup.hpp"

#include "algorithms/parallel.hpp"
#include "algorithms/picture_plane.hpp"
#include "algorithms/union_find.hpp"

#include <algorithm>
#include <atomic>
#include <execution>
#include <functional>
#include <cmath>
#include <numeric>
#include <optional>
#include <unordered_map>

namespace hlr {
namespace {

// Exact picture coordinates with unnormalised rational axes: orthographic (P·r, P·u), with
// r = up × v and u = v × r; perspective ((P - E)·r / (P - E)·d, (P - E)·u / (P - E)·d) with
// d = target - E. An affine (or, in front of the eye, projective) image of the drawing's own
// coordinates: equal points, collinear points and the order along a line are the same.
// The clean-up's working state: endpoint 2k is piece k's start (t0), 2k + 1 its end (t1).
class Dedup {
 public:
  Dedup(const Drawing2D& d, const LineDrawing& r, const Camera& cam) : d_(d), r_(&r), screen_(cam), points_(2 * d.lines.size()) {}
  /// The ends' keys given, and each end's exact 3D point on demand.
  Dedup(const Drawing2D& d, const std::vector<std::uint64_t>& keys, const std::function<Point3(std::uint32_t)>& end_point,
        const Camera& cam)
      : d_(d), keys_(&keys), end_point_(&end_point), screen_(cam), points_(2 * d.lines.size()) {}

  CleanDrawing run(const DedupOptions& opt) {
    CleanDrawing out;
    out.pieces_in = d_.lines.size();
    tolerance();
    join_same_keys(opt.threads);
    join_close_points();
    std::vector<std::uint32_t> point_of(points_.parent.size(), UINT32_MAX);
    auto point = [&](std::uint32_t e) {
      std::uint32_t root = points_.find(e);
      if (point_of[root] == UINT32_MAX) {
        point_of[root] = static_cast<std::uint32_t>(out.points.size());
        out.points.push_back(xy(root));
        out.point_ends.push_back(root);
      }
      return point_of[root];
    };
    std::vector<char> degenerate(d_.lines.size(), 0);
    for (std::uint32_t k = 0; k < d_.lines.size(); ++k)
      if (!d_.lines[k].pulled && points_.find(2 * k) == points_.find(2 * k + 1)) degenerate[k] = 1, ++out.zero_length;
    UnionFind groups(d_.lines.size());
    if (opt.overlaps) find_overlaps(degenerate, groups, opt.threads);
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> members;  // groups of two or more, by root
    for (std::uint32_t k = 0; k < d_.lines.size(); ++k)
      if (!degenerate[k] && groups.find(k) != k) members[groups.find(k)].push_back(k);
    for (std::uint32_t k = 0; k < d_.lines.size(); ++k) {
      if (degenerate[k] || groups.find(k) != k) continue;
      auto it = members.find(k);
      if (it == members.end()) {
        out.edges.push_back(edge(k, point(2 * k), point(2 * k + 1)));
        continue;
      }
      std::vector<std::uint32_t>& m = it->second;
      m.insert(m.begin(), k);  // the root is the group's smallest piece
      ++out.overlap_groups;
      out.overlapped_pieces += m.size();
      resolve(m, out, point);
    }
    out.exact_point_tests = point_tests_;
    out.exact_line_tests = line_tests_;
    return out;
  }

 private:
  const Polyline2D& line(std::uint32_t e) const { return d_.lines[e / 2]; }
  std::array<double, 2> xy(std::uint32_t e) const { return d_.points[line(e).first + (e & 1)]; }
  bool pulled(std::uint32_t e) const { return line(e).pulled; }

  const Exact2& exact(std::uint32_t e) {
    auto it = exact_.find(e);
    if (it != exact_.end()) return it->second;
    if (!r_) return exact_.emplace(e, screen_.project((*end_point_)(e))).first->second;
    const Polyline2D& l = line(e);
    const PieceRef& ref = d_.sources[l.first_edge];
    const Segment& s = r_->segments[ref.segment];
    const Piece& p = s.pieces[ref.piece];
    return exact_.emplace(e, screen_.project(s.at(e & 1 ? p.t1 : p.t0))).first->second;
  }

  // Doubles of the picture carry errors near 1e-15 of its largest coordinate (a few roundings
  // from exact values in a frame of unit size or of the input's size; perspective divides by
  // depths at least 1e-4 of the largest): delta = 1e-9 of it leaves a margin above 1e3.
  void tolerance() {
    double m = 0;
    for (std::uint32_t e = 0; e < points_.parent.size(); ++e) {
      auto p = xy(e);
      m = std::max({m, std::fabs(p[0]), std::fabs(p[1])});
    }
    delta_ = 1e-9 * std::max(m, 1e-300);
  }

  // Ends that are the same mesh vertex, or the same boundary between two pieces of a segment,
  // are the same point without arithmetic.
  void join_same_keys(unsigned threads) {
    const ParallelLoop loop(threads);
    const std::size_t n = points_.parent.size();
    constexpr std::uint64_t kNone = UINT64_MAX;  // a pulled end: no key
    std::vector<std::uint64_t> key(n);
    loop.for_each(n, 8192, [&](std::size_t i) {
      const auto e = static_cast<std::uint32_t>(i);
      if (pulled(e)) {
        key[e] = kNone;
        return;
      }
      if (keys_) {
        key[e] = (*keys_)[e];
        return;
      }
      const Polyline2D& l = line(e);
      const PieceRef& ref = d_.sources[l.first_edge];
      const Segment& s = r_->segments[ref.segment];
      const Piece& p = s.pieces[ref.piece];
      const Rational& t = e & 1 ? p.t1 : p.t0;
      int v = s.kind == Segment::Kind::Edge ? (t == 0 ? s.v0 : t == 1 ? s.v1 : -1) : -1;
      key[e] = v >= 0 ? (std::uint64_t{1} << 63) | (static_cast<std::uint64_t>(s.body) << 32) | static_cast<std::uint32_t>(v)
                      : (static_cast<std::uint64_t>(ref.segment) << 32) | static_cast<std::uint32_t>(ref.piece + (e & 1));
    });
    // The vertices of the first body by a table: each end's parent is the smallest end of its
    // vertex (the sets are fresh here, so that is their union-find forest, the root being the
    // smallest end as any order of unions gives); the rest sorted and united.
    constexpr std::uint64_t kBody0 = std::uint64_t{1} << 63;
    auto body0 = [&](std::uint64_t k) { return k != kNone && (k >> 32) == (kBody0 >> 32); };
    std::uint64_t top = 0;
    std::size_t with_key = 0;
    for (std::uint64_t k : key) {
      if (body0(k)) top = std::max(top, k & 0xffffffffu);
      with_key += k != kNone;
    }
    std::vector<std::pair<std::uint64_t, std::uint32_t>> rest;
    if (top < 8 * static_cast<std::uint64_t>(with_key) + 1024) {
      std::vector<std::uint32_t> first(static_cast<std::size_t>(top) + 1, UINT32_MAX);
      loop.for_each(n, 8192, [&](std::size_t e) {
        if (!body0(key[e])) return;
        std::atomic_ref<std::uint32_t> f(first[static_cast<std::size_t>(key[e] & 0xffffffffu)]);
        std::uint32_t cur = f.load(std::memory_order_relaxed);
        while (e < cur && !f.compare_exchange_weak(cur, static_cast<std::uint32_t>(e), std::memory_order_relaxed)) {
        }
      });
      loop.for_each(n, 8192, [&](std::size_t e) {
        if (body0(key[e])) points_.parent[e] = first[static_cast<std::size_t>(key[e] & 0xffffffffu)];
      });
      for (std::uint32_t e = 0; e < n; ++e)
        if (key[e] != kNone && !body0(key[e])) rest.emplace_back(key[e], e);
    } else {
      for (std::uint32_t e = 0; e < n; ++e)
        if (key[e] != kNone) rest.emplace_back(key[e], e);
    }
    std::vector<std::uint64_t>().swap(key);
    std::sort(std::execution::par, rest.begin(), rest.end());
    for (std::size_t i = 1; i < rest.size(); ++i)
      if (rest[i].first == rest[i - 1].first) points_.unite(rest[i].second, rest[i - 1].second);
  }

  // Ends within delta in both coordinates are compared exactly; farther ones differ. Ends
  // already joined by their keys are one exact point: of each such group only the ends whose
  // doubles differ from its root's take part (the root stands for the rest), so the groups
  // found, and their roots (the smallest end), are those of comparing every end.
  void join_close_points() {
    struct End {
      double x, y;
      std::uint32_t e;
    };
    std::vector<End> order;
    order.reserve(points_.parent.size());
    for (std::uint32_t e = 0; e < points_.parent.size(); ++e)
      if (!pulled(e)) {
        auto p = xy(e);
        const std::uint32_t root = points_.find(e);
        if (root != e && xy(root) == p) continue;
        order.push_back({p[0], p[1], e});
      }
    std::sort(std::execution::par, order.begin(), order.end(), [](const End& a, const End& b) {
      return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.e < b.e)));
    });
    for (std::size_t i = 0; i < order.size(); ++i) {
      for (std::size_t j = i + 1; j < order.size(); ++j) {
        if (order[j].x - order[i].x > delta_) break;
        if (std::fabs(order[j].y - order[i].y) > delta_) continue;
        if (points_.find(order[i].e) == points_.find(order[j].e)) continue;
        ++point_tests_;
        if (exact(order[i].e) == exact(order[j].e)) points_.unite(order[i].e, order[j].e);
      }
    }
  }

  // Can pieces a and b lie on one line of the picture and overlap in more than a point? A
  // double filter with margin 8 delta (exact overlap passes it), then the exact test.
  bool overlap(std::uint32_t a, std::uint32_t b) {
    if (!maybe_overlap(a, b)) return false;
    return exact_overlap(a, b);
  }

  bool maybe_overlap(std::uint32_t a, std::uint32_t b) const {
    auto A0 = xy(2 * a), A1 = xy(2 * a + 1), B0 = xy(2 * b), B1 = xy(2 * b + 1);
    // Plain square roots (within 2 ulp; drawing coordinates are below 2^100): far inside the
    // margin of 8·delta = 8e-9 of the drawing, and faster than hypot.
    auto length = [](double dx, double dy) { return std::sqrt(dx * dx + dy * dy); };
    double la = length(A1[0] - A0[0], A1[1] - A0[1]), lb = length(B1[0] - B0[0], B1[1] - B0[1]);
    if (lb > la) std::swap(A0, B0), std::swap(A1, B1), std::swap(la, lb);
    const double m = 8 * delta_;
    if (la > 4 * delta_) {
      double nx = (A1[0] - A0[0]) / la, ny = (A1[1] - A0[1]) / la;
      auto off = [&](const std::array<double, 2>& p) { return std::fabs(nx * (p[1] - A0[1]) - ny * (p[0] - A0[0])); };
      if (off(B0) > m || off(B1) > m) return false;
      double s0 = nx * (B0[0] - A0[0]) + ny * (B0[1] - A0[1]), s1 = nx * (B1[0] - A0[0]) + ny * (B1[1] - A0[1]);
      if (std::max(s0, s1) <= -m || std::min(s0, s1) >= la + m) return false;
    }
    return true;
  }

  bool exact_overlap(std::uint32_t a, std::uint32_t b) {
    ++line_tests_;
    const Exact2 &p0 = exact(2 * a), &p1 = exact(2 * a + 1), &q0 = exact(2 * b), &q1 = exact(2 * b + 1);
    if (orient2d(p0, p1, q0) != 0 || orient2d(p0, p1, q1) != 0) return false;
    int ax = p0[0] != p1[0] ? 0 : 1;
    const Rational &alo = std::min(p0[ax], p1[ax]), &ahi = std::max(p0[ax], p1[ax]);
    const Rational &blo = std::min(q0[ax], q1[ax]), &bhi = std::max(q0[ax], q1[ax]);
    return std::max(alo, blo) < std::min(ahi, bhi);
  }

  // A grid over the picture; each piece goes into every cell within delta of it (walking the
  // columns of its major axis), and pieces sharing a cell are tested.
  void find_overlaps(const std::vector<char>& degenerate, UnionFind& groups, unsigned threads) {
    std::vector<std::uint32_t> live;
    for (std::uint32_t k = 0; k < d_.lines.size(); ++k)
      if (!degenerate[k] && !d_.lines[k].pulled) live.push_back(k);
    if (live.size() < 2) return;
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (std::uint32_t k : live)
      for (std::uint32_t e : {2 * k, 2 * k + 1}) {
        auto p = xy(e);
        x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
      }
    const double pad = 16 * delta_;
    x0 -= pad, y0 -= pad, x1 += pad, y1 += pad;
    const int g = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(live.size()))), 1, 2048);
    const double cw = (x1 - x0) / g, ch = (y1 - y0) / g;
    auto cx = [&](double x) { return std::clamp(static_cast<int>((x - x0) / cw), 0, g - 1); };
    auto cy = [&](double y) { return std::clamp(static_cast<int>((y - y0) / ch), 0, g - 1); };
    const double m = 8 * delta_;
    // The cells of each piece (conservative: every cell within 8 delta of it).
    auto for_cells = [&](std::uint32_t k, auto&& visit) {
      auto a = xy(2 * k), b = xy(2 * k + 1);
      bool by_x = std::fabs(b[0] - a[0]) >= std::fabs(b[1] - a[1]);
      int u = by_x ? 0 : 1, v = 1 - u;
      if (a[u] > b[u]) std::swap(a, b);
      const double w = by_x ? cw : ch, o = by_x ? x0 : y0;
      int c0 = by_x ? cx(a[0] - m) : cy(a[1] - m), c1 = by_x ? cx(b[0] + m) : cy(b[1] + m);
      for (int c = c0; c <= c1; ++c) {
        double lo = std::max(a[u], o + c * w - m), hi = std::min(b[u], o + (c + 1) * w + m);
        if (lo > hi) lo = hi = std::clamp(lo, a[u], b[u]);
        auto at = [&](double t) { return b[u] == a[u] ? a[v] : a[v] + (b[v] - a[v]) * ((t - a[u]) / (b[u] - a[u])); };
        double v0 = std::min(at(lo), at(hi)) - m, v1 = std::max(at(lo), at(hi)) + m;
        int r0 = by_x ? cy(v0) : cx(v0), r1 = by_x ? cy(v1) : cx(v1);
        for (int r = r0; r <= r1; ++r) visit(by_x ? static_cast<std::size_t>(r) * g + c : static_cast<std::size_t>(c) * g + r);
      }
    };
    const std::size_t n_cells = static_cast<std::size_t>(g) * g;
    ParallelLoop loop(threads);
    // Each piece's cells on all cores (counted, then written at the piece's offset), then
    // grouped by cell in piece order: each cell lists its pieces in the order of `live`.
    std::vector<std::uint32_t> count(live.size() + 1, 0);
    loop.for_each(live.size(), 4096, [&](std::size_t i) {
      std::uint32_t n = 0;
      for_cells(live[i], [&](std::size_t) { ++n; });
      count[i + 1] = n;
    });
    for (std::size_t i = 0; i < live.size(); ++i) count[i + 1] += count[i];
    std::vector<std::uint32_t> cell_of(count.back());
    loop.for_each(live.size(), 4096, [&](std::size_t i) {
      std::uint32_t at = count[i];
      for_cells(live[i], [&](std::size_t cell) { cell_of[at++] = static_cast<std::uint32_t>(cell); });
    });
    // Grouped by cell on all cores: a cell's pieces come in any order (the pairs are sorted
    // before the exact tests, so nothing depends on it).
    std::vector<std::uint32_t> start(n_cells + 1, 0), items;
    {
      std::vector<std::atomic<std::uint32_t>> n(n_cells);
      loop.run(cell_of.size(), 1 << 16, [&](unsigned, std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) n[cell_of[i]].fetch_add(1, std::memory_order_relaxed);
      });
      for (std::size_t c = 0; c < n_cells; ++c) start[c + 1] = start[c] + n[c].load(std::memory_order_relaxed);
      for (std::size_t c = 0; c < n_cells; ++c) n[c].store(start[c], std::memory_order_relaxed);
      items.resize(start[n_cells]);
      loop.run(live.size(), 4096, [&](unsigned, std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i)
          for (std::uint32_t at = count[i]; at < count[i + 1]; ++at)
            items[n[cell_of[at]].fetch_add(1, std::memory_order_relaxed)] = live[i];
      });
    }
    // Pairs that pass the double filter, found on all cores; the exact tests in a fixed order.
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> found(loop.workers());
    loop.run(n_cells, 256, [&](unsigned worker, std::size_t begin, std::size_t end) {
      for (std::size_t c = begin; c < end; ++c)
        for (std::uint32_t i = start[c]; i < start[c + 1]; ++i)
          for (std::uint32_t j = i + 1; j < start[c + 1]; ++j) {
            std::uint32_t a = items[i], b = items[j];
            if (a == b) continue;
            if (d_.sources[d_.lines[a].first_edge].segment == d_.sources[d_.lines[b].first_edge].segment) continue;
            if (maybe_overlap(a, b)) found[worker].emplace_back(std::min(a, b), std::max(a, b));
          }
    });
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (auto& f : found) pairs.insert(pairs.end(), f.begin(), f.end());
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    for (auto [a, b] : pairs)
      if (groups.find(a) != groups.find(b) && exact_overlap(a, b)) groups.unite(a, b);
  }

  CleanEdge edge(std::uint32_t k, std::uint32_t p, std::uint32_t q) const {
    const Polyline2D& l = d_.lines[k];
    return CleanEdge{p, q, d_.sources[l.first_edge], l.kind, l.visible, l.through, l.body};
  }

  // Pieces on one line of the picture: cut at every end (exact order along the line), draw
  // each part once with the piece that wins it (visible first, then the stronger kind, then
  // the first piece).
  template <class PointOf>
  void resolve(const std::vector<std::uint32_t>& m, CleanDrawing& out, PointOf& point) {
    const Exact2 &f0 = exact(2 * m[0]), &f1 = exact(2 * m[0] + 1);
    const int ax = f0[0] != f1[0] ? 0 : 1;
    std::vector<std::uint32_t> ends;
    for (std::uint32_t k : m) ends.push_back(2 * k), ends.push_back(2 * k + 1);
    std::sort(ends.begin(), ends.end(), [&](std::uint32_t a, std::uint32_t b) {
      int c = cmp(exact(a)[ax], exact(b)[ax]);
      return c < 0 || (c == 0 && a < b);
    });
    std::vector<std::uint32_t> breaks;  // one end per distinct position
    std::unordered_map<std::uint32_t, std::size_t> index;
    for (std::uint32_t e : ends) {
      if (breaks.empty() || exact(breaks.back())[ax] != exact(e)[ax]) breaks.push_back(e);
      index[e] = breaks.size() - 1;
    }
    double before = 0, after = 0;
    auto len = [&](std::uint32_t a, std::uint32_t b) {
      auto p = xy(a), q = xy(b);
      return std::hypot(q[0] - p[0], q[1] - p[1]);
    };
    for (std::uint32_t k : m) before += len(2 * k, 2 * k + 1);
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
      int best = -1;
      for (std::uint32_t k : m) {
        std::size_t lo = std::min(index[2 * k], index[2 * k + 1]), hi = std::max(index[2 * k], index[2 * k + 1]);
        if (lo > i || hi < i + 1) continue;
        if (best < 0 || wins(d_.lines[k], d_.lines[best])) best = static_cast<int>(k);
      }
      if (best < 0) continue;
      out.edges.push_back(edge(static_cast<std::uint32_t>(best), point(breaks[i]), point(breaks[i + 1])));
      after += len(breaks[i], breaks[i + 1]);
    }
    out.duplicate_length += std::max(0.0, before - after);
  }

  static bool wins(const Polyline2D& a, const Polyline2D& b) {
    if (a.visible != b.visible) return a.visible;
    if (a.through != b.through) return a.through;
    return kind_priority(a.kind) > kind_priority(b.kind);
  }

  const Drawing2D& d_;
  const LineDrawing* r_ = nullptr;
  const std::vector<std::uint64_t>* keys_ = nullptr;
  const std::function<Point3(std::uint32_t)>* end_point_ = nullptr;
  PicturePlane screen_;
  UnionFind points_;
  std::unordered_map<std::uint32_t, Exact2> exact_;
  double delta_ = 0;
  std::size_t point_tests_ = 0, line_tests_ = 0;
};

}  // namespace

int kind_priority(LineKind k) {
  switch (k) {
    case LineKind::Silhouette: return 4;
    case LineKind::Boundary: return 3;
    case LineKind::Crease: return 2;
    case LineKind::Intersection: return 1;
    case LineKind::Edge: return 0;
  }
  return 0;
}

CleanDrawing dedup_drawing(const Drawing2D& drawing, const LineDrawing& lines, const Camera& camera, const DedupOptions& options) {
  Dedup d(drawing, lines, camera);
  return d.run(options);
}

CleanDrawing dedup_by_keys(const Drawing2D& drawing, const std::vector<std::uint64_t>& end_keys,
                           const std::function<Point3(std::uint32_t)>& end_point, const Camera& camera, const DedupOptions& options) {
  Dedup d(drawing, end_keys, end_point, camera);
  return d.run(options);
}

}  // namespace hlr
