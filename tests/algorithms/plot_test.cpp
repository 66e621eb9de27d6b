// The plotting 2D stage: exact clean-up (points, end-on edges, overlaps), chaining
// into the fewest strokes, pen order, dashes, pages, and the writers read back.
#include "algorithms/plot/plot.hpp"

#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>
#include <gtest/gtest.h>
#include <png.h>
#include <zlib.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "algorithms/picture/path_chaining.hpp"
#include "algorithms/plot/dashes.hpp"
#include "algorithms/plot/pen_order.hpp"
#include "algorithms/support/parallel.hpp"
#include "io/pipeline/render.hpp"
#include "io/views/standard_views.hpp"
#include "io/writers/cairo_text.hpp"
#include "io/writers/plot_output.hpp"
#include "io/writers/svg_writer.hpp"

namespace hlr {
namespace {

const std::string kData = HLR_DATA_DIR;

// ---------------------------------------------------------------- chaining
std::vector<std::array<std::uint32_t, 2>> random_graph(std::mt19937& rng, std::size_t n, std::size_t m) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(n - 1));
  while (edges.size() < m) {
    std::uint32_t a = pick(rng), b = pick(rng);
    if (a == b || !seen.insert({std::min(a, b), std::max(a, b)}).second) continue;
    edges.push_back({a, b});
  }
  return edges;
}

TEST(PathChaining, ReachesTheEulerBoundAndDrawsEveryEdgeOnce) {
  std::mt19937 rng(13);
  for (int round = 0; round < 200; ++round) {
    std::size_t n = 2 + rng() % 40, m = std::min<std::size_t>(rng() % 60 + 1, n * (n - 1) / 2);
    auto edges = random_graph(rng, n, m);
    auto chains = chain_edges(n, edges);
    EXPECT_EQ(chains.size(), minimum_chain_count(n, edges)) << "round " << round;
    std::vector<int> used(edges.size(), 0);
    for (const Chain& c : chains) {
      ASSERT_EQ(c.edges.size() + (c.closed ? 0 : 1), c.points.size());
      for (std::size_t i = 0; i < c.edges.size(); ++i) {
        const auto& e = edges[c.edges[i]];
        std::uint32_t a = c.points[i], b = c.points[(i + 1) % c.points.size()];
        EXPECT_TRUE((e[0] == a && e[1] == b) || (e[0] == b && e[1] == a)) << "round " << round;
        ++used[c.edges[i]];
      }
    }
    for (int u : used) EXPECT_EQ(u, 1) << "round " << round;
  }
}

TEST(PathChaining, NamedGraphs) {
  // A square: one closed stroke.
  auto sq = chain_edges(4, {{0, 1}, {1, 2}, {2, 3}, {3, 0}});
  ASSERT_EQ(sq.size(), 1u);
  EXPECT_TRUE(sq[0].closed);
  // A star of three edges: two strokes (odd vertices 0, 1, 2, 3 -> 2).
  EXPECT_EQ(chain_edges(4, {{0, 1}, {0, 2}, {0, 3}}).size(), 2u);
  // A cube's 12 edges (8 vertices of degree 3): 4 strokes.
  std::vector<std::array<std::uint32_t, 2>> cube;
  for (std::uint32_t v = 0; v < 8; ++v)
    for (std::uint32_t b : {1u, 2u, 4u})
      if (!(v & b)) cube.push_back({v, v | b});
  EXPECT_EQ(chain_edges(8, cube).size(), 4u);
  EXPECT_EQ(minimum_chain_count(8, cube), 4u);
  // Two separate triangles: two closed strokes.
  auto two = chain_edges(6, {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}});
  ASSERT_EQ(two.size(), 2u);
  EXPECT_TRUE(two[0].closed && two[1].closed);
}

// ---------------------------------------------------------------- pen order
TEST(PenOrder, TwoOptNeverLengthensAndHelpsOnRandomStrokes) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 100);
  double greedy = 0, final = 0;
  for (int round = 0; round < 5; ++round) {
    std::vector<Stroke> strokes;
    for (int i = 0; i < 2000; ++i) {
      Point2 a{u(rng), u(rng)};
      strokes.push_back(Stroke{{a, {a[0] + u(rng) / 50, a[1] + u(rng) / 50}}, false});
    }
    PenOrder o = order_strokes(strokes, {0, 100});
    EXPECT_LE(o.pen_up, o.pen_up_greedy + 1e-9);
    greedy += o.pen_up_greedy, final += o.pen_up;
    std::vector<std::uint32_t> sorted = o.order;
    std::sort(sorted.begin(), sorted.end());
    for (std::uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);  // a permutation
    // The reported travel is the travel of the strokes as ordered and turned.
    std::vector<Stroke> placed;
    for (std::size_t i = 0; i < o.order.size(); ++i) {
      Stroke s = strokes[o.order[i]];
      if (o.reversed[i]) std::reverse(s.points.begin(), s.points.end());
      placed.push_back(s);
    }
    EXPECT_NEAR(pen_up_length(placed, {0, 100}), o.pen_up, 1e-6);
    EXPECT_LT(o.pen_up, 0.5 * pen_up_length(strokes, {0, 100}));
  }
  EXPECT_LT(final, 0.97 * greedy) << "2-opt should shorten greedy nearest-neighbour travel on random strokes";
}

// Open, closed, one-point and empty strokes together; the neighbour lists are built on several
// cores: the order must not depend on how many, and closed strokes start where the order says.
TEST(PenOrder, MixedStrokesSameOrderOnAnyThreadCount) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 100);
  std::vector<Stroke> strokes;
  for (int i = 0; i < 3000; ++i) {
    Point2 a{u(rng), u(rng)};
    switch (i % 5) {
      case 0: strokes.push_back(Stroke{{a, {a[0] + 1, a[1]}, {a[0] + 1, a[1] + 1}}, true}); break;  // a triangle
      case 1: strokes.push_back(Stroke{{a}, false}); break;                                       // a dot
      case 2: if (i % 20 == 2) { strokes.push_back(Stroke{}); break; } [[fallthrough]];             // empty
      default: strokes.push_back(Stroke{{a, {a[0] + u(rng) / 30, a[1] + u(rng) / 30}}, false});
    }
  }
  PenOrderOptions one, four;
  one.threads = 1, four.threads = 4;
  PenOrder a = order_strokes(strokes, {0, 100}, one), b = order_strokes(strokes, {0, 100}, four);
  EXPECT_EQ(a.order, b.order);
  EXPECT_EQ(a.reversed, b.reversed);
  EXPECT_EQ(a.start, b.start);
  EXPECT_EQ(a.pen_up, b.pen_up);
  EXPECT_LT(a.pen_up, 0.97 * a.pen_up_greedy);
  std::vector<Stroke> placed;
  for (std::size_t i = 0; i < a.order.size(); ++i) {
    Stroke s = strokes[a.order[i]];
    if (s.closed) std::rotate(s.points.begin(), s.points.begin() + a.start[i], s.points.end());
    else if (a.reversed[i]) std::reverse(s.points.begin(), s.points.end());
    placed.push_back(s);
  }
  EXPECT_NEAR(pen_up_length(placed, {0, 100}), a.pen_up, 1e-6);
}

// ---------------------------------------------------------------- dashes
TEST(Dashes, PatternRunsOnAcrossCorners) {
  // An L of 5 + 5 with dash 3, gap 1: dashes [0,3], [4,7] (across the corner), [8,10].
  auto d = cut_dashes({{0, 0}, {5, 0}, {5, 5}}, false, 3, 1);
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[1].size(), 3u);  // the corner is inside the second dash
  EXPECT_DOUBLE_EQ(d[1][0][0], 4);
  EXPECT_DOUBLE_EQ(d[1][2][1], 2);
  EXPECT_DOUBLE_EQ(d[2][0][1], 3);
  double total = 0;
  for (const auto& s : d)
    for (std::size_t i = 1; i < s.size(); ++i) total += std::hypot(s[i][0] - s[i - 1][0], s[i][1] - s[i - 1][1]);
  EXPECT_DOUBLE_EQ(total, 8);
}

// ---------------------------------------------------------------- the exact clean-up
RenderResult render_view(const std::string& file, const std::string& view) {
  RenderOptions o;
  auto sv = standard_view(view, false);
  o.view.direction = sv->direction;
  o.view.up = sv->up;
  return render_files({file}, o);
}

// Brute force in doubles, independent of the exact code: no two drawn edges of the output
// overlap along a line by more than a tolerance.
double overlap_length(const Plot& p) {
  struct E {
    Point2 a, b;
  };
  std::vector<E> es;
  for (const PlotLayer& l : p.layers)
    for (const Stroke& s : l.strokes)
      for (std::size_t i = 0; i + 1 < s.points.size() + (s.closed ? 1 : 0); ++i)
        es.push_back({s.points[i], s.points[(i + 1) % s.points.size()]});
  double total = 0, tol = 1e-9;
  for (std::size_t i = 0; i < es.size(); ++i)
    for (std::size_t j = i + 1; j < es.size(); ++j) {
      Point2 a = es[i].a, b = es[i].b;
      double L = std::hypot(b[0] - a[0], b[1] - a[1]);
      if (L < tol) continue;
      double nx = (b[0] - a[0]) / L, ny = (b[1] - a[1]) / L;
      auto off = [&](Point2 q) { return std::fabs(nx * (q[1] - a[1]) - ny * (q[0] - a[0])); };
      if (off(es[j].a) > tol || off(es[j].b) > tol) continue;
      double s0 = nx * (es[j].a[0] - a[0]) + ny * (es[j].a[1] - a[1]), s1 = nx * (es[j].b[0] - a[0]) + ny * (es[j].b[1] - a[1]);
      total += std::max(0.0, std::min(L, std::max(s0, s1)) - std::max(0.0, std::min(s0, s1)) - 1e-9);
    }
  return total;
}

TEST(PlotCleanUp, CubeFrontViewIsOneClosedSquare) {
  RenderResult r = render_view(kData + "/cube.off", "front");
  PlotOptions po;
  po.hidden = true;
  Plot p = make_plot(r.drawing, r.camera, po);
  EXPECT_EQ(p.stats.zero_length, 4u);  // the four edges along the view
  EXPECT_EQ(p.stats.edges, 4u);
  ASSERT_EQ(p.layers.size(), 1u);  // the back edges lie under the front ones: no hidden layer
  ASSERT_EQ(p.layers[0].strokes.size(), 1u);
  EXPECT_TRUE(p.layers[0].strokes[0].closed);
  EXPECT_EQ(overlap_length(p), 0);
}

TEST(PlotCleanUp, AxisViewsDrawNothingTwice) {
  std::vector<std::string> files = {kData + "/demo.yaml", kData + "/cube.off", kData + "/l_prism.off"};
  for (const char* m : {"/fandisk.off", "/cube-meshed.off"})  // CGAL's meshes, when extracted
    if (std::filesystem::exists(std::string(HLR_CORPUS_DIR) + m)) files.push_back(std::string(HLR_CORPUS_DIR) + m);
  for (const std::string& file : files)
    for (const std::string view : {"front", "top", "right", "back", "left", "bottom"}) {
      RenderResult r = render_view(file, view);
      PlotOptions po;
      po.hidden = true;
      Plot p = make_plot(r.drawing, r.camera, po);
      EXPECT_EQ(overlap_length(p), 0) << file << " " << view;
      EXPECT_EQ(p.stats.path_count, p.stats.min_path_count) << file << " " << view;
      PlotOptions raw = po;
      raw.dedup = raw.chain = false;
      Plot q = make_plot(r.drawing, r.camera, raw);
      // Nothing is lost: the raw pieces' length is the clean length plus the duplicates.
      EXPECT_NEAR(q.stats.pen_down_length, p.stats.pen_down_length + p.stats.duplicate_length,
                  1e-9 * q.stats.pen_down_length)
          << file << " " << view;
    }
}

// Perspective: the eye on the line of a cube's edge (seen end-on) and in the planes of two
// faces (their edges fall on one line of the picture); and random stacks of boxes with shared
// faces in axis views. Nothing is drawn twice, nothing is lost.
TEST(PlotCleanUp, PerspectiveAndRandomBoxes) {
  auto check = [](const RenderResult& r, const std::string& what, bool expect_end_on) {
    PlotOptions po;
    po.hidden = true;
    Plot p = make_plot(r.drawing, r.camera, po);
    EXPECT_EQ(overlap_length(p), 0) << what;
    EXPECT_EQ(p.stats.path_count, p.stats.min_path_count) << what;
    if (expect_end_on) {
      EXPECT_GT(p.stats.zero_length, 0u) << what;
    }
    PlotOptions raw = po;
    raw.dedup = raw.chain = false;
    Plot q = make_plot(r.drawing, r.camera, raw);
    EXPECT_NEAR(q.stats.pen_down_length, p.stats.pen_down_length + p.stats.duplicate_length, 1e-9 * q.stats.pen_down_length) << what;
    // Visible wins: the visible layers hold exactly the visible-only drawing's length.
    Plot v = make_plot(r.drawing, r.camera, PlotOptions{});
    double visible = 0;
    for (const PlotLayer& l : p.layers)
      if (l.visible)
        for (const Stroke& s : l.strokes) visible += stroke_length(s);
    EXPECT_NEAR(visible, v.stats.pen_down_length, 1e-9 * visible + 1e-12) << what;
    return p;
  };
  RenderOptions o;
  o.view.eye = Point3(1, 1, 5);
  o.view.target = Point3(0, 0, 0);
  Plot p = check(render_files({kData + "/cube.off"}, o), "cube, eye on an edge's line", true);
  EXPECT_GT(p.stats.overlap_groups, 0u);
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> c(0, 4);
  for (int round = 0; round < 12; ++round) {
    Scene scene;
    for (int b = 0; b < 4; ++b) {
      int x = c(rng), y = c(rng), z = c(rng);
      Polyhedron box = make_box(Point3(x, y, z), Point3(x + 1 + c(rng) % 2, y + 1, z + 1 + c(rng) % 3));
      SceneBody body{"box" + std::to_string(b), "random", std::move(box), identity_transform(), {}, {}, {}};
      scene.bodies.push_back(std::move(body));
    }
    for (const char* v : {"front", "top", "right"}) {
      RenderOptions ro;
      auto sv = standard_view(v, false);
      ro.view.direction = sv->direction;
      ro.view.up = sv->up;
      check(render({scene}, ro), "random boxes round " + std::to_string(round) + " " + v, true);
    }
  }
}

// Pieces that meet end to end on one line of the picture (a row of boxes seen along an axis:
// every edge of the row touches the next at an exact point) are told apart by the filter, not
// by exact tests: the shared end is the same exact point and the other ends lie on opposite
// sides of it. Nothing is drawn twice, nothing is lost, and the exact line tests stay few.
TEST(PlotCleanUp, PiecesMeetingEndToEndNeedNoExactTest) {
  Scene scene;
  for (int b = 0; b < 40; ++b) {  // a row of touching boxes along x, alternately taller
    Polyhedron box = make_box(Point3(b, 0, 0), Point3(b + 1, 1 + b % 2, 1));
    scene.bodies.push_back(SceneBody{"box" + std::to_string(b), "row", std::move(box), identity_transform(), {}, {}, {}});
  }
  for (const char* v : {"front", "top"}) {
    RenderOptions ro;
    auto sv = standard_view(v, false);
    ro.view.direction = sv->direction;
    ro.view.up = sv->up;
    RenderResult r = render({scene}, ro);
    PlotOptions po;
    po.hidden = true;
    Plot p = make_plot(r.drawing, r.camera, po);
    EXPECT_EQ(overlap_length(p), 0) << v;
    PlotOptions raw = po;
    raw.dedup = raw.chain = false;
    Plot q = make_plot(r.drawing, r.camera, raw);
    EXPECT_NEAR(q.stats.pen_down_length, p.stats.pen_down_length + p.stats.duplicate_length, 1e-9 * q.stats.pen_down_length) << v;
    // Without the end-to-end rule every pair of neighbouring collinear pieces (hundreds here)
    // went to an exact test; now only pieces that may overlap in more than a point do.
    EXPECT_LT(p.stats.exact_line_tests, p.stats.pieces / 2) << v << ": " << p.stats.exact_line_tests << " of " << p.stats.pieces;
  }
}

// Visible wins: where a visible and a hidden piece overlap only the visible one is drawn, and
// every visible piece of the raw drawing is covered by visible strokes.
TEST(PlotCleanUp, VisibleLengthIsKept) {
  RenderResult r = render_view(kData + "/demo.yaml", "front");
  PlotOptions po;
  po.hidden = true;
  Plot p = make_plot(r.drawing, r.camera, po);
  PlotOptions vis;
  Plot v = make_plot(r.drawing, r.camera, vis);  // visible only
  double visible_clean = 0, visible_only = 0;
  for (const PlotLayer& l : p.layers)
    if (l.visible)
      for (const Stroke& s : l.strokes) visible_clean += stroke_length(s);
  for (const PlotLayer& l : v.layers)
    for (const Stroke& s : l.strokes) visible_only += stroke_length(s);
  EXPECT_NEAR(visible_clean, visible_only, 1e-9 * visible_only);
}

// A segment's pieces need not meet: a hatch line has a gap where its cap has a hole, a line
// clipped to a region where it leaves it. The clean-up draws exactly the pieces (visible ones
// here), never across a gap: random segments, each with gaps between its pieces (some pieces
// touching, some segments on one line of the picture), against the raw pieces' length.
TEST(PlotCleanUp, PiecesWithGapsBetweenThemStayApart) {
  std::mt19937 rng(41);
  std::uniform_int_distribution<int> c(-6, 6), cut(1, 15);
  const Camera cam = make_orthographic(Vector3(1, 2, 3));
  for (int round = 0; round < 20; ++round) {
    LineDrawing d;
    for (int k = 0; k < 12; ++k) {
      Segment s;
      s.kind = Segment::Kind::Intersection;
      s.line = k % 2 ? LineKind::Hatch : LineKind::Intersection;
      s.body = s.body2 = 0;
      s.face0 = s.face1 = 0;
      Point3 a(c(rng), c(rng), c(rng)), b(c(rng), c(rng), c(rng));
      if (k % 3 == 2) a = d.segments.back().from(), b = d.segments.back().to();  // on one line with the last
      if (a == b) continue;
      s.set_ends(a, b);
      std::set<int> at;  // parameters in sixteenths: pieces between every other pair, some sharing an end
      for (int i = 0; i < 6; ++i) at.insert(cut(rng));
      std::vector<int> t = {0};
      t.insert(t.end(), at.begin(), at.end());
      t.push_back(16);
      std::vector<Piece> pieces;
      for (std::size_t i = 0; i + 1 < t.size(); i += (i % 3 == 0 ? 1 : 2)) pieces.push_back(Piece{Rational(t[i], 16), Rational(t[i + 1], 16), true});
      for (Piece& q : pieces) q.t0.canonicalize(), q.t1.canonicalize();
      s.pieces = std::move(pieces);
      d.segments.push_back(std::move(s));
    }
    PlotOptions po;
    Plot p = make_plot(d, cam, po);
    PlotOptions raw = po;
    raw.dedup = raw.chain = false;
    Plot q = make_plot(d, cam, raw);
    EXPECT_NEAR(q.stats.pen_down_length, p.stats.pen_down_length + p.stats.duplicate_length, 1e-9 * q.stats.pen_down_length) << "round " << round;
    EXPECT_EQ(overlap_length(p), 0) << "round " << round;
  }
}

// Many pieces in one grid cell of the overlap search, on a few shared lines and on lines
// beside them (parallel, a hair apart), with lengths from the whole line down to a few
// nanometres at a scale of thousands: the cell's sweep by distance from its centre must
// still bring every overlapping pair to the exact test. Nothing drawn twice, nothing lost.
TEST(PlotCleanUp, CrowdedCellsFindEveryOverlap) {
  std::mt19937 rng(77);
  std::uniform_int_distribution<int> c(-1000, 1000), side(0, 2);
  std::uniform_int_distribution<std::int64_t> u(0, (std::int64_t{1} << 20) - 1);
  const Camera cam = make_orthographic(Vector3(1, 2, 3));
  for (int round = 0; round < 6; ++round) {
    LineDrawing d;
    auto add = [&](const Point3& a, const Point3& b) {
      if (a == b) return;
      Segment s;
      s.kind = Segment::Kind::Intersection;
      s.line = LineKind::Intersection;
      s.body = s.body2 = 0;
      s.face0 = s.face1 = 0;
      s.set_ends(a, b);
      s.pieces = {Piece{Rational(0), Rational(1), true}};
      d.segments.push_back(std::move(s));
    };
    for (int line = 0; line < 12; ++line) {
      const Point3 a(c(rng), c(rng), c(rng)), b(c(rng), c(rng), c(rng));
      if (a == b) continue;
      add(a, b);  // the whole line, and parts of it: long, short, and 2^-40 of it
      Segment base;
      base.set_ends(a, b);
      for (int k = 0; k < 14; ++k) {
        const int bits = k % 3 == 2 ? 40 : 20;
        const std::int64_t den = std::int64_t{1} << bits, t0 = u(rng) << (bits - 20);
        const std::int64_t t1 = k % 2 ? t0 + 1 + u(rng) % 64 : den - 1 - u(rng) % 8;
        if (t1 > t0) add(base.at(Rational(t0, den)), base.at(Rational(t1, den)));
      }
      for (int k = 0; k < 6; ++k) {  // beside it: the line moved by one unit along an axis
        const int axis = side(rng), by = k % 2 ? 1 : -1;
        const Vector3 step(axis == 0 ? by : 0, axis == 1 ? by : 0, axis == 2 ? by : 0);
        add(base.at(Rational(u(rng), std::int64_t{1} << 20)) + step, b + step);
      }
    }
    PlotOptions po;
    Plot p = make_plot(d, cam, po);
    PlotOptions raw = po;
    raw.dedup = raw.chain = false;
    Plot q = make_plot(d, cam, raw);
    EXPECT_GE(p.stats.overlap_groups, 12u) << "round " << round;
    EXPECT_NEAR(q.stats.pen_down_length, p.stats.pen_down_length + p.stats.duplicate_length, 1e-9 * q.stats.pen_down_length) << "round " << round;
    EXPECT_EQ(overlap_length(p), 0) << "round " << round;
  }
}

// ---------------------------------------------------------------- pages and writers
TEST(PlotOutput, PagesAndScales) {
  EXPECT_EQ(parse_page_size("A4"), (std::array<double, 2>{210, 297}));
  EXPECT_EQ(parse_page_size("a3"), (std::array<double, 2>{297, 420}));
  EXPECT_EQ(parse_page_size("100x50mm"), (std::array<double, 2>{100, 50}));
  EXPECT_THROW(parse_page_size("B7"), std::invalid_argument);
  EXPECT_DOUBLE_EQ(parse_scale("1:2"), 0.5);
  EXPECT_DOUBLE_EQ(parse_scale("5:1"), 5);
  EXPECT_THROW(parse_scale("1:0"), std::invalid_argument);
  RenderResult r = render_view(kData + "/cube.off", "front");
  Plot p = make_plot(r.drawing, r.camera);
  PageOptions o;
  o.page = parse_page_size("A4");
  o.scale = 10;  // the unit cube at 10:1: a 20 mm square (coordinates -1..1)
  Sheet s = layout_single(p, o);
  EXPECT_DOUBLE_EQ(s.width_mm, 210);
  Point2 lo = s.views[0].page({p.bounds[0], p.bounds[1]}), hi = s.views[0].page({p.bounds[2], p.bounds[3]});
  EXPECT_NEAR(hi[0] - lo[0], 10 * (p.bounds[2] - p.bounds[0]), 1e-9);
  EXPECT_NEAR((lo[0] + hi[0]) / 2, 105, 1e-9);  // centred
  EXPECT_NEAR((lo[1] + hi[1]) / 2, 148.5, 1e-9);
  o.landscape = true;
  EXPECT_DOUBLE_EQ(layout_single(p, o).width_mm, 297);
}

struct DxfCounter : DL_CreationAdapter {
  std::set<std::string> layers;
  std::map<std::string, int> polylines;
  int vertices = 0;
  void addLayer(const DL_LayerData& d) override { layers.insert(d.name); }
  void addPolyline(const DL_PolylineData&) override { ++polylines[attributes.getLayer()]; }
  void addVertex(const DL_VertexData&) override { ++vertices; }
};

TEST(PlotOutput, DxfReadsBackWithLayersAndStrokes) {
  RenderResult r = render_files({kData + "/demo.yaml"});
  PlotOptions po;
  po.hidden = true;
  Plot p = make_plot(r.drawing, r.camera, po);
  order_plot(p, {p.bounds[0], p.bounds[3]});
  PageOptions o;
  o.page = parse_page_size("A4");
  o.landscape = true;
  Sheet sheet = layout_single(p, o);
  std::string dxf = sheet_to_dxf(sheet, PlotStyle{});
  auto path = std::filesystem::temp_directory_path() / "hlr_plot_test.dxf";
  std::ofstream(path, std::ios::binary) << dxf;
  DxfCounter c;
  DL_Dxf reader;
  ASSERT_TRUE(reader.in(path.string(), &c));
  int strokes = 0;
  for (const PlotLayer& l : p.layers) {
    EXPECT_TRUE(c.layers.count(l.name())) << l.name();
    EXPECT_EQ(c.polylines[l.name()], static_cast<int>(l.strokes.size())) << l.name();
    strokes += static_cast<int>(l.strokes.size());
  }
  EXPECT_GT(strokes, 10);
  std::filesystem::remove(path);
}

TEST(PlotOutput, SvgHasInkscapeLayersAndOnePathPerStroke) {
  RenderResult r = render_files({kData + "/demo.yaml"});
  PlotOptions po;
  po.hidden = true;
  Plot p = make_plot(r.drawing, r.camera, po);
  Sheet sheet = layout_single(p, PageOptions{});
  std::string svg = sheet_to_svg(sheet, PlotStyle{});
  std::size_t paths = 0, strokes = 0;
  for (std::size_t a = 0; (a = svg.find("<path ", a)) != std::string::npos; ++a) ++paths;
  for (const PlotLayer& l : p.layers) strokes += l.strokes.size();
  EXPECT_EQ(paths, strokes);
  EXPECT_NE(svg.find("inkscape:groupmode=\"layer\" inkscape:label=\"1 visible-silhouette\""), std::string::npos);
  EXPECT_NE(svg.find("id=\"hidden-crease\""), std::string::npos);
  EXPECT_EQ(svg.find("<line"), std::string::npos);
}

}  // namespace
}  // namespace hlr
