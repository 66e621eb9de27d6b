// The torture suite for the filled products (docs/design.md, "Checks"): seeded random scenes
// through the library's render pipeline (io/render.hpp, as `hlr render` calls it), every
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

#include "face_oracle.hpp"
#include "io/render.hpp"
#include "io/scene.hpp"

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
  Polyhedron tetra() {
    for (;;) {
      std::vector<Point3> v;
      for (int i = 0; i < 4; ++i) v.emplace_back(q(0, 8, 2), q(0, 8, 2), q(0, 8, 2));
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

std::string yaml_of(const std::vector<Body>& bodies, const std::string& view, bool lights) {
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
  if (lights) y << "lighting:\n  lights:\n    - {type: directional, direction: [2, -1, 3]}\n    - {type: point, position: [-30, -20, 40]}\n";
  return y.str();
}

struct Count {
  long surfaces = 0, transparency = 0, shadows = 0, skipped = 0, scenes = 0, repaired = 0;
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

struct Hit {
  Rational nearness;  // larger is nearer
  int id;
  std::array<Rational, 3> at;
};

// Every face the sight ray through picture point q meets, far to near; empty with `unsure`
// when the ray grazes a face's border or two faces at one depth.
std::vector<Hit> sight(const std::vector<test::OracleFace>& faces, const Camera& cam, const PicturePlane& pp, const Exact2& q, bool& unsure) {
  const Vector3 &r = pp.r(), &u = pp.u(), &d = pp.d();
  const Rational rr = dot(r, r), uu = dot(u, u), dd = dot(d, d);
  std::array<Rational, 3> base, dir;
  for (int k = 0; k < 3; ++k) {
    if (cam.perspective) base[k] = cam.eye[k], dir[k] = q[0] * dd / rr * r[k] + q[1] * dd / uu * u[k] + d[k];
    else base[k] = q[0] / rr * r[k] + q[1] / uu * u[k], dir[k] = cam.direction[k];
  }
  std::vector<Hit> hits;
  unsure = false;
  for (const test::OracleFace& f : faces) {
    Rational nd = f.a * dir[0] + f.b * dir[1] + f.c * dir[2];
    if (nd == 0) continue;
    Rational t = -(f.a * base[0] + f.b * base[1] + f.c * base[2] + f.d) / nd;
    if (cam.perspective && t <= 0) continue;
    std::array<Rational, 3> x{base[0] + t * dir[0], base[1] + t * dir[1], base[2] + t * dir[2]};
    int in = test::in_face(f, x);
    if (in < 0) continue;
    if (in == 0) unsure = true;
    hits.push_back({cam.perspective ? Rational(-t) : t, f.id, x});
  }
  std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.nearness < b.nearness; });
  for (std::size_t i = 1; i < hits.size(); ++i) unsure = unsure || hits[i].nearness == hits[i - 1].nearness;
  return hits;
}

// Does the light reach x on face `self`, on the side the viewer sees? -1: unsure.
int lit(const std::vector<test::OracleFace>& faces, const test::OracleFace& self, const Camera& cam, const LightPlace& l,
        const std::array<Rational, 3>& x) {
  auto f = [](const test::OracleFace& g, const Rational& px, const Rational& py, const Rational& pz) { return Rational(g.a * px + g.b * py + g.c * pz + g.d); };
  const int viewer = cam.perspective ? sgn(f(self, cam.eye.x(), cam.eye.y(), cam.eye.z()))
                                     : sgn(self.a * cam.direction.x() + self.b * cam.direction.y() + self.c * cam.direction.z());
  const int light = l.directional ? sgn(self.a * l.toward.x() + self.b * l.toward.y() + self.c * l.toward.z())
                                  : sgn(f(self, l.position.x(), l.position.y(), l.position.z()));
  if (light == 0) return 0;  // the face lies in a plane through the light: in its shadow (documented)
  if (light != viewer) return 0;
  std::array<Rational, 3> dir;
  for (int k = 0; k < 3; ++k) dir[k] = l.directional ? l.toward[k] : l.position[k] - x[k];
  bool unsure = false;
  for (const test::OracleFace& g : faces) {
    if (g.id == self.id) continue;
    Rational nd = g.a * dir[0] + g.b * dir[1] + g.c * dir[2];
    if (nd == 0) continue;
    Rational t = -(g.a * x[0] + g.b * x[1] + g.c * x[2] + g.d) / nd;
    if (t < 0 || (!l.directional && t > 1)) continue;
    int in = test::in_face(g, {x[0] + t * dir[0], x[1] + t * dir[1], x[2] + t * dir[2]});
    if (in < 0) continue;
    if (t == 0 || in == 0) {
      unsure = true;
      continue;
    }
    return 0;
  }
  return unsure ? -1 : 1;
}

void run_scene(const std::vector<Body>& bodies, const std::string& view, const std::string& what, std::mt19937& rng, Count& n) {
  std::vector<const Polyhedron*> input;
  std::vector<char> glass;
  for (const Body& b : bodies) input.push_back(&b.p), glass.push_back(b.glass);
  for (bool shadows : {false, true}) {
    RenderOptions o;
    o.surfaces = true;
    o.shadows = shadows;
    RenderResult r = render({load_scene_text(yaml_of(bodies, view, shadows), "torture.yaml")}, o);
    const PicturePlane pp(r.camera);
    const auto faces = test::oracle_faces(input, pp);  // the input's faces, numbered as the input
    std::vector<int> first;
    for (std::size_t b = 0, k = 0; b < input.size(); k += input[b]->num_faces(), ++b) first.push_back(static_cast<int>(k));
    for (const DrawingBody& d : r.names) n.repaired += !d.removed_faces.empty();
    auto face_id = [&](int b, int f) { return first[b] + r.names[b].output_face(f); };
    ASSERT_EQ(faces.size(), static_cast<std::size_t>(first.back() + input.back()->num_faces()));
    if (!shadows) {
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
      continue;
    }
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
            const int want = lit(faces, self, r.camera, places[i], hits.back().at);
            if (want < 0) {
              ++n.skipped;
              continue;
            }
            ++n.shadows;
            EXPECT_EQ(((reg.lights >> i) & 1u) != 0, want == 1) << what << ": body " << sf.body << " face "
                                                                 << r.names[sf.body].output_face(sf.face) << ", light " << i;
          }
        }
  }
  ++n.scenes;
}

}  // namespace

TEST(ProductTorture, SurfacesTransparencyAndShadowsAgreeWithRayCasting) {
  const long scenes = env_long("HLR_TORTURE_SCENES", 60);
  const unsigned seed = static_cast<unsigned>(env_long("HLR_TORTURE_SEED", 11));
  Gen g(seed);
  Count n;
  const char* views[] = {"{direction: [0, 0, 1], up: [0, 1, 0]}", "{direction: [1, 0, 0], up: [0, 0, 1]}",
                         "{direction: [1, 1, 0], up: [0, 0, 1]}", "{direction: [1, 13/10, 17/10], up: [0, 0, 1]}",
                         "{direction: [-2, 1, 3], up: [0, 0, 1]}", "{eye: [25, -18, 21], target: [4, 4, 3], up: [0, 0, 1]}",
                         "{eye: [-9, 14, 16], target: [3, 3, 3], up: [0, 0, 1]}"};
  for (long k = 0; k < scenes && !HasFailure(); ++k) {
    std::vector<Body> bodies;
    const int count = g.uniform(2, 4);
    for (int i = 0; i < count; ++i) {
      const int kind = g.uniform(0, 5);
      Polyhedron p = kind <= 1 ? g.box() : kind == 2 ? g.seam_box() : kind == 3 ? g.tetra() : kind == 4 ? g.sheet() : g.box();
      bodies.push_back(Body{std::move(p), g.uniform(0, 2) == 0});
    }
    if (k % 3 == 0) bodies.back().p = g.seam_box(), bodies.back().glass = true;  // a repaired glass body
    if (k % 4 == 1) bodies.front().glass = bodies.back().glass = true;           // several glass bodies
    const std::string view = views[k % (sizeof views / sizeof *views)];
    std::mt19937 rng(static_cast<unsigned>(seed * 1000 + k));
    run_scene(bodies, view, "seed " + std::to_string(seed) + ", scene " + std::to_string(k) + ", view " + view, rng, n);
  }
  std::cout << "[torture] products: " << n.scenes << " scenes, " << n.surfaces << " surface, " << n.transparency << " transparency and "
            << n.shadows << " shadow samples agree; " << n.skipped << " on borders skipped; " << n.repaired << " repaired bodies\n";
  EXPECT_GT(n.surfaces, 12 * scenes);
  EXPECT_GT(n.transparency, 2 * scenes);
  EXPECT_GT(n.shadows, 10 * scenes);
  EXPECT_GT(n.repaired, scenes / 2);
}
