// Lines seen through transparent faces (algorithms/hlr/see_through_lines.*, course notes
// section 41): the refinement of the pieces is exact (named cases by hand), and an independent
// exact oracle agrees on every piece: at random exact points of it, the sight ray toward the
// eye crosses no face (visible), only faces of see-through bodies (through), or a face of an
// opaque body (hidden); every face of the scene with its own planes and point-in-polygon
// (face_oracle.hpp). Scenes: glass in front of opaque, touching and flush, interpenetrating,
// nested, an open glass sheet, the eye close to a face, numbers beyond doubles.
#include "algorithms/hlr/see_through_lines.hpp"

#include <gtest/gtest.h>

#include <random>

#include "algorithms/hlr/face_occluders.hpp"
#include "io/pipeline/render.hpp"
#include "io/readers/scene.hpp"
#include "io/writers/svg_writer.hpp"
#include "support/face_oracle.hpp"
#include "support/numbers.hpp"

using namespace hlr;

namespace {

using hlr::test::Q;
Point3 P(const Rational& x, const Rational& y, const Rational& z) { return Point3(x, y, z); }
Piece piece(const char* t0, const char* t1, bool visible) { return Piece{Q(t0), Q(t1), visible}; }

TEST(SeeThroughLines, RefineMarksHiddenPartsVisibleWithoutTheGlass) {
  // Full: visible [0, 1/4], hidden [1/4, 1]; opaque only: visible [0, 1/2], hidden [1/2, 1].
  auto out = refine_through({piece("0", "1/4", true), piece("1/4", "1", false)},
                            {piece("0", "1/2", true), piece("1/2", "1", false)});
  ASSERT_EQ(out.size(), 3u);
  EXPECT_TRUE(out[0].visible);
  EXPECT_EQ(out[0].t1, Q("1/4"));
  EXPECT_FALSE(out[1].visible);
  EXPECT_TRUE(out[1].through);
  EXPECT_EQ(out[1].t0, Q("1/4"));
  EXPECT_EQ(out[1].t1, Q("1/2"));
  EXPECT_FALSE(out[2].through);
  EXPECT_EQ(out[2].t0, Q("1/2"));
  EXPECT_EQ(out[2].t1, Q("1"));
}

TEST(SeeThroughLines, RefineKeepsHiddenWhereTheOpaqueAloneHides) {
  auto out = refine_through({piece("0", "1", false)}, {piece("0", "1/3", false), piece("1/3", "2/3", true), piece("2/3", "1", false)});
  ASSERT_EQ(out.size(), 3u);
  EXPECT_FALSE(out[0].through);
  EXPECT_TRUE(out[1].through);
  EXPECT_EQ(out[1].t0, Q("1/3"));
  EXPECT_EQ(out[1].t1, Q("2/3"));
  EXPECT_FALSE(out[2].through);
}

TEST(SeeThroughLines, RefineLeavesClippedAndBehindTheEyeAlone) {
  Piece behind = piece("0", "1/2", false);
  behind.behind_eye = true;
  auto out = refine_through({behind, piece("1/2", "1", false)}, {piece("0", "1", true)});
  ASSERT_EQ(out.size(), 2u);
  EXPECT_TRUE(out[0].behind_eye);
  EXPECT_FALSE(out[0].through);
  EXPECT_TRUE(out[1].through);
}

// ---- the oracle

struct Scene3 {
  std::vector<Polyhedron> bodies;
  std::vector<char> see;
};

Polyhedron box(Rational k, int x0, int y0, int z0, int x1, int y1, int z1) {
  return make_box(P(k * x0, k * y0, k * z0), P(k * x1, k * y1, k * z1));
}
Polyhedron sheet(Rational k) {  // an open glass quad standing in x = 5/2
  return Polyhedron({P(k * Q("5/2"), k * -2, k * -1), P(k * Q("5/2"), k * 6, k * -1), P(k * Q("5/2"), k * 6, k * 4),
                     P(k * Q("5/2"), k * -2, k * 4)},
                    {{0, 1, 2, 3}});
}

// 1 visible, 0 through, -1 hidden, 2 not sure (the ray touches an edge or lies in a face plane).
int oracle(const std::vector<test::OracleFace>& faces, const std::vector<char>& see, const Camera& cam, const Point3& x) {
  std::array<Rational, 3> dir;
  for (int k = 0; k < 3; ++k) dir[k] = cam.perspective ? cam.eye[k] - x[k] : cam.direction[k];
  bool opaque = false, glass = false;
  for (const test::OracleFace& f : faces) {
    Rational at = f.a * x[0] + f.b * x[1] + f.c * x[2] + f.d;
    Rational nd = f.a * dir[0] + f.b * dir[1] + f.c * dir[2];
    if (nd == 0) {
      if (at == 0) return 2;  // the ray lies in the face's plane
      continue;
    }
    Rational s = -at / nd;
    if (s <= 0 || (cam.perspective && s >= 1)) continue;  // not between the point and the eye
    int in = test::in_face(f, {x[0] + s * dir[0], x[1] + s * dir[1], x[2] + s * dir[2]});
    if (in == 0) return 2;
    if (in < 0) continue;
    (see[f.body] ? glass : opaque) = true;
  }
  return opaque ? -1 : glass ? 0 : 1;
}

long through_samples = 0;  // oracle answers "through": the check sees the class it checks

long check(const Scene3& sc, const Camera& cam, EdgeSelection edges, unsigned seed) {
  std::vector<const Polyhedron*> ptrs;
  for (const auto& p : sc.bodies) ptrs.push_back(&p);
  LineOptions o;
  o.edges = edges;
  LineDrawing d = face_occluders(ptrs, cam, o);
  mark_see_through(d, ptrs, cam, o, sc.see);
  auto faces = test::oracle_faces(ptrs, PicturePlane(cam));
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> w(1, 999);
  long checked = 0;
  for (const Segment& s : d.segments)
    for (const Piece& p : s.pieces) {
      if (p.behind_eye || p.clipped) continue;
      for (int k = 0; k < 3; ++k) {
        Rational a(w(rng)), t = p.t0 + (p.t1 - p.t0) * a / 1000;
        int want = oracle(faces, sc.see, cam, s.at(t));
        if (want == 2) continue;
        ++checked;
        through_samples += want == 0;
        int got = p.visible ? 1 : p.through ? 0 : -1;
        EXPECT_EQ(got, want) << "segment of body " << s.body << " (" << s.v0 << ", " << s.v1 << ") at t = " << t;
      }
    }
  return checked;
}

std::vector<Camera> cameras(const Rational& k) {
  return {make_orthographic(Vector3(Q("1.2"), Q("-2"), Q("1.5")), Vector3(0, 0, 1)),
          make_orthographic(Vector3(0, -1, 0), Vector3(0, 0, 1)),  // along faces: flush faces seen edge-on
          make_perspective(P(k * 9, k * -7, k * 6), P(k * 2, k * 2, k), Vector3(0, 0, 1)),
          make_perspective(P(k * Q("5/2"), k * Q("-101/100"), k), P(k * 2, k * 2, k), Vector3(0, 0, 1))};  // eye close to a face
}

long run_all(const Rational& k) {
  std::vector<Scene3> scenes;
  // Glass in front of an opaque block and a smaller opaque box (the demo's kind).
  scenes.push_back({{box(k, 0, 2, 0, 3, 4, 2), box(k, 1, -1, 0, 4, 1, 3), box(k, 3, 2, 0, 4, 3, 1)}, {0, 1, 0}});
  // Touching and flush: glass sitting on the block's face (y = 2) and flush with its bottom.
  scenes.push_back({{box(k, 0, 2, 0, 3, 4, 2), box(k, 1, 0, 0, 4, 2, 3)}, {0, 1}});
  // Interpenetrating: the glass pierces the block.
  scenes.push_back({{box(k, 0, 2, 0, 3, 4, 2), box(k, 1, 1, 1, 4, 3, 3)}, {0, 1}});
  // Nested: an opaque box inside a glass box, and glass inside glass.
  scenes.push_back({{box(k, 0, 0, 0, 4, 4, 4), box(k, 1, 1, 1, 3, 3, 3)}, {1, 0}});
  scenes.push_back({{box(k, 0, 0, 0, 4, 4, 4), box(k, 1, 1, 1, 3, 3, 3)}, {1, 1}});
  // An open glass sheet across an opaque box, and an opaque sheet behind glass.
  scenes.push_back({{box(k, 0, 0, 0, 4, 4, 3), sheet(k)}, {0, 1}});
  scenes.push_back({{box(k, 0, 0, 0, 4, 4, 3), sheet(k)}, {1, 0}});
  long n = 0;
  for (const Scene3& sc : scenes)
    for (const Camera& cam : cameras(k))
      for (EdgeSelection e : {EdgeSelection::All, EdgeSelection::Feature}) n += check(sc, cam, e, static_cast<unsigned>(n));
  return n;
}

TEST(SeeThroughLines, AgreesWithRayCastingOnGlassTouchingNestedInterpenetratingAndOpen) {
  through_samples = 0;
  EXPECT_GT(run_all(Rational(1)), 2000);
  EXPECT_GT(through_samples, 500);
}

TEST(SeeThroughLines, AgreesWithRayCastingOnNumbersBeyondDoubles) {
  Rational big = 1;
  for (int i = 0; i < 400; ++i) big *= 10;
  EXPECT_GT(run_all(big), 2000);
  EXPECT_GT(run_all(1 / big), 2000);
}

TEST(SeeThroughLines, NothingIsThroughWithoutGlass) {
  std::vector<Polyhedron> b{box(1, 0, 2, 0, 3, 4, 2), box(1, 1, -1, 0, 4, 1, 3)};
  std::vector<const Polyhedron*> ptrs{&b[0], &b[1]};
  Camera cam = cameras(1)[0];
  LineDrawing d = face_occluders(ptrs, cam, {EdgeSelection::All});
  EXPECT_EQ(mark_see_through(d, ptrs, cam, {EdgeSelection::All}, {0, 0}), 0u);
  for (const Segment& s : d.segments)
    for (const Piece& p : s.pieces) EXPECT_FALSE(p.through);
}

// End to end: the demo's glass shows its back edges and the block behind it as through layers
// in the SVG and pieces in the JSON; --no-through makes them hidden lines again.
TEST(SeeThroughLines, DemoDrawsThroughLayersAndNoThroughHidesThem) {
  Scene s = load_scene(std::string(HLR_DATA_DIR) + "/transparency_demo.yaml");
  RenderOptions o;
  RenderResult r = render({s}, o);
  EXPECT_GT(r.through_pieces, 0u);
  bool glass_back = false, block = false, pyramid = false;
  for (const Segment& seg : r.drawing.segments)
    for (const Piece& p : seg.pieces)
      if (p.through) (seg.body == 2 ? glass_back : seg.body == 0 ? block : pyramid) = true;
  EXPECT_TRUE(glass_back);
  EXPECT_TRUE(block);
  EXPECT_TRUE(pyramid);
  std::string svg = to_svg(r.names, r.drawing, r.camera, SvgOptions{});
  EXPECT_NE(svg.find("<g id=\"through\""), std::string::npos);
  o.through_lines = false;
  RenderResult h = render({load_scene(std::string(HLR_DATA_DIR) + "/transparency_demo.yaml")}, o);
  EXPECT_EQ(h.through_pieces, 0u);
  for (const Segment& seg : h.drawing.segments)
    for (const Piece& p : seg.pieces) EXPECT_FALSE(p.through);
}

}  // namespace
