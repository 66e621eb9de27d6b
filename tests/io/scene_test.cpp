// Scene files (io/readers/scene.hpp): bodies from meshes, inline lists and boxes; transforms; view.
#include "io/readers/scene.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "algorithms/solids/convexity.hpp"
#include "support/numbers.hpp"

using namespace hlr;

namespace {
const std::string kData = HLR_DATA_DIR;
using hlr::test::Q;

std::string scene_file(const std::string& name, const std::string& text) {
  auto dir = std::filesystem::temp_directory_path() / ("hlr_scene_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::string path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

InputError load_error(const std::string& text, const std::string& name = "s.yaml") {
  try {
    load_scene(scene_file(name, text));
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError("", 0, "");
}
}  // namespace

TEST(Scene, DemoSceneLoadsAsFiveConvexSolids) {
  Scene s = load_scene(kData + "/demo.yaml");
  ASSERT_EQ(s.bodies.size(), 5u);
  EXPECT_EQ(s.view.type, View::Type::Orthographic);
  EXPECT_EQ(s.view.direction, Vector3(Q("1.2"), -2, Q("1.5")));
  EXPECT_TRUE(s.view.up_given);
  EXPECT_EQ(s.view.up, Vector3(0, 0, 1));
  ASSERT_TRUE(s.light);
  for (const auto& b : s.bodies) {
    EXPECT_TRUE(b.body.report().valid_solid()) << b.name;
    EXPECT_TRUE(convexity(b.body).convex()) << b.name;
  }
  // pyramid.off translated by (3.5, 1, 1): its apex (1, 1, 2) is now (4.5, 2, 3).
  EXPECT_EQ(s.bodies[1].name, "pyramid");
  EXPECT_EQ(s.bodies[1].body.vertices()[4], Point3(Q("9/2"), 2, 3));
  EXPECT_EQ(s.bodies[1].source, kData + "/pyramid.off");
  // The wedge, rotated 90 degrees about z (exact) then moved by (2, 0.5, 1): (2,0,0) -> (2, 2.5, 1).
  EXPECT_EQ(s.bodies[3].body.vertices()[1], Point3(2, Q("5/2"), 1));
  EXPECT_TRUE(s.bodies[3].notes.empty());
  // The tilted cube's 30-degree rotation is realised as a rational rotation, and says so.
  ASSERT_EQ(s.bodies[4].notes.size(), 1u);
  EXPECT_NE(s.bodies[4].notes[0].find("30 degrees"), std::string::npos);
}

TEST(Scene, InlineFacesInAnyOrientation) {
  Scene s = load_scene(scene_file("inline.yaml", R"(
bodies:
  - name: tet
    vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    faces: [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]
)"));
  const Polyhedron& p = s.bodies[0].body;
  EXPECT_TRUE(p.report().valid_solid());
  EXPECT_EQ(six_signed_volume(p.vertices(), p.faces()), 1);
  EXPECT_EQ(s.bodies[0].source, s.file);
}

TEST(Scene, TransformsComposeInOrder) {
  Scene s = load_scene(scene_file("t.yaml", R"(
bodies:
  - box: {min: [0, 0, 0], max: [1, 1, 1]}
    transform:
      - scale: 2
      - translate: [1, 0, 0]
      - rotate: {axis: z, degrees: 90}
      - reflect: x
      - matrix: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1/2, 1]]
view: {eye: [10, 10, 10], target: [0, 0, 0], up: [0, 0, 1]}
light: [0, 0, -1]
)"));
  // (1,1,1) -> scale (2,2,2) -> (3,2,2) -> rot z 90: (-2,3,2) -> reflect x: (2,3,2) -> z + 1/2.
  EXPECT_EQ(s.bodies[0].body.vertices()[7], Point3(2, 3, Q("5/2")));
  EXPECT_EQ(s.bodies[0].name, "body 0");
  EXPECT_TRUE(s.bodies[0].body.report().valid_solid());
  // The mirror image keeps its faces counter-clockwise from outside.
  EXPECT_GT(six_signed_volume(s.bodies[0].body.vertices(), s.bodies[0].body.faces()), 0);
  EXPECT_EQ(s.view.type, View::Type::Perspective);
  EXPECT_EQ(s.view.eye, Point3(10, 10, 10));
  EXPECT_EQ(s.view.up, Vector3(0, 0, 1));
}

TEST(Scene, JsonScenesToo) {
  Scene s = load_scene(scene_file("s.json", R"({"bodies": [{"box": {"min": [0, 0, 0], "max": [0.1, 1, 1]}}],
  "view": {"direction": [0, 0, 1]}})"));
  EXPECT_EQ(s.bodies[0].body.vertices()[7].x(), Q("1/10"));
}

TEST(Scene, ErrorsHaveLineNumbers) {
  InputError e = load_error("bodies:\n  - box: {min: [0, 0, 0], max: [1, 1, 1]}\nview:\n  direction: [0, 0, 1]\n  zoom: 3\n");
  EXPECT_EQ(e.line(), 5);
  EXPECT_NE(e.message().find("unknown key 'zoom'"), std::string::npos);
  e = load_error("bodies:\n  - box: {min: [0, 0, 0], max: [1, 1, 1]}\n    transform:\n      - shear: [1, 2]\n");
  EXPECT_EQ(e.line(), 4);
  EXPECT_NE(e.message().find("unknown transform 'shear'"), std::string::npos);
  e = load_error("bodies:\n  - box: {min: [0, 0, 0], max: [1, 1, 1]}\n    box: {min: [0, 0, 0], max: [1, 1, 1]}\n");
  EXPECT_NE(e.message().find("appears twice"), std::string::npos);
  e = load_error("bodies:\n  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n    faces: [[0, 1, 7]]\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_NE(e.message().find("uses vertex 7"), std::string::npos);
  e = load_error("bodies: []\n");
  EXPECT_NE(e.message().find("non-empty"), std::string::npos);
  e = load_error("bodies:\n  - box: {min: [0, 0, 0], max: [1, 1, 1]}\n    transform:\n      - scale: 0\n");
  EXPECT_NE(e.message().find("flattens"), std::string::npos);
  e = load_error("bodies:\n  - box: {min: [0, 0, 0], max: [1, 1, 1]}\n    transform:\n      - rotate: {axis: w, degrees: 3}\n");
  EXPECT_NE(e.message().find("axis must be x, y or z"), std::string::npos);
  e = load_error("bodies:\n  - mesh: [a, b]\n");
  EXPECT_NE(e.message().find("mesh must be text"), std::string::npos);
  e = load_error(std::string(200, '[') + std::string(200, ']'));
  EXPECT_NE(e.message().find("nesting"), std::string::npos);
  e = load_error("bodies:\n  - box: {min: [0, 0, 0], max: [1, 1, 1]}\n    transform:\n      - matrix: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0]]\n");
  EXPECT_NE(e.message().find("singular"), std::string::npos);
}
