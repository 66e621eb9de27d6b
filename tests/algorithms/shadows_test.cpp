// Shadows as exact polygons (algorithms/surfaces/shadows.*), checked by an independent exact
// oracle (face_oracle.hpp): random points of every lit and every shadow polygon, taken on the
// face in exact 3D, are cast toward the light (along the direction of a directional light, on
// the open segment to a point light) against every face polygon of the scene in rationals. A
// lit point must reach the light from the side of its face the viewer sees; a shadow point
// must not. Points whose ray grazes a face's border are skipped (a set of no area). Scenes by
// name: boxes on a ground plane, a pyramid on a box, touching and flush bodies, two lights, a
// perspective view, a point light.
#include "algorithms/surfaces/shadows.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <set>
#include <string>

#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/surfaces/light_cube.hpp"
#include "support/face_oracle.hpp"
#include "support/numbers.hpp"

using namespace hlr;
using test::in_face;
using test::oracle_faces;
using test::OracleFace;

namespace {

using hlr::test::Q;
Point3 P(const char* x, const char* y, const char* z) { return Point3(Q(x), Q(y), Q(z)); }
Vector3 V(const char* x, const char* y, const char* z) { return Vector3(Q(x), Q(y), Q(z)); }
Polyhedron box(const char* x0, const char* y0, const char* z0, const char* x1, const char* y1, const char* z1) {
  return make_box(P(x0, y0, z0), P(x1, y1, z1));
}
std::vector<const Polyhedron*> ptrs(const std::vector<Polyhedron>& v) {
  std::vector<const Polyhedron*> out;
  for (const auto& p : v) out.push_back(&p);
  return out;
}
Polyhedron ground(const char* z) {
  return Polyhedron({P("-6", "-6", z), P("12", "-6", z), P("12", "12", z), P("-6", "12", z)}, {{0, 1, 2, 3}});
}
LightPlace directional(const char* x, const char* y, const char* z) { return LightPlace{true, V(x, y, z), Point3()}; }
LightPlace point(const char* x, const char* y, const char* z) { return LightPlace{false, Vector3(), P(x, y, z)}; }

int in_polygon(const VisiblePolygon& p, const Exact2& q) { return test::in_rings(p.outer_2d, p.holes_2d, q); }

enum class Reach { Lit, Dark, Unsure };

// Does the light reach point x of face `self` on the side the viewer sees?
Reach reach(const std::vector<OracleFace>& faces, const OracleFace& self, const Camera& cam, const LightPlace& l,
            const std::array<Rational, 3>& x) {
  auto f = [&](const OracleFace& g, const Rational& px, const Rational& py, const Rational& pz) -> Rational { return g.a * px + g.b * py + g.c * pz + g.d; };
  int viewer = cam.perspective ? sgn(f(self, cam.eye.x(), cam.eye.y(), cam.eye.z()))
                               : sgn(self.a * cam.direction.x() + self.b * cam.direction.y() + self.c * cam.direction.z());
  int light = l.directional ? sgn(self.a * l.toward.x() + self.b * l.toward.y() + self.c * l.toward.z())
                            : sgn(f(self, l.position.x(), l.position.y(), l.position.z()));
  if (light == 0) return Reach::Unsure;  // grazing
  if (light != viewer) return Reach::Dark;
  std::array<Rational, 3> dir;
  for (int k = 0; k < 3; ++k) dir[k] = l.directional ? l.toward[k] : l.position[k] - x[k];
  bool unsure = false;
  for (const OracleFace& g : faces) {
    if (g.id == self.id) continue;
    Rational nd = g.a * dir[0] + g.b * dir[1] + g.c * dir[2];
    if (nd == 0) continue;
    Rational t = -(g.a * x[0] + g.b * x[1] + g.c * x[2] + g.d) / nd;
    if (t < 0 || (!l.directional && t > 1)) continue;
    std::array<Rational, 3> h{x[0] + t * dir[0], x[1] + t * dir[1], x[2] + t * dir[2]};
    int in = in_face(g, h);
    if (in < 0) continue;
    if (t == 0) {  // x on another face's plane (touching bodies): unsure unless that face is beside
      unsure = true;
      continue;
    }
    if (in > 0) return Reach::Dark;
    unsure = true;
  }
  return unsure ? Reach::Unsure : Reach::Lit;
}

struct Tally {
  long lit = 0, dark = 0, skipped = 0;
};

Tally check_shadows(const std::vector<Polyhedron>& bodies, const Camera& cam, const std::vector<LightPlace>& lights, int samples,
                    unsigned seed = 1, Shadows* out = nullptr) {
  auto b = ptrs(bodies);
  LineOptions lo;
  lo.edges = EdgeSelection::All;
  lo.classify_all = true;
  VisibleSurfaces vs = visible_surfaces(b, cam, face_occluders(b, cam, lo));
  Shadows sh = shadows(b, cam, vs, lights);
  PicturePlane pp(cam);
  auto faces = oracle_faces(b, pp);
  std::vector<int> offset;
  for (std::size_t i = 0, n = 0; i < b.size(); n += b[i]->num_faces(), ++i) offset.push_back(static_cast<int>(n));
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> w(1, 997);
  Tally t;
  EXPECT_EQ(sh.faces.size(), vs.faces.size());
  for (const ShadowFace& sf : sh.faces) {
    const OracleFace& self = faces[offset[sf.body] + sf.face];
    // The regions cover the visible part exactly.
    Rational regions = 0;
    for (const ShadowRegion& r : sf.regions) regions += r.polygon.area2;
    EXPECT_EQ(regions, sf.area2);
    for (std::size_t i = 0; i < lights.size(); ++i) {
      Rational split = 0;
      for (int part = 0; part < 2; ++part)
        for (const VisiblePolygon& p : sf.by_light[i][part]) {
          split += p.area2;
          for (int s = 0; s < samples; ++s) {
            std::array<Rational, 3> x{0, 0, 0};
            Rational sum = 0;
            for (const Point3& c : p.outer) {
              Rational k(w(rng));
              for (int j = 0; j < 3; ++j) x[j] += k * c[j];
              sum += k;
            }
            for (auto& c : x) c /= sum;
            if (in_polygon(p, pp.project(Point3(x[0], x[1], x[2]))) <= 0) {
              ++t.skipped;  // outside this (non-convex) polygon, or on its border
              continue;
            }
            Reach r = reach(faces, self, cam, lights[i], x);
            if (r == Reach::Unsure) {
              ++t.skipped;
              continue;
            }
            bool lit = r == Reach::Lit;
            (lit ? t.lit : t.dark)++;
            EXPECT_EQ(lit, part == 0) << "body " << sf.body << " face " << sf.face << " light " << i << " point (" << x[0] << ", "
                                      << x[1] << ", " << x[2] << ")";
          }
        }
      EXPECT_EQ(split, sf.area2) << "lit and shadow of light " << i << " cover the visible part";
    }
  }
  if (out) *out = std::move(sh);
  return t;
}

Camera ortho(const char* x, const char* y, const char* z, const char* up = "0,0,1") {
  Rational u[3];
  std::string t = up;
  for (int k = 0; k < 3; ++k) {
    auto c = t.find(',');
    u[k] = Q(t.substr(0, c).c_str());
    t = c == std::string::npos ? "" : t.substr(c + 1);
  }
  return make_orthographic(V(x, y, z), Vector3(u[0], u[1], u[2]));
}

}  // namespace

TEST(Shadows, BoxesOnAGroundPlane) {
  std::vector<Polyhedron> b{ground("0"), box("0", "0", "0", "2", "2", "2"), box("4", "1", "0", "5", "3", "3")};
  for (const Camera& cam : {ortho("1", "-1.3", "1.7"), ortho("-2", "-1", "3")}) {
    Tally t = check_shadows(b, cam, {directional("1", "2", "3")}, 8);
    EXPECT_GT(t.lit, 20);
    EXPECT_GT(t.dark, 20);
  }
}

TEST(Shadows, GroundShadowOfABoxIsExact) {
  // Light straight above at (1, 1, 1) direction: the unit cube on the ground casts the square
  // [0,1]² moved by (-1, -1) per unit of height, so the ground's shadow is the hexagon between.
  std::vector<Polyhedron> b{ground("0"), box("0", "0", "0", "1", "1", "1")};
  Shadows sh;
  check_shadows(b, ortho("0", "0", "1", "0,1,0"), {directional("1", "1", "1")}, 4, 1, &sh);
  Rational shadow = -1;
  for (const ShadowFace& f : sh.faces)
    if (f.body == 0) shadow = f.shadow_area2 / 2;
  // Seen from above the box hides [0,1]²; the shadow seen on the ground is the hexagon minus it:
  // the union of [0,1]² and [-1,0]² and the two triangles joining them, less [0,1]²: 2.
  EXPECT_EQ(shadow, 2);
}

TEST(Shadows, PyramidOnABoxUnderAPointLight) {
  Polyhedron pyr({P("1", "1", "1"), P("3", "1", "1"), P("3", "3", "1"), P("1", "3", "1"), P("2", "2", "3")},
                 {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
  std::vector<Polyhedron> b{box("0", "0", "0", "4", "4", "1"), pyr};
  Tally t = check_shadows(b, ortho("1", "-1.3", "1.7"), {point("7", "5", "8")}, 10);
  EXPECT_GT(t.lit, 10);
  EXPECT_GT(t.dark, 10);
}

TEST(Shadows, TouchingAndFlushBodies) {
  std::vector<Polyhedron> b{ground("0"), box("0", "0", "0", "4", "4", "1"), box("1", "1", "1", "3", "3", "2"),
                            box("0", "0", "1", "4", "1", "3")};
  Tally t = check_shadows(b, ortho("1", "-1.3", "1.7"), {directional("-1", "-2", "4")}, 8);
  EXPECT_GT(t.lit, 20);
  EXPECT_GT(t.dark, 10);
}

TEST(Shadows, TwoLightsAndAPerspectiveView) {
  std::vector<Polyhedron> b{ground("0"), box("0", "0", "0", "2", "2", "2"), box("3", "0", "0", "4", "3", "1")};
  Camera cam = make_perspective(P("9", "-7", "6"), P("2", "1", "1"), V("0", "0", "1"));
  Shadows sh;
  Tally t = check_shadows(b, cam, {directional("1", "2", "3"), point("-4", "6", "7")}, 8, 3, &sh);
  EXPECT_GT(t.lit, 20);
  EXPECT_GT(t.dark, 20);
  // Some ground is lit by one light only, some by both, some by none.
  std::set<unsigned> masks;
  for (const ShadowFace& f : sh.faces)
    if (f.body == 0)
      for (const ShadowRegion& r : f.regions) masks.insert(r.lights);
  EXPECT_EQ(masks, (std::set<unsigned>{0, 1, 2, 3}));
}

TEST(Shadows, PointLightAmongTheBodiesLightsEveryWay) {
  // No single view from a lamp between two boxes on the ground has every body in front: the six
  // views of a cube around it light both boxes' near sides and the ground, and the boxes cast
  // shadows on the ground both ways. A lamp inside a box is refused.
  std::vector<Polyhedron> b{ground("0"), box("0", "0", "0", "2", "2", "2"), box("4", "0", "0", "6", "2", "2")};
  EXPECT_THROW(light_camera(ptrs(b), point("3", "1", "1")), std::invalid_argument);
  const Camera cam = make_perspective(P("3", "-9", "7"), P("3", "1", "0"));
  Shadows sh;
  Tally t = check_shadows(b, cam, {point("3", "1", "1")}, 8, 3, &sh);
  EXPECT_GT(t.lit, 20);
  EXPECT_GT(t.dark, 20);
  EXPECT_EQ(sh.cube_views.at(0).size(), 6u);
  const auto bp = ptrs(b);
  LineOptions lo;
  lo.edges = EdgeSelection::All;
  lo.classify_all = true;
  const VisibleSurfaces vs = visible_surfaces(bp, cam, face_occluders(bp, cam, lo));
  EXPECT_THROW(shadows(bp, cam, vs, {point("1", "1", "1")}), std::invalid_argument);
}

TEST(Shadows, ALampInThePlaneOfAFaceLeavesThatFaceOutOfItsViews) {
  // The lamp at y = 1 lies in the plane of the first box's face y = 1 (and z = 0 of the ground's):
  // those faces are edge-on from it, hide nothing from it and are in its shadow, so no cube view
  // holds them (with them, a view from the lamp once lifted a region through a face's horizon).
  std::vector<Polyhedron> b{ground("0"), box("0", "-1", "0", "2", "1", "2"), box("4", "0", "0", "6", "2", "2")};
  const Point3 lamp = P("3", "1", "1");
  int faces = 0;
  for (const LightCubeView& v : light_cube(ptrs(b), lamp))
    for (std::size_t k = 0; k < v.parts.size(); ++k)
      for (std::size_t f = 0; f < v.parts[k].num_faces(); ++f) {
        ++faces;
        EXPECT_NE(v.parts[k].planes()[f].value(lamp), 0) << "body " << v.body[k] << " face " << v.face[k][f];
      }
  EXPECT_GT(faces, 12);
  const Camera cam = make_perspective(P("3", "-9", "7"), P("3", "1", "0"));
  Tally t = check_shadows(b, cam, {point("3", "1", "1")}, 8, 5);
  EXPECT_GT(t.lit, 20);
  EXPECT_GT(t.dark, 20);
}

TEST(Shadows, RandomBoxesAndLights) {
  // Random boxes (sixteenths, some touching or interpenetrating) on the ground, a random
  // directional light and a random point light above them, random views.
  std::mt19937 rng(23);
  std::uniform_int_distribution<int> c(0, 48), e(4, 24), d(-6, 6), up(2, 8);
  long lit = 0, dark = 0;
  const int rounds = std::getenv("HLR_SHADOW_ROUNDS") ? std::atoi(std::getenv("HLR_SHADOW_ROUNDS")) : 4;
  for (int round = 0; round < rounds; ++round) {
    std::vector<Polyhedron> b{ground("0")};
    for (int i = 0; i < 4; ++i) {
      int x = c(rng), y = c(rng), z = i == 0 ? 0 : c(rng) / 4;
      b.push_back(make_box(Point3(rational(x, 16), rational(y, 16), rational(z, 16)),
                           Point3(rational(x + e(rng), 16), rational(y + e(rng), 16), rational(z + e(rng), 16))));
    }
    LightPlace sun{true, Vector3(Rational(d(rng)), Rational(d(rng)), Rational(up(rng))), Point3()};
    LightPlace lamp{false, Vector3(), Point3(Rational(d(rng)), Rational(d(rng)), Rational(8 + up(rng)))};
    Camera cam = round % 2 ? make_orthographic(Vector3(Rational(d(rng)) + rational(1, 3), Rational(-7), Rational(up(rng))), Vector3(Rational(0), Rational(0), Rational(1)))
                           : make_perspective(Point3(Rational(9), Rational(-8), Rational(7)), Point3(Rational(2), Rational(2), Rational(0)),
                                              Vector3(Rational(0), Rational(0), Rational(1)));
    Tally t = check_shadows(b, cam, {sun, lamp}, 4, static_cast<unsigned>(round));
    lit += t.lit, dark += t.dark;
  }
  EXPECT_GT(lit, 50);
  EXPECT_GT(dark, 50);
}

TEST(Shadows, PointLightAboveAWideGroundLooksDown) {
  // The ground reaches behind the light's view toward the scene's centre; looking straight
  // down, the light has every vertex in front of it, and the shadows are checked as ever.
  std::vector<Polyhedron> b{ground("0"), box("0", "0", "0", "1", "1", "1")};
  Camera lc = light_camera(ptrs(b), point("6", "6", "2"));
  EXPECT_EQ(lc.target.z(), lc.eye.z() - 1);  // along -z
  Tally t = check_shadows(b, ortho("1", "-1.3", "1.7"), {point("6", "6", "2")}, 10);
  EXPECT_GT(t.lit, 10);
  EXPECT_GT(t.dark, 5);
}
