// Lines that coincide on the page (algorithms/plot/coincident_lines.hpp; docs/design.md, "Lines
// that coincide on the page"): the grid of cells and direction classes must find every kept
// segment that covers a part of a stroke. The oracle states the rule with no search at all:
// every segment of every stroke is compared with every segment kept before it. Plots of
// near-parallel families (spacing around the tolerance, angles near 3 degrees and near a half
// turn), dense lattices finer than the tolerance, long diagonals, closed strokes, repeated and
// tiny points and coordinates far from the origin must come out point for point the same.
#include "algorithms/plot/coincident_lines.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "algorithms/support/parallel.hpp"

namespace hlr {
namespace {

// ------------------------------------------------------------------ the oracle
struct Seg {
  Point2 a, b;
};

int oracle_rank(const PlotLayer& l) {
  int k = 0;
  for (std::size_t i = 0; i < std::size(kLayerKinds); ++i)
    if (kLayerKinds[i] == l.kind) k = static_cast<int>(i);
  return (l.visible && !l.through ? 0 : (l.through ? 1 : 2)) * 100 + k;
}

bool oracle_takes_part(LineKind k) {
  return !is_tone(k) && k != LineKind::Hatch && k != LineKind::SectionLine && k != LineKind::SectionMark && k != LineKind::Overhead;
}

// The part of pq within tol of ab, alongside it and within 3 degrees of its direction.
std::pair<double, double> oracle_covered(const Point2& p, const Point2& q, const Seg& s, double tol) {
  const double dx = q[0] - p[0], dy = q[1] - p[1], len2 = dx * dx + dy * dy;
  const double ex = s.b[0] - s.a[0], ey = s.b[1] - s.a[1], elen2 = ex * ex + ey * ey;
  if (!(len2 > 0) || !(elen2 > 0)) return {1, 0};
  if (std::fabs(dx * ey - dy * ex) > 0.0523 * std::sqrt(len2 * elen2)) return {1, 0};
  double lo = 0, hi = 1;
  auto keep = [&](double f0, double f1, double low, double high) {
    const double df = f1 - f0;
    if (df == 0) {
      if (f0 < low || f0 > high) lo = 1, hi = 0;
      return;
    }
    double t0 = (low - f0) / df, t1 = (high - f0) / df;
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0), hi = std::min(hi, t1);
  };
  keep(((p[0] - s.a[0]) * ex + (p[1] - s.a[1]) * ey) / elen2, ((q[0] - s.a[0]) * ex + (q[1] - s.a[1]) * ey) / elen2, 0, 1);
  const double elen = std::sqrt(elen2);
  keep(((p[0] - s.a[0]) * ey - (p[1] - s.a[1]) * ex) / elen, ((q[0] - s.a[0]) * ey - (q[1] - s.a[1]) * ex) / elen, -tol, tol);
  return {lo, hi};
}

CoincidentStats oracle_merge(Plot& plot, double tol) {
  CoincidentStats st;
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < plot.layers.size(); ++i)
    if (oracle_takes_part(plot.layers[i].kind)) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return oracle_rank(plot.layers[a]) < oracle_rank(plot.layers[b]); });
  std::vector<Seg> kept;
  for (std::size_t li : order) {
    std::vector<Stroke> out;
    for (const Stroke& s : plot.layers[li].strokes) {
      std::vector<Point2> pts = s.points;
      if (s.closed && pts.size() > 2) pts.push_back(pts.front());
      const std::size_t first_out = out.size();
      std::vector<std::vector<std::pair<double, double>>> runs(pts.size() > 1 ? pts.size() - 1 : 0);
      bool touched = false;
      for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const double len = std::hypot(pts[i + 1][0] - pts[i][0], pts[i + 1][1] - pts[i][1]);
        std::vector<std::pair<double, double>> covers;
        for (const Seg& k : kept) {  // every kept segment: no search
          auto c = oracle_covered(pts[i], pts[i + 1], k, tol);
          if (c.second > c.first) covers.push_back(c);
        }
        std::sort(covers.begin(), covers.end());
        std::vector<std::pair<double, double>> all;
        for (const auto& c : covers)
          if (!all.empty() && c.first <= all.back().second + 1e-12) all.back().second = std::max(all.back().second, c.second);
          else all.push_back(c);
        for (const auto& r : all)
          if (!((r.second - r.first) * len < tol && r.first > 0 && r.second < 1)) runs[i].push_back(r);
        touched = touched || !runs[i].empty();
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
          auto part = [&](double t0, double t1) {
            if (cur.points.empty() || cur.points.back() != point(t0)) {
              flush();
              cur.points.push_back(point(t0));
            }
            cur.points.push_back(point(t1));
          };
          double at = 0;
          for (const auto& [c0, c1] : runs[i]) {
            if (c1 <= at) continue;
            if (c0 > at) part(at, c0);
            st.length_removed += (c1 - std::max(c0, at)) * len;
            ++st.pieces_removed;
            at = c1;
            flush();
          }
          if (at < 1) part(at, 1);
        }
        flush();
      }
      for (std::size_t o = first_out; o < out.size(); ++o) {
        std::vector<Point2> q = out[o].points;
        if (out[o].closed && q.size() > 2) q.push_back(q.front());
        for (std::size_t k = 0; k + 1 < q.size(); ++k) kept.push_back({q[k], q[k + 1]});
      }
    }
    plot.layers[li].strokes = std::move(out);
  }
  std::vector<PlotLayer> layers;
  for (PlotLayer& l : plot.layers)
    if (!l.strokes.empty()) layers.push_back(std::move(l));
  plot.layers = std::move(layers);
  return st;
}

// ------------------------------------------------------------------ random plots
struct Maker {
  std::mt19937 rng;
  double tol, origin;
  double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
  Point2 at(double x, double y) { return {origin + x, origin + y}; }

  // A family of near-parallel strokes: spacing around the tolerance, directions within a few
  // degrees (some just over 3), some reversed.
  void family(std::vector<Stroke>& out) {
    const double angle = uni(0, M_PI), n = 2 + static_cast<int>(uni(0, 8));
    const double cx = uni(0, 100 * tol), cy = uni(0, 100 * tol);
    for (int k = 0; k < n; ++k) {
      const double a = angle + (uni(0, 1) < 0.3 ? uni(-0.06, 0.06) : uni(-0.01, 0.01)) + (uni(0, 1) < 0.2 ? M_PI : 0);
      const double off = uni(-2, 2) * tol, len = uni(0.5, 40) * tol, shift = uni(-10, 10) * tol;
      const double nx = -std::sin(angle), ny = std::cos(angle), dx = std::cos(a), dy = std::sin(a);
      Stroke s;
      const int parts = 1 + static_cast<int>(uni(0, 4));
      for (int i = 0; i <= parts; ++i) {
        const double t = shift + len * i / parts + (i > 0 && i < parts ? uni(-0.2, 0.2) * tol : 0);
        s.points.push_back(at(cx + off * nx + t * dx, cy + off * ny + t * dy));
        if (uni(0, 1) < 0.05) s.points.push_back(s.points.back());  // a repeated point
      }
      out.push_back(std::move(s));
    }
  }
  // A triangular lattice finer than the tolerance, as a dense mesh seen from afar draws.
  void lattice(std::vector<Stroke>& out) {
    const double h = uni(0.3, 1.2) * tol, turn = uni(0, M_PI);
    const double ox = uni(0, 50 * tol), oy = uni(0, 50 * tol);
    auto p = [&](double i, double j) {
      const double x = (i + 0.5 * j) * h, y = j * h * std::sqrt(3.0) / 2;
      return at(ox + x * std::cos(turn) - y * std::sin(turn), oy + x * std::sin(turn) + y * std::cos(turn));
    };
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) {
        out.push_back(Stroke{{p(i, j), p(i + 1, j)}, false});
        out.push_back(Stroke{{p(i, j), p(i, j + 1)}, false});
        out.push_back(Stroke{{p(i + 1, j), p(i, j + 1)}, false});
      }
  }
  void polygon(std::vector<Stroke>& out) {
    Stroke s;
    const double cx = uni(0, 100 * tol), cy = uni(0, 100 * tol), r = uni(1, 30) * tol;
    const int n = 3 + static_cast<int>(uni(0, 6));
    for (int i = 0; i < n; ++i) s.points.push_back(at(cx + r * std::cos(2 * M_PI * i / n), cy + r * std::sin(2 * M_PI * i / n)));
    s.closed = true;
    out.push_back(std::move(s));
  }
  void diagonal(std::vector<Stroke>& out) {  // across the whole drawing, many cells long
    const double y0 = uni(0, 100 * tol), y1 = uni(0, 100 * tol);
    out.push_back(Stroke{{at(-5 * tol, y0), at(105 * tol, y1)}, false});
    out.push_back(Stroke{{at(-5 * tol, y0 + uni(-1.5, 1.5) * tol), at(105 * tol, y1 + uni(-1.5, 1.5) * tol)}, false});
  }
  void tiny(std::vector<Stroke>& out) {  // far shorter than the tolerance, some of a few ulps
    const double x = uni(0, 100 * tol), y = uni(0, 100 * tol);
    const double d = uni(0, 1) < 0.5 ? uni(1e-6, 1e-2) * tol : std::nextafter(origin + x, INFINITY) - (origin + x);
    out.push_back(Stroke{{at(x, y), at(x + d, y + d * uni(-1, 1)), at(x + 3 * tol, y)}, false});
  }

  Plot plot() {
    Plot p;
    const LineKind kinds[] = {LineKind::Edge, LineKind::Silhouette, LineKind::Crease, LineKind::Boundary, LineKind::Hatch, LineKind::Intersection};
    const int layers = 1 + static_cast<int>(uni(0, 5));
    for (int l = 0; l < layers; ++l) {
      PlotLayer layer;
      layer.kind = kinds[static_cast<int>(uni(0, 6))];
      layer.visible = uni(0, 1) < 0.7;
      layer.through = !layer.visible && uni(0, 1) < 0.3;
      const int groups = 1 + static_cast<int>(uni(0, 6));
      for (int g = 0; g < groups; ++g) {
        const double r = uni(0, 1);
        if (r < 0.45) family(layer.strokes);
        else if (r < 0.6) lattice(layer.strokes);
        else if (r < 0.75) polygon(layer.strokes);
        else if (r < 0.85) diagonal(layer.strokes);
        else tiny(layer.strokes);
      }
      std::shuffle(layer.strokes.begin(), layer.strokes.end(), rng);
      p.layers.push_back(std::move(layer));
    }
    return p;
  }
};

void expect_same(const Plot& got, const Plot& want, const std::string& what) {
  ASSERT_EQ(got.layers.size(), want.layers.size()) << what;
  for (std::size_t l = 0; l < got.layers.size(); ++l) {
    const auto &g = got.layers[l], &w = want.layers[l];
    ASSERT_EQ(g.kind, w.kind) << what;
    ASSERT_EQ(g.strokes.size(), w.strokes.size()) << what << " layer " << l;
    for (std::size_t s = 0; s < g.strokes.size(); ++s) {
      ASSERT_EQ(g.strokes[s].closed, w.strokes[s].closed) << what << " layer " << l << " stroke " << s;
      ASSERT_EQ(g.strokes[s].points, w.strokes[s].points) << what << " layer " << l << " stroke " << s;
    }
  }
}

TEST(CoincidentLines, GridFindsEveryCoverTheWholeComparisonFinds) {
  std::size_t removed = 0, total = 0;
  for (unsigned seed = 1; seed <= 300; ++seed) {
    Maker m{std::mt19937(seed), 0, 0};
    m.tol = std::pow(10.0, m.uni(-3, 2));
    m.origin = seed % 3 == 0 ? 1e6 : (seed % 3 == 1 ? 0 : -37.5 * m.tol);
    Plot p = m.plot();
    for (const auto& l : p.layers) total += l.strokes.size();
    Plot want = p;
    const CoincidentStats got_st = merge_coincident_lines(p, m.tol);
    const CoincidentStats want_st = oracle_merge(want, m.tol);
    expect_same(p, want, "seed " + std::to_string(seed));
    EXPECT_EQ(got_st.pieces_removed, want_st.pieces_removed) << "seed " << seed;
    EXPECT_EQ(got_st.length_removed, want_st.length_removed) << "seed " << seed;
    removed += want_st.pieces_removed;
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(removed, total / 4);  // the plots do coincide, a lot
}

TEST(CoincidentLines, ParallelNeighboursOfALongLineAndAHalfTurn) {
  // A kept line 100 tolerances long; a reversed one 0.6 tolerance beside it goes; one as long,
  // 2 degrees off and crossing it, keeps its ends, where it is further than the tolerance; a
  // short one 3.5 degrees off stays whole.
  const double tol = 0.01;
  Plot p;
  PlotLayer l;
  l.strokes.push_back(Stroke{{{0, 0}, {1, 0}}, false});
  l.strokes.push_back(Stroke{{{0.9, 0.006}, {0.1, 0.006}}, false});
  const double a2 = 2 * M_PI / 180, a35 = 3.5 * M_PI / 180;
  l.strokes.push_back(Stroke{{{0.5 - 0.5 * std::cos(a2), -0.5 * std::sin(a2)}, {0.5 + 0.5 * std::cos(a2), 0.5 * std::sin(a2)}}, false});
  l.strokes.push_back(Stroke{{{0.3 - 0.05 * std::cos(a35), -0.05 * std::sin(a35)}, {0.3 + 0.05 * std::cos(a35), 0.05 * std::sin(a35)}}, false});
  p.layers.push_back(l);
  Plot want = p;
  merge_coincident_lines(p, tol);
  oracle_merge(want, tol);
  expect_same(p, want, "long line");
  ASSERT_EQ(p.layers.size(), 1u);
  ASSERT_EQ(p.layers[0].strokes.size(), 4u);
  EXPECT_EQ(p.layers[0].strokes[0].points, (std::vector<Point2>{{0, 0}, {1, 0}}));
  for (int end : {1, 2}) {  // the 2-degree line's ends: from where it is the tolerance away
    const auto& e = p.layers[0].strokes[end].points;
    ASSERT_EQ(e.size(), 2u);
    EXPECT_NEAR(std::fabs(e[end == 1 ? 1 : 0][1]), tol, 1e-12);
  }
  EXPECT_EQ(p.layers[0].strokes[3].points, l.strokes[3].points);
}

// Merges a plot of one layer on all cores: the same strokes and statistics as the oracle, and
// the same strokes on one thread; returns the parts the oracle left out.
std::size_t merge_as_oracle_on_any_threads(const PlotLayer& l, double tol, const std::string& what) {
  Plot p;
  p.layers.push_back(l);
  Plot want = p, one = p;
  const CoincidentStats got = merge_coincident_lines(p, tol);
  const CoincidentStats expected = oracle_merge(want, tol);
  expect_same(p, want, what);
  EXPECT_EQ(got.pieces_removed, expected.pieces_removed) << what;
  EXPECT_EQ(got.length_removed, expected.length_removed) << what;
  {
    const ThreadLimit single(1);
    merge_coincident_lines(one, tol);
  }
  expect_same(p, one, "one thread, " + what);
  return expected.pieces_removed;
}

// A random walk of n steps of 0.5 to 2.5 tolerances, turning a little at each.
std::vector<Point2> random_walk(std::mt19937& rng, int n, double tol) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Point2> walk{{0, 0}};
  double angle = 0;
  for (int i = 0; i < n; ++i) {
    angle += 0.3 * u(rng);
    const double step = tol * (1.5 + u(rng));
    walk.push_back({walk.back()[0] + step * std::cos(angle), walk.back()[1] + step * std::sin(angle)});
  }
  return walk;
}

// Strokes of thousands of segments (a mesh's chained paths) are looked at on all cores: a
// random walk, the same walk retraced beside it within the tolerance (reversed, with noise)
// and a closed one through both, against the oracle and against one thread. And two long
// strokes in one batch (1,500 and 2,000 segments, under its 4,096): the second retraces the
// first, so it is looked at again against what the first kept, its segments on all cores.
TEST(CoincidentLines, LongStrokesOnAllCoresAsTheOracle) {
  std::size_t removed = 0, again = 0;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    const double tol = 0.01;
    const std::vector<Point2> walk = random_walk(rng, 5000, tol);
    std::vector<Point2> beside(walk.rbegin(), walk.rend());
    for (Point2& q : beside) q = {q[0] + 0.4 * tol * u(rng), q[1] + 0.4 * tol * u(rng)};
    std::vector<Point2> loop;
    for (std::size_t i = 0; i < walk.size(); i += 2) loop.push_back({walk[i][0] + 0.2 * tol, walk[i][1] - 0.1 * tol});
    PlotLayer l;
    l.strokes = {Stroke{walk, false}, Stroke{beside, false}, Stroke{loop, true}};
    removed += merge_as_oracle_on_any_threads(l, tol, "long strokes, seed " + std::to_string(seed));
    if (HasFatalFailure()) return;
    PlotLayer batch;
    batch.strokes = {Stroke{std::vector<Point2>(beside.begin() + 250, beside.begin() + 1751), false},
                     Stroke{std::vector<Point2>(walk.begin() + 3000, walk.end()), false}};
    again += merge_as_oracle_on_any_threads(batch, tol, "a long stroke again in its batch, seed " + std::to_string(seed));
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(removed, 300u);
  EXPECT_GT(again, 300u);
}

// Many short strokes in a small square (the dense band of a mesh's silhouette) are looked at
// in batches on all cores: each stroke also against what the batch's earlier strokes kept.
// Half retrace an earlier stroke within the tolerance (reversed, with noise), some in the same
// batch; against the oracle and against one thread.
TEST(CoincidentLines, ShortStrokesInBatchesAsTheOracle) {
  std::size_t removed = 0;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    const double tol = 0.01;
    PlotLayer l;
    std::size_t segments = 0;
    while (segments < 3000) {
      std::vector<Point2> walk;
      if (!l.strokes.empty() && u(rng) > 0) {  // an earlier stroke (often a recent one) retraced
        const std::size_t back = std::min<std::size_t>(l.strokes.size(), 1 + static_cast<std::size_t>(8 * (u(rng) + 1)));
        const auto& from = l.strokes[l.strokes.size() - back].points;
        walk.assign(from.rbegin(), from.rend());
        for (Point2& q : walk) q = {q[0] + 0.4 * tol * u(rng), q[1] + 0.4 * tol * u(rng)};
      } else {
        walk.push_back({0.2 * u(rng), 0.2 * u(rng)});
        double angle = M_PI * u(rng);
        const int n = 5 + static_cast<int>(18 * (u(rng) + 1));
        for (int i = 0; i < n; ++i) {
          angle += 0.2 * u(rng);
          const double step = tol * (1.5 + u(rng));
          walk.push_back({walk.back()[0] + step * std::cos(angle), walk.back()[1] + step * std::sin(angle)});
        }
      }
      segments += walk.size() - 1;
      l.strokes.push_back(Stroke{walk, false});
    }
    removed += merge_as_oracle_on_any_threads(l, tol, "short strokes, seed " + std::to_string(seed));
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(removed, 300u);
}

}  // namespace
}  // namespace hlr
