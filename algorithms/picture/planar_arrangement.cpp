// The exact arrangement of picture segments (course notes sections 25 and 31). See
// planar_arrangement.hpp; the filters' error bounds are proven in docs/design.md ("Visible
// surfaces as exact polygons").
#include "algorithms/picture/planar_arrangement.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

#include "algorithms/support/parallel.hpp"

namespace hlr {
namespace {

// Exact signs over points with doubles beside them. The doubles are trusted only when every
// non-zero one lies in [2^-400, 2^400] (then products of two do not underflow or overflow).
class Signs {
 public:
  Signs(const std::vector<Exact2>& p, const std::vector<std::array<double, 2>>& a, bool filter)
      : p_(p), a_(a), filter_(filter) {}

  // Orientation of k against i -> j: the one filter of kernel/predicates_2d.hpp, then exact.
  int orient(std::uint32_t i, std::uint32_t j, std::uint32_t k, std::size_t* exact = nullptr) const {
    if (filter_)
      if (const int s = orient2d_filter(a_[i], a_[j], a_[k])) return s;
    if (exact) ++*exact;
    return orient2d(p_[i], p_[j], p_[k]);
  }

  // Sign of coordinate `ax` of j minus that of i (the comparison filter, then exact).
  int cmp(std::uint32_t i, std::uint32_t j, int ax) const {
    if (filter_)
      if (const int s = compare_filter(a_[i][ax], a_[j][ax])) return s;
    return sgn(p_[j][ax] - p_[i][ax]);
  }

 private:
  const std::vector<Exact2>& p_;
  const std::vector<std::array<double, 2>>& a_;
  bool filter_;
};

// The doubles may decide only if each is zero exactly when its value is, and the others lie in
// [2^-400, 2^400] (an underflowed 0 or an overflowed infinity turns every filter off).
bool filter_usable(const std::vector<Exact2>& pts, const std::vector<std::array<double, 2>>& a) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!hlr::filter_usable(pts[i], a[i])) return false;
  return true;
}

std::array<double, 2> approx_of(const Exact2& p) { return {p[0].get_d(), p[1].get_d()}; }

// Equal points joined: sort by doubles (equal points have equal doubles), compare exactly
// inside runs of equal doubles.
std::vector<std::uint32_t> join_equal_points(const std::vector<Exact2>& pts, const std::vector<std::array<double, 2>>& ap) {
  std::vector<std::uint32_t> order(pts.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return ap[a] < ap[b] || (ap[a] == ap[b] && a < b); });
  std::vector<std::uint32_t> rep(pts.size());
  std::iota(rep.begin(), rep.end(), 0u);
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j < order.size() && ap[order[j]] == ap[order[i]]) ++j;
    for (std::size_t a = i; a < j; ++a) {
      if (rep[order[a]] != order[a]) continue;
      for (std::size_t b = a + 1; b < j; ++b)
        if (rep[order[b]] == order[b] && pts[order[a]] == pts[order[b]]) rep[order[b]] = order[a];
    }
    i = j;
  }
  return rep;
}

// Candidate pairs of segments: a grid over the picture, each segment in every cell its box
// (widened far beyond the doubles' error) overlaps; visit(worker, a, b) for each pair whose
// widened boxes meet, once: in the cell that holds the low corner of their boxes' overlap
// (that cell is in both segments' ranges), so no list of pairs is made or sorted.
template <class Visit>
void visit_candidate_pairs(const std::vector<std::array<std::uint32_t, 2>>& segs, const std::vector<std::array<double, 2>>& ap,
                           const ParallelLoop& loop, Visit&& visit) {
  if (segs.size() < 2) return;
  bool finite = true;
  for (const auto& s : segs)
    for (std::uint32_t p : s) finite = finite && std::isfinite(ap[p][0]) && std::isfinite(ap[p][1]);
  if (!finite) {  // coordinates beyond doubles: every pair (such scenes are small)
    for (std::uint32_t a = 0; a < segs.size(); ++a)
      for (std::uint32_t b = a + 1; b < segs.size(); ++b) visit(0u, a, b);
    return;
  }
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (const auto& s : segs)
    for (std::uint32_t p : s) {
      x0 = std::min(x0, ap[p][0]), x1 = std::max(x1, ap[p][0]);
      y0 = std::min(y0, ap[p][1]), y1 = std::max(y1, ap[p][1]);
    }
  const double pad = box_pad({x0, x1, y0, y1});
  x0 -= pad, y0 -= pad, x1 += pad, y1 += pad;
  const int g = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(segs.size()))), 1, 2048);
  const double cw = (x1 - x0) / g, ch = (y1 - y0) / g;
  auto cx = [&](double x) { return std::clamp(static_cast<int>((x - x0) / cw), 0, g - 1); };
  auto cy = [&](double y) { return std::clamp(static_cast<int>((y - y0) / ch), 0, g - 1); };
  // Each segment's box widened by pad: [lo - pad, hi + pad] on both axes.
  std::vector<std::array<double, 4>> box(segs.size());
  loop.for_each(segs.size(), 4096, [&](std::size_t k) {
    const auto &a = ap[segs[k][0]], &b = ap[segs[k][1]];
    box[k] = {std::min(a[0], b[0]) - pad, std::min(a[1], b[1]) - pad, std::max(a[0], b[0]) + pad, std::max(a[1], b[1]) + pad};
  });
  auto cells = [&](std::uint32_t k, auto&& each) {
    const auto& bx = box[k];
    const int i0 = cx(bx[0]), i1 = cx(bx[2]), j0 = cy(bx[1]), j1 = cy(bx[3]);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) each(static_cast<std::size_t>(j) * g + i);
  };
  const std::size_t n_cells = static_cast<std::size_t>(g) * g;
  std::vector<std::uint32_t> start(n_cells + 1, 0);
  for (std::uint32_t k = 0; k < segs.size(); ++k) cells(k, [&](std::size_t c) { ++start[c + 1]; });
  for (std::size_t c = 0; c < n_cells; ++c) start[c + 1] += start[c];
  std::vector<std::uint32_t> items(start[n_cells]), fill(start.begin(), start.end() - 1);
  for (std::uint32_t k = 0; k < segs.size(); ++k) cells(k, [&](std::size_t c) { items[fill[c]++] = k; });
  loop.run(n_cells, 256, [&](unsigned w, std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c)
      for (std::uint32_t i = start[c]; i < start[c + 1]; ++i)
        for (std::uint32_t j = i + 1; j < start[c + 1]; ++j) {
          const std::uint32_t a = items[i], b = items[j];
          const auto &p = box[a], &q = box[b];
          // The widened boxes meet (each widened by pad: a gap of up to 2·pad is no gap).
          if (p[2] < q[0] || q[2] < p[0] || p[3] < q[1] || q[3] < p[1]) continue;
          const std::size_t owner = static_cast<std::size_t>(cy(std::max(p[1], q[1]))) * g + cx(std::max(p[0], q[0]));
          if (owner != c) continue;
          visit(w, std::min(a, b), std::max(a, b));
        }
  });
}

// Is point k strictly inside segment (i, j)? (k is neither end.)
bool inside_segment(const Signs& s, std::uint32_t i, std::uint32_t j, std::uint32_t k, std::size_t* exact) {
  if (k == i || k == j) return false;
  if (s.orient(i, j, k, exact) != 0) return false;
  int ax = s.cmp(i, j, 0) != 0 ? 0 : 1;
  int a = s.cmp(i, k, ax), b = s.cmp(k, j, ax);
  return a != 0 && a == b;
}

struct Split {
  std::uint32_t segment, point;
};

// The crossing point of segments (a, b) and (c, d), crossing properly.
Exact2 crossing_point(const Exact2& a, const Exact2& b, const Exact2& c, const Exact2& d) {
  Rational ux = b[0] - a[0], uy = b[1] - a[1], vx = d[0] - c[0], vy = d[1] - c[1];
  Rational t = ((c[0] - a[0]) * vy - (c[1] - a[1]) * vx) / (ux * vy - uy * vx);
  return {a[0] + t * ux, a[1] + t * uy};
}

}  // namespace

PlanarArrangement build_arrangement(std::vector<Exact2> points, const std::vector<std::array<std::uint32_t, 2>>& segments,
                                    const ArrangementOptions& options) {
  PlanarArrangement out;
  std::vector<std::array<double, 2>> ap(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) ap[i] = approx_of(points[i]);
  std::vector<std::uint32_t> rep = join_equal_points(points, ap);
  std::vector<std::array<std::uint32_t, 2>> segs;
  segs.reserve(segments.size());
  for (const auto& s : segments) {
    std::array<std::uint32_t, 2> t{rep[s[0]], rep[s[1]]};
    if (t[0] != t[1]) segs.push_back(t);
  }
  const bool filter = filter_usable(points, ap);
  std::size_t exact = 0;

  // Points inside segments: the ends of other segments, and proper crossings.
  std::vector<Split> splits;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> crossing_pairs;
  {
    // On all cores, each worker into its own lists; the splits are sorted below and the
    // crossing pairs here, so the result does not depend on the thread count.
    Signs sg(points, ap, filter);
    ParallelLoop loop(options.threads);
    struct Found {
      std::vector<Split> splits;
      std::vector<std::pair<std::uint32_t, std::uint32_t>> crossings;
      std::size_t exact = 0;
    };
    PerWorker<Found> found(loop);
    visit_candidate_pairs(segs, ap, loop, [&](unsigned w, std::uint32_t a, std::uint32_t b) {
      Found& f = found[w];
      std::uint32_t p0 = segs[a][0], p1 = segs[a][1], q0 = segs[b][0], q1 = segs[b][1];
      for (std::uint32_t q : {q0, q1})
        if (inside_segment(sg, p0, p1, q, &f.exact)) f.splits.push_back({a, q});
      for (std::uint32_t p : {p0, p1})
        if (inside_segment(sg, q0, q1, p, &f.exact)) f.splits.push_back({b, p});
      if (p0 == q0 || p0 == q1 || p1 == q0 || p1 == q1) return;
      int o0 = sg.orient(p0, p1, q0, &f.exact), o1 = sg.orient(p0, p1, q1, &f.exact);
      if (o0 == 0 || o1 == 0 || o0 == o1) return;
      int o2 = sg.orient(q0, q1, p0, &f.exact), o3 = sg.orient(q0, q1, p1, &f.exact);
      if (o2 == 0 || o3 == 0 || o2 == o3) return;
      f.crossings.emplace_back(a, b);
    });
    for (unsigned w = 0; w < found.size(); ++w) {
      const Found& f = found[w];
      splits.insert(splits.end(), f.splits.begin(), f.splits.end());
      crossing_pairs.insert(crossing_pairs.end(), f.crossings.begin(), f.crossings.end());
      exact += f.exact;
    }
    std::sort(crossing_pairs.begin(), crossing_pairs.end());
  }
  // Crossing points, equal ones joined (three segments through one point).
  std::map<Exact2, std::uint32_t> crossing_id;
  for (auto [a, b] : crossing_pairs) {
    Exact2 x = crossing_point(points[segs[a][0]], points[segs[a][1]], points[segs[b][0]], points[segs[b][1]]);
    auto [it, fresh] = crossing_id.emplace(std::move(x), static_cast<std::uint32_t>(points.size()));
    if (fresh) {
      points.push_back(it->first);
      ap.push_back(approx_of(it->first));
    }
    splits.push_back({a, it->second});
    splits.push_back({b, it->second});
  }
  out.crossings = crossing_pairs.size();
  out.splits = splits.size();
  // A crossing point may equal an input point that lies on neither segment's candidate list
  // only if it is inside both segments, which the end tests above found: join anyway.
  {
    std::vector<std::uint32_t> rep2 = join_equal_points(points, ap);
    for (auto& s : splits) s.point = rep2[s.point];
  }
  const bool filter2 = filter && filter_usable(points, ap);
  Signs sg(points, ap, filter2);

  // Each segment cut at its inner points in order along it; equal pieces kept once.
  std::sort(splits.begin(), splits.end(), [](const Split& x, const Split& y) {
    return x.segment < y.segment || (x.segment == y.segment && x.point < y.point);
  });
  std::vector<std::array<std::uint32_t, 3>> pieces;  // from, to, segment
  for (std::size_t s = 0, k = 0; s < segs.size(); ++s) {
    std::vector<std::uint32_t> inner;
    for (; k < splits.size() && splits[k].segment == s; ++k)
      if (inner.empty() || inner.back() != splits[k].point) inner.push_back(splits[k].point);
    std::uint32_t a = segs[s][0], b = segs[s][1];
    int ax = sg.cmp(a, b, 0) != 0 ? 0 : 1, dir = sg.cmp(a, b, ax);
    std::sort(inner.begin(), inner.end(), [&](std::uint32_t p, std::uint32_t q) { return sg.cmp(p, q, ax) == dir; });
    std::uint32_t prev = a;
    inner.push_back(b);
    for (std::uint32_t p : inner) {
      pieces.push_back({std::min(prev, p), std::max(prev, p), static_cast<std::uint32_t>(s)});
      prev = p;
    }
  }
  std::sort(pieces.begin(), pieces.end());
  pieces.erase(std::unique(pieces.begin(), pieces.end(),
                           [](const auto& x, const auto& y) { return x[0] == y[0] && x[1] == y[1]; }),
               pieces.end());

  // Half-edges, sorted counter-clockwise around each point.
  const std::size_t ne = pieces.size();
  out.origin.resize(2 * ne);
  out.source.resize(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    out.origin[2 * e] = pieces[e][0];
    out.origin[2 * e + 1] = pieces[e][1];
    out.source[e] = pieces[e][2];
  }
  std::vector<std::uint32_t> start(points.size() + 1, 0);
  for (std::uint32_t o : out.origin) ++start[o + 1];
  for (std::size_t i = 0; i < points.size(); ++i) start[i + 1] += start[i];
  std::vector<std::uint32_t> around(2 * ne), fill(start.begin(), start.end() - 1);
  for (std::uint32_t h = 0; h < 2 * ne; ++h) around[fill[out.origin[h]]++] = h;
  ParallelLoop loop(options.threads);
  PerWorker<std::size_t> exact_per(loop, 0);
  std::vector<std::uint32_t> position(2 * ne);
  loop.run(points.size(), 1024, [&](unsigned w, std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      auto half = [&](std::uint32_t h) {  // 0: direction in [0, pi), 1: in [pi, 2 pi)
        std::uint32_t b = out.head(h);
        int dy = sg.cmp(static_cast<std::uint32_t>(v), b, 1);
        return dy > 0 || (dy == 0 && sg.cmp(static_cast<std::uint32_t>(v), b, 0) > 0) ? 0 : 1;
      };
      std::sort(around.begin() + start[v], around.begin() + start[v + 1], [&](std::uint32_t g, std::uint32_t h) {
        int hg = half(g), hh = half(h);
        if (hg != hh) return hg < hh;
        return sg.orient(static_cast<std::uint32_t>(v), out.head(g), out.head(h), &exact_per[w]) > 0;
      });
      for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) position[around[i]] = i;
    }
  });
  for (unsigned w = 0; w < exact_per.size(); ++w) exact += exact_per[w];
  // next(h) for h = a -> b: the half-edge leaving b just clockwise of b -> a.
  out.next.resize(2 * ne);
  for (std::uint32_t h = 0; h < 2 * ne; ++h) {
    std::uint32_t t = h ^ 1, b = out.origin[t], i = position[t];
    out.next[h] = around[i == start[b] ? start[b + 1] - 1 : i - 1];
  }
  // Cycles.
  out.cycle.assign(2 * ne, UINT32_MAX);
  for (std::uint32_t h = 0; h < 2 * ne; ++h) {
    if (out.cycle[h] != UINT32_MAX) continue;
    std::uint32_t c = static_cast<std::uint32_t>(out.cycle_edge.size());
    out.cycle_edge.push_back(h);
    for (std::uint32_t g = h; out.cycle[g] == UINT32_MAX; g = out.next[g]) out.cycle[g] = c;
  }
  out.points = std::move(points);
  out.approx = std::move(ap);
  out.filters = filter2;
  out.exact_tests = exact;
  return out;
}

namespace {

Rational area2_of(const PlanarArrangement& arr, const std::vector<std::uint32_t>& ring) {
  Rational s = 0;
  for (std::uint32_t h : ring) {
    const Exact2 &a = arr.points[arr.origin[h]], &b = arr.points[arr.head(h)];
    s += a[0] * b[1] - a[1] * b[0];
  }
  return s;
}

// Sign of a ring's area: the doubles' shoelace sum when its error bound (design.md) allows.
int area_sign(const PlanarArrangement& arr, const std::vector<std::uint32_t>& ring) {
  double sum = 0, mag = 0;
  const bool ok = arr.filters;
  for (std::uint32_t h : ring) {
    const auto &a = arr.approx[arr.origin[h]], &b = arr.approx[arr.head(h)];
    double p = a[0] * b[1], q = a[1] * b[0];
    sum += p - q;
    mag += std::fabs(p) + std::fabs(q);
  }
  double bound = (16 + 2 * static_cast<double>(ring.size())) * kToDoubleError * mag;
  if (ok && sum > bound) return 1;
  if (ok && sum < -bound) return -1;
  return sgn(area2_of(arr, ring));
}

// Is m strictly inside the ring (m is on none of its edges)? Crossing number, exact.
bool inside_ring(const PlanarArrangement& arr, const std::vector<std::uint32_t>& ring, const Exact2& m) {
  bool in = false;
  for (std::uint32_t h : ring) {
    const Exact2 &a = arr.points[arr.origin[h]], &b = arr.points[arr.head(h)];
    bool ua = a[1] > m[1], ub = b[1] > m[1];
    if (ua == ub) continue;
    if ((orient2d(a, b, m) > 0) == ub) in = !in;
  }
  return in;
}

}  // namespace

std::vector<LabelledRegion> merge_regions(const PlanarArrangement& a, const std::vector<int>& cycle_label, int background,
                                         bool exact_area) {
  const std::size_t nh = a.origin.size();
  auto label = [&](std::uint32_t h) { return cycle_label[a.cycle[h]]; };
  std::vector<char> kept(nh);
  for (std::uint32_t h = 0; h < nh; ++h) kept[h] = label(h) != label(h ^ 1);
  // next among kept half-edges: from h's next, turn on clockwise around the head (next(h) is
  // the first clockwise of twin(h); twin(next(g)) then next again is the next clockwise).
  auto next_kept = [&](std::uint32_t h) {
    std::uint32_t g = a.next[h];
    while (!kept[g]) g = a.next[g ^ 1];
    return g;
  };
  std::vector<char> seen(nh, 0);
  struct Ring {
    int label;
    std::vector<std::uint32_t> pts;
    Rational area2;
    std::uint32_t first_half;
  };
  std::vector<Ring> outers, holes;
  // Every ring has at least two half-edges: room for all, so that growing never copies the
  // rings' GMP areas (mpq_class's move is not noexcept).
  outers.reserve(nh / 2 + 1);
  holes.reserve(nh / 2 + 1);
  for (std::uint32_t h = 0; h < nh; ++h) {
    if (!kept[h] || seen[h] || label(h) == background) continue;
    Ring r{label(h), {}, 0, h};
    for (std::uint32_t g = h; !seen[g]; g = next_kept(g)) {
      seen[g] = 1;
      r.pts.push_back(g);
    }
    int sign = area_sign(a, r.pts);
    if (exact_area) r.area2 = area2_of(a, r.pts);
    if (sign > 0)
      outers.push_back(std::move(r));
    else if (sign < 0)
      holes.push_back(std::move(r));
  }
  std::vector<LabelledRegion> out(outers.size());
  std::vector<std::array<double, 4>> box(outers.size());  // doubles' box, widened: only skips
  std::multimap<int, std::size_t> by_label;
  for (std::size_t i = 0; i < outers.size(); ++i) {
    out[i].label = outers[i].label;
    out[i].outer = outers[i].pts;
    out[i].area2 = outers[i].area2;
    by_label.emplace(outers[i].label, i);
    std::array<double, 4> b{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (std::uint32_t h : outers[i].pts) {
      const auto& p = a.approx[a.origin[h]];
      b = {std::min(b[0], p[0]), std::min(b[1], p[1]), std::max(b[2], p[0]), std::max(b[3], p[1])};
    }
    double pad = box_pad({b[0], b[1], b[2], b[3]});
    box[i] = {b[0] - pad, b[1] - pad, b[2] + pad, b[3] + pad};
  }
  for (Ring& hole : holes) {
    const std::uint32_t h = hole.first_half;
    const Exact2 &p = a.points[a.origin[h]], &q = a.points[a.head(h)];
    Exact2 m{(p[0] + q[0]) / 2, (p[1] + q[1]) / 2};
    const auto &pa = a.approx[a.origin[h]], &qa = a.approx[a.head(h)];
    const double mx = (pa[0] + qa[0]) / 2, my = (pa[1] + qa[1]) / 2;
    // Candidates of the hole's label whose box holds the point, smallest first: the first
    // that contains it is the innermost.
    std::vector<std::size_t> cand;
    auto [lo, hi] = by_label.equal_range(hole.label);
    for (auto it = lo; it != hi; ++it) {
      const auto& b = box[it->second];
      if (!a.filters || (b[0] <= mx && mx <= b[2] && b[1] <= my && my <= b[3])) cand.push_back(it->second);
    }
    // Outers of one label containing the point are nested: the innermost has the least area.
    std::size_t best = SIZE_MAX;
    for (std::size_t c : cand) {
      if (!inside_ring(a, outers[c].pts, m)) continue;
      if (best != SIZE_MAX) {
        if (!exact_area) {
          outers[best].area2 = area2_of(a, outers[best].pts);
          outers[c].area2 = area2_of(a, outers[c].pts);
        }
        if (!(outers[c].area2 < outers[best].area2)) continue;
      }
      best = c;
    }
    if (best == SIZE_MAX) throw std::logic_error("merge_regions: a hole outside every region of its label");
    out[best].holes.push_back(std::move(hole.pts));
    out[best].area2 += hole.area2;
  }
  std::vector<std::size_t> idx(out.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](std::size_t x, std::size_t y) {
    return out[x].label < out[y].label ||
           (out[x].label == out[y].label && a.origin[out[x].outer.front()] < a.origin[out[y].outer.front()]);
  });
  std::vector<LabelledRegion> sorted;
  sorted.reserve(out.size());
  for (std::size_t i : idx) sorted.push_back(std::move(out[i]));
  return sorted;
}

}  // namespace hlr
