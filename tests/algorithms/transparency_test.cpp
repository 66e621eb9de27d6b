// Transparency (algorithms/surfaces/transparency.*): the regions of equal face lists are exact
// (two layers: three regions with their lists and exact areas), and the colours follow the
// notes' models exactly: with ambient light only (ka = 1, kd = ks = 0, white light) a face's
// colour is its material colour, so the expected colours are written down by hand: linear
// I = (1 − τ)·I1 + τ·I2; Kay's τ = τmin + (τmax − τmin)(1 − (1 − |n_z|)^p) on a face facing the
// viewer (τ = τmax) and on one tilted to |n_z| = 3/5; the path-length model τ^(1/|cos φ|).
#include "algorithms/surfaces/transparency.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/hlr/face_occluders.hpp"
#include "io/pipeline/render.hpp"
#include "io/readers/scene.hpp"
#include "support/numbers.hpp"

using namespace hlr;

namespace {

using hlr::test::Q;
Point3 P(const char* x, const char* y, const char* z) { return Point3(Q(x), Q(y), Q(z)); }
Polyhedron quad(const Point3& a, const Point3& b, const Point3& c, const Point3& d) { return Polyhedron({a, b, c, d}, {{0, 1, 2, 3}}); }

// Two quads seen from +z: red [0,2]² at z = 0, the second [1,3] x [0,2] at z = 1 (or tilted).
std::string two_layers(const std::string& front_vertices, const std::string& glass) {
  return "bodies:\n"
         "  - name: red\n    vertices: [[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0]]\n    faces: [[0, 1, 2, 3]]\n"
         "    material: {colour: [1, 0, 0], ka: 1, kd: 0, ks: 0}\n"
         "  - name: glass\n    vertices: " + front_vertices + "\n    faces: [[0, 1, 2, 3]]\n"
         "    material: {colour: [0, 0, 1], ka: 1, kd: 0, ks: 0, " + glass + "}\n"
         "view: {direction: [0, 0, 1], up: [0, 1, 0]}\n"
         "lighting: {ambient: [1, 1, 1], lights: []}\n";
}

// The final colour of the region whose list is `faces` (bodies only: one face each).
std::map<std::vector<int>, Rgb> colours(const std::string& yaml) {
  RenderOptions o;
  o.surfaces = true;
  RenderResult r = render({load_scene_text(yaml, "two_layers.yaml")}, o);
  std::map<std::vector<int>, Rgb> out;
  EXPECT_TRUE(r.transparent);
  if (!r.transparent) return out;
  for (std::size_t k = 0; k < r.transparent->regions.size(); ++k) {
    std::vector<int> bodies;
    for (auto [b, f] : r.transparent->regions[k].faces) bodies.push_back(b);
    out[bodies] = r.transparent_colours[k];
  }
  return out;
}

void expect_rgb(const Rgb& got, const Rgb& want) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1e-12) << "channel " << k;
}

}  // namespace

TEST(Transparency, TwoLayersGiveThreeExactRegions) {
  std::vector<Polyhedron> b{quad(P("0", "0", "0"), P("2", "0", "0"), P("2", "2", "0"), P("0", "2", "0")),
                            quad(P("1", "0", "1"), P("3", "0", "1"), P("3", "2", "1"), P("1", "2", "1"))};
  std::vector<const Polyhedron*> ptrs{&b[0], &b[1]};
  Camera cam = make_orthographic(Vector3(Q("0"), Q("0"), Q("1")), Vector3(Q("0"), Q("1"), Q("0")));
  LineDrawing lines = face_occluders(ptrs, cam, {EdgeSelection::All});
  TransparentPicture tp = transparent_regions(ptrs, cam, lines, {0, 1});
  std::map<std::vector<std::pair<int, int>>, Rational> area;
  for (const TransparentRegion& r : tp.regions) area[r.faces] += r.polygon.area2 / 2;
  std::map<std::vector<std::pair<int, int>>, Rational> want{
      {{{0, 0}}, 2}, {{{0, 0}, {1, 0}}, 2}, {{{1, 0}}, 2}};
  EXPECT_EQ(area, want);
  // Opaque on top: the red quad behind is hidden where they overlap.
  TransparentPicture op = transparent_regions(ptrs, cam, lines, {1, 0});
  std::map<std::vector<std::pair<int, int>>, Rational> area2;
  for (const TransparentRegion& r : op.regions) area2[r.faces] += r.polygon.area2 / 2;
  std::map<std::vector<std::pair<int, int>>, Rational> want2{{{{0, 0}}, 2}, {{{1, 0}}, 4}};
  EXPECT_EQ(area2, want2);
}

TEST(Transparency, LinearModelColoursByHand) {
  auto c = colours(two_layers("[[1, 0, 1], [3, 0, 1], [3, 2, 1], [1, 2, 1]]", "transparency: 0.25"));
  ASSERT_EQ(c.size(), 3u);
  expect_rgb(c[{0}], {1, 0, 0});
  expect_rgb(c[{0, 1}], {0.25, 0, 0.75});      // 3/4 of the glass's blue over 1/4 of the red
  expect_rgb(c[{1}], {0.25, 0.25, 1});         // over white paper
}

TEST(Transparency, KayModelColoursByHand) {
  // Facing the viewer: |n_z| = 1, τ = τmax = 0.6.
  auto c = colours(two_layers("[[1, 0, 1], [3, 0, 1], [3, 2, 1], [1, 2, 1]]",
                              "transparency: 0.6, transparency_model: kay, transparency_min: 0.2, transparency_power: 2"));
  expect_rgb(c[{0, 1}], {0.6, 0, 0.4});
  // Tilted: normal (0, -4, 3)/5 (the quad rises along y by 4/3 per unit), |n_z| = 3/5:
  // τ = 0.2 + 0.4·(1 − (2/5)²) = 0.536.
  auto t = colours(two_layers("[[1, 0, 1], [3, 0, 1], [3, 3/2, 3], [1, 3/2, 3]]",
                              "transparency: 0.6, transparency_model: kay, transparency_min: 0.2, transparency_power: 2"));
  const double tau = 0.2 + 0.4 * (1 - 0.4 * 0.4);
  expect_rgb(t[{0, 1}], {tau, 0, 1 - tau});
}

TEST(Transparency, PathLengthModelColoursByHand) {
  // τ^(1/|cos φ|): facing, τ = 0.5; tilted to |cos φ| = 3/5, τ = 0.5^(5/3).
  auto c = colours(two_layers("[[1, 0, 1], [3, 0, 1], [3, 2, 1], [1, 2, 1]]", "transparency: 0.5, transparency_model: path"));
  expect_rgb(c[{0, 1}], {0.5, 0, 0.5});
  auto t = colours(two_layers("[[1, 0, 1], [3, 0, 1], [3, 3/2, 3], [1, 3/2, 3]]", "transparency: 0.5, transparency_model: path"));
  const double tau = std::pow(0.5, 5.0 / 3.0);
  expect_rgb(t[{0, 1}], {tau, 0, 1 - tau});
}

TEST(Transparency, GlassBoxShowsItsBackFacesAndWhatIsBehind) {
  Scene s = load_scene(std::string(HLR_DATA_DIR) + "/transparency_demo.yaml");
  RenderOptions o;
  o.surfaces = true;
  RenderResult r = render({s}, o);
  ASSERT_TRUE(r.transparent);
  bool back_face = false, block_through = false;
  for (const TransparentRegion& reg : r.transparent->regions) {
    bool glass = false;
    for (auto [b, f] : reg.faces) {
      if (b == 2 && r.drawing.facing[2][f] < 0) back_face = true;
      glass = glass || b == 2;
    }
    if (glass && reg.faces.front().first == 0) block_through = true;
  }
  EXPECT_TRUE(back_face);
  EXPECT_TRUE(block_through);
}

// ---- the exact oracle: along the sight ray through random points of every region, the faces
// met (every face of the scene, its own planes and point-in-polygon: face_oracle.hpp), sorted
// back to front from the nearest opaque one, are the region's list.

#include <random>

#include "support/face_oracle.hpp"

namespace {

long check_picture(const std::vector<const Polyhedron*>& ptrs, const Camera& cam, const TransparentPicture& tp, const std::vector<char>& see,
                   unsigned seed, int samples = 6, std::size_t stride = 1);

long check_regions(const std::vector<Polyhedron>& bodies, const Camera& cam, const std::vector<char>& see, unsigned seed) {
  std::vector<const Polyhedron*> ptrs;
  for (const auto& p : bodies) ptrs.push_back(&p);
  LineDrawing lines = face_occluders(ptrs, cam, {EdgeSelection::All});
  return check_picture(ptrs, cam, transparent_regions(ptrs, cam, lines, see), see, seed);
}

// Every `stride`-th region of the picture against the sight rays through `samples` random points.
long check_picture(const std::vector<const Polyhedron*>& ptrs, const Camera& cam, const TransparentPicture& tp, const std::vector<char>& see,
                   unsigned seed, int samples, std::size_t stride) {
  PicturePlane pp(cam);
  auto faces = test::oracle_faces(ptrs, pp);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> w(1, 997);
  long checked = 0;
  const Vector3 &r = pp.r(), &u = pp.u(), &d = pp.d();
  const Rational rr = dot(r, r), uu = dot(u, u), dd = dot(d, d);
  for (std::size_t k = 0; k < tp.regions.size(); k += stride)
    for (int s = 0; s < samples; ++s) {
      const TransparentRegion& reg = tp.regions[k];
      Rational sx = 0, sy = 0, sw = 0;
      for (const Exact2& c : reg.polygon.outer_2d) {
        Rational k(w(rng));
        sx += k * c[0], sy += k * c[1], sw += k;
      }
      Exact2 q{sx / sw, sy / sw};
      if (test::in_rings(reg.polygon.outer_2d, reg.polygon.holes_2d, q) <= 0) continue;
      // Every face the sight ray through q meets, far to near.
      const std::vector<test::SightHit> hits = test::sight_hits(faces, cam, pp, q);
      bool unsure = false;
      for (std::size_t i = 0; i < hits.size(); ++i) unsure = unsure || hits[i].in == 0 || (i && hits[i].nearness == hits[i - 1].nearness);
      if (unsure) continue;
      std::vector<std::pair<int, int>> want;
      for (const test::SightHit& h : hits) {
        const test::OracleFace& f = faces[h.id];
        if (!see[f.body]) want.clear();
        want.emplace_back(f.body, f.face);
      }
      ++checked;
      EXPECT_EQ(reg.faces, want) << "region point (" << q[0] << ", " << q[1] << ")";
    }
  return checked;
}

}  // namespace

TEST(Transparency, RegionsAgreeWithRayCasting) {
  std::vector<Polyhedron> b{make_box(P("0", "2", "0"), P("3", "4", "2")), make_box(P("1", "-1/2", "0"), P("9/2", "3/2", "5/2")),
                            make_box(P("2", "0", "1"), P("5/2", "3", "3")),
                            quad(P("-1", "-1", "-1/2"), P("6", "-1", "-1/2"), P("6", "5", "-1/2"), P("-1", "5", "-1/2"))};
  long n = 0;
  for (const Camera& cam : {make_orthographic(Vector3(Q("1.2"), Q("-2"), Q("1.5")), Vector3(Q("0"), Q("0"), Q("1"))),
                            make_orthographic(Vector3(Q("0"), Q("0"), Q("1")), Vector3(Q("0"), Q("1"), Q("0"))),
                            make_perspective(P("9", "-7", "6"), P("2", "2", "1"), Vector3(Q("0"), Q("0"), Q("1")))})
    for (const std::vector<char>& see : {std::vector<char>{0, 1, 0, 0}, std::vector<char>{0, 1, 1, 0}, std::vector<char>{1, 1, 1, 1}})
      n += check_regions(b, cam, see, static_cast<unsigned>(n));
  EXPECT_GT(n, 100);
}

// Through the render pipeline, as `hlr render --surfaces` runs it: every see-through body is
// see-through. Two glass unit boxes one behind the other, seen along z: one region, and the
// sight line meets four faces, back to front.
TEST(Transparency, TwoGlassBoxesInARowShowFourFacesInOrder) {
  const std::string yaml =
      "bodies:\n"
      "  - {name: far, box: {min: [0, 0, 0], max: [1, 1, 1]}, material: {transparency: 0.5}}\n"
      "  - {name: near, box: {min: [0, 0, 2], max: [1, 1, 3]}, material: {transparency: 0.5}}\n"
      "view: {direction: [0, 0, 1], up: [0, 1, 0]}\n";
  RenderOptions o;
  o.surfaces = true;
  RenderResult r = render({load_scene_text(yaml, "glass.yaml")}, o);
  ASSERT_TRUE(r.transparent);
  ASSERT_EQ(r.transparent->regions.size(), 1u);
  // Box faces: 4 is z = min, 5 is z = max (make_box); back to front.
  const std::vector<std::pair<int, int>> want = {{0, 4}, {0, 5}, {1, 4}, {1, 5}};
  EXPECT_EQ(r.transparent->regions[0].faces, want);
  EXPECT_EQ(r.transparent->regions[0].polygon.area2, 2);
}

// The glass demo (a glass cube and a glass sphere of 2,000 faces over a floor, perspective):
// its regions list the faces the sight rays meet (it listed one face per region of the sphere).
TEST(Transparency, GlassDemoRegionsAreWhatTheSightRaysMeet) {
  RenderOptions o;
  o.surfaces = true;
  RenderResult r = render({load_scene(std::string(HLR_DATA_DIR) + "/glass_demo.yaml")}, o);
  ASSERT_TRUE(r.transparent);
  std::vector<const Polyhedron*> ptrs;
  std::vector<char> see;
  std::size_t longest = 0;
  for (std::size_t b = 0; b < r.bodies.size(); ++b) ptrs.push_back(&r.bodies[b]->body), see.push_back(body_material(r, b).transparency > 0);
  for (const TransparentRegion& reg : r.transparent->regions) longest = std::max(longest, reg.faces.size());
  EXPECT_GE(longest, 3u) << "a sight ray through both sides of the sphere meets its two faces and the floor";
  EXPECT_GT(check_picture(ptrs, r.camera, *r.transparent, see, 5, 1, 5), 500);
}
