// Whitted ray tracing (algorithms/raster/ray_tracing.*; course notes 43-45): total internal
// reflection decided exactly at the critical angle, refracted directions that satisfy Snell's
// law in squared form, a mirror that shows exactly the colour of what it reflects, a glass slab
// that shifts a ray by the amount worked by hand, and the raster pipeline end to end (the four
// algorithms write the same face-id buffer; the camera JSON's exact grid).
#include "algorithms/raster/ray_tracing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "io/pipeline/raster.hpp"
#include "io/pipeline/section.hpp"
#include "support/numbers.hpp"

using namespace hlr;

namespace {

using hlr::test::Q;
Point3 P(double x, double y, double z) { return Point3(rational_from_double(x), rational_from_double(y), rational_from_double(z)); }
Polyhedron quad(const Point3& a, const Point3& b, const Point3& c, const Point3& d) { return Polyhedron({a, b, c, d}, {{0, 1, 2, 3}}); }

Material ambient_only(Rgb c) {
  Material m;
  m.colour = c;
  m.ka = 1, m.kd = 0, m.ks = 0;
  return m;
}

Lighting white_ambient() {
  Lighting l;
  l.ambient = {1, 1, 1};
  return l;
}

TEST(RayTracing, TotalInternalReflectionIsExactAtTheCriticalAngle) {
  // d = (3, 0, -4), n = (0, 0, 1): sin²θ = 9/25; η = 5/3 is exactly the critical ratio.
  const std::array<Rational, 3> d{3, 0, -4}, n{0, 0, 1};
  EXPECT_FALSE(exact_total_internal_reflection(d, n, Q("5/3")));  // grazes: refracted along the surface
  EXPECT_TRUE(exact_total_internal_reflection(d, n, Q("5/3") + Q("1/1000000000000000000000")));
  EXPECT_FALSE(exact_total_internal_reflection(d, n, Q("5/3") - Q("1/1000000000000000000000")));
  EXPECT_FALSE(exact_total_internal_reflection(d, n, Q("2/3")));  // into a denser medium: never
  // The same with non-unit vectors and the normal on the other side.
  EXPECT_FALSE(exact_total_internal_reflection({6, 0, -8}, {0, 0, -7}, Q("5/3")));
}

TEST(RayTracing, RefractedDirectionsSatisfySnellsLawSquared) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int n_refracted = 0, n_total = 0;
  for (int k = 0; k < 2000; ++k) {
    Vec3d d{u(rng), u(rng), u(rng)}, n{u(rng), u(rng), u(rng)};
    double ld = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), ln = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int c = 0; c < 3; ++c) d[c] /= ld, n[c] /= ln;
    double dn = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
    if (dn > 0) n = {-n[0], -n[1], -n[2]}, dn = -dn;
    const double eta = k % 2 ? 1 / 1.5 : 1.5;
    Vec3d t;
    const bool ok = refract(d, n, eta, t);
    const double sin2_i = 1 - dn * dn;
    ASSERT_EQ(ok, eta * eta * sin2_i <= 1) << k;
    if (!ok) {
      ++n_total;
      continue;
    }
    ++n_refracted;
    const double tn = t[0] * n[0] + t[1] * n[1] + t[2] * n[2];
    EXPECT_NEAR(1 - tn * tn, eta * eta * sin2_i, 1e-12);  // sin²θt = η²·sin²θi
    EXPECT_LT(tn, 0);                                      // it goes on through the surface
  }
  EXPECT_GT(n_refracted, 1000);
  EXPECT_GT(n_total, 100);
}

TEST(RayTracing, AMirrorShowsTheColourOfWhatItReflects) {
  // A mirror in z = 0 and a red wall in y = 5 facing the ray: the ray from (0, -5, 1) to the
  // origin reflects to (0, 5, 1).
  std::vector<Polyhedron> b{quad(P(-10, -10, 0), P(10, -10, 0), P(10, 10, 0), P(-10, 10, 0)),
                            quad(P(-10, 5, -10), P(-10, 5, 10), P(10, 5, 10), P(10, 5, -10))};
  Material mirror = ambient_only({0, 0, 0});
  mirror.reflection = 1;
  WhittedScene s({&b[0], &b[1]}, {mirror, ambient_only({1, 0, 0})}, white_ambient(), {3, {1, 1, 1}});
  const double l = std::sqrt(26.0);
  Rgb c = s.trace({0, -5, 1}, {0, 5 / l, -1 / l}, 3);
  EXPECT_NEAR(c[0], 1, 1e-12);
  EXPECT_NEAR(c[1], 0, 1e-12);
  EXPECT_NEAR(c[2], 0, 1e-12);
}

TEST(RayTracing, AGlassSlabShiftsTheRayByHand) {
  // A slab 0 <= z <= 1 of index 3/2, a floor at z = -1: red for x < 2.75, blue beyond. A ray
  // from (0, 0, 2) at 45 degrees: straight it would meet the floor at x = 3 (blue); refracted,
  // sin θt = sin 45° / 1.5, tan θt = 0.5345, it meets the floor at x = 1 + 0.5345 + 1 = 2.5345.
  Polyhedron slab = make_box(P(-10, -10, 0), P(10, 10, 1));
  std::vector<Polyhedron> floor{quad(P(-10, -10, -1), P(2.75, -10, -1), P(2.75, 10, -1), P(-10, 10, -1)),
                                quad(P(2.75, -10, -1), P(10, -10, -1), P(10, 10, -1), P(2.75, 10, -1))};
  Material glass = ambient_only({1, 1, 1});
  glass.transparency = 1, glass.ior = 1.5;
  WhittedScene s({&slab, &floor[0], &floor[1]}, {glass, ambient_only({1, 0, 0}), ambient_only({0, 0, 1})}, white_ambient(),
                 {5, {1, 1, 1}});
  const double h = std::sqrt(0.5);
  Rgb c = s.trace({0, 0, 2}, {h, 0, -h}, 5);
  EXPECT_NEAR(c[0], 1, 1e-12) << "the refracted ray meets the red part";
  EXPECT_NEAR(c[2], 0, 1e-12);
  double t;
  int body, face;
  ASSERT_TRUE(s.hit({0, 0, 2}, {h, 0, -h}, t, body, face));
  EXPECT_EQ(body, 0);
  EXPECT_NEAR(t, std::sqrt(2.0), 1e-12);
}

TEST(RasterPipeline, FourAlgorithmsWriteTheSameIdsAndTheCameraGridIsExact) {
  const std::string scene = std::string(HLR_DATA_DIR) + "/demo.yaml";
  RasterOptions o;
  o.width = 96, o.height = 64;
  std::string ids[4];
  int k = 0;
  for (RasterAlgorithm a : {RasterAlgorithm::ZBuffer, RasterAlgorithm::Scanline, RasterAlgorithm::Warnock, RasterAlgorithm::RayCast}) {
    o.algorithm = a;
    RasterResult r = raster_files({scene}, o);
    ids[k++] = ids_png(r.ids);
    if (a != RasterAlgorithm::ZBuffer) continue;
    // The camera JSON: the centre of sample (i, j) is origin + (i + 1/2)·right + (j + 1/2)·down,
    // and it projects to the grid's exact picture point.
    auto cam = nlohmann::json::parse(raster_camera_json(r));
    auto vec = [&](const char* key) {
      return std::array<Rational, 3>{Q(cam[key][0].get<std::string>().c_str()), Q(cam[key][1].get<std::string>().c_str()),
                                     Q(cam[key][2].get<std::string>().c_str())};
    };
    auto origin = vec("origin"), right = vec("right"), down = vec("down");
    PicturePlane pp(r.render.camera);
    for (auto [i, j] : {std::pair{0, 0}, std::pair{37, 21}, std::pair{95, 63}}) {
      Rational a = Rational(2 * i + 1, 2), b = Rational(2 * j + 1, 2);
      Point3 c(origin[0] + a * right[0] + b * down[0], origin[1] + a * right[1] + b * down[1], origin[2] + a * right[2] + b * down[2]);
      EXPECT_EQ(pp.project(c), r.scene.grid.centre(i, j)) << i << ", " << j;
    }
    EXPECT_EQ(static_cast<int>(r.rgb.size()), 96 * 64 * 3);
  }
  EXPECT_EQ(ids[1], ids[0]);
  EXPECT_EQ(ids[2], ids[0]);
  EXPECT_EQ(ids[3], ids[0]);
}

TEST(RasterPipeline, BadSizesAreClearErrorsAndAnEyeInsideABodySeesItsCap) {
  RasterOptions o;
  o.samples = 17;
  EXPECT_THROW(raster_files({std::string(HLR_DATA_DIR) + "/cube.off"}, o), std::invalid_argument);
  o.samples = 1;
  o.width = o.height = 16;
  o.view.eye = P(0.5, 0.5, 0.5);  // inside the cube: the near plane's cap fills the picture
  const RasterResult r = raster_files({std::string(HLR_DATA_DIR) + "/cube.off"}, o);
  ASSERT_TRUE(r.render.eye_cut);
  ASSERT_GE(r.ids.at(8, 8), 0);
  const std::array<int, 2> cap = r.scene.faces[r.ids.at(8, 8)];
  EXPECT_EQ(r.render.bodies[cap[0]]->section_cap[cap[1]], kEyeCap);
  int seen = 0;  // the cap (a hexagon: the view is diagonal) fills the image fitted to it
  for (int id : r.ids.ids) {
    EXPECT_TRUE(id == r.ids.at(8, 8) || id == -1);
    seen += id >= 0;
  }
  EXPECT_GT(seen, 16 * 16 / 3);
  o.bounces = 1;  // secondary rays would miss what the cut removed
  EXPECT_THROW(raster_files({std::string(HLR_DATA_DIR) + "/cube.off"}, o), std::invalid_argument);
}

}  // namespace

namespace {

// Blinn's perturbed normal (notes 42) worked by hand on the face z = 0: Q_u = x, Q_w = y,
// P = b·sin(2πu/s)·sin(2πw/s). At (0, s/4): P_u = b·2π/s, P_w = 0, so n' ∝ n − P_u·Q_u.
TEST(Texture, BumpMapPerturbsTheNormalAsTheNotesSay) {
  Material m;
  const Vec3d n{0, 0, 1};
  EXPECT_EQ(bumped_normal(m, {0.3, 0.7, 0}, n), n);  // no bump map
  m.bump = 0.05, m.bump_size = 2;
  const double pu = 0.05 * 2 * M_PI / 2;
  Vec3d b = bumped_normal(m, {0, 0.5, 0}, n);
  const double l = std::sqrt(1 + pu * pu);
  EXPECT_NEAR(b[0], -pu / l, 1e-15);
  EXPECT_NEAR(b[1], 0, 1e-15);
  EXPECT_NEAR(b[2], 1 / l, 1e-15);
  Vec3d flat = bumped_normal(m, {0, 0, 0}, n);  // P_u = P_w = 0 at the origin
  EXPECT_NEAR(flat[2], 1, 1e-15);
}

TEST(Texture, CheckerCellsAlternateAcrossTheFace) {
  Material m;
  m.colour = {1, 1, 1}, m.colour2 = {0, 0, 0}, m.checker = 1;
  const Vec3d up{0, 0, 1};
  EXPECT_EQ(surface_colour(m, {0.5, 0.5, -1e-17}, up), m.colour);  // z is across the face: ignored
  EXPECT_EQ(surface_colour(m, {1.5, 0.5, 1e-17}, up), m.colour2);
  EXPECT_EQ(surface_colour(m, {1.5, 1.5, 0}, up), m.colour);
  EXPECT_EQ(surface_colour(m, {-0.5, 0.5, 0}, up), m.colour2);
}

}  // namespace

#include <filesystem>
#include <fstream>

namespace {

TEST(Texture, ImageTexelsAtTheirCentresAndRepeating) {
  TextureImage t;
  t.width = 2, t.height = 2;
  t.rgb = {255, 0, 0, 0, 255, 0,    // top row: red, green
           0, 0, 255, 255, 255, 255};  // bottom row: blue, white
  auto near = [](const Rgb& a, const Rgb& b) { return std::fabs(a[0] - b[0]) + std::fabs(a[1] - b[1]) + std::fabs(a[2] - b[2]) < 1e-12; };
  EXPECT_TRUE(near(t.at(0.25, 0.75), {1, 0, 0}));  // (u, v) = (0, 0) is the bottom-left corner
  EXPECT_TRUE(near(t.at(0.75, 0.75), {0, 1, 0}));
  EXPECT_TRUE(near(t.at(0.25, 0.25), {0, 0, 1}));
  EXPECT_TRUE(near(t.at(1.75, -0.75), {1, 1, 1}));  // repeats
  EXPECT_TRUE(near(t.at(0.5, 0.75), {0.5, 0.5, 0}));  // halfway between red and green
}

// An OBJ square with texture coordinates u = x/4, v = y/4 seen along z, lit by ambient light
// only: every pixel shows the texture at its centre's (u, v).
TEST(Texture, ObjTextureCoordinatesMapTheImageOntoTheFace) {
  const auto dir = std::filesystem::temp_directory_path() / "hlr_texture_test";
  std::filesystem::create_directories(dir);
  std::vector<std::uint8_t> img;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) img.insert(img.end(), {static_cast<std::uint8_t>(60 * i), static_cast<std::uint8_t>(60 * j), 128});
  std::ofstream(dir / "t.png", std::ios::binary) << png_rgb(4, 4, img);
  std::ofstream(dir / "sq.obj") << "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 0 4 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";
  std::ofstream(dir / "s.yaml") << "bodies:\n  - mesh: sq.obj\n    material: {texture: t.png, ka: 1, kd: 0, ks: 0}\n"
                                   "view: {direction: [0, 0, 1], up: [0, 1, 0]}\nlighting: {ambient: [1, 1, 1], lights: []}\n";
  RasterOptions o;
  o.width = 40, o.height = 40;
  TextureImage t;
  t.width = t.height = 4;
  t.rgb = img;
  for (RasterShading sh : {RasterShading::Flat, RasterShading::Phong}) {
    o.shading = sh;
    RasterResult r = raster_files({(dir / "s.yaml").string()}, o);
    int checked = 0;
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 40; ++i) {
        if (r.ids.at(i, j) < 0) continue;
        const double u = r.scene.grid.cx(i) / 4, v = r.scene.grid.cy(j) / 4;
        const Rgb want = t.at(u, v);
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(r.rgb[(static_cast<std::size_t>(j) * 40 + i) * 3 + k], std::lround(want[k] * 255), 1) << i << ", " << j;
        ++checked;
      }
    EXPECT_GT(checked, 1000);
  }
}

}  // namespace
