// The 2D stage's exact clean-up (see line_dedup.hpp; course notes section 20).
#include "algorithms/picture/line_dedup.hpp"

#include "algorithms/support/parallel.hpp"
#include "algorithms/support/parallel_scan.hpp"
#include "algorithms/picture/picture_plane.hpp"
#include "algorithms/support/uninitialised.hpp"
#include "algorithms/support/union_find.hpp"

#include <algorithm>
#include <atomic>
#include <execution>
#include <functional>
#include <map>
#include <stdexcept>
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
    const ParallelLoop loop(opt.threads);
    const std::size_t nl = d_.lines.size(), ne = points_.parent.size();
    out.pieces_in = nl;
    tolerance(loop);
    join_same_keys(opt.threads);
    join_close_points(loop);
    // Pieces seen end-on (both ends one point), read on all cores.
    std::vector<char> degenerate(nl, 0);
    loop.for_each(nl, 8192, [&](std::size_t k) {
      degenerate[k] = !d_.lines[k].pulled && root_of(points_.parent, 2 * k) == root_of(points_.parent, 2 * k + 1);
    });
    out.zero_length = static_cast<std::size_t>(std::count(degenerate.begin(), degenerate.end(), 1));
    UnionFind groups(nl);
    if (opt.overlaps) find_overlaps(degenerate, groups, opt.threads);
    // Every end's point: its set's smallest end (after the overlap search, whose arrays are
    // gone), the forest flattened in place so that each end's parent is its root (no array
    // beside: the stage's peak). A parent read mid-way is an ancestor still, so the walks agree.
    std::vector<std::uint32_t>& root = points_.parent;
    loop.for_each(ne, 8192, [&](std::size_t e) {
      auto r = static_cast<std::uint32_t>(e);
      for (std::uint32_t up; (up = std::atomic_ref<std::uint32_t>(root[r]).load(std::memory_order_relaxed)) != r;) r = up;
      std::atomic_ref<std::uint32_t>(root[e]).store(r, std::memory_order_relaxed);
    });
    // Groups of two or more pieces (few): resolved in the order of their roots (the smallest
    // piece), one at a time (they share the cache of exact points).
    std::vector<std::uint32_t> group(nl);
    loop.for_each(nl, 8192, [&](std::size_t k) { group[k] = root_of(groups.parent, k); });
    groups = UnionFind(0);
    std::map<std::uint32_t, std::vector<std::uint32_t>> members;
    for (std::uint32_t k : parallel_select(nl, [&](std::size_t k) { return !degenerate[k] && group[k] != k; }, loop))
      members[group[k]].push_back(k);
    std::vector<std::uint32_t> group_roots;
    std::vector<std::vector<Part>> group_parts;
    for (auto& [r, m] : members) {
      m.insert(m.begin(), r);
      ++out.overlap_groups;
      out.overlapped_pieces += m.size();
      group_roots.push_back(r);
      group_parts.push_back(resolve(m, root, out.duplicate_length));
    }
    auto group_of = [&](std::size_t k) -> std::ptrdiff_t {
      auto it = std::lower_bound(group_roots.begin(), group_roots.end(), k);
      return it != group_roots.end() && *it == k ? it - group_roots.begin() : -1;
    };
    // Each piece's edges, in piece order: none (seen end-on, or in another piece's group), its
    // own, or its group's parts; their ends first as points' root ends.
    std::vector<std::size_t> at = parallel_offsets(
        nl,
        [&](std::size_t k) -> std::size_t {
          if (degenerate[k] || group[k] != k) return 0;
          const std::ptrdiff_t g = group_roots.empty() ? -1 : group_of(k);
          return g < 0 ? 1 : group_parts[static_cast<std::size_t>(g)].size();
        },
        loop);
    const std::size_t n_edges = at[nl];
    if (n_edges >= (std::size_t{1} << 31)) throw std::length_error("2D stage: more than 2^31 edges");
    out.edges.resize(n_edges);
    loop.for_each(nl, 4096, [&](std::size_t k) {
      std::size_t w = at[k];
      if (at[k + 1] == w) return;
      const std::ptrdiff_t g = group_roots.empty() ? -1 : group_of(k);
      if (g < 0) {
        out.edges[w] = edge(static_cast<std::uint32_t>(k), root[2 * k], root[2 * k + 1]);
        return;
      }
      for (const Part& part : group_parts[static_cast<std::size_t>(g)]) out.edges[w++] = edge(part.piece, part.p, part.q);
    });
    // (the per-piece arrays are freed before the points are numbered: the stage's peak)
    std::vector<std::size_t>().swap(at);
    std::vector<std::uint32_t>().swap(group);
    std::vector<char>().swap(degenerate);
    number_points(out, loop);
    out.exact_point_tests = point_tests_;
    out.exact_line_tests = line_tests_;
    return out;
  }

 private:
  // A drawn part of an overlap group: the piece that wins it, and its ends' root ends.
  struct Part {
    std::uint32_t piece, p, q;
  };

  static std::uint32_t root_of(const std::vector<std::uint32_t>& parent, std::size_t a) {  // no path changes: any thread
    while (parent[a] != a) a = parent[a];
    return static_cast<std::uint32_t>(a);
  }

  // The edges' ends, given as root ends, become point numbers: points numbered in the order of
  // their first use (edge by edge, start before end), on all cores: each root's first position
  // by an atomic minimum, the first positions listed in order, then every end renumbered.
  void number_points(CleanDrawing& out, const ParallelLoop& loop) {
    const std::size_t uses = 2 * out.edges.size();
    auto root_at = [&](std::size_t u) { const CleanEdge& c = out.edges[u / 2]; return u & 1 ? c.q : c.p; };
    RawVector<std::uint32_t> first(points_.parent.size());
    loop.for_each(first.size(), 1 << 16, [&](std::size_t r) { first[r] = UINT32_MAX; });
    loop.for_each(uses, 8192, [&](std::size_t u) {
      std::atomic_ref<std::uint32_t> f(first[root_at(u)]);
      std::uint32_t cur = f.load(std::memory_order_relaxed);
      while (u < cur && !f.compare_exchange_weak(cur, static_cast<std::uint32_t>(u), std::memory_order_relaxed)) {
      }
    });
    const std::vector<std::uint32_t> firsts = parallel_select(uses, [&](std::size_t u) { return first[root_at(u)] == u; }, loop);
    out.points.resize(firsts.size());
    out.point_ends.resize(firsts.size());
    RawVector<std::uint32_t>& number = first;  // each root's entry read above, now its number
    loop.for_each(firsts.size(), 8192, [&](std::size_t i) {
      const std::uint32_t r = root_at(firsts[i]);
      out.points[i] = xy(r);
      out.point_ends[i] = r;
      number[r] = static_cast<std::uint32_t>(i);
    });
    loop.for_each(out.edges.size(), 8192, [&](std::size_t i) {
      out.edges[i].p = number[out.edges[i].p];
      out.edges[i].q = number[out.edges[i].q];
    });
  }

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
  // A drawing whose doubles are not all finite (a view whose frame the doubles cannot hold,
  // such as a point light far from a scene of 2^-1100) has no filter: every pair is compared
  // exactly (blind_).
  void tolerance(const ParallelLoop& loop) {
    std::vector<double> most(loop.workers(), 0.0);
    std::vector<char> finite(loop.workers(), 1);
    loop.run(points_.parent.size(), 16384, [&](unsigned w, std::size_t begin, std::size_t end) {
      double m = most[w];
      bool ok = true;
      for (std::size_t e = begin; e < end; ++e) {
        auto p = xy(static_cast<std::uint32_t>(e));
        ok = ok && std::isfinite(p[0]) && std::isfinite(p[1]);
        m = std::max({m, std::fabs(p[0]), std::fabs(p[1])});
      }
      most[w] = m;
      finite[w] = finite[w] && ok;
    });
    blind_ = std::find(finite.begin(), finite.end(), 0) != finite.end();
    const double m = *std::max_element(most.begin(), most.end());
    delta_ = blind_ ? 0 : box_pad({m});
  }

  // Ends that are the same mesh vertex, or the same boundary between two pieces of a segment
  // (one's end at the other's start: pieces need not meet), are the same point without
  // arithmetic.
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
      // A boundary between pieces: piece k starts at boundary 2k, and ends at boundary 2k + 2
      // where piece k + 1 starts at the same parameter, else at its own 2k + 3 (a gap follows).
      std::uint32_t boundary = 2 * static_cast<std::uint32_t>(ref.piece);
      const auto next = static_cast<std::size_t>(ref.piece) + 1;
      if (e & 1) boundary += next < s.pieces.size() && s.pieces[next].t0 == p.t1 ? 2 : 3;
      key[e] = v >= 0 ? (std::uint64_t{1} << 63) | (static_cast<std::uint64_t>(s.body) << 32) | static_cast<std::uint32_t>(v)
                      : (static_cast<std::uint64_t>(ref.segment) << 32) | boundary;
    });
    // The vertices of the first body by a table: each end's parent is the smallest end of its
    // vertex (the sets are fresh here, so that is their union-find forest, the root being the
    // smallest end as any order of unions gives); the rest sorted and united.
    constexpr std::uint64_t kBody0 = std::uint64_t{1} << 63;
    auto body0 = [&](std::uint64_t k) { return k != kNone && (k >> 32) == (kBody0 >> 32); };
    PerWorker<std::uint64_t> tops(loop, 0);
    PerWorker<std::size_t> counts(loop, 0);
    loop.run(n, 65536, [&](unsigned w, std::size_t b, std::size_t e) {
      std::uint64_t t = tops[w];
      std::size_t c = counts[w];
      for (std::size_t i = b; i < e; ++i) {
        if (body0(key[i])) t = std::max(t, key[i] & 0xffffffffu);
        c += key[i] != kNone;
      }
      tops[w] = t, counts[w] = c;
    });
    std::uint64_t top = 0;
    std::size_t with_key = 0;
    for (unsigned w = 0; w < tops.size(); ++w) top = std::max(top, tops[w]), with_key += counts[w];
    const bool table = top < 8 * static_cast<std::uint64_t>(with_key) + 1024;
    if (table) {
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
    }
    std::vector<std::pair<std::uint64_t, std::uint32_t>> rest;
    {
      const std::vector<std::uint32_t> ends =
          parallel_select(n, [&](std::size_t e) { return key[e] != kNone && !(table && body0(key[e])); }, loop);
      reserve_touched(rest, ends.size(), loop);
      rest.resize(ends.size());
      loop.for_each(ends.size(), 8192, [&](std::size_t i) { rest[i] = {key[ends[i]], ends[i]}; });
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
  void join_close_points(const ParallelLoop& loop) {
    struct End {
      double x, y;
      std::uint32_t e;
    };
    std::vector<End> order;
    {  // (the list of taken ends is freed before the sort)
      const std::vector<std::uint32_t> taking = parallel_select(points_.parent.size(), [&](std::size_t i) {
        const auto e = static_cast<std::uint32_t>(i);
        if (pulled(e)) return false;
        const std::uint32_t root = root_of(points_.parent, e);
        return root == e || xy(root) != xy(e);
      }, loop);
      order.resize(taking.size());
      loop.for_each(taking.size(), 8192, [&](std::size_t i) {
        auto p = xy(taking[i]);
        order[i] = {p[0], p[1], taking[i]};
      });
    }
    if (blind_) {  // no filter: every pair of ends, exactly
      for (std::size_t i = 0; i < order.size(); ++i)
        for (std::size_t j = i + 1; j < order.size(); ++j) {
          const std::uint32_t a = order[i].e, b = order[j].e;
          if (points_.find(a) == points_.find(b)) continue;
          ++point_tests_;
          if (exact(a) == exact(b)) points_.unite(a, b);
        }
      return;
    }
    sort_ends(order, loop);
    // The pairs within delta on all cores, listed per fixed chunk of i (so in the order of
    // (i, j) whatever the thread count); then compared exactly in that order.
    constexpr std::size_t kChunk = 16384;
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> close((order.size() + kChunk - 1) / kChunk);
    loop.for_each(close.size(), 1, [&](std::size_t c) {
      std::vector<std::pair<std::uint32_t, std::uint32_t>> list;  // (a local: neighbouring chunks' lists share a cache line)
      for (std::size_t i = c * kChunk, end = std::min(order.size(), i + kChunk); i < end; ++i)
        for (std::size_t j = i + 1; j < order.size(); ++j) {
          if (order[j].x - order[i].x > delta_) break;
          if (std::fabs(order[j].y - order[i].y) <= delta_) list.emplace_back(order[i].e, order[j].e);  // a filter: exact test below
        }
      close[c] = std::move(list);
    });
    for (const auto& list : close)
      for (auto [a, b] : list) {
        if (points_.find(a) == points_.find(b)) continue;
        ++point_tests_;
        if (exact(a) == exact(b)) points_.unite(a, b);
      }
  }

  // Ends in the order of (x, y, end): a radix sort by x scaled to 32 bits (which never
  // decreases with x), then each run of one scaled key by the whole order; the same order as
  // a sort by (x, y, end), in a tenth of its time on millions of ends.
  template <class End>
  static void sort_ends(std::vector<End>& order, const ParallelLoop& loop) {
    auto before = [](const End& a, const End& b) { return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.e < b.e))); };
    double lo = INFINITY, hi = -INFINITY;
    for (const End& p : order) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
    const double scale = hi > lo ? 4294967295.0 / (hi - lo) : 0;
    if (!std::isfinite(scale)) {  // (x all alike, or a range beyond the doubles)
      std::sort(order.begin(), order.end(), before);
      return;
    }
    auto key = [&](const End& p) { return static_cast<std::uint32_t>(std::min((p.x - lo) * scale, 4294967295.0)); };
    radix_sort(order, key, loop);
    for (std::size_t i = 0, j; i < order.size(); i = j) {
      const std::uint32_t k = key(order[i]);
      for (j = i + 1; j < order.size() && key(order[j]) == k;) ++j;
      if (j - i > 1) std::sort(order.begin() + static_cast<std::ptrdiff_t>(i), order.begin() + static_cast<std::ptrdiff_t>(j), before);
    }
  }

  // A piece in the overlap search: its picture ends, length and unit direction (worked out
  // once per piece and cell, not once per pair), and the piece it is.
  struct Near {
    std::array<double, 2> a, b;
    double len, nx, ny;
    std::uint32_t piece, ra, rb;  // ra, rb: the root ends of its start and end (its exact points)
  };

  static Near near_piece(const std::array<double, 2>& a, const std::array<double, 2>& b, std::uint32_t piece, std::uint32_t ra,
                         std::uint32_t rb) {
    // Plain square roots (within 2 ulp; drawing coordinates are below 2^100): far inside the
    // margin of 8·delta = 8e-9 of the drawing, and faster than hypot.
    const double dx = b[0] - a[0], dy = b[1] - a[1], len = std::sqrt(dx * dx + dy * dy);
    return {a, b, len, len > 0 ? dx / len : 0.0, len > 0 ? dy / len : 0.0, piece, ra, rb};
  }

  // Can two pieces lie on one line of the picture and overlap in more than a point? A double
  // filter with margin 8 delta measured from the longer one (exact overlap passes it); the
  // exact test follows.
  bool maybe_overlap(const Near& first, const Near& second) const {
    if (blind_) return true;
    const bool swap = second.len > first.len;
    const Near& A = swap ? second : first;
    const Near& B = swap ? first : second;
    const double m = 8 * delta_;
    if (A.len > 4 * delta_) {
      auto off = [&](const std::array<double, 2>& p) { return std::fabs(A.nx * (p[1] - A.a[1]) - A.ny * (p[0] - A.a[0])); };
      if (off(B.a) > m || off(B.b) > m) return false;
      double s0 = A.nx * (B.a[0] - A.a[0]) + A.ny * (B.a[1] - A.a[1]), s1 = A.nx * (B.b[0] - A.a[0]) + A.ny * (B.b[1] - A.a[1]);
      if (std::max(s0, s1) <= -m || std::min(s0, s1) >= A.len + m) return false;
      // An end of B that is exactly an end of A (the same root): B overlaps A in more than a
      // point only if its other end lies on A's side of that point (pieces meeting end to end
      // on one line, as the edges of boxes in a row seen along an axis, need no exact test).
      if ((B.ra == A.ra && s1 <= -m) || (B.rb == A.ra && s0 <= -m)) return false;
      if ((B.ra == A.rb && s1 >= A.len + m) || (B.rb == A.rb && s0 >= A.len + m)) return false;
    }
    return true;
  }

  // A piece of a cell in cell_pairs' sweep: its line's distance from the cell's centre, and
  // how far from that another piece's line can lie when the two pass maybe_overlap with this
  // one as the shorter piece B.
  struct LineKey {
    double at, reach;
    std::uint32_t i;  // in the cell
  };

  // Calls visit(i, j), i < j, for every pair of the cell's pieces that can pass maybe_overlap
  // (and some more): all pairs of a small cell; else, with the pieces sorted by their lines'
  // distances from the cell's centre o, each piece with those within its reach when it is B.
  // None that passes is left out: maybe_overlap finds B's ends within m = 8 delta of A's line
  // (computed; within 9 delta exactly), so the lines' angle has sin <= 2 m / |B|, and their
  // distances from o differ by at most m + pi m |o - B.a| / |B| (the lines undirected, the
  // angle at most pi / 2). The reach, 12 delta + 46 delta D / |B| with D the largest
  // coordinate difference between o and B's ends (within sqrt 2 of the distance), is above it.
  // A B of at most 4 delta (both pieces short: maybe_overlap passes them all) reaches all. A
  // length or distance that is not finite (an overflow) makes the cell's pairs all pairs.
  template <class Visit>
  void cell_pairs(const std::vector<Near>& cell, const std::array<double, 2>& o, std::vector<LineKey>& keys, Visit&& visit) const {
    const std::size_t k = cell.size();
    auto all_pairs = [&] {
      for (std::size_t i = 0; i < k; ++i)
        for (std::size_t j = i + 1; j < k; ++j) visit(i, j);
    };
    if (blind_ || k < 8) return all_pairs();
    keys.clear();
    for (std::size_t i = 0; i < k; ++i) {
      const Near& p = cell[i];
      const double at = std::fabs(p.nx * (o[1] - p.a[1]) - p.ny * (o[0] - p.a[0]));
      const double d = std::max({std::fabs(o[0] - p.a[0]), std::fabs(o[1] - p.a[1]), std::fabs(o[0] - p.b[0]), std::fabs(o[1] - p.b[1])});
      if (!std::isfinite(at) || !std::isfinite(d) || !std::isfinite(p.len)) return all_pairs();
      keys.push_back({at, p.len > 4 * delta_ ? 12 * delta_ + 46 * delta_ * (d / p.len) : INFINITY, static_cast<std::uint32_t>(i)});
    }
    std::sort(keys.begin(), keys.end(), [](const LineKey& x, const LineKey& y) { return x.at < y.at; });
    // Each pair from the sweep of its B: maybe_overlap's second piece, unless the first is shorter.
    auto is_b = [&](std::uint32_t x, std::uint32_t y) { return x < y ? cell[x].len < cell[y].len : cell[x].len <= cell[y].len; };
    for (std::size_t a = 0; a < k; ++a) {
      const LineKey& s = keys[a];
      auto take = [&](const LineKey& t) {
        if (is_b(s.i, t.i)) visit(std::min(s.i, t.i), std::max(s.i, t.i));
      };
      for (std::size_t b = a + 1; b < k && keys[b].at - s.at <= s.reach; ++b) take(keys[b]);
      for (std::size_t b = a; b-- > 0 && s.at - keys[b].at <= s.reach;) take(keys[b]);
    }
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

  // A grid over the picture; each piece goes into every cell within 8 delta of it (walking the
  // columns of its major axis), and pieces sharing a cell are tested.
  void find_overlaps(const std::vector<char>& degenerate, UnionFind& groups, unsigned threads) {
    const ParallelLoop loop(threads);
    const std::vector<std::uint32_t> live =
        parallel_select(d_.lines.size(), [&](std::size_t k) { return !degenerate[k] && !d_.lines[k].pulled; }, loop);
    if (live.size() < 2) return;
    // Each live piece's ends' roots, in the order of `live`; its ends are read from the
    // drawing (a record of ends and roots, 40 bytes a piece, was the largest array of a
    // large drawing's output stage).
    struct Rec {
      std::array<double, 2> a, b;  // the piece is live[i], its segment read only for a pair the filter passes
      std::uint32_t ra, rb;        // its ends' roots
    };
    RawVector<std::array<std::uint32_t, 2>> roots(live.size());  // (each written below, on all cores)
    auto rec = [&](std::size_t i) {
      const Polyline2D& l = d_.lines[live[i]];
      return Rec{d_.points[l.first], d_.points[l.first + 1], roots[i][0], roots[i][1]};
    };
    PerWorker<std::array<double, 4>> boxes(loop, {INFINITY, INFINITY, -INFINITY, -INFINITY});
    loop.run(live.size(), 8192, [&](unsigned w, std::size_t begin, std::size_t end) {
      std::array<double, 4>& bx = boxes[w];
      for (std::size_t i = begin; i < end; ++i) {
        roots[i] = {root_of(points_.parent, 2 * std::size_t{live[i]}), root_of(points_.parent, 2 * std::size_t{live[i]} + 1)};
        const Polyline2D& l = d_.lines[live[i]];
        for (const auto& p : {d_.points[l.first], d_.points[l.first + 1]})
          bx = {std::min(bx[0], p[0]), std::min(bx[1], p[1]), std::max(bx[2], p[0]), std::max(bx[3], p[1])};
      }
    });
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (unsigned w = 0; w < boxes.size(); ++w) {
      const auto& bx = boxes[w];
      x0 = std::min(x0, bx[0]), y0 = std::min(y0, bx[1]), x1 = std::max(x1, bx[2]), y1 = std::max(y1, bx[3]);
    }
    const double pad = 16 * delta_;
    x0 -= pad, y0 -= pad, x1 += pad, y1 += pad;
    // (cells of about 16 pieces: a cell's pairs come from a sweep, not all k^2 / 2 of them)
    const int g = blind_ ? 1 : std::clamp(static_cast<int>(std::sqrt(static_cast<double>(live.size())) / 4), 1, 2048);
    const double cw = (x1 - x0) / g, ch = (y1 - y0) / g;
    auto cell = [g](double c) { return c >= 1 ? static_cast<int>(std::min(c, static_cast<double>(g - 1))) : 0; };  // (NaN: 0)
    auto cx = [&](double x) { return g == 1 ? 0 : cell((x - x0) / cw); };
    auto cy = [&](double y) { return g == 1 ? 0 : cell((y - y0) / ch); };
    const double m = 8 * delta_;
    // The cells of each piece (conservative: every cell within 8 delta of it).
    auto for_cells = [&](const Rec& r, auto&& visit) {
      auto a = r.a, b = r.b;
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
    // Each piece's cells counted per cell on all cores, then each piece entered in its cells
    // (its cells worked out again: no list of them, the stage's largest array), grouped by
    // cell: a cell's pieces come in any order (the pairs are sorted before the exact tests, so
    // nothing depends on it).
    std::vector<std::uint32_t> start;
    RawVector<std::uint32_t> items;
    {
      std::vector<std::atomic<std::uint32_t>> n(n_cells);
      loop.for_each(live.size(), 4096,
                    [&](std::size_t i) { for_cells(rec(i), [&](std::size_t cell) { n[cell].fetch_add(1, std::memory_order_relaxed); }); });
      start = parallel_offsets<std::uint32_t>(n_cells, [&](std::size_t c) { return n[c].load(std::memory_order_relaxed); }, loop);
      loop.for_each(n_cells, 1 << 16, [&](std::size_t c) { n[c].store(start[c], std::memory_order_relaxed); });
      items.resize(start[n_cells]);
      loop.for_each(live.size(), 4096, [&](std::size_t i) {
        for_cells(rec(i), [&](std::size_t cell) { items[n[cell].fetch_add(1, std::memory_order_relaxed)] = static_cast<std::uint32_t>(i); });
      });
    }
    // The cell where a pair is tested: the cell of P, the start of the shorter piece's span
    // along the longer one's line (clamped to the longer piece; its start when both are
    // shorter than 4 delta). Two pieces that overlap in more than a point both lie within
    // rounding of P (far inside the 8-delta margin of their cells), so both are entered in
    // P's cell; a pair found in other cells they share is left to it. Longer piece: by
    // length, then by index (the same choice in every cell).
    auto meet_cell = [&](const Near& first, const Near& second) -> std::size_t {
      const bool swap = second.len > first.len || (second.len == first.len && second.piece < first.piece);
      const Near& L = swap ? second : first;
      const Near& S = swap ? first : second;
      std::array<double, 2> p = L.a;
      if (L.len > 4 * delta_) {
        const double s0 = L.nx * (S.a[0] - L.a[0]) + L.ny * (S.a[1] - L.a[1]), s1 = L.nx * (S.b[0] - L.a[0]) + L.ny * (S.b[1] - L.a[1]);
        const double t = std::clamp(std::min(s0, s1), 0.0, L.len);
        p = {L.a[0] + L.nx * t, L.a[1] + L.ny * t};
      }
      return static_cast<std::size_t>(cy(p[1])) * g + static_cast<std::size_t>(cx(p[0]));
    };
    // Pairs that pass the double filter, found on all cores; the exact tests in a fixed order.
    PerWorker<std::vector<std::pair<std::uint32_t, std::uint32_t>>> found(loop);
    loop.run(n_cells, 256, [&](unsigned worker, std::size_t begin, std::size_t end) {
      std::vector<Near> cell;
      std::vector<LineKey> keys;
      for (std::size_t c = begin; c < end; ++c) {
        if (start[c + 1] - start[c] < 2) continue;
        cell.clear();
        for (std::uint32_t i = start[c]; i < start[c + 1]; ++i) {
          const Rec r = rec(items[i]);
          cell.push_back(near_piece(r.a, r.b, live[items[i]], r.ra, r.rb));
        }
        auto segment = [&](std::uint32_t k) { return d_.sources[d_.lines[k].first_edge].segment; };
        const std::array<double, 2> centre = {x0 + (static_cast<double>(c % g) + 0.5) * cw, y0 + (static_cast<double>(c / g) + 0.5) * ch};
        cell_pairs(cell, centre, keys, [&](std::size_t i, std::size_t j) {
          const Near &A = cell[i], &B = cell[j];
          if (A.piece == B.piece || !maybe_overlap(A, B) || segment(A.piece) == segment(B.piece)) return;
          if (meet_cell(A, B) != c) return;  // the pair's own cell tests it (not every cell the two share)
          found[worker].emplace_back(std::min(A.piece, B.piece), std::max(A.piece, B.piece));
        });
      }
    });
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (unsigned w = 0; w < found.size(); ++w) pairs.insert(pairs.end(), found[w].begin(), found[w].end());
    std::sort(std::execution::par, pairs.begin(), pairs.end());
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
  std::vector<Part> resolve(const std::vector<std::uint32_t>& m, const std::vector<std::uint32_t>& root, double& duplicate_length) {
    std::vector<Part> parts;
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
      parts.push_back({static_cast<std::uint32_t>(best), root[breaks[i]], root[breaks[i + 1]]});
      after += len(breaks[i], breaks[i + 1]);
    }
    duplicate_length += std::max(0.0, before - after);
    return parts;
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
  bool blind_ = false;  // the doubles are not all finite: no filter, every pair compared exactly
  std::size_t point_tests_ = 0, line_tests_ = 0;
};

}  // namespace

int kind_priority(LineKind k) {
  switch (k) {
    case LineKind::Cut:
      return 5;
    case LineKind::Polyline:
      return 0;  // a line of its own: under the bodies' edges where they coincide
    case LineKind::Hatch:
    case LineKind::Tone1:
    case LineKind::Tone2:
    case LineKind::Tone3:
    case LineKind::Tone4:
    case LineKind::Tone5:
    case LineKind::Tone6:
    case LineKind::Tone7:
    case LineKind::Tone8:
      return -1;
    case LineKind::Overhead:
      return -2;
    case LineKind::SectionLine:
    case LineKind::SectionMark:
      return -3;
    case LineKind::Silhouette: return 4;
    case LineKind::Boundary: return 3;
    case LineKind::Crease: return 2;
    case LineKind::Tangent:
      return 1;
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
