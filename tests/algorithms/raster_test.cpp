// The image-space algorithms (course notes 29-35): z-buffer, scan-line, Warnock and
// ray casting give the same face at every pixel centre, that face is the one an independent
// exact ray cast finds (every face of the scene, its own planes and point-in-polygon:
// face_oracle.hpp; nearest, then toward the viewer, then the lower face number), and the vector
// route's visible polygons of that face contain the centre. Scenes with the hard places:
// touching and flush boxes, interpenetrating boxes, coplanar overlapping quads, an open surface
// seen from both sides, views along faces (centres exactly on edges), perspective with the eye
// close to a face, and fandisk.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <random>

#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/raster/raster_scene.hpp"
#include "algorithms/raster/ray_casting.hpp"
#include "algorithms/raster/scanline.hpp"
#include "algorithms/raster/warnock.hpp"
#include "algorithms/raster/zbuffer.hpp"
#include "algorithms/surfaces/visible_surfaces.hpp"
#include "io/readers/mesh_reader.hpp"
#include "support/face_oracle.hpp"
#include "support/numbers.hpp"

using namespace hlr;

namespace {

using hlr::test::Q;
Point3 P(const Rational& x, const Rational& y, const Rational& z) { return Point3(x, y, z); }
Polyhedron box(int x0, int y0, int z0, int x1, int y1, int z1) { return make_box(P(x0, y0, z0), P(x1, y1, z1)); }
Polyhedron quad(const Point3& a, const Point3& b, const Point3& c, const Point3& d) { return Polyhedron({a, b, c, d}, {{0, 1, 2, 3}}); }

struct Frames {
  RasterScene scene;
  FaceIdBuffer z, s, w, r;
};

Frames run_all(const std::vector<const Polyhedron*>& bodies, const Camera& cam, int w, int h) {
  LineDrawing lines = face_occluders(bodies, cam, {EdgeSelection::Feature});
  Frames r{raster_scene(bodies, cam, lines, w, h), {}, {}, {}, {}};
  r.z = zbuffer(r.scene);
  r.s = scanline(r.scene);
  r.w = warnock(r.scene);
  r.r = ray_cast(r.scene);
  return r;
}

void expect_same(const Frames& r) {
  std::size_t bad_s = 0, bad_w = 0, bad_r = 0;
  for (std::size_t k = 0; k < r.z.ids.size(); ++k) {
    bad_s += r.s.ids[k] != r.z.ids[k];
    bad_w += r.w.ids[k] != r.z.ids[k];
    bad_r += r.r.ids[k] != r.z.ids[k];
  }
  EXPECT_EQ(bad_s, 0u) << "scan-line differs from the z-buffer";
  EXPECT_EQ(bad_w, 0u) << "Warnock differs from the z-buffer";
  EXPECT_EQ(bad_r, 0u) << "ray casting differs from the z-buffer";
}

// The independent oracle: the face seen at the centre of pixel (i, j).
int oracle_face(const std::vector<test::OracleFace>& faces, const Camera& cam, const PicturePlane& pp, const Exact2& q) {
  const test::SightRay ray = test::sight_ray(cam, pp, q);
  const std::array<Rational, 3> &base = ray.base, &dir = ray.dir;
  int best = -1, best_rank = 0;
  Rational best_near;
  for (const test::OracleFace& f : faces) {
    Rational nd = f.a * dir[0] + f.b * dir[1] + f.c * dir[2];
    if (nd == 0) continue;
    Rational t = -(f.a * base[0] + f.b * base[1] + f.c * base[2] + f.d) / nd;
    if (cam.perspective && t <= 0) continue;
    if (test::in_face(f, {base[0] + t * dir[0], base[1] + t * dir[1], base[2] + t * dir[2]}) < 0) continue;
    Rational nearness = cam.perspective ? Rational(-t) : t;
    // Toward the viewer: the face's normal against the ray's direction back to the viewer.
    Rational toward = cam.perspective ? -(f.a * dir[0] + f.b * dir[1] + f.c * dir[2]) : nd;
    int rank = toward > 0 ? 0 : 1;
    if (best < 0 || nearness > best_near || (nearness == best_near && (rank < best_rank || (rank == best_rank && f.id < best)))) {
      best = f.id, best_near = nearness, best_rank = rank;
    }
  }
  return best;
}

long check_oracle(const std::vector<const Polyhedron*>& bodies, const Camera& cam, const Frames& r, int stride) {
  PicturePlane pp(cam);
  auto faces = test::oracle_faces(bodies, pp);
  long checked = 0;
  for (int j = 0; j < r.z.height; j += stride)
    for (int i = 0; i < r.z.width; i += stride) {
      int want = oracle_face(faces, cam, pp, r.scene.grid.centre(i, j));
      ++checked;
      if (r.z.at(i, j) != want) {
        ADD_FAILURE() << "pixel (" << i << ", " << j << "): face " << r.z.at(i, j) << ", the oracle sees " << want;
        return checked;
      }
    }
  return checked;
}

// The vector route's visible polygons of the face seen at a centre contain it (closed).
long check_vector(const std::vector<const Polyhedron*>& bodies, const Camera& cam, const Frames& r, int stride) {
  LineDrawing all = face_occluders(bodies, cam, {EdgeSelection::All, 30, true, true});
  VisibleSurfaces vs = visible_surfaces(bodies, cam, all);
  std::map<std::pair<int, int>, const VisibleFace*> of;
  for (const VisibleFace& f : vs.faces) of[{f.body, f.face}] = &f;
  long checked = 0;
  for (int j = 0; j < r.z.height; j += stride)
    for (int i = 0; i < r.z.width; i += stride) {
      int id = r.z.at(i, j);
      if (id < 0) continue;
      auto [b, f] = r.scene.faces[id];
      auto it = of.find({b, f});
      if (it == of.end()) {
        ADD_FAILURE() << "face (" << b << ", " << f << ") seen at pixel (" << i << ", " << j << ") has no visible polygon";
        return checked;
      }
      Exact2 q = r.scene.grid.centre(i, j);
      bool in = false;
      for (const VisiblePolygon& p : it->second->polygons) in = in || test::in_rings(p.outer_2d, p.holes_2d, q) >= 0;
      ++checked;
      if (!in) {
        ADD_FAILURE() << "pixel (" << i << ", " << j << ") of face (" << b << ", " << f << ") outside its visible polygons";
        return checked;
      }
    }
  return checked;
}

std::vector<Camera> cameras() {
  return {make_orthographic(Vector3(Q("1.2"), Q("-2"), Q("1.5")), Vector3(0, 0, 1)),
          make_orthographic(Vector3(0, -1, 0), Vector3(0, 0, 1)),  // along faces: centres on edges
          make_orthographic(Vector3(1, -1, 1), Vector3(0, 0, 1)),
          make_perspective(P(9, -7, 6), P(2, 2, 1), Vector3(0, 0, 1)),
          make_perspective(P(Q("5/2"), Q("-101/100"), 1), P(2, 2, 1), Vector3(0, 0, 1))};  // close to a face
}

bool all_in_front(const std::vector<const Polyhedron*>& bodies, const Camera& cam) {
  for (const Polyhedron* p : bodies)
    for (const Point3& v : p->vertices())
      if (cam.perspective && cam.in_front(v) != Sign::Positive) return false;
  return true;
}

// `scale`: the scene's coordinates are the cameras' times this (perspective eyes and targets
// scaled with them).
void check_scene(const std::vector<Polyhedron>& b, int size = 48, const Rational& scale = 1) {
  std::vector<const Polyhedron*> ptrs;
  for (const auto& p : b) ptrs.push_back(&p);
  for (Camera cam : cameras()) {
    if (cam.perspective) {
      cam.eye = P(cam.eye.x() * scale, cam.eye.y() * scale, cam.eye.z() * scale);
      cam.target = P(cam.target.x() * scale, cam.target.y() * scale, cam.target.z() * scale);
    }
    if (!all_in_front(ptrs, cam)) continue;
    Frames r = run_all(ptrs, cam, size, size * 3 / 4);
    expect_same(r);
    EXPECT_GT(check_oracle(ptrs, cam, r, 1), 0);
    check_vector(ptrs, cam, r, 1);
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(Raster, GridCentresAreExactDyadicPoints) {
  std::vector<Polyhedron> b{box(0, 0, 0, 3, 2, 1)};
  std::vector<const Polyhedron*> ptrs{&b[0]};
  Camera cam = make_orthographic(Vector3(0, 0, 1), Vector3(0, 1, 0));
  RasterScene s = raster_scene(ptrs, cam, face_occluders(ptrs, cam), 300, 200);
  const RasterGrid& g = s.grid;
  EXPECT_EQ(g.centre(0, 0)[0], g.x0 + g.xstep / 2);
  EXPECT_EQ(g.centre(7, 5)[1], g.y1 - Rational(11, 2) * g.ystep);
  EXPECT_EQ(Rational(g.dxstep), g.xstep);
  for (const Rational& step : {g.xstep, g.ystep}) {
    mpz_class den = step.get_den();
    EXPECT_EQ(den & (den - 1), 0) << "the step is dyadic";
  }
  // Square pixels in true lengths although the picture axes differ in length.
  Camera slant = make_orthographic(Vector3(Q("1.2"), Q("-2"), Q("1.5")), Vector3(0, 0, 1));
  RasterScene t = raster_scene(ptrs, slant, face_occluders(ptrs, slant), 300, 200);
  PicturePlane pp(slant);
  const double wx = t.grid.dxstep / std::sqrt(to_double(dot(pp.r(), pp.r()))), wy = t.grid.dystep / std::sqrt(to_double(dot(pp.u(), pp.u())));
  EXPECT_NE(dot(pp.r(), pp.r()), dot(pp.u(), pp.u()));
  EXPECT_NEAR(wx / wy, 1.0, 1e-5);
}

TEST(Raster, TouchingFlushAndInterpenetratingBoxes) {
  check_scene({box(0, 2, 0, 3, 4, 2), box(1, 0, 0, 4, 2, 3), box(3, 2, 0, 4, 3, 1)});  // touching, flush
  check_scene({box(0, 2, 0, 3, 4, 2), box(1, 1, 1, 4, 3, 3)});                         // interpenetrating
}

TEST(Raster, CoplanarOverlappingQuadsAndAnOpenSurface) {
  check_scene({quad(P(0, 0, 0), P(3, 0, 0), P(3, 3, 0), P(0, 3, 0)), quad(P(1, 1, 0), P(4, 1, 0), P(4, 4, 0), P(1, 4, 0)),
               box(1, 1, 0, 2, 2, 2)});
  check_scene({quad(P(Q("5/2"), -2, -1), P(Q("5/2"), 6, -1), P(Q("5/2"), 6, 4), P(Q("5/2"), -2, 4)), box(0, 0, 0, 4, 4, 3)});
}

// Every face as a fan of triangles: the raster scene's triangle route (interval filters on
// the vertices' picture points, the depth from the corners, no face planes).
Polyhedron fanned(const Polyhedron& p) {
  std::vector<Face> faces;
  for (const Face& f : p.faces())
    for (std::size_t k = 1; k + 1 < f.size(); ++k) faces.push_back({f[0], f[k], f[k + 1]});
  return Polyhedron(p.vertices(), faces);
}

std::vector<Polyhedron> fanned(const std::vector<Polyhedron>& b) {
  std::vector<Polyhedron> out;
  for (const Polyhedron& p : b) out.push_back(fanned(p));
  return out;
}

std::vector<Polyhedron> scaled(const std::vector<Polyhedron>& b, const Rational& k) {
  std::vector<Polyhedron> out;
  for (const Polyhedron& p : b) {
    std::vector<Point3> v;
    for (const Point3& x : p.vertices()) v.push_back(P(x.x() * k, x.y() * k, x.z() * k));
    out.push_back(Polyhedron(v, p.faces()));
  }
  return out;
}

std::vector<std::vector<Polyhedron>> hard_scenes() {
  return {{box(0, 2, 0, 3, 4, 2), box(1, 0, 0, 4, 2, 3), box(3, 2, 0, 4, 3, 1)},  // touching, flush
          {box(0, 2, 0, 3, 4, 2), box(1, 1, 1, 4, 3, 3)},                         // interpenetrating
          {quad(P(Q("5/2"), -2, -1), P(Q("5/2"), 6, -1), P(Q("5/2"), 6, 4), P(Q("5/2"), -2, 4)), box(0, 0, 0, 4, 4, 3)}};
}

TEST(Raster, TriangleMeshesTakeTheFilteredRouteAndAgreeWithTheOracle) {
  for (const auto& scene : hard_scenes()) check_scene(fanned(scene));
  // Triangles and quads in one scene: one body of each kind.
  check_scene({fanned(box(0, 2, 0, 3, 4, 2)), box(1, 1, 1, 4, 3, 3)});
}

TEST(Raster, TwinBodiesTieInDepthAtEveryCentre) {
  // Coincident faces: every covered centre is a depth tie, decided by the exact depths (kept
  // per face) and the rule (toward the viewer, then the lower face number).
  check_scene({box(0, 0, 0, 3, 2, 2), box(0, 0, 0, 3, 2, 2)});
  check_scene({fanned(box(0, 0, 0, 3, 2, 2)), fanned(box(0, 0, 0, 3, 2, 2))});
  const std::vector<Polyhedron> twins{fanned(box(0, 0, 0, 3, 2, 2)), fanned(box(0, 0, 0, 3, 2, 2))};
  std::vector<const Polyhedron*> ptrs{&twins[0], &twins[1]};
  Frames r = run_all(ptrs, cameras()[0], 24, 18);
  EXPECT_GT(r.scene.counters.depth_exact.load(), 50u);
  for (std::int32_t id : r.z.ids) EXPECT_LT(id, static_cast<std::int32_t>(twins[0].num_faces())) << "the first body's face wins every tie";
}

TEST(Raster, RandomTrianglesAgreeWithTheOracleWithTheEyeCloseAndAlongFaces) {
  // Random triangles (coordinates k/8 in [0, 4]³, a third of them in the plane z = 2, so
  // coplanar overlaps, shared planes and piercing), one open body and one body per triangle,
  // seen by the standard cameras, along the z axis (the coplanar ones edge-on) and from an eye
  // half a unit below the lowest ones.
  std::mt19937 rng(17);
  auto c = [&] { return Rational(static_cast<long>(rng() % 33), 8); };
  for (int round = 0; round < 2; ++round) {
    std::vector<Point3> v;
    std::vector<Face> f;
    for (int t = 0; t < 24; ++t) {
      const bool flat = t % 3 == 0;
      for (int k = 0; k < 3; ++k) v.push_back(P(c(), c(), flat ? Rational(2) : c()));
      f.push_back({3 * t, 3 * t + 1, 3 * t + 2});
    }
    std::vector<Polyhedron> one{Polyhedron(v, f)}, many;
    for (int t = 0; t < 24; ++t) many.push_back(Polyhedron({v[3 * t], v[3 * t + 1], v[3 * t + 2]}, {{0, 1, 2}}));
    for (const auto* scene : {&one, &many}) {
      check_scene(*scene, 40);
      std::vector<const Polyhedron*> ptrs;
      for (const auto& p : *scene) ptrs.push_back(&p);
      for (const Camera& cam : {make_orthographic(Vector3(0, 0, 1), Vector3(0, 1, 0)),
                                make_perspective(P(2, 2, Q("-1/2")), P(2, 2, 2), Vector3(0, 1, 0))}) {
        Frames r = run_all(ptrs, cam, 40, 30);
        expect_same(r);
        EXPECT_GT(check_oracle(ptrs, cam, r, 1), 0);
        check_vector(ptrs, cam, r, 1);
        if (::testing::Test::HasFailure()) return;
      }
    }
  }
}

TEST(Raster, CoordinatesBeyondTheDoubleFiltersFallBackToExact) {
  // 10^130 puts picture points beyond 2^400 (the filters' limit: exact projections, exact
  // depths, sides left to exact tests); 10^-130 puts products among the subnormals.
  mpz_class ten = 10, big;
  mpz_pow_ui(big.get_mpz_t(), ten.get_mpz_t(), 130);
  for (const Rational& k : {Rational(big), Rational(1 / Rational(big))}) {
    const std::vector<Polyhedron> pierce = hard_scenes()[1];
    check_scene(scaled(fanned(pierce), k), 16, k);
    check_scene(scaled(pierce, k), 16, k);
  }
  // The huge scene really takes the exact route: every side test falls back.
  const std::vector<Polyhedron> huge = scaled(fanned(hard_scenes()[1]), Rational(big));
  std::vector<const Polyhedron*> ptrs{&huge[0], &huge[1]};
  const Camera cam = cameras()[0];
  Frames r = run_all(ptrs, cam, 16, 12);
  EXPECT_GT(r.scene.counters.inside_exact.load(), 100u);
}

TEST(Raster, NextUpStepsLikeNextafterAwayFromZero) {
  const double inf = std::numeric_limits<double>::infinity(), dmax = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::denorm_min();
  for (double v : {1.0, -1.0, 0.1, -3e-300, 5e300, dmax, -dmax, tiny, -tiny, 0x1p-1022, -0x1p-1022, -inf}) {
    EXPECT_EQ(next_up(v), std::nextafter(v, inf)) << v;
    EXPECT_EQ(next_down(v), std::nextafter(v, -inf)) << v;
  }
  EXPECT_EQ(next_up(inf), inf);
  EXPECT_EQ(next_down(-inf), -inf);
  EXPECT_EQ(next_up(0.0), 0x1p-1022);  // a bound, and no subnormal
  EXPECT_EQ(next_down(-0.0), -0x1p-1022);
  EXPECT_TRUE(std::isnan(next_up(std::nan(""))));
}

TEST(Raster, CgalMeshesFourAlgorithmsAgreeWithTheVectorRoute) {
  for (const char* name : {"/fandisk.off", "/bunny00.off"}) {  // CGAL's meshes, when extracted
    const std::string file = std::string(HLR_CORPUS_DIR) + name;
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "scripts/extract_corpus.sh has not run";
    Polyhedron m = load_mesh(file);
    std::vector<const Polyhedron*> ptrs{&m};
    for (const Camera& cam : {make_orthographic(Vector3(1, Q("1.3"), Q("1.7"))), make_perspective(P(3, 4, 5), P(0, 0, 0))}) {
      Frames r = run_all(ptrs, cam, 256, 256);
      expect_same(r);
      EXPECT_GT(check_vector(ptrs, cam, r, 3), 300) << name;
    }
  }
}

}  // namespace
