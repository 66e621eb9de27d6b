// The method table (io/pipeline/method_table.hpp): every row has its own name, parses back to
// itself, and the pipeline's refusals list exactly the methods the table says can do the job.
#include "io/pipeline/render_methods.hpp"

#include <gtest/gtest.h>

#include <set>

using namespace hlr;

TEST(RenderMethods, EveryRowHasItsNameAndSteps) {
  std::set<std::string> names;
  for (const RenderMethodEntry& m : render_methods()) {
    EXPECT_TRUE(names.insert(m.name).second) << m.name;
    EXPECT_EQ(parse_render_method(m.name), m.method);
    EXPECT_EQ(&method_entry(m.method), &m);
    EXPECT_TRUE(m.draws_lines() || m.makes_polygons()) << m.name << " does nothing";
  }
  EXPECT_EQ(render_methods().front().method, RenderMethod::Faces);  // the default first
  EXPECT_EQ(render_methods().front().name, std::string("faces"));
  try {
    parse_render_method("painter");
    ADD_FAILURE() << "an unknown method was taken";
  } catch (const std::invalid_argument& e) {
    for (const std::string& n : render_method_names()) EXPECT_NE(std::string(e.what()).find(n), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("(got 'painter')"), std::string::npos) << e.what();
  }
}

TEST(RenderMethods, RefusalsNameTheMethodsThatCan) {
  Scene s;
  s.bodies.push_back(SceneBody{"cube", "(test)", make_box(Point3(0, 0, 0), Point3(1, 1, 1)), identity_transform(), {}, {}});
  auto refused = [&](RenderOptions o) {
    std::vector<Scene> scenes{s};
    try {
      render(std::move(scenes), o);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("rendered");
  };
  RenderOptions o;
  o.method = RenderMethod::Roberts;
  o.surfaces = true;
  EXPECT_EQ(refused(o), "--surfaces works with --method faces, weiler-atherton or priority");
  o.method = RenderMethod::Priority;
  o.shadows = true;
  EXPECT_EQ(refused(o), "--shadows works with --method faces");
  // A method without a lines step makes polygons even when not asked for surfaces.
  RenderOptions p;
  p.method = RenderMethod::Priority;
  std::vector<Scene> scenes{s};
  EXPECT_TRUE(render(std::move(scenes), p).priority.has_value());
}
