// Section views on a sheet (io/output/section_views.hpp, ISO 128-40): a section's view looks
// from the removed side and takes its standard view's place; the section line appears in every
// orthographic view that sees the plane edge-on and in no other, at the plane's trace, with its
// wide ends beyond the scene's box, the arrows' tips on the line pointing the way the section
// view looks, and the letters past the arrows.
#include "io/output/section_views.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "algorithms/plot/plot.hpp"
#include "io/pipeline/render.hpp"
#include "io/writers/plot_output.hpp"

using namespace hlr;

namespace {

Scene box_scene() {
  Scene s;
  s.file = "box.yaml";
  s.bodies.push_back(SceneBody{"box", "box.yaml", make_box(Point3(0, 0, 0), Point3(2, 2, 2)), identity_transform(), {}, {}, {}, std::nullopt});
  return s;
}

const PlotLayer* layer(const Plot& p, LineKind k) {
  for (const PlotLayer& l : p.layers)
    if (l.kind == k) return &l;
  return nullptr;
}

}  // namespace

TEST(SectionViews, TheStandardViewThatLooksTheSameWay) {
  const NamedSection a = named_section("A", Plane(1, 0, 0, -1), false);  // keep x <= 1: seen from +x
  EXPECT_EQ(a.standard, "right");
  const ViewRequest v = section_view_request(a, false);
  EXPECT_EQ(*v.direction, Vector3(1, 0, 0));
  EXPECT_EQ(*v.up, Vector3(0, 1, 0));
  EXPECT_EQ(named_section("B", Plane(0, 0, 3, -1), true).standard, "top");    // z up: from +z is the top view
  EXPECT_EQ(named_section("B", Plane(0, 0, -3, 1), false).standard, "back");  // y up: from -z
  const NamedSection c = named_section("C", Plane(1, 1, 0, 0), false);
  EXPECT_EQ(c.standard, "");
  EXPECT_EQ(*section_view_request(c, false).up, Vector3(0, 1, 0));
  EXPECT_EQ(section_view_label(a), "A\u2013A");
  EXPECT_EQ(section_of_view_name(section_view_name("A")), "A");
  EXPECT_EQ(section_of_view_name("front"), "");
  EXPECT_THROW(named_section("", Plane(1, 0, 0, 0), false), std::invalid_argument);
  EXPECT_THROW(named_section("D", Plane(0, 0, 0, 1), false), std::invalid_argument);
}

TEST(SectionViews, TheSectionLineWhereThePlaneIsSeenEdgeOn) {
  const NamedSection a = named_section("A", Plane(1, 0, 0, -1), false);  // x = 1 through the box [0, 2]^3
  std::vector<RenderResult> results(4);
  RenderOptions front, top, iso, section;
  front.view.direction = Vector3(0, 0, 1);
  top.view.direction = Vector3(0, 1, 0), top.view.up = Vector3(0, 0, -1);
  iso.view.direction = Vector3(1, 1, 1);
  section.view = section_view_request(a, false);
  section.section_view = a;
  results[0] = render({box_scene()}, front);
  results[1] = render({box_scene()}, top);
  results[2] = render({box_scene()}, iso);
  results[3] = render({box_scene()}, section);
  ASSERT_TRUE(results[3].section_view);
  EXPECT_EQ(results[3].bodies[0]->body.num_vertices(), 8u);  // the half box [0, 1] x [0, 2]^2
  std::vector<Plot> plots;
  std::vector<const RenderResult*> ptrs;
  for (const RenderResult& r : results) plots.push_back(make_plot(r.drawing, r.camera)), ptrs.push_back(&r);
  std::vector<const Plot*> pp;
  for (const Plot& p : plots) pp.push_back(&p);
  const Sheet sheet = layout_views(pp, {{0, 0}, {0, 1}, {1, 1}, {1, 0}}, {"FRONT", "TOP", "ISO", "A\u2013A"}, PageOptions{});
  add_section_lines(plots, ptrs, sheet);
  for (int i : {2, 3}) {  // the iso view sees the plane obliquely, the section view face-on
    EXPECT_EQ(layer(plots[i], LineKind::SectionMark), nullptr) << i;
    EXPECT_TRUE(plots[i].texts.empty()) << i;
  }
  for (int i : {0, 1}) {
    SCOPED_TRACE(i);
    const double mm = 1 / sheet.views[i].scale, tol = 1e-9;
    const PlotLayer* marks = layer(plots[i], LineKind::SectionMark);
    const PlotLayer* chain = layer(plots[i], LineKind::SectionLine);
    ASSERT_NE(marks, nullptr);
    ASSERT_NE(chain, nullptr);
    // The trace is x = 1 on the page in both views (front: y up; top: -z up), from 0 to 2 or -2 to 0.
    const double lo = i == 0 ? 0 : -2, hi = lo + 2;
    ASSERT_EQ(marks->strokes.size(), 2u + 4u);    // two wide ends, two arrows of shaft and head
    std::vector<std::pair<double, double>> ends;  // the wide ends' extents along the line
    for (int k : {0, 1}) {
      const auto& e = marks->strokes[k].points;
      for (const auto& p : e) EXPECT_NEAR(p[0], 1, tol);
      ends.push_back(std::minmax(e.front()[1], e.back()[1]));
    }
    std::sort(ends.begin(), ends.end());
    EXPECT_NEAR(ends[0].first, lo - 6 * mm, tol);
    EXPECT_NEAR(ends[0].second, lo + 2 * mm, tol);
    EXPECT_NEAR(ends[1].first, hi - 2 * mm, tol);
    EXPECT_NEAR(ends[1].second, hi + 6 * mm, tol);
    // The arrows look toward -x (into what is kept): shafts on the removed side, tips on the line.
    for (int k : {2, 4}) {
      const auto& shaft = marks->strokes[k].points;
      EXPECT_NEAR(shaft[0][0], 1 + 7 * mm, tol);
      EXPECT_NEAR(shaft[1][0], 1 + 3 * mm, tol);
      const auto& head = marks->strokes[k + 1].points;
      EXPECT_TRUE(marks->strokes[k + 1].closed);
      EXPECT_NEAR(head[0][0], 1, tol);
    }
    for (const Stroke& s : chain->strokes)
      for (const auto& p : s.points) {
        EXPECT_NEAR(p[0], 1, tol);
        EXPECT_GE(p[1], lo + 2 * mm - tol);
        EXPECT_LE(p[1], hi - 2 * mm + tol);
      }
    EXPECT_GE(chain->strokes.size(), 3u);  // a long dash, a dot, a long dash at least
    ASSERT_EQ(plots[i].texts.size(), 2u);
    for (const PlotText& t : plots[i].texts) {
      EXPECT_EQ(t.text, "A");
      EXPECT_NEAR(t.at[0], 1 + 10.5 * mm, tol);
    }
  }
}
