// Filled products with the eye among the bodies (docs/design.md, "Views from inside"): every
// body is cut by the near plane before the visible surfaces, the shadows, the priority list and
// the rasters run, and the near plane's caps are faces. Checked by exact ray casting against the
// uncut input (support/face_oracle.hpp): along the sight ray through a point, what lies nearer
// than the near plane is gone; where the ray's point on the near plane lies inside a body, that
// body's cap is seen; else the nearest face beyond; a shadow region is lit by a light exactly
// where the segment toward it meets no face of the uncut input. Seeded random rooms of boxes
// (walls with a window, floor, a ceiling or none as in a courtyard, furniture that pierces walls
// and each other), the eye inside at random, close to a wall or not, looking anywhere; the sun
// through the window and a lamp in the room (six views of a cube around it, light_cube.hpp);
// random points of every visible polygon, every shadow region, every painted polygon and every
// raster sample of the four algorithms.
#include <gtest/gtest.h>

#include <iostream>
#include <random>
#include <sstream>

#include "algorithms/raster/ray_casting.hpp"
#include "algorithms/raster/scanline.hpp"
#include "algorithms/raster/warnock.hpp"
#include "io/pipeline/raster.hpp"
#include "io/pipeline/render.hpp"
#include "io/pipeline/section.hpp"
#include "io/readers/scene.hpp"
#include "support/face_oracle.hpp"

namespace hlr {
namespace {

// What the sight ray through a picture point shows: a face of the input (body, face), a body's
// near cap (face -1), nothing (body -1); `unsure` where it grazes a border or meets a tie.
struct Seen {
  int body = -1, face = -1;
  bool unsure = false;
  int id = -1;  // the oracle's face seen, and the point seen on it
  std::array<Rational, 3> at;
  bool operator==(const Seen& o) const { return body == o.body && face == o.face; }
};

Seen expected(const std::vector<test::OracleFace>& faces, int bodies, const Camera& cam, const PicturePlane& pp, const Plane& cut, const Exact2& q) {
  const test::SightRay ray = test::sight_ray(cam, pp, q);
  const Rational nd = cut.a() * ray.dir[0] + cut.b() * ray.dir[1] + cut.c() * ray.dir[2];
  const Rational tn = -(cut.a() * ray.base[0] + cut.b() * ray.base[1] + cut.c() * ray.base[2] + cut.d()) / nd;
  Seen s;
  std::vector<int> crossings(bodies);
  const test::SightHit* nearest = nullptr;
  bool tie = false;
  const std::vector<test::SightHit> hits = test::sight_hits(faces, cam, pp, q);
  for (const test::SightHit& h : hits) {  // far to near
    const Rational t = -h.nearness;
    if (t == tn || h.in == 0) s.unsure = true;
    if (t < tn) continue;
    ++crossings[faces[h.id].body];
    tie = nearest && nearest->nearness == h.nearness;
    nearest = &h;
  }
  int inside = 0;
  for (int b = 0; b < bodies; ++b)
    if (crossings[b] % 2) ++inside, s.body = b;
  if (inside > 1) s.unsure = true;  // two caps in one place
  if (inside == 1) return s;
  s.unsure = s.unsure || tie;
  if (nearest) s.body = faces[nearest->id].body, s.face = faces[nearest->id].face, s.id = nearest->id, s.at = nearest->at;
  return s;
}

// A rendered face as the oracle names it: the input body (bodies wholly behind the near plane
// are gone from the render; the rest are named b<k> by the input), its face or its near cap.
Seen named(const RenderResult& r, int body, int face) {
  const int input = std::stoi(r.names[body].name.substr(1));
  if (r.bodies[body]->section_cap.size() > static_cast<std::size_t>(face) && r.bodies[body]->section_cap[face] == kEyeCap)
    return Seen{input, -1, false, -1, {}};
  return Seen{input, r.names[body].output_face(face), false, -1, {}};
}

std::optional<Exact2> inside_point(const std::vector<Exact2>& outer, const std::vector<std::vector<Exact2>>& holes, std::mt19937& rng) {
  std::uniform_int_distribution<int> w(1, 997);
  Rational sx = 0, sy = 0, sw = 0;
  for (const Exact2& c : outer) {
    const Rational k(w(rng));
    sx += k * c[0], sy += k * c[1], sw += k;
  }
  const Exact2 q{sx / sw, sy / sw};
  if (test::in_rings(outer, holes, q) <= 0) return std::nullopt;
  return q;
}

// The faces a transparency region shows, back to front from the nearest opaque one: the faces
// beyond the near plane, then the caps of the bodies the near plane's point lies in. Empty with
// `unsure` where the ray grazes a border, meets two faces at one depth or lies in two bodies there.
std::vector<std::pair<int, int>> expected_stack(const std::vector<test::OracleFace>& faces, const std::vector<char>& glass, const Camera& cam,
                                                const PicturePlane& pp, const Plane& cut, const Exact2& q, bool& unsure) {
  const test::SightRay ray = test::sight_ray(cam, pp, q);
  const Rational nd = cut.a() * ray.dir[0] + cut.b() * ray.dir[1] + cut.c() * ray.dir[2];
  const Rational tn = -(cut.a() * ray.base[0] + cut.b() * ray.base[1] + cut.c() * ray.base[2] + cut.d()) / nd;
  std::vector<std::pair<int, int>> want;
  std::vector<int> crossings(glass.size());
  unsure = false;
  const std::vector<test::SightHit> hits = test::sight_hits(faces, cam, pp, q);
  for (std::size_t i = 0; i < hits.size(); ++i) {  // far to near
    const test::SightHit& h = hits[i];
    const Rational t = -h.nearness;
    unsure = unsure || t == tn || h.in == 0 || (i && h.nearness == hits[i - 1].nearness);
    if (t < tn) continue;
    const int b = faces[h.id].body;
    ++crossings[b];
    if (!glass[b]) want.clear();
    want.push_back({b, faces[h.id].face});
  }
  int inside = 0;
  for (std::size_t b = 0; b < glass.size(); ++b) {
    if (crossings[b] % 2 == 0) continue;
    ++inside;
    if (!glass[b]) want.clear();
    want.push_back({static_cast<int>(b), -1});
  }
  unsure = unsure || inside > 1;
  return want;
}

struct Room {
  std::string yaml;
  int bodies = 0;
  std::vector<char> glass;  // per body: see-through
};

// A room of boxes on a quarter grid, the eye inside it (not in a body) with a 90-degree lens.
Room random_room(std::mt19937& rng) {
  auto quarter = [&](int lo, int hi) -> Rational { return Rational(std::uniform_int_distribution<int>(lo, hi)(rng), 4); };
  const Rational W = quarter(12, 28), D = quarter(12, 20), H = quarter(10, 12), t(1, 5);
  std::ostringstream y;
  Room room;
  std::vector<std::array<Rational, 6>> boxes;
  auto box = [&](Rational x0, Rational y0, Rational z0, Rational x1, Rational y1, Rational z1) { boxes.push_back({x0, y0, z0, x1, y1, z1}); };
  box(-t, -t, -t, W + t, D + t, 0);                                                                         // floor
  box(-t, D, 0, W + t, D + t, H);                                                                           // back wall
  box(-t, -t, 0, 0, D, H);                                                                                  // left wall
  box(0, -t, 0, W, 0, H);                                                                                   // front wall
  const Rational s0 = quarter(2, 6), s1 = s0 + quarter(2, 6), z0 = quarter(2, 4), z1 = z0 + quarter(2, 4);  // the window
  box(W, -t, 0, W + t, D + t, z0);
  box(W, -t, z1, W + t, D + t, H);
  box(W, -t, z0, W + t, s0, z1);
  box(W, s1, z0, W + t, D + t, z1);
  box(W + t / 4, s0, z0, W + t / 2, s1, z1);  // the pane: glass touching the opening on four sides
  room.glass.assign(boxes.size(), 0);
  room.glass.back() = 1;
  if (rng() % 2) box(-t, -t, H, W + t, D + t, H + t), room.glass.push_back(0);  // a ceiling (else a courtyard)
  const int furniture = 1 + static_cast<int>(rng() % 3);
  for (int k = 0; k < furniture; ++k) {  // may pierce a wall and each other; a third of them glass
    const Rational x0 = quarter(-1, 4 * 7 - 4), y0 = quarter(-1, 4 * 5 - 4), z = quarter(0, 2);
    box(x0, y0, z, x0 + quarter(2, 8), y0 + quarter(2, 8), z + quarter(2, 6));
    room.glass.push_back(rng() % 3 == 0);
  }
  // The eye: inside the room, in no body; a third of the time within 0.05 to 0.15 of a wall.
  auto fine = [&](const Rational& lo, const Rational& hi) -> Rational {
    return lo + (hi - lo) * Rational(std::uniform_int_distribution<int>(1, 96)(rng), 97);
  };
  // near_wall: a third of the time within 0.15 of the wall x = 0; in_plane: half of the time one
  // coordinate on a box's face plane (a lamp in the plane of a wall's face: edge-on from it).
  auto free_point = [&](bool near_wall, bool in_plane) {
    std::array<Rational, 3> p;
    for (bool ok = false; !ok;) {
      p = {fine(Rational(1, 20), W - Rational(1, 20)), fine(Rational(1, 20), D - Rational(1, 20)), fine(Rational(1, 4), H - Rational(1, 4))};
      if (near_wall && rng() % 3 == 0) p[0] = fine(Rational(1, 20), Rational(3, 20));
      if (in_plane && rng() % 2 == 0) {
        const auto& b = boxes[rng() % boxes.size()];
        const int k = static_cast<int>(rng() % 3);
        p[k] = b[k + 3 * (rng() % 2)];
      }
      ok = true;
      for (const auto& b : boxes)
        if (b[0] <= p[0] && p[0] <= b[3] && b[1] <= p[1] && p[1] <= b[4] && b[2] <= p[2] && p[2] <= b[5]) ok = false;
    }
    return p;
  };
  const std::array<Rational, 3> eye = free_point(true, false), lamp = free_point(false, true);
  std::array<Rational, 3> look;
  do {
    for (auto& c : look) c = Rational(std::uniform_int_distribution<int>(-40, 40)(rng), 10);
  } while (look[0] == 0 && look[1] == 0);
  look[2] = look[2] / 4;
  y << "bodies:\n";
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    const auto& b = boxes[k];
    y << "  - name: b" << k << "\n    box: {min: [" << b[0] << ", " << b[1] << ", " << b[2] << "], max: [" << b[3] << ", " << b[4] << ", " << b[5]
      << "]}\n";
    if (room.glass[k]) y << "    material: {colour: [0.3, 0.5, 0.9], transparency: 0.6}\n";
  }
  y << "camera:\n  eye: [" << eye[0] << ", " << eye[1] << ", " << eye[2] << "]\n  target: [" << eye[0] + look[0] << ", " << eye[1] + look[1] << ", "
    << eye[2] + look[2] << "]\n  up: [0, 0, 1]\n  fov: 90\n";
  y << "lighting:\n  lights:\n    - {type: directional, direction: [3, 1, 2]}\n";                     // the sun, through the window
  y << "    - {type: point, position: [" << lamp[0] << ", " << lamp[1] << ", " << lamp[2] << "]}\n";  // a lamp in the room
  room.yaml = y.str();
  room.bodies = static_cast<int>(boxes.size());
  return room;
}

struct Counts {
  long surfaces = 0, transparency = 0, caps = 0, priority = 0, raster = 0, shadows = 0, skipped = 0;
};

void check_room(const Room& room, std::mt19937& rng, Counts& n) {
  const Scene input = load_scene_text(room.yaml, "room.yaml");
  std::vector<const Polyhedron*> polys;
  for (const SceneBody& b : input.bodies) polys.push_back(&b.body);
  const auto faces = test::oracle_faces(polys);
  for (int product = 0; product < 4; ++product) {  // surfaces, priority, raster, shadows
    RenderResult r;
    RasterResult rr;
    if (product != 2) {
      RenderOptions o;
      o.surfaces = product == 0;
      o.shadows = product == 3;
      if (product == 1) o.method = RenderMethod::Priority;
      o.near = Rational(1, 8);
      r = render({load_scene_text(room.yaml, "room.yaml")}, o);
    } else {
      RasterOptions ro;
      ro.width = 24, ro.height = 16;
      rr = raster({load_scene_text(room.yaml, "room.yaml")}, ro);
      r = rr.render;
    }
    ASSERT_TRUE(r.eye_cut) << room.yaml;
    const PicturePlane pp(r.camera);
    auto check = [&](const Exact2& q, const Seen& got, long& count) {
      const Seen want = expected(faces, room.bodies, r.camera, pp, *r.eye_cut, q);
      if (want.unsure) return void(++n.skipped);
      ++count;
      n.caps += want.body >= 0 && want.face < 0;
      EXPECT_TRUE(got == want) << "product " << product << ": got body " << got.body << " face " << got.face << ", want body " << want.body
                               << " face " << want.face << "\n"
                               << room.yaml;
    };
    if (product == 0) {
      for (const VisibleFace& vf : r.surfaces->faces)
        for (const VisiblePolygon& p : vf.polygons)
          for (int s = 0; s < 3; ++s)
            if (auto q = inside_point(p.outer_2d, p.holes_2d, rng)) check(*q, named(r, vf.body, vf.face), n.surfaces);
      if (!r.transparent)  // none only when no glass is seen
        for (const VisibleFace& vf : r.surfaces->faces) EXPECT_FALSE(room.glass[named(r, vf.body, vf.face).body]) << room.yaml;
      if (r.transparent)
        for (const TransparentRegion& reg : r.transparent->regions)
          for (int s = 0; s < 2; ++s) {
            auto q = inside_point(reg.polygon.outer_2d, reg.polygon.holes_2d, rng);
            if (!q) continue;
            bool unsure = false;
            const auto want = expected_stack(faces, room.glass, r.camera, pp, *r.eye_cut, *q, unsure);
            if (unsure) {
              ++n.skipped;
              continue;
            }
            std::vector<std::pair<int, int>> got;
            for (auto [b, f] : reg.faces) {
              const Seen g = named(r, b, f);
              got.push_back({g.body, g.face});
            }
            ++n.transparency;
            EXPECT_EQ(got, want) << "a transparency region\n" << room.yaml;
          }
    } else if (product == 1) {  // the last polygon painted over a point
      const PriorityResult& pr = *r.priority;
      for (int k : pr.order)
        for (int s = 0; s < 2; ++s) {
          auto q = inside_point(pr.polygons[k].pts, {}, rng);
          if (!q) continue;
          int last = -1;
          bool border = false;
          for (int i : pr.order) {
            const int in = test::in_ring(pr.polygons[i].pts, *q);
            border = border || in == 0;
            if (in > 0) last = i;
          }
          if (border || last < 0) continue;
          check(*q, named(r, pr.polygons[last].body, pr.polygons[last].face), n.priority);
        }
    } else if (product == 3) {  // each shadow region: lit by the sun and by the lamp exactly where the ray toward each is free
      const std::vector<LightPlace> lights = render_light_places(r);
      ASSERT_EQ(lights.size(), 2u);
      for (const ShadowFace& sf : r.shadows->faces)
        for (const ShadowRegion& reg : sf.regions)
          for (int s = 0; s < 2; ++s) {
            auto q = inside_point(reg.polygon.outer_2d, reg.polygon.holes_2d, rng);
            if (!q) continue;
            const Seen want = expected(faces, room.bodies, r.camera, pp, *r.eye_cut, *q);
            if (want.unsure || !(want == named(r, sf.body, sf.face))) {
              ++n.skipped;
              continue;
            }
            for (unsigned i = 0; i < 2; ++i) {
              const int light = want.face < 0 ? 0 : test::lit(faces, faces[want.id], r.camera, lights[i], want.at);
              if (light < 0) {
                ++n.skipped;
                continue;
              }
              ++n.shadows;
              EXPECT_EQ((reg.lights >> i) & 1u, static_cast<unsigned>(light))
                  << "light " << i << ", a shadow region of body " << want.body << " face " << want.face << "\n"
                  << room.yaml;
            }
          }
    } else {  // the face at every sample centre, all four algorithms
      const RasterScene& rs = rr.scene;
      for (const FaceIdBuffer& f : {rr.ids, scanline(rs), warnock(rs), ray_cast(rs)})
        for (int j = 0; j < rs.grid.height; ++j)
          for (int i = 0; i < rs.grid.width; ++i) {
            const int id = f.at(i, j);
            check(rs.grid.centre(i, j), id < 0 ? Seen{} : named(r, rs.faces[id][0], rs.faces[id][1]), n.raster);
          }
    }
  }
}

TEST(InteriorFill, EveryFilledProductAgreesWithRayCastingFromInside) {
  std::mt19937 rng(20261203);
  Counts n;
  for (int scene = 0; scene < 10; ++scene) check_room(random_room(rng), rng, n);
  std::cout << "samples: surfaces " << n.surfaces << ", transparency " << n.transparency << ", priority " << n.priority << ", raster " << n.raster
            << ", shadows " << n.shadows << ", caps " << n.caps << ", skipped " << n.skipped << "\n";
  EXPECT_GT(n.surfaces, 400);
  EXPECT_GT(n.transparency, 200);
  EXPECT_GT(n.priority, 350);
  EXPECT_GT(n.raster, 4 * 10 * 300);
  EXPECT_GT(n.shadows, 400);
  EXPECT_GT(n.caps, 0) << "some samples see a wall's inside on the near plane";
  EXPECT_LT(n.skipped * 20, n.surfaces + n.transparency + n.priority + n.raster + n.shadows);
}

TEST(InteriorFill, TheRoomsFrameIsTheRastersPicture) {
  // data/interior_room.yaml: a 90-degree lens at 3:2; --size WIDTH takes the frame's aspect and
  // the grid is the frame: its extreme sample centres lie half a pixel inside it.
  RasterOptions o;
  o.width = 60, o.height = 0;
  const RasterResult r = raster_files({std::string(HLR_DATA_DIR) + "/interior_room.yaml"}, o);
  ASSERT_TRUE(r.render.pyramid && r.render.eye_cut);
  EXPECT_EQ(r.width, 60);
  EXPECT_EQ(r.height, 40);
  const double hx = to_double(r.render.pyramid->half_x);
  EXPECT_LE(r.scene.grid.cx(0), -hx + r.scene.grid.dxstep);
  EXPECT_GE(r.scene.grid.cx(0), -hx);
  EXPECT_GE(r.scene.grid.cx(59), hx - r.scene.grid.dxstep);
  EXPECT_LE(r.scene.grid.cx(59), hx);
}

}  // namespace
}  // namespace hlr
