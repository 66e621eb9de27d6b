// The user's own 3D lines (io/readers/polyline_file.hpp, io/pipeline/polylines.hpp): the file
// format and its errors, and every piece of random polylines among random boxes (touching,
// interpenetrating; lines through them, along their faces and edges, from their corners)
// checked by the exact ray-casting oracle, orthographic and in perspective, also with the eye
// among the bodies.
#include <gtest/gtest.h>

#include <random>

#include "io/pipeline/render.hpp"
#include "io/readers/input_error.hpp"
#include "io/readers/polyline_file.hpp"
#include "support/ray_oracle.hpp"

using namespace hlr;

namespace {

Point3 P(long x, long y, long z) { return Point3(Rational(x), Rational(y), Rational(z)); }

}  // namespace

TEST(Polylines, FileFormat) {
  const auto l = parse_polylines("# a spiral's start\n0 0 0  1,2,3 1/2 -0.25 7\n\n  4 5 6 7 8 9 # two points\n", "a.txt");
  ASSERT_EQ(l.size(), 2u);
  ASSERT_EQ(l[0].size(), 3u);
  EXPECT_EQ(l[0][2], Point3(Rational(1, 2), Rational(-1, 4), Rational(7)));
  EXPECT_EQ(l[1][1], P(7, 8, 9));
  auto error = [](const std::string& text) {
    try {
      parse_polylines(text, "bad.txt");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("0 0 0 1 1 1\n0 0 0 1 1\n"), "bad.txt:2: 5 numbers: a polyline's points are x y z, three numbers each");
  EXPECT_EQ(error("\n\n1 2 3\n"), "bad.txt:3: a polyline needs at least two points");
  EXPECT_EQ(error("1 2 x 4 5 6\n"), "bad.txt:1: 'x' is not a number (a polyline is x y z x y z ...)");
}

TEST(Polylines, OracleAmongRandomBoxes) {
  std::mt19937 rng(4111);
  std::uniform_int_distribution<long> c(0, 6), len(1, 4), coord(-2, 10), pick(0, 5);
  test::Tally tally;
  long pieces = 0, hidden = 0, visible = 0;
  for (int trial = 0; trial < 24; ++trial) {
    Scene s;
    s.file = "boxes.yaml";
    std::vector<std::array<long, 6>> boxes;
    for (int k = 0; k < 3; ++k) {
      std::array<long, 6> b;
      for (int a = 0; a < 3; ++a) b[a] = c(rng), b[a + 3] = b[a] + len(rng);
      if (k == 1 && trial % 3 == 0) b = {boxes[0][3], boxes[0][1], boxes[0][2], boxes[0][3] + 2, boxes[0][4], boxes[0][5]};  // touching
      boxes.push_back(b);
      s.bodies.push_back(SceneBody{"box" + std::to_string(k),
                                   "boxes.yaml",
                                   make_box(P(b[0], b[1], b[2]), P(b[3], b[4], b[5])),
                                   identity_transform(),
                                   {},
                                   {},
                                   {},
                                   std::nullopt});
    }
    RenderOptions o;
    // Points anywhere, on a box's corner, or on its face planes: lines through, along and into the boxes.
    auto point = [&]() {
      const auto& b = boxes[pick(rng) % 3];
      switch (pick(rng)) {
        case 0:
          return P(b[0], b[1], b[2]);
        case 1:
          return P(b[3], coord(rng), coord(rng));
        case 2:
          return P(coord(rng), b[4], b[2] + 1);
        default:
          return P(coord(rng), coord(rng), coord(rng));
      }
    };
    for (int k = 0; k < 6; ++k) {
      Polyline3 l;
      for (int j = 0; j < 4; ++j) l.push_back(point());
      o.polylines.push_back(std::move(l));
    }
    if (trial % 4 == 3) o.view.eye = P(3, 4, 5);  // among the bodies
    else if (trial % 2) o.view.eye = P(15 + trial, 12, 19);
    else o.view.direction = Vector3(Rational(1 + trial % 3), Rational(2), Rational(3 - trial % 5));
    const RenderResult r = render({s}, o);
    LineDrawing lines;
    for (const Segment& sg : r.drawing.segments)
      if (sg.line == LineKind::Polyline) {
        lines.segments.push_back(sg);
        for (const Piece& p : sg.pieces) ++pieces, hidden += !p.visible, visible += p.visible;
      }
    std::vector<std::vector<test::OraclePlane>> planes;
    for (const SceneBody* b : r.bodies) planes.push_back(test::oracle_planes(b->body));
    test::sample_check(lines, planes, r.camera, tally, "polylines");
  }
  EXPECT_EQ(tally.disagreements, 0);
  EXPECT_GT(tally.samples, 1000);
  EXPECT_GT(hidden, 50);
  EXPECT_GT(visible, 50);
}
