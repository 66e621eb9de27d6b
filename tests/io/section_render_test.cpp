// Sections through the render pipeline (io/pipeline/section.hpp): the drawing of a scene cut by
// a plane equals, exactly, the drawing of the same scene with the removed parts deleted by hand
// and the caps added as faces (random boxes that touch and interpenetrate, axis planes at
// their faces' heights and between, orthographic and perspective views, lines and surfaces);
// cut lines are their own class; bodies that take no cut stay whole and hide hatch lines (the
// only bodies that can, when the caps face the eye); CGAL's fandisk and
// couplingdown drawn cut equal their cut meshes drawn whole.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <random>

#include "algorithms/picture/picture_plane.hpp"
#include "algorithms/sections/section_cut.hpp"
#include "io/pipeline/render.hpp"
#include "io/pipeline/section.hpp"
#include "io/readers/mesh_reader.hpp"
#include "support/numbers.hpp"

using namespace hlr;

namespace {

Point3 P(long x, long y, long z) { return Point3(Rational(x), Rational(y), Rational(z)); }

struct Box {
  std::array<long, 3> lo, hi;
  bool cut = true;
};

Scene scene_of(const std::vector<Box>& boxes) {
  Scene s;
  s.file = "boxes.yaml";
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Box& b = boxes[i];
    const Point3 lo = P(b.lo[0], b.lo[1], b.lo[2]), hi = P(b.hi[0], b.hi[1], b.hi[2]);
    s.bodies.push_back(SceneBody{"box" + std::to_string(i), "boxes.yaml", make_box(lo, hi), identity_transform(), {}, {}, {}, std::nullopt});
    s.bodies.back().cut = b.cut;
  }
  return s;
}

// The visible drawing as maximal visible intervals on each exact picture line.
using Lines = std::map<std::array<Rational, 3>, std::vector<std::pair<Rational, Rational>>>;
Lines visible_lines(const LineDrawing& d, const Camera& camera) {
  const PicturePlane pp(camera);
  Lines raw;
  for (const Segment& s : d.segments)
    for (const Piece& p : s.pieces) {
      if (!p.visible || p.behind_eye || p.clipped) continue;
      const Exact2 a = pp.project(s.at(p.t0)), b = pp.project(s.at(p.t1));
      Rational A = b[1] - a[1], B = a[0] - b[0];
      if (A == 0 && B == 0) continue;
      const Rational k = A != 0 ? A : B;
      A /= k, B /= k;
      const Rational C = A * a[0] + B * a[1];
      const int axis = B != 0 ? 0 : 1;
      Rational u = a[axis], v = b[axis];
      if (v < u) std::swap(u, v);
      raw[{A, B, C}].push_back({u, v});
    }
  for (auto& [line, iv] : raw) {
    std::sort(iv.begin(), iv.end());
    std::vector<std::pair<Rational, Rational>> merged;
    for (auto& x : iv)
      if (!merged.empty() && x.first <= merged.back().second) merged.back().second = std::max(merged.back().second, x.second);
      else merged.push_back(x);
    iv = std::move(merged);
  }
  return raw;
}

Lines visible_lines(const RenderResult& r) { return visible_lines(r.drawing, r.camera); }

}  // namespace

TEST(SectionRender, EqualsTheSceneCutByHand) {
  std::mt19937 rng(4021);
  std::uniform_int_distribution<long> c(0, 6), len(1, 4), h2(0, 14);
  int compared = 0, with_caps = 0;
  for (int trial = 0; trial < 24; ++trial) {
    std::vector<Box> boxes;
    for (int k = 0; k < 4; ++k) {
      Box b;
      for (int a = 0; a < 3; ++a) b.lo[a] = c(rng), b.hi[a] = b.lo[a] + len(rng);
      boxes.push_back(b);
    }
    const int axis = trial % 3;
    const Rational h = Rational(h2(rng)) / 2;  // at the boxes' faces' heights and between them
    const bool below = trial % 2 == 0;
    // By hand: each box clipped to the kept side (a box wholly on the other side left out).
    std::vector<std::array<Rational, 3>> his;
    std::vector<std::array<Rational, 3>> los;
    for (const Box& b : boxes) {
      std::array<Rational, 3> lo = {Rational(b.lo[0]), Rational(b.lo[1]), Rational(b.lo[2])};
      std::array<Rational, 3> hi = {Rational(b.hi[0]), Rational(b.hi[1]), Rational(b.hi[2])};
      if (below) hi[axis] = std::min(hi[axis], h);
      else lo[axis] = std::max(lo[axis], h);
      if (!(lo[axis] < hi[axis])) continue;
      los.push_back(lo), his.push_back(hi);
    }
    if (los.empty()) continue;
    Scene by_hand;
    by_hand.file = "boxes.yaml";
    for (std::size_t i = 0; i < los.size(); ++i)
      by_hand.bodies.push_back(SceneBody{"box",
                                         "boxes.yaml",
                                         make_box(Point3(los[i][0], los[i][1], los[i][2]), Point3(his[i][0], his[i][1], his[i][2])),
                                         identity_transform(),
                                         {},
                                         {},
                                         {},
                                         std::nullopt});
    RenderOptions o;
    Rational n[3] = {0, 0, 0};
    n[axis] = below ? 1 : -1;
    o.section = {Plane(n[0], n[1], n[2], below ? Rational(-h) : h)};
    const bool perspective = trial % 4 == 3;
    if (perspective) {
      o.view.eye = P(23, 17, 29);
      o.view.target = P(3, 3, 3);
    } else {
      std::uniform_int_distribution<long> d(-3, 3);
      Vector3 v;
      do v = Vector3(d(rng), d(rng), d(rng));
      while (v.is_zero() || v.x() == 0);
      o.view.direction = v;
    }
    RenderOptions plain = o;
    plain.section.clear();
    for (bool surfaces : {false, true}) {
      SCOPED_TRACE("trial " + std::to_string(trial) + (surfaces ? ", surfaces" : ", lines"));
      o.surfaces = plain.surfaces = surfaces && !perspective;
      const RenderResult cut = render({scene_of(boxes)}, o);
      const RenderResult hand = render({by_hand}, plain);
      EXPECT_EQ(cut.bodies.size(), by_hand.bodies.size());
      EXPECT_EQ(visible_lines(cut), visible_lines(hand));
      bool caps = false;
      for (const Segment& s : cut.drawing.segments) caps = caps || s.line == LineKind::Cut;
      with_caps += caps;
      ++compared;
    }
  }
  EXPECT_GT(compared, 30);
  EXPECT_GT(with_caps, 10);
}

TEST(SectionRender, ABodyThatTakesNoCutStaysWhole) {
  std::vector<Box> boxes = {{{0, 0, 0}, {4, 4, 4}, true}, {{1, 1, -1}, {2, 2, 6}, false}};  // a shaft through a block
  RenderOptions o;
  o.section = {Plane(0, 0, 1, -2)};  // keep z <= 2
  o.view.direction = Vector3(1, 2, 3);
  const RenderResult r = render({scene_of(boxes)}, o);
  ASSERT_EQ(r.bodies.size(), 2u);
  EXPECT_FALSE(r.bodies[0]->section_part.empty());
  EXPECT_TRUE(r.bodies[1]->section_part.empty());
  EXPECT_EQ(r.bodies[1]->body.num_vertices(), 8u);
  int cut_lines = 0;
  for (const Segment& s : r.drawing.segments) cut_lines += s.line == LineKind::Cut;
  EXPECT_EQ(cut_lines, 4);  // the block's cap: its square (the shaft meets it in intersection lines)
  int crossing = 0;
  for (const Segment& s : r.drawing.segments) crossing += s.kind == Segment::Kind::Intersection;
  EXPECT_GE(crossing, 4);
}

// A cap seen edge-on (the view's direction in its plane, or the eye in it) shows no area: it
// takes no hatch, and no page point is lifted onto it (the lift divides by the view's
// component along the cap's normal). Views along each axis plane and the eye in the plane, for
// caps of each axis and an oblique one; a view just off the plane hatches.
TEST(SectionRender, CapsSeenEdgeOnTakeNoHatch) {
  const std::vector<Box> boxes = {{{0, 0, 0}, {4, 4, 4}, true}};
  const std::vector<std::pair<Plane, std::vector<Vector3>>> cases = {{Plane(1, 0, 0, -2), {Vector3(0, 1, 0), Vector3(0, 0, 1), Vector3(0, 3, -2)}},
                                                                     {Plane(0, 1, 0, -2), {Vector3(1, 0, 0), Vector3(0, 0, -1), Vector3(5, 0, 1)}},
                                                                     {Plane(0, 0, 1, -2), {Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(-1, 7, 0)}},
                                                                     {Plane(1, 1, 0, -4), {Vector3(1, -1, 0), Vector3(0, 0, 1), Vector3(2, -2, 3)}}};
  for (const auto& [plane, along] : cases) {
    for (const Vector3& v : along) {
      RenderOptions o;
      o.section = {plane};
      o.view.direction = v;
      const RenderResult r = render({scene_of(boxes)}, o);
      EXPECT_TRUE(cap_hatching(r, 10, 0.35, 1).segments.empty()) << plane.a() << " " << plane.b() << " " << plane.c() << " seen along " << v;
    }
    RenderOptions persp;  // the eye in the cap's plane, outside the box
    persp.section = {plane};
    const Point3 eye = plane.c() != 0 ? P(9, 11, 2) : (plane.b() != 0 && plane.a() == 0 ? P(9, 2, 13) : (plane.b() != 0 ? P(-3, 7, 5) : P(2, 9, 13)));
    ASSERT_EQ(plane.value(eye), 0);
    persp.view.eye = eye;
    persp.view.target = P(2, 2, 2);
    EXPECT_TRUE(cap_hatching(render({scene_of(boxes)}, persp), 10, 0.35, 1).segments.empty()) << "eye " << eye;
  }
  RenderOptions off;  // just off the plane x = 2: the cap shows, thin, and is hatched
  off.section = {Plane(1, 0, 0, -2)};
  off.view.direction = Vector3(Rational(1, 20), Rational(1), Rational(0));
  EXPECT_FALSE(cap_hatching(render({scene_of(boxes)}, off), 10, 0.35, 1).segments.empty());
}

// When every cap faces the eye, the hatch pass takes only the bodies the section did not cut as
// occluders (no kept point lies between the eye and such a cap), and none when every body was
// cut (orthographic: every hatch line seen whole). Its visible hatch must equal
// the pass with every body an occluder (forced here by calling the planes a cut-away's, which
// turns the rule off), on random blocks and shafts that take no cut (in front of the caps,
// through them, touching them), caps seen from the removed side and from the kept side,
// orthographic and perspective.
TEST(SectionRender, HatchBehindNoCutBodyOnlyIsHidden) {
  std::mt19937 rng(977);
  std::uniform_int_distribution<long> c(0, 6), len(1, 4), d(-3, 3);
  int hatched = 0, unseen = 0;
  for (int trial = 0; trial < 24; ++trial) {
    std::vector<Box> boxes;
    for (int k = 0; k < 4; ++k) {
      Box b;
      for (int a = 0; a < 3; ++a) b.lo[a] = c(rng), b.hi[a] = b.lo[a] + len(rng);
      b.cut = k != 3 || trial % 2 == 0;  // a shaft, in every other scene
      boxes.push_back(b);
    }
    const int axis = trial % 3;
    RenderOptions o;
    Rational n[3] = {0, 0, 0};
    n[axis] = 1;
    o.section = {Plane(n[0], n[1], n[2], -Rational(c(rng)) - Rational(1, 2))};
    if (trial % 4 == 3) {
      o.view.eye = trial % 8 == 3 ? P(23, 17, 29) : P(-13, -11, -17);
      o.view.target = P(3, 3, 3);
    } else {
      Vector3 v;
      do {
        const long x = d(rng), y = d(rng), z = d(rng);  // (in this order on every compiler)
        v = Vector3(x, y, z);
      } while (v.is_zero() || v[axis] == 0);
      o.view.direction = v;
    }
    SCOPED_TRACE("trial " + std::to_string(trial));
    RenderResult r = render({scene_of(boxes)}, o);
    const LineDrawing fast = cap_hatching(r, 10, 0.35, 1);
    r.section_cut_away = true;
    const LineDrawing all = cap_hatching(r, 10, 0.35, 1);
    // (A hatch line seen whole is one segment; the per-face pass takes it in short chunks.)
    const Lines a = visible_lines(fast, r.camera), b = visible_lines(all, r.camera);
    EXPECT_EQ(a, b);
    unseen += has_caps(r) && all.segments.empty();
    for (const auto& [line, iv] : a) hatched += static_cast<int>(iv.size());
  }
  EXPECT_GT(hatched, 100) << hatched;
  EXPECT_GT(unseen, 2);  // caps seen from the kept side: hidden by their own body
}

TEST(SectionRender, RemovingEveryBodyIsAnError) {
  RenderOptions o;
  o.section = {Plane(0, 0, 1, 10)};  // keep z <= -10
  EXPECT_THROW(render({scene_of({{{0, 0, 0}, {1, 1, 1}, true}})}, o), std::invalid_argument);
}

// CGAL's fandisk and couplingdown: the section's drawing equals the drawing of the mesh that
// cut_solid makes, rendered as a plain mesh (crease 0: every edge between faces that are not
// coplanar, so the cut lines on both sides and no seam inside a face), orthographic and
// perspective.
TEST(SectionRender, CgalMeshesEqualTheirCutMeshes) {
  int meshes = 0;
  for (const char* name : {"fandisk.off", "couplingdown.off"}) {
    const std::string path = std::string(HLR_CORPUS_DIR) + "/" + name;
    if (!std::filesystem::exists(path)) continue;  // scripts/extract_corpus.sh makes them
    ++meshes;
    const Polyhedron body = load_mesh(path);
    std::array<Rational, 3> lo{body.vertices()[0].x(), body.vertices()[0].y(), body.vertices()[0].z()}, hi = lo;
    for (const Point3& v : body.vertices())
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
    const Point3 mid((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
    const std::vector<Plane> planes = {Plane(0, 0, 1, -mid.z()), Plane(1, -2, 3, -(mid.x() - 2 * mid.y() + 3 * mid.z()) - Rational(1, 50))};
    for (const Plane& h : planes)
      for (bool perspective : {false, true}) {
        SCOPED_TRACE(std::string(name) + " plane " + to_string(h) + (perspective ? " perspective" : ""));
        const CutSolid cut = cut_solid(body, {h});
        ASSERT_EQ(cut.state, CutSolid::State::Cut);
        Scene whole, by_hand;
        whole.file = by_hand.file = "mesh.yaml";
        whole.bodies.push_back(SceneBody{"m", "mesh.yaml", body, identity_transform(), {}, {}, {}, std::nullopt});
        by_hand.bodies.push_back(SceneBody{"m", "mesh.yaml", Polyhedron(cut.vertices, cut.faces), identity_transform(), {}, {}, {}, std::nullopt});
        RenderOptions o;
        o.lines.crease_degrees = 0;
        if (perspective) {
          o.view.eye = Point3(hi[0] + (hi[0] - lo[0]), hi[1] + 2 * (hi[1] - lo[1]), hi[2] + 3 * (hi[2] - lo[2]));
          o.view.target = mid;
        } else {
          o.view.direction = Vector3(1, Rational(13, 10), Rational(17, 10));
        }
        RenderOptions plain = o;
        o.section = {h};
        const RenderResult a = render({whole}, o), b = render({by_hand}, plain);
        const Lines la = visible_lines(a), lb = visible_lines(b);
        EXPECT_GT(la.size(), 100u);
        EXPECT_EQ(la, lb);
      }
  }
  if (meshes == 0) GTEST_SKIP() << "CGAL's meshes are not extracted (scripts/extract_corpus.sh)";
}
