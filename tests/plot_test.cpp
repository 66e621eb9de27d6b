// The plotting 2D stage (issue 13): exact clean-up (points, end-on edges, overlaps), chaining
// into the fewest strokes, pen order, dashes, pages, and the writers read back.
#include <gtest/gtest.h>
#include <png.h>
#include <zlib.h>

#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "algorithms/plot/dashes.hpp"
#include "algorithms/picture/path_chaining.hpp"
#include "algorithms/plot/pen_order.hpp"
#include "algorithms/plot/plot.hpp"
#include "io/writers/cairo_text.hpp"
#include "io/writers/plot_output.hpp"
#include "io/pipeline/render.hpp"
#include "io/pipeline/standard_views.hpp"
#include "io/writers/svg_writer.hpp"
#include "algorithms/support/parallel.hpp"

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


// A plot of random strokes of `sizes` points, open and closed (pieces of the writers' text
// end at 4096 points), in a visible layer, and the shorter ones scaled down in a hidden one
// (for dashes).
Plot long_stroke_plot(unsigned seed, std::initializer_list<std::size_t> sizes) {
  Plot p;
  PlotLayer vis, hid;
  hid.visible = false;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-50, 50);
  for (std::size_t n : sizes) {
    for (bool closed : {false, true}) {
      Stroke s;
      s.closed = closed && n > 2;
      for (std::size_t i = 0; i < n; ++i) s.points.push_back({u(rng), u(rng)});
      vis.strokes.push_back(s);
      if (n > 4097) continue;
      for (Point2& q : s.points) q = {q[0] / 20, q[1] / 20};  // short dashes' worth
      hid.strokes.push_back(s);
    }
  }
  p.layers = {vis, hid};
  p.bounds = {-50, -50, 50, 50};
  return p;
}

// A writer's text on 1, 2 and 8 threads, which must be the same: the one-thread text.
std::string same_on_all_thread_counts(const std::function<std::string()>& write) {
  std::string first;
  for (unsigned threads : {1u, 2u, 8u}) {
    ThreadLimit limit(threads);
    const std::string text = write();
    if (first.empty()) first = text;
    EXPECT_EQ(text, first) << threads << " threads";
  }
  return first;
}

PlotStyle hidden_cut_into_dashes() {
  PlotStyle style;
  style.hidden_dashed = true;
  style.dashes = DashMode::Geometry;
  return style;
}

// Long strokes are formatted in pieces on all cores (plot_svg.cpp): every path, whatever its
// length (pieces end at 4096 points) and whether closed, must read exactly as formatted point
// by point, with 1, 2 and 8 threads; hidden strokes cut into dashes go through the same code.
TEST(PlotOutput, SvgPathsOfLongStrokesReadPointByPoint) {
  const Plot p = long_stroke_plot(7, {1, 2, 3, 4095, 4096, 4097, 8192, 8193, 20000});
  const PlotLayer& vis = p.layers[0];
  const Sheet sheet = layout_single(p, PageOptions{});
  const SheetView& v = sheet.views.at(0);
  std::string expected;  // the visible layer's paths, point by point
  for (const Stroke& s : vis.strokes) {
    expected += "  <path d=\"M";
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const Point2 q = v.page(s.points[i]);
      if (i > 1) expected += ' ';
      expected += svg_number(q[0]) + ' ' + svg_number(q[1]);
      if (i == 0) expected += 'L';
    }
    expected += std::string(s.closed ? "Z" : "") + "\"/>\n";
  }
  const PlotStyle style = hidden_cut_into_dashes();
  const std::string svg = same_on_all_thread_counts([&] { return sheet_to_svg(sheet, style); });
  const std::size_t at = svg.find("id=\"visible-edge\"");
  ASSERT_NE(at, std::string::npos);
  const std::size_t from = svg.find('\n', at) + 1;
  EXPECT_EQ(svg.substr(from, expected.size()), expected);
  EXPECT_EQ(svg.compare(from + expected.size(), 5, "</g>\n"), 0);
  std::size_t dashes = 0;
  for (std::size_t a = svg.find("id=\"hidden-edge\""); (a = svg.find("<path ", a)) != std::string::npos; ++a) ++dashes;
  EXPECT_GT(dashes, 1000u);
}


// DXF numbers as dxflib writes them ("%.16f" with the trailing zeros cut to one after the
// point): the oracle for the entities made on all cores (plot_dxf.cpp).
std::string dxf_real(double v) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "%.16f", v);
  std::string t = buf;
  const std::size_t dot = t.find('.');
  while (dot != std::string::npos && t.size() > dot + 2 && t.back() == '0') t.pop_back();
  return t;
}

struct DxfStrokes : DL_CreationAdapter {
  std::map<std::string, std::vector<std::vector<Point2>>> strokes;
  std::map<std::string, std::vector<int>> flags;
  std::string layer;
  void addPolyline(const DL_PolylineData& d) override {
    layer = attributes.getLayer();
    strokes[layer].emplace_back();
    flags[layer].push_back(d.flags);
  }
  void addVertex(const DL_VertexData& d) override { strokes[layer].back().push_back({d.x, d.y}); }
};

// The entities are written here, not by dxflib (which flushes its file after every number):
// long strokes (pieces end at 4096 points), closed ones and cut dashes must read back point by
// point, every number in dxflib's format, every handle unique, the same text on 1, 2 and 8
// threads.
TEST(PlotOutput, DxfLongStrokesReadBackPointByPoint) {
  Plot p = long_stroke_plot(11, {1, 2, 3, 4095, 4096, 4097, 9000});
  p.layers[0].strokes.push_back(Stroke{{{0, 0}, {1e-9, -2.5e-17}, {-0.0, 12345.678}}, false});  // tiny, negative zero
  const PlotLayer& vis = p.layers[0];
  const Sheet sheet = layout_single(p, PageOptions{});
  const SheetView& v = sheet.views.at(0);
  const PlotStyle style = hidden_cut_into_dashes();
  const std::string first = same_on_all_thread_counts([&] { return sheet_to_dxf(sheet, style); });
  // Group codes and values, pair by pair: handles unique, the visible layer's x values as
  // dxflib would write them.
  std::istringstream lines(first);
  std::string code, value, layer;
  std::set<std::string> handles;
  std::vector<std::string> xs;
  while (std::getline(lines, code) && std::getline(lines, value)) {
    if (code == "  5" || code == "105") {
      EXPECT_TRUE(handles.insert(value).second) << "handle " << value << " twice";
    }
    if (code == "  8") layer = value;
    if (code == " 10" && layer == "visible-edge") xs.push_back(value);
  }
  std::vector<std::string> want;
  for (const Stroke& s : vis.strokes)
    for (const Point2& q : s.points) want.push_back(dxf_real(v.page(q)[0]));
  EXPECT_EQ(xs, want);
  auto path = std::filesystem::temp_directory_path() / "hlr_plot_long.dxf";
  std::ofstream(path, std::ios::binary) << first;
  DxfStrokes c;
  DL_Dxf reader;
  ASSERT_TRUE(reader.in(path.string(), &c));
  std::filesystem::remove(path);
  ASSERT_EQ(c.strokes["visible-edge"].size(), vis.strokes.size());
  for (std::size_t k = 0; k < vis.strokes.size(); ++k) {
    const auto& got = c.strokes["visible-edge"][k];
    ASSERT_EQ(got.size(), vis.strokes[k].points.size()) << k;
    EXPECT_EQ(c.flags["visible-edge"][k] & 1, vis.strokes[k].closed ? 1 : 0) << k;
    for (std::size_t i = 0; i < got.size(); ++i) {
      const Point2 q = v.page(vis.strokes[k].points[i]);
      ASSERT_NEAR(got[i][0], q[0], 1e-12) << k << " " << i;
      ASSERT_NEAR(got[i][1], sheet.height_mm - q[1], 1e-12) << k << " " << i;
    }
  }
  EXPECT_GT(c.strokes["hidden-edge"].size(), 1000u);  // the dashes
}

// A PDF read back as a reader would: the cross-reference table's offsets, the objects, the
// page's content stream inflated, its operators in order.
struct PdfRead {
  std::map<int, std::string> objects;  // number -> text between "N 0 obj" and "endobj"
  std::string content;                 // the page's content stream, inflated
  std::vector<std::string> layers;     // the optional-content groups' names, in /Order
};

PdfRead read_pdf(const std::string& pdf) {
  PdfRead r;
  EXPECT_EQ(pdf.rfind("%PDF-1.5\n", 0), 0u);
  EXPECT_EQ(pdf.substr(pdf.size() - 6), "%%EOF\n");
  const std::size_t sx = pdf.rfind("startxref\n");
  const std::size_t xref = std::stoul(pdf.substr(sx + 10));
  EXPECT_EQ(pdf.compare(xref, 5, "xref\n"), 0);
  std::istringstream table(pdf.substr(xref + 5));
  int first = -1, count = 0;
  table >> first >> count;
  EXPECT_EQ(first, 0);
  table.ignore(1);
  for (int k = 0; k < count; ++k) {
    std::string entry(20, ' ');
    table.read(entry.data(), 20);
    EXPECT_EQ(entry.substr(17), k == 0 ? "f \n" : "n \n") << k;
    if (k == 0) continue;
    const std::size_t at = std::stoul(entry.substr(0, 10));
    const std::string head = std::to_string(k) + " 0 obj\n";
    EXPECT_EQ(pdf.compare(at, head.size(), head), 0) << "object " << k << " is not at its offset " << at;
    const std::size_t end = pdf.find("\nendobj\n", at);
    r.objects[k] = pdf.substr(at + head.size(), end - at - head.size());
  }
  EXPECT_NE(pdf.find("trailer\n<< /Size " + std::to_string(count) + " /Root 1 0 R"), std::string::npos);
  const std::string& c = r.objects[4];
  const std::size_t length = std::stoul(c.substr(c.find("/Length ") + 8));
  const std::size_t at = c.find("stream\n") + 7;
  EXPECT_EQ(c.compare(at + length, 10, "\nendstream"), 0) << "the stream's /Length";
  z_stream z{};
  EXPECT_EQ(inflateInit(&z), Z_OK);
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(c.data() + at));
  z.avail_in = static_cast<uInt>(length);
  std::vector<char> buf(1 << 16);
  int rc = Z_OK;
  while (rc == Z_OK) {
    z.next_out = reinterpret_cast<Bytef*>(buf.data());
    z.avail_out = static_cast<uInt>(buf.size());
    rc = inflate(&z, Z_NO_FLUSH);
    r.content.append(buf.data(), buf.size() - z.avail_out);
  }
  EXPECT_EQ(rc, Z_STREAM_END) << "the content stream is not one whole zlib stream (checksum included)";
  EXPECT_EQ(z.avail_in, 0u);
  inflateEnd(&z);
  const std::string& catalog = r.objects[1];
  const std::size_t order = catalog.find("/Order [");
  if (order != std::string::npos) {
    std::istringstream refs(catalog.substr(order + 8, catalog.find(']', order) - order - 8));
    int n = 0;
    std::string zero, R;
    while (refs >> n >> zero >> R) {
      const std::string& g = r.objects[n];
      const std::size_t name = g.find("/Name (") + 7;
      r.layers.push_back(g.substr(name, g.find(") >>", name) - name));
    }
  }
  return r;
}

// The strokes of the content's layer `k` (its "/OC /Lk BDC" ... "EMC"): each "x y m", "x y l"
// ..., "h" when closed, "S", as the coordinates' text.
struct PdfStroke {
  std::vector<std::string> xy;  // "x y" per point
  bool closed = false;
};
std::vector<PdfStroke> pdf_layer_strokes(const std::string& content, std::size_t k) {
  const std::string tag = "/OC /L" + std::to_string(k) + " BDC\n";
  const std::size_t from = content.find(tag);
  EXPECT_NE(from, std::string::npos) << tag;
  std::istringstream lines(content.substr(from + tag.size(), content.find("EMC\n", from) - from - tag.size()));
  std::vector<PdfStroke> out;
  PdfStroke s;
  for (std::string line; std::getline(lines, line);) {
    const char op = line.back();
    if (line.size() > 2 && line[line.size() - 2] == ' ' && (op == 'm' || op == 'l')) {
      EXPECT_EQ(op == 'm', s.xy.empty()) << line;
      s.xy.push_back(line.substr(0, line.size() - 2));
    } else if (line == "h") {
      s.closed = true;
    } else if (line == "S") {
      out.push_back(s);
      s = PdfStroke{};
    }
  }
  EXPECT_TRUE(s.xy.empty());
  return out;
}

// A PNG's pixels as grey levels (libpng's simplified reader).
std::vector<std::uint8_t> png_grey(const std::string& png, int& w, int& h) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  EXPECT_TRUE(png_image_begin_read_from_memory(&image, png.data(), png.size()));
  image.format = PNG_FORMAT_GRAY;
  std::vector<std::uint8_t> grey(PNG_IMAGE_SIZE(image));
  EXPECT_TRUE(png_image_finish_read(&image, nullptr, grey.data(), 0, nullptr));
  w = static_cast<int>(image.width), h = static_cast<int>(image.height);
  return grey;
}

// The PNG is drawn in bands of 64 rows on all cores, each stroke cut to the parts that reach
// its band (dashed parts stroked with the dash offset of their arc length): the picture must
// be the one drawn on one surface, up to the arcs' polygon tolerance at the cuts, and the same
// bytes on 1, 2 and 8 threads. Long random strokes (every band cuts them many times), pattern
// dashes, lines seen through, fills.
TEST(PngWriter, BandsDrawAsOneSurface) {
  Plot p = long_stroke_plot(17, {2, 3, 40, 300});
  for (Stroke& s : p.layers[1].strokes)
    for (Point2& q : s.points) q = {q[0] * 20, q[1] * 20};  // hidden strokes across the page too
  PlotLayer through = p.layers[0];
  through.visible = false, through.through = true;
  through.strokes.resize(3);
  p.layers.push_back(through);
  PlotFill fill;
  fill.colour = {0.2, 0.6, 0.9};
  fill.rings = {{{-40, -40}, {40, -30}, {0, 45}}, {{-5, -5}, {5, -5}, {0, 5}}};
  p.fills.push_back(fill);
  PlotStyle style;
  style.hidden_dashed = true;  // pattern dashes
  const Sheet sheet = layout_single(p, PageOptions{});
  int w = 0, h = 0, w1 = 0, h1 = 0;
  const std::string banded = same_on_all_thread_counts([&] { return sheet_to_png(sheet, style, 120); });
  const std::vector<std::uint8_t> a = png_grey(banded, w, h);
  const std::vector<std::uint8_t> b = png_grey(png_in_bands(sheet, style, 120, 1 << 30), w1, h1);
  ASSERT_EQ(w, w1);
  ASSERT_EQ(h, h1);
  ASSERT_GT(h, 640);  // ten bands and more
  // Pixels more than 16 levels apart: the arcs' polygons at the cuts, and dash ends moved by
  // cairo's 1/256-pixel points summed along the whole stroke (the bands start each part's
  // pattern from the exact arc length).
  std::size_t apart = 0, dark = 0;
  int most = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const int d = std::abs(int(a[i]) - int(b[i]));
    apart += d > 16;
    dark += b[i] < 128;
    most = std::max(most, d);
  }
  EXPECT_GT(dark, a.size() / 20);
  EXPECT_LE(most, 64) << apart << " pixels apart";
  EXPECT_LT(apart, dark / 1000) << "most " << most;
}

// The PDF is written here (plot_pdf.cpp), its content made in pieces and deflated in chunks on
// all cores: the file must read back object by object, its stream as one zlib stream, every
// stroke point by point as formatted (1, 2 and 8 threads, the same bytes), its layers those of
// the SVG, and the content over a MiB (several chunks).
TEST(PdfWriter, StrokesReadBackPointByPoint) {
  const Plot p = long_stroke_plot(13, {1, 2, 3, 4095, 4096, 4097, 8192, 8193, 20000, 70000});
  const PlotLayer& vis = p.layers[0];
  const Sheet sheet = layout_single(p, PageOptions{});
  const SheetView& v = sheet.views.at(0);
  const PlotStyle style = hidden_cut_into_dashes();
  const PdfRead r = read_pdf(same_on_all_thread_counts([&] { return sheet_to_pdf(sheet, style); }));
  EXPECT_GT(r.content.size(), std::size_t{3} << 20);
  const std::vector<std::string> names = sheet_layer_names(sheet);
  ASSERT_EQ(r.layers.size(), names.size());
  for (std::size_t n = 0; n < names.size(); ++n) EXPECT_EQ(r.layers[n], std::to_string(n + 1) + " " + names[n]);
  EXPECT_EQ(r.content.rfind("q\n2.834645669291 0 0 -2.834645669291 0 " + svg_number(sheet.height_mm * 72 / 25.4) + " cm\n", 0), 0u);
  const std::vector<PdfStroke> got = pdf_layer_strokes(r.content, 0);
  ASSERT_EQ(got.size(), vis.strokes.size());
  for (std::size_t k = 0; k < got.size(); ++k) {
    ASSERT_EQ(got[k].xy.size(), vis.strokes[k].points.size()) << k;
    EXPECT_EQ(got[k].closed, vis.strokes[k].closed) << k;
    for (std::size_t i = 0; i < got[k].xy.size(); ++i) {
      const Point2 q = v.page(vis.strokes[k].points[i]);
      ASSERT_EQ(got[k].xy[i], svg_number(q[0]) + " " + svg_number(q[1])) << k << " " << i;
    }
  }
  // The hidden layer: the dashes page_strokes cuts, one path each.
  std::vector<char> closed;
  const auto dashes = page_strokes(v, p.layers[1], style, &closed);
  const std::vector<PdfStroke> hidden = pdf_layer_strokes(r.content, 1);
  ASSERT_EQ(hidden.size(), dashes.size());
  for (std::size_t k = 0; k < dashes.size(); ++k) {
    ASSERT_EQ(hidden[k].xy.size(), dashes[k].size()) << k;
    EXPECT_EQ(hidden[k].xy.back(), svg_number(dashes[k].back()[0]) + " " + svg_number(dashes[k].back()[1])) << k;
  }
}

// Pattern dashes, widths, the grey of lines seen through, fills and labels as the SVG has them.
TEST(PdfWriter, StylesFillsAndLabels) {
  Plot p;
  PlotLayer vis, hid, through;
  vis.kind = LineKind::Silhouette;
  vis.strokes.push_back(Stroke{{{0, 0}, {10, 0}, {10, 10}}, true});
  hid.visible = false;
  hid.kind = through.kind = LineKind::Silhouette;
  hid.strokes.push_back(Stroke{{{0, 5}, {10, 5}}, false});
  through.visible = false;
  through.through = true;
  through.strokes.push_back(Stroke{{{5, 0}, {5, 10}}, false});
  p.layers = {vis, through, hid};
  PlotFill fill;
  fill.colour = {1, 0.5, 0};
  fill.rings = {{{0, 0}, {10, 0}, {10, 10}}};
  p.fills.push_back(fill);
  p.bounds = {0, 0, 10, 10};
  Sheet sheet = layout_single(p, PageOptions{});
  sheet.views[0].label = "FRONT";
  sheet.caption = "scale (1:1)";
  const PdfRead r = read_pdf(sheet_to_pdf(sheet, PlotStyle{}));
  ASSERT_EQ(r.layers, (std::vector<std::string>{"surfaces", "1 visible-silhouette", "2 through-silhouette", "3 hidden-silhouette", "labels"}));
  EXPECT_NE(r.content.find("/OC /L0 BDC\n1 j\n1 0.502 0 rg\n1 0.502 0 RG\n0.080 w\n"), std::string::npos) << r.content.substr(0, 300);
  EXPECT_NE(r.content.find(" l\nh\nB*\nEMC\n"), std::string::npos);
  EXPECT_NE(r.content.find("/OC /L1 BDC\n0.500 w\n0 0 0 RG\n[] 0 d\n"), std::string::npos);
  EXPECT_NE(r.content.find("/OC /L2 BDC\n0.250 w\n0.502 0.502 0.502 RG\n[] 0 d\n"), std::string::npos);
  EXPECT_NE(r.content.find("/OC /L3 BDC\n0.250 w\n0 0 0 RG\n[3.000 0.750] 0 d\n"), std::string::npos);
  // Labels: glyph outlines filled, in the labels layer, nothing after it but the end.
  const std::size_t labels = r.content.find("/OC /L4 BDC\n0 g\n");
  ASSERT_NE(labels, std::string::npos);
  const std::string text = r.content.substr(labels);
  EXPECT_GT(std::count(text.begin(), text.end(), '\n'), 100);
  EXPECT_NE(text.find(" c\n"), std::string::npos);  // curves: the glyphs' outlines
  EXPECT_EQ(text.substr(text.size() - 8), "f\nEMC\nQ\n");
  EXPECT_NE(r.objects.at(1).find("/OCProperties"), std::string::npos);
  EXPECT_EQ(r.objects.at(3).find("/Font"), std::string::npos);  // no font: outlines
}

TEST(PdfWriter, LabelOutlinesAnywhereOnThePage) {
  // cairo drops glyphs outside an image surface; the outlines come from an unbounded one.
  for (double x : {0.0, 204.9, 5000.0}) {
    const std::vector<OutlineOp> ops = text_outline("FRONT", x, x / 2, 0.5, 3.5);
    ASSERT_GT(ops.size(), 20u) << x;
    double lo = 1e300, hi = -1e300;
    for (const OutlineOp& o : ops)
      if (o.op != 'h') lo = std::min(lo, o.v[0]), hi = std::max(hi, o.v[0]);
    EXPECT_NEAR((lo + hi) / 2, x, 0.5) << x;  // centred
    EXPECT_GT(hi - lo, 8.0);                    // five letters of 3.5 mm
    EXPECT_LT(hi - lo, 14.0);
  }
}

}  // namespace
}  // namespace hlr
