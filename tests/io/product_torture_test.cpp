// The torture suite for the filled products (docs/design.md, "Checks"): seeded random scenes
// through the library's render pipeline (io/pipeline/render.hpp, as `hlr render` calls it), every
// visible surface, transparency region and shadow region sampled and checked by exact ray
// casting against the input bodies (face_oracle.hpp: its own planes and point-in-polygon).
// Scenes: boxes (thin slabs among them), tetrahedra, open sheets, boxes whose top is two
// triangles and a zero-area triangle on the seam (the loader repairs them: every face number in
// the outputs must still be the input's), on a quarter grid so that bodies touch, share planes
// and pierce each other; several see-through bodies, glass inside and touching other bodies;
// orthographic views along axes, faces and edges and in general directions, and perspective
// views from near and far; a directional light and a point light. The test command runs
// 60 scenes; scripts/torture.sh runs many more (HLR_TORTURE_SCENES, HLR_TORTURE_SEED).
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <sstream>

#include "algorithms/raster/ray_casting.hpp"
#include "algorithms/raster/scanline.hpp"
#include "algorithms/raster/warnock.hpp"
#include "io/pipeline/horizon.hpp"
#include "io/pipeline/raster.hpp"
#include "io/pipeline/render.hpp"
#include "io/readers/scene.hpp"
#include "support/face_oracle.hpp"

using namespace hlr;

namespace {

long env_long(const char* name, long fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atol(v) : fallback;
}

struct Body {
  Polyhedron p;
  bool glass = false;
};

struct Gen {
  std::mt19937 rng;
  explicit Gen(unsigned seed) : rng(seed) {}
  int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  Rational q(int lo, int hi, int den) {
    Rational r(uniform(lo * den, hi * den), den);
    r.canonicalize();
    return r;
  }
  std::array<Rational, 6> extent() {
    std::array<Rational, 6> e;
    const int thin = uniform(0, 4) == 0 ? uniform(0, 2) : -1;
    for (int k = 0; k < 3; ++k) {
      e[k] = q(0, 6, 4);
      Rational size = k == thin ? Rational(1, uniform(4, 8)) : q(1, 3, 2);
      size.canonicalize();
      e[k + 3] = e[k] + size;
    }
    return e;
  }
  Polyhedron box() {
    auto e = extent();
    return make_box(Point3(e[0], e[1], e[2]), Point3(e[3], e[4], e[5]));
  }
  // A box whose top (z = max) is two triangles with a zero-area triangle on their seam, the
  // faces in a shuffled order: the loader removes the seam triangle.
  Polyhedron seam_box() {
    auto e = extent();
    std::vector<Point3> v;
    for (int i = 0; i < 8; ++i) v.emplace_back(e[(i & 1) ? 3 : 0], e[(i & 2) ? 4 : 1], e[(i & 4) ? 5 : 2]);
    v.emplace_back((e[0] + e[3]) / 2, (e[1] + e[4]) / 2, e[5]);  // 8: the seam's middle
    std::vector<Face> f = {{0, 2, 3, 1}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}, {4, 5, 7}, {4, 7, 8}, {4, 8, 7, 6}};
    std::shuffle(f.begin(), f.end(), rng);
    return Polyhedron(v, f);
  }
  // A box whose faces all turn inward (an exporter's inside-out component): the loader turns
  // it; its face numbers stay.
  Polyhedron inside_out_box() {
    Polyhedron b = box();
    std::vector<Face> f = b.faces();
    for (Face& x : f) std::reverse(x.begin(), x.end());
    return Polyhedron(b.vertices(), f);
  }
  // A box strictly inside `outer`'s box (glass inside glass, a body inside glass).
  Polyhedron inside(const Polyhedron& outer) {
    std::array<Rational, 6> e{outer.vertices()[0].x(), outer.vertices()[0].y(), outer.vertices()[0].z(), 0, 0, 0};
    for (int k = 0; k < 3; ++k) e[k + 3] = e[k];
    for (const Point3& v : outer.vertices())
      for (int k = 0; k < 3; ++k) e[k] = std::min(e[k], v[k]), e[k + 3] = std::max(e[k + 3], v[k]);
    std::array<Rational, 3> lo, hi;
    for (int k = 0; k < 3; ++k) {
      const Rational w = e[k + 3] - e[k];
      lo[k] = e[k] + w * Rational(uniform(1, 3), 8), hi[k] = e[k + 3] - w * Rational(uniform(1, 3), 8);
      lo[k].canonicalize(), hi[k].canonicalize();
    }
    return make_box(Point3(lo[0], lo[1], lo[2]), Point3(hi[0], hi[1], hi[2]));
  }
  Polyhedron tetra() {
    for (;;) {
      std::vector<Point3> v;
      for (int i = 0; i < 4; ++i) {  // one coordinate at a time: the same scenes whatever the compiler's argument order
        Rational x = q(0, 8, 2), y = q(0, 8, 2), z = q(0, 8, 2);
        v.emplace_back(x, y, z);
      }
      std::vector<Face> f = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
      if (six_signed_volume(v, f) == 0) continue;
      return Polyhedron(v, orient_faces(v, f));
    }
  }
  Polyhedron sheet() {  // an open quad in an axis plane
    auto e = extent();
    const int k = uniform(0, 2);
    std::vector<Point3> v;
    for (int c = 0; c < 4; ++c) {
      std::array<Rational, 3> p{e[0], e[1], e[2]};
      const int a = (k + 1) % 3, b = (k + 2) % 3, ca = (c == 1 || c == 2) ? 1 : 0, cb = c >= 2 ? 1 : 0;
      p[a] = ca ? e[a + 3] : e[a];
      p[b] = cb ? e[b + 3] : e[b];
      v.emplace_back(p[0], p[1], p[2]);
    }
    return Polyhedron(v, {{0, 1, 2, 3}});
  }
};

std::string yaml_of(const std::vector<Body>& bodies, const std::string& view, bool lights, const std::string& ground = "") {
  std::ostringstream y;
  y << "bodies:\n";
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Polyhedron& p = bodies[b].p;
    y << "  - name: b" << b << "\n    vertices: [";
    for (std::size_t v = 0; v < p.num_vertices(); ++v) {
      const Point3& q = p.vertices()[v];
      y << (v ? ", " : "") << "[" << to_string(q.x()) << ", " << to_string(q.y()) << ", " << to_string(q.z()) << "]";
    }
    y << "]\n    faces: [";
    for (std::size_t f = 0; f < p.num_faces(); ++f) {
      y << (f ? ", " : "") << "[";
      for (std::size_t k = 0; k < p.faces()[f].size(); ++k) y << (k ? ", " : "") << p.faces()[f][k];
      y << "]";
    }
    y << "]\n";
    if (bodies[b].glass) y << "    material: {colour: [0.3, 0.5, 0.9], transparency: 0.6}\n";
  }
  y << "view: " << view << "\n";
  if (!ground.empty()) y << "ground: " << ground << "\n";
  if (lights) y << "lighting:\n  lights:\n    - {type: directional, direction: [2, -1, 3]}\n    - {type: point, position: [-30, -20, 40]}\n";
  return y.str();
}

struct Count {
  long surfaces = 0, transparency = 0, shadows = 0, priority = 0, raster = 0, horizon = 0, skipped = 0, scenes = 0, repaired = 0;
};

// A random point inside the rings (a weighted mean of the outer corners, kept when inside).
std::optional<Exact2> inside_point(const VisiblePolygon& p, std::mt19937& rng) {
  std::uniform_int_distribution<int> w(1, 997);
  Rational sx = 0, sy = 0, sw = 0;
  for (const Exact2& c : p.outer_2d) {
    Rational k(w(rng));
    sx += k * c[0], sy += k * c[1], sw += k;
  }
  Exact2 q{sx / sw, sy / sw};
  if (test::in_rings(p.outer_2d, p.holes_2d, q) <= 0) return std::nullopt;
  return q;
}

using Hit = test::SightHit;

// Every face the sight ray through picture point q meets, far to near; `unsure` when the ray
// grazes a face's border or meets two faces at one depth.
std::vector<Hit> sight(const std::vector<test::OracleFace>& faces, const Camera& cam, const PicturePlane& pp, const Exact2& q, bool& unsure) {
  std::vector<Hit> hits = test::sight_hits(faces, cam, pp, q);
  unsure = false;
  for (std::size_t i = 0; i < hits.size(); ++i) unsure = unsure || hits[i].in == 0 || (i && hits[i].nearness == hits[i - 1].nearness);
  return hits;
}

// The face seen at a picture point by the raster rule (the nearest; at equal depth the face
// toward the viewer, then the lower number): -2 when the ray grazes a border.
int seen_face(const std::vector<test::OracleFace>& faces, const Camera& cam, const PicturePlane& pp, const Exact2& q) {
  bool unsure;
  std::vector<Hit> hits = sight(faces, cam, pp, q, unsure);
  if (hits.empty()) return -1;
  // Grazing a border decides nothing only when another face is as near; the rule takes ties.
  int best = -1, rank = 2;
  const test::SightRay ray = test::sight_ray(cam, pp, q);
  for (const Hit& h : hits) {
    if (h.nearness != hits.back().nearness) continue;
    const test::OracleFace& f = faces[h.id];
    const Rational nd = f.a * ray.dir[0] + f.b * ray.dir[1] + f.c * ray.dir[2];
    const int rk = (cam.perspective ? -nd : nd) > 0 ? 0 : 1;
    if (rk < rank || (rk == rank && h.id < best)) best = h.id, rank = rk;
  }
  for (const Hit& h : hits)  // a border at the nearest depth: the rule's faces may differ by the border
    if (h.nearness == hits.back().nearness && h.in == 0) return -2;
  return best;
}

struct Scene3 {
  std::vector<Body> bodies;
  std::string view, ground;
  bool tiny = false;  // coordinates far below doubles: no raster (its grid is doubles, within 2^±500)
};

void run_scene(const Scene3& sc, const std::string& what, std::mt19937& rng, Count& n) {
  std::vector<char> glass;
  for (const Body& b : sc.bodies) glass.push_back(b.glass);
  for (int product = 0; product < (sc.tiny ? 3 : 4); ++product) {  // surfaces and transparency, shadows, priority, raster
    const bool shadows = product == 1;
    RenderOptions o;
    o.surfaces = product <= 1;
    o.shadows = shadows;
    o.near = Rational(1, 1000000);  // the eye close to a face is nearer than the default near plane
    if (product == 2) o.method = RenderMethod::Priority;
    std::vector<Scene> scenes{load_scene_text(yaml_of(sc.bodies, sc.view, shadows, product == 1 ? sc.ground : ""), "torture.yaml")};
    RasterResult raster_result;
    RenderResult r;
    if (product == 3) {
      RasterOptions ro;
      ro.width = 28, ro.height = 20;
      raster_result = raster(std::move(scenes), ro);
      r = raster_result.render;
    } else {
      r = render(std::move(scenes), o);
    }
    // The oracle's bodies: the input's (before any repair), and the scene's ground.
    std::vector<const Polyhedron*> input;
    for (const Body& b : sc.bodies) input.push_back(&b.p);
    for (std::size_t b = sc.bodies.size(); b < r.bodies.size(); ++b) input.push_back(&r.bodies[b]->body), glass.resize(r.bodies.size(), 0);
    const PicturePlane pp(r.camera);
    auto faces = test::oracle_faces(input, pp);  // the input's faces, numbered as the input
    // A closed body's outside is where its volume is positive: an inside-out box's faces point
    // inward, so their planes turn (the tie rule names the face whose outside faces the viewer).
    for (test::OracleFace& f : faces) {
      const Polyhedron& p = *input[f.body];
      if (p.num_faces() > 1 && six_signed_volume(p.vertices(), p.faces()) < 0) f.a = -f.a, f.b = -f.b, f.c = -f.c, f.d = -f.d;
    }
    std::vector<int> first;
    for (std::size_t b = 0, k = 0; b < input.size(); k += input[b]->num_faces(), ++b) first.push_back(static_cast<int>(k));
    for (const DrawingBody& d : r.names) n.repaired += !d.removed_faces.empty();
    auto face_id = [&](int b, int f) { return first[b] + r.names[b].output_face(f); };
    ASSERT_EQ(faces.size(), static_cast<std::size_t>(first.back() + input.back()->num_faces()));
    if (product == 0) {
      for (const VisibleFace& vf : r.surfaces->faces)  // the nearest face along the sight ray
        for (const VisiblePolygon& p : vf.polygons)
          for (int s = 0; s < 3; ++s) {
            auto q = inside_point(p, rng);
            bool unsure;
            if (!q) continue;
            auto hits = sight(faces, r.camera, pp, *q, unsure);
            if (unsure || hits.empty()) {
              ++n.skipped;
              continue;
            }
            ++n.surfaces;
            EXPECT_EQ(hits.back().id, face_id(vf.body, vf.face)) << what << ": surface of body " << vf.body << " face "
                                                                  << r.names[vf.body].output_face(vf.face);
          }
      if (r.transparent)
        for (const TransparentRegion& reg : r.transparent->regions)
          for (int s = 0; s < 3; ++s) {
            auto q = inside_point(reg.polygon, rng);
            bool unsure;
            if (!q) continue;
            auto hits = sight(faces, r.camera, pp, *q, unsure);
            if (unsure) {
              ++n.skipped;
              continue;
            }
            std::vector<int> want, got;
            for (const Hit& h : hits) {
              if (!glass[faces[h.id].body]) want.clear();
              want.push_back(h.id);
            }
            for (auto [b, f] : reg.faces) got.push_back(face_id(b, f));
            ++n.transparency;
            EXPECT_EQ(got, want) << what << ": a transparency region";
          }
    } else if (product == 1) {
      const std::vector<LightPlace> places = render_light_places(r);
      for (const ShadowFace& sf : r.shadows->faces)
        for (const ShadowRegion& reg : sf.regions)
          for (int s = 0; s < 2; ++s) {
            auto q = inside_point(reg.polygon, rng);
            bool unsure;
            if (!q) continue;
            auto hits = sight(faces, r.camera, pp, *q, unsure);
            if (unsure || hits.empty() || hits.back().id != face_id(sf.body, sf.face)) {
              ++n.skipped;
              continue;
            }
            const test::OracleFace& self = faces[hits.back().id];
            for (std::size_t i = 0; i < places.size(); ++i) {
              const int want = test::lit(faces, self, r.camera, places[i], hits.back().at);
              if (want < 0) {
                ++n.skipped;
                continue;
              }
              ++n.shadows;
              EXPECT_EQ(((reg.lights >> i) & 1u) != 0, want == 1) << what << ": body " << sf.body << " face "
                                                                   << r.names[sf.body].output_face(sf.face) << ", light " << i;
            }
          }
    } else if (product == 2) {  // the last polygon painted over a point is the face the ray meets first
      const PriorityResult& pr = *r.priority;
      for (std::size_t k = 0; k < pr.order.size(); ++k)
        for (int s = 0; s < 2; ++s) {
          VisiblePolygon ring;
          ring.outer_2d = pr.polygons[pr.order[k]].pts;
          auto q = inside_point(ring, rng);
          if (!q) continue;
          int last = -1;
          bool border = false;
          for (int i : pr.order) {
            const int in = test::in_ring(pr.polygons[i].pts, *q);
            border = border || in == 0;
            if (in > 0) last = i;
          }
          bool unsure;
          auto hits = sight(faces, r.camera, pp, *q, unsure);
          if (border || unsure || hits.empty() || last < 0) {
            ++n.skipped;
            continue;
          }
          ++n.priority;
          EXPECT_EQ(face_id(pr.polygons[last].body, pr.polygons[last].face), hits.back().id) << what << ": the painter's list";
        }
    } else {  // the face at every sample centre, all four algorithms
      const RasterScene& rs = raster_result.scene;
      std::vector<FaceIdBuffer> frames{raster_result.ids, scanline(rs), warnock(rs), ray_cast(rs)};
      for (int j = 0; j < rs.grid.height; ++j)
        for (int i = 0; i < rs.grid.width; ++i) {
          const int want = seen_face(faces, r.camera, pp, rs.grid.centre(i, j));
          if (want == -2) {
            ++n.skipped;
            continue;
          }
          for (const FaceIdBuffer& f : frames) {
            const int id = f.at(i, j);
            const int got = id < 0 ? -1 : face_id(rs.faces[id][0], rs.faces[id][1]);
            ++n.raster;
            EXPECT_EQ(got, want) << what << ": sample (" << i << ", " << j << ")";
          }
        }
    }
  }
  if (::testing::Test::HasFailure() && std::getenv("HLR_TORTURE_DUMP"))  // the scene as a scene file, to run by hand
    std::cout << "# " << what << "\n" << yaml_of(sc.bodies, sc.view, true, sc.ground);
  ++n.scenes;
}

// The floating horizon's drawing (render_horizon) by exact ray casting against its own
// triangulated surface: the middle of every piece is visible exactly when the sight ray from it
// toward the viewer meets no triangle.
void run_horizon(std::mt19937& rng, Count& n, const std::string& what) {
  const int nx = std::uniform_int_distribution<int>(3, 7)(rng), nz = std::uniform_int_distribution<int>(2, 6)(rng);
  HeightGrid g;
  for (int i = 0; i < nx; ++i) g.xs.push_back(Rational(i));
  for (int j = 0; j < nz; ++j) g.zs.push_back(Rational(j));
  const int top = std::uniform_int_distribution<int>(0, 1)(rng) ? 1 : 4;  // terraces (equal heights) or hills
  for (int k = 0; k < nx * nz; ++k) g.ys.push_back(Rational(std::uniform_int_distribution<int>(-top, top)(rng)));
  const int views[][3] = {{0, 1, 2}, {1, 2, 4}, {-1, 2, 3}, {2, 1, 5}, {0, 3, -2}, {1, -1, 3}, {-3, 2, -4}, {1, 5, 1}, {3, 1, 1}};
  const auto& vw = views[std::uniform_int_distribution<int>(0, 8)(rng)];
  const Camera cam = make_orthographic(Vector3(vw[0], vw[1], vw[2]), Vector3(0, 1, 0));
  RenderResult r = render_horizon(g, cam, "surface", 0, vw[0] != 0 ? "both" : "z");
  const Polyhedron& surface = r.bodies[0]->body;
  const auto faces = test::oracle_faces({&surface}, PicturePlane(cam));
  for (const Segment& s : r.drawing.segments)
    for (const Piece& p : s.pieces) {
      const Point3 m = s.at((p.t0 + p.t1) / 2);
      bool hit = false, unsure = false;
      for (const test::OracleFace& f : faces) {
        const Rational nd = f.a * cam.direction.x() + f.b * cam.direction.y() + f.c * cam.direction.z();
        if (nd == 0) continue;
        const Rational t = -(f.a * m.x() + f.b * m.y() + f.c * m.z() + f.d) / nd;
        if (t <= 0) continue;
        const int in = test::in_face(f, {m.x() + t * cam.direction.x(), m.y() + t * cam.direction.y(), m.z() + t * cam.direction.z()});
        hit = hit || in > 0;
        unsure = unsure || in == 0;
      }
      if (!hit && unsure) {
        ++n.skipped;
        continue;
      }
      ++n.horizon;
      EXPECT_EQ(p.visible, !hit) << what << ": grid " << nx << "x" << nz << ", view " << vw[0] << "," << vw[1] << "," << vw[2] << ", edge "
                                 << s.v0 << "-" << s.v1 << " at " << m;
    }
}

}  // namespace

// Scaled by 2^-1100: every coordinate far below the doubles' range (the filters cannot hold it).
Polyhedron tiny(const Polyhedron& p) {
  const Rational k(mpz_class(1), mpz_class(1) << 1100);
  std::vector<Point3> v;
  for (const Point3& q : p.vertices()) v.emplace_back(q.x() * k, q.y() * k, q.z() * k);
  return Polyhedron(v, p.faces());
}

TEST(ProductTorture, EveryProductAgreesWithRayCasting) {
  const long scenes = env_long("HLR_TORTURE_SCENES", 60);
  const unsigned seed = static_cast<unsigned>(env_long("HLR_TORTURE_SEED", 11));
  Gen g(seed);
  Count n;
  const char* views[] = {"{direction: [0, 0, 1], up: [0, 1, 0]}", "{direction: [1, 0, 0], up: [0, 0, 1]}",
                         "{direction: [1, 1, 0], up: [0, 0, 1]}", "{direction: [1, 13/10, 17/10], up: [0, 0, 1]}",
                         "{direction: [-2, 1, 3], up: [0, 0, 1]}", "{eye: [25, -18, 21], target: [4, 4, 3], up: [0, 0, 1]}",
                         "{eye: [-9, 14, 16], target: [3, 3, 3], up: [0, 0, 1]}", "close"};
  for (long k = 0; k < scenes && !HasFailure(); ++k) {
    Scene3 sc;
    const int count = g.uniform(2, 4);
    for (int i = 0; i < count; ++i) {
      const int kind = g.uniform(0, 6);
      Polyhedron p = kind <= 1 ? g.box() : kind == 2 ? g.seam_box() : kind == 3 ? g.tetra() : kind == 4 ? g.sheet() : kind == 5 ? g.inside_out_box() : g.box();
      sc.bodies.push_back(Body{std::move(p), g.uniform(0, 2) == 0});
    }
    if (k % 3 == 0) sc.bodies.back().p = g.seam_box(), sc.bodies.back().glass = true;  // a repaired glass body
    if (k % 4 == 1) sc.bodies.front().glass = sc.bodies.back().glass = true;           // several glass bodies
    if (k % 5 == 2) {  // glass inside glass, or a body inside glass
      Polyhedron outer = g.box();
      Polyhedron in = g.inside(outer);
      sc.bodies.push_back(Body{std::move(outer), true});
      sc.bodies.push_back(Body{std::move(in), g.uniform(0, 1) == 0});
    }
    std::string view = views[k % (sizeof views / sizeof *views)];
    if (view == "close") {  // the eye a hair outside the bodies' top, looking down
      Rational top = sc.bodies[0].p.vertices()[0].z();
      for (const Body& b : sc.bodies)
        for (const Point3& v : b.p.vertices()) top = std::max(top, v.z());
      const std::string ex = to_string(Rational(g.q(1, 8, 4))), ey = to_string(Rational(g.q(1, 8, 4)));
      view = "{eye: [" + ex + ", " + ey + ", " + to_string(Rational(top + Rational(1, 1000))) + "], target: [" + ex + ", " + ey + ", 0], up: [0, 1, 0]}";
    }
    if (k % 10 == 7) {  // numbers far outside doubles (orthographic views: the eye would need scaling too)
      for (Body& b : sc.bodies) b.p = tiny(b.p);
      sc.tiny = true;
      if (view.find("eye") != std::string::npos) view = views[3];
    }
    const int gz = g.uniform(1, 5);  // a ground through the bodies, or under them
    sc.ground = k % 2 ? "z = " + std::to_string(gz) : "z = 0";
    if (k % 10 == 7 || view.find("eye") != std::string::npos) sc.ground.clear();  // the ground is wide: it would reach behind an eye
    sc.view = view;
    std::mt19937 rng(static_cast<unsigned>(seed * 1000 + k));
    run_scene(sc, "seed " + std::to_string(seed) + ", scene " + std::to_string(k) + ", view " + view, rng, n);
    run_horizon(rng, n, "seed " + std::to_string(seed) + ", scene " + std::to_string(k));
  }
  std::cout << "[torture] products: " << n.scenes << " scenes; samples that agree: " << n.surfaces << " surfaces, " << n.transparency
            << " transparency, " << n.shadows << " shadows, " << n.priority << " priority, " << n.raster << " raster, " << n.horizon
            << " horizon; " << n.skipped << " on borders skipped; " << n.repaired << " repaired bodies\n";
  EXPECT_GT(n.surfaces, 12 * scenes);
  EXPECT_GT(n.transparency, 2 * scenes);
  EXPECT_GT(n.shadows, 10 * scenes);
  EXPECT_GT(n.priority, 5 * scenes);
  EXPECT_GT(n.raster, 1000 * scenes);
  EXPECT_GT(n.horizon, 10 * scenes);
  EXPECT_GT(n.repaired, scenes / 2);
}
