// The priority list (algorithms/surfaces/priority_list.*), checked by an independent exact
// oracle: at random picture points, the last polygon of the painted list that contains the
// point must belong to the face the sight ray through the point meets first, found by casting
// the ray in rationals against every face polygon of the scene (its own ray, its own Newell
// planes, its own point-in-polygon; ties in one plane by facing, then face number, as the
// visible surfaces decide them). Points on a polygon's border are skipped (a set of no area).
// Scenes by name: the three-stick cycle, a cycle of three open polygons, piercing polygons,
// interpenetrating boxes, touching and coplanar faces, views along faces, perspective with the
// eye near a face, random triangles, CGAL's fandisk.
#include "algorithms/surfaces/priority_list.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <random>

#include "algorithms/hlr/face_occluders.hpp"
#include "io/readers/mesh_reader.hpp"
#include "io/readers/scene.hpp"
#include "support/face_oracle.hpp"
#include "support/numbers.hpp"

using namespace hlr;

namespace {

const std::string kData = HLR_DATA_DIR;
const std::string kCorpus = HLR_CORPUS_DIR;
using hlr::test::Q;
Point3 P(const char* x, const char* y, const char* z) { return Point3(Q(x), Q(y), Q(z)); }
Polyhedron box(const char* x0, const char* y0, const char* z0, const char* x1, const char* y1, const char* z1) {
  return make_box(P(x0, y0, z0), P(x1, y1, z1));
}
Camera ortho(const char* x, const char* y, const char* z) { return make_orthographic(Vector3(Q(x), Q(y), Q(z))); }
Camera persp(const char* x, const char* y, const char* z, const Point3& target) { return make_perspective(P(x, y, z), target); }
std::vector<const Polyhedron*> ptrs(const std::vector<Polyhedron>& v) {
  std::vector<const Polyhedron*> out;
  for (const auto& p : v) out.push_back(&p);
  return out;
}
Polyhedron quad(const Point3& a, const Point3& b, const Point3& c, const Point3& d) { return Polyhedron({a, b, c, d}, {{0, 1, 2, 3}}); }
Polyhedron parallelepiped(const Point3& o, const Point3& e1, const Point3& e2, const Point3& e3) {
  std::vector<Point3> vs;
  for (int k = 0; k < 8; ++k) {
    std::array<Rational, 3> c;
    for (int i = 0; i < 3; ++i) c[i] = o[i] + (k & 1 ? e1[i] : Rational(0)) + (k & 2 ? e2[i] : Rational(0)) + (k & 4 ? e3[i] : Rational(0));
    vs.emplace_back(c[0], c[1], c[2]);
  }
  return Polyhedron(std::move(vs), {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}});
}

// ---- the oracle (faces: face_oracle.hpp)

using test::box_of;
using test::in_box;
using test::in_face;
using test::oracle_faces;
using test::OracleFace;

struct Hit {
  int id = -1;  // global face number, -1: nothing
  bool border = false;
};

// The face the sight ray through picture point q meets first. Orthographic: the ray
// q.x r/|r|² + q.y u/|u|² + s v (larger s nearer); perspective: E + l (q.x |d|²/|r|² r +
// q.y |d|²/|u|² u + d), l > 0, smaller nearer.
Hit first_face(const std::vector<OracleFace>& faces, const Camera& cam, const PicturePlane& pp, const Exact2& q) {
  const Vector3 &r = pp.r(), &u = pp.u(), &d = pp.d();
  Rational rr = dot(r, r), uu = dot(u, u), dd = dot(d, d);
  std::array<Rational, 3> base, dir;
  for (int k = 0; k < 3; ++k) {
    if (cam.perspective) {
      base[k] = cam.eye[k];
      dir[k] = q[0] * dd / rr * r[k] + q[1] * dd / uu * u[k] + d[k];
    } else {
      base[k] = q[0] / rr * r[k] + q[1] / uu * u[k];
      dir[k] = cam.direction[k];
    }
  }
  struct Found {
    Rational t;
    bool front;
    int id;
  };
  // Nearer along the ray, then (same point) the face toward the viewer, then the lower number.
  auto before = [&](const Found& x, const Found& y) {
    if (x.t != y.t) return cam.perspective ? x.t < y.t : x.t > y.t;
    if (x.front != y.front) return x.front;
    return x.id < y.id;
  };
  std::optional<Found> best;
  std::vector<Rational> borders;
  const std::array<double, 2> qd{q[0].get_d(), q[1].get_d()};
  for (const OracleFace& f : faces) {
    if (!in_box(f.box, qd)) continue;  // its picture is far from q (scenes in the doubles' range)
    Rational nd = f.a * dir[0] + f.b * dir[1] + f.c * dir[2];
    if (nd == 0) continue;
    Rational t = -(f.a * base[0] + f.b * base[1] + f.c * base[2] + f.d) / nd;
    if (cam.perspective && t <= 0) continue;
    std::array<Rational, 3> x{base[0] + t * dir[0], base[1] + t * dir[1], base[2] + t * dir[2]};
    int in = in_face(f, x);
    if (in < 0) continue;
    if (in == 0) {
      borders.push_back(t);
      continue;
    }
    // Facing: the eye (or the direction toward the viewer) on the positive side of its plane.
    bool front = cam.perspective ? f.a * cam.eye.x() + f.b * cam.eye.y() + f.c * cam.eye.z() + f.d > 0 : nd > 0;
    Found here{t, front, f.id};
    if (!best || before(here, *best)) best = here;
  }
  Hit h;
  if (best) h.id = best->id;
  for (const Rational& t : borders)  // a border as near as the face seen: the point is on an outline
    if (!best || t == best->t || (cam.perspective ? t < best->t : t > best->t)) h.border = true;
  return h;
}

// 1 inside, 0 on the border, -1 outside a convex counter-clockwise polygon.
int in_convex(const std::vector<Exact2>& p, const Exact2& q) {
  int res = 1;
  for (std::size_t i = 0; i < p.size(); ++i) {
    int o = orient2d(p[i], p[(i + 1) % p.size()], q);
    if (o < 0) return -1;
    if (o == 0) res = 0;
  }
  return res;
}

struct Tally {
  long checked = 0, wrong = 0, skipped = 0;
};

Tally check_painter(const std::vector<const Polyhedron*>& bodies, const Camera& cam, int samples_per_face, unsigned seed = 1,
                    PriorityResult* out = nullptr, std::size_t max_points = 3000) {
  LineOptions lo;
  lo.edges = EdgeSelection::All;
  LineDrawing lines = face_occluders(bodies, cam, lo);
  PriorityResult pr = priority_list(bodies, cam, lines);
  PicturePlane pp(cam);
  auto faces = oracle_faces(bodies, pp);
  std::vector<int> offset;
  for (std::size_t b = 0, n = 0; b < bodies.size(); n += bodies[b]->num_faces(), ++b) offset.push_back(static_cast<int>(n));
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> w(1, 997);
  Tally t;
  // Sample points: random interior points of every face's picture (and of the painted parts).
  std::vector<Exact2> points;
  for (const OracleFace& f : faces) {
    std::vector<Exact2> pic;
    for (const Point3& v : f.v) pic.push_back(pp.project(v));
    if (picture_area2(pic) == 0) continue;  // seen edge-on: every point of it is on an outline
    for (int s = 0; s < samples_per_face; ++s) {
      Rational sx = 0, sy = 0, sw = 0;
      for (const Exact2& c : pic) {
        Rational k(w(rng));
        sx += k * c[0], sy += k * c[1], sw += k;
      }
      points.push_back({sx / sw, sy / sw});
    }
  }
  std::shuffle(points.begin(), points.end(), rng);
  if (points.size() > max_points) points.resize(max_points);
  std::vector<std::array<double, 4>> painted_box;
  for (const PriorityPolygon& p : pr.polygons) painted_box.push_back(box_of(p.pts));
  for (const Exact2& q : points) {
    Hit h = first_face(faces, cam, pp, q);
    int painted = -1;
    bool border = h.border;
    const std::array<double, 2> qd{q[0].get_d(), q[1].get_d()};
    for (auto it = pr.order.rbegin(); it != pr.order.rend() && !border; ++it) {
      if (!in_box(painted_box[*it], qd)) continue;
      int in = in_convex(pr.polygons[*it].pts, q);
      if (in == 0) border = true;
      if (in > 0) {
        painted = offset[pr.polygons[*it].body] + pr.polygons[*it].face;
        break;
      }
    }
    if (border) {
      ++t.skipped;
      continue;
    }
    ++t.checked;
    if (painted != h.id) {
      ++t.wrong;
      if (t.wrong <= 5) ADD_FAILURE() << "at (" << q[0] << ", " << q[1] << ") the painter shows face " << painted << ", the ray meets " << h.id;
    }
  }
  EXPECT_EQ(t.wrong, 0);
  EXPECT_GT(t.checked, t.skipped);
  // Every polygon painted once, each with an area, each of a face of the scene.
  std::vector<char> seen(pr.polygons.size(), 0);
  for (int i : pr.order) {
    EXPECT_FALSE(seen[i]);
    seen[i] = 1;
    EXPECT_GT(picture_area2(pr.polygons[i].pts), 0);
  }
  if (out) *out = std::move(pr);
  return t;
}

std::vector<Camera> views(const Point3& target) {
  return {ortho("1", "1.3", "1.7"), ortho("0", "0", "1"), ortho("1", "1", "0"), ortho("-2", "1", "3"),
          ortho("1", "0", "0"),     ortho("3", "-1", "-2"), persp("9", "7", "6", target), persp("-5", "8", "3", target)};
}

long check_views(const std::vector<Polyhedron>& bodies, const Point3& target, int samples = 6) {
  long checked = 0;
  for (const Camera& c : views(target)) checked += check_painter(ptrs(bodies), c, samples).checked;
  return checked;
}

std::vector<Polyhedron> three_sticks() {
  return {parallelepiped(P("0", "0", "0"), P("6", "0", "2"), P("0", "1", "0"), P("0", "0", "1/2")),
          parallelepiped(P("5", "0", "0"), P("0", "6", "2"), P("1", "0", "0"), P("0", "0", "1/2")),
          parallelepiped(P("6", "6", "0"), P("-6", "-6", "5/2"), P("1/2", "-1/2", "0"), P("0", "0", "1/2"))};
}

}  // namespace

TEST(PriorityList, SingleBoxNeedsNoCut) {
  std::vector<Polyhedron> b{box("0", "0", "0", "1", "1", "1")};
  PriorityResult pr;
  check_painter(ptrs(b), ortho("1", "1", "1"), 8, 1, &pr);
  EXPECT_EQ(pr.order.size(), 3u);  // the three faces toward the viewer
  EXPECT_EQ(pr.splits, 0u);
  EXPECT_EQ(pr.swaps, 0u);
}

TEST(PriorityList, BoxBehindBoxIsPaintedFirst) {
  // Seen along -z... from +z: the lower box is farther and is painted first, whole.
  std::vector<Polyhedron> b{box("0", "0", "2", "2", "2", "3"), box("1", "1", "0", "3", "3", "1")};
  PriorityResult pr;
  check_painter(ptrs(b), ortho("0", "0", "1"), 8, 1, &pr);
  ASSERT_EQ(pr.order.size(), 2u);
  EXPECT_EQ(pr.polygons[pr.order[0]].body, 1);
  EXPECT_EQ(pr.polygons[pr.order[1]].body, 0);
  EXPECT_EQ(pr.splits, 0u);
}

TEST(PriorityList, ThreeStickCycleIsCut) {
  auto b = three_sticks();
  PriorityResult pr;
  check_painter(ptrs(b), ortho("0", "0", "1"), 12, 1, &pr);
  EXPECT_GT(pr.splits, 0u);  // no order of whole faces exists
  EXPECT_GT(check_views(b, P("3", "3", "1"), 6), 200);
}

TEST(PriorityList, CycleOfThreeOpenPolygons) {
  Scene s = load_scene(kData + "/problems/weiler_atherton_cycle.yaml");
  std::vector<Polyhedron> b;
  for (const auto& body : s.bodies) b.push_back(body.body);
  PriorityResult pr;
  check_painter(ptrs(b), ortho("0", "0", "1"), 30, 1, &pr);
  EXPECT_GT(pr.cycles + pr.splits, 0u);
  check_views(b, P("3", "3", "1"), 10);
}

TEST(PriorityList, PiercingPolygonsAreCutByThePlane) {
  // Two rectangles crossing like an X seen from the side: each is in front along half.
  std::vector<Polyhedron> b{quad(P("0", "0", "0"), P("4", "0", "2"), P("4", "2", "2"), P("0", "2", "0")),
                            quad(P("0", "0", "2"), P("0", "2", "2"), P("4", "2", "0"), P("4", "0", "0"))};
  PriorityResult pr;
  check_painter(ptrs(b), ortho("0", "0", "1"), 20, 1, &pr);
  EXPECT_GE(pr.splits, 1u);
  // The cut runs along x = 2, where the planes meet: some part has a corner there.
  bool at_two = false;
  for (int i : pr.order)
    for (const Point3& c : pr.polygons[i].corners) at_two |= c.x() == 2 && c.z() == 1;
  EXPECT_TRUE(at_two);
  check_views(b, P("2", "1", "1"), 10);
}

TEST(PriorityList, InterpenetratingBoxes) {
  std::vector<Polyhedron> b{box("0", "0", "0", "3", "3", "3"), box("1", "1", "-1", "5", "2", "2")};
  check_views(b, P("2", "2", "1"));
}

TEST(PriorityList, TouchingAndSharedFaces) {
  check_views({box("0", "0", "0", "4", "4", "1"), box("1", "1", "1", "3", "3", "2")}, P("2", "2", "1"));
  check_views({box("0", "0", "0", "2", "2", "2"), box("2", "0", "0", "4", "2", "2")}, P("2", "1", "1"));
  check_views({box("0", "0", "0", "6", "4", "1"), box("0", "0", "1", "6", "1", "3")}, P("3", "2", "1"));
}

TEST(PriorityList, CoplanarOverlappingOpenSurfaces) {
  // Two quads in one plane overlap: the tie goes to the face toward the viewer, then the lower
  // face number; a slanted quad and a box too.
  std::vector<Polyhedron> b{quad(P("0", "0", "0"), P("3", "0", "0"), P("3", "2", "0"), P("0", "2", "0")),
                            quad(P("1", "1", "0"), P("4", "1", "0"), P("4", "3", "0"), P("1", "3", "0")),
                            quad(P("0", "0", "1"), P("2", "0", "1"), P("2", "2", "3"), P("0", "2", "3")),
                            box("2", "-1", "-1", "3", "0", "2")};
  check_views(b, P("2", "1", "1"));
  // Seen from below the first two quads face away; still the lower number is on top.
  check_painter(ptrs(b), ortho("0", "0", "-1"), 10);
}

TEST(PriorityList, ViewsAlongFacesAndEdges) {
  std::vector<Polyhedron> b{box("0", "0", "0", "2", "2", "2"), box("1", "1", "2", "3", "3", "3"), box("3", "0", "0", "4", "4", "1")};
  for (const Camera& c : {ortho("1", "0", "0"), ortho("0", "1", "0"), ortho("1", "1", "0"), ortho("0", "0", "-1")})
    check_painter(ptrs(b), c, 6);
}

TEST(PriorityList, EyeCloseToAFace) {
  std::vector<Polyhedron> b{box("0", "0", "0", "2", "2", "2"), box("3", "0", "0", "5", "2", "2")};
  EXPECT_GT(check_painter(ptrs(b), persp("2.5", "1", "2.001", P("2.5", "1", "0")), 10).checked, 0);
}

TEST(PriorityList, DemoScene) {
  Scene s = load_scene(kData + "/demo.yaml");
  std::vector<Polyhedron> b;
  for (const auto& body : s.bodies) b.push_back(body.body);
  check_views(b, P("3", "2", "1"), 3);
}

TEST(PriorityList, RandomTriangles) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> c(0, 1024), e(-200, 200);
  for (int round = 0; round < 3; ++round) {
    std::vector<Polyhedron> b;
    for (int i = 0; i < 40; ++i) {
      int x = c(rng), y = c(rng), z = c(rng);
      auto p = [&](int dx, int dy, int dz) { return Point3(rational(x + dx, 1024), rational(y + dy, 1024), rational(z + dz, 1024)); };
      b.push_back(Polyhedron({p(0, 0, 0), p(e(rng), e(rng), e(rng)), p(e(rng), e(rng), e(rng))}, {{0, 1, 2}}));
    }
    for (const Camera& cam : {ortho("1", "1.3", "1.7"), ortho("0", "0", "1"), persp("3", "2", "4", P("0.5", "0.5", "0.5"))})
      check_painter(ptrs(b), cam, 6, static_cast<unsigned>(round));
  }
}

TEST(PriorityList, Fandisk) {
  std::string path = kCorpus + "/fandisk.off";
  ASSERT_TRUE(std::filesystem::exists(path)) << path << " (scripts/extract_corpus.sh)";
  std::vector<Polyhedron> b{load_mesh(path)};
  PriorityResult pr;
  check_painter(ptrs(b), ortho("1", "1.3", "1.7"), 1, 1, &pr, 1500);
  Point3 centre(Rational(0), Rational(0), Rational(0));
  for (const Point3& v : b[0].vertices()) centre = Point3(centre.x() + v.x(), centre.y() + v.y(), centre.z() + v.z());
  Rational n(static_cast<long>(b[0].num_vertices()));
  centre = Point3(centre.x() / n, centre.y() / n, centre.z() / n);
  Camera cam = make_perspective(Point3(centre.x() + 3, centre.y() + 4, centre.z() + 5), centre);
  check_painter(ptrs(b), cam, 1, 2, nullptr, 1500);
}

TEST(PriorityList, NestedBodies) {
  // A box inside a closed box is hidden; a box inside an open box (no top) is seen through the
  // opening, its top framed by the inner walls.
  std::vector<Polyhedron> closed{box("0", "0", "0", "4", "4", "4"), box("1", "1", "1", "3", "3", "3")};
  check_views(closed, P("2", "2", "2"));
  Polyhedron cup = box("0", "0", "0", "4", "4", "3");
  std::vector<Face> faces;
  for (std::size_t f = 0; f < cup.num_faces(); ++f) {
    bool top = true;
    for (int v : cup.faces()[f]) top = top && cup.vertices()[v].z() == 3;
    if (!top) faces.push_back(cup.faces()[f]);
  }
  std::vector<Polyhedron> open{Polyhedron(cup.vertices(), faces), box("1", "1", "0", "3", "3", "2")};
  PriorityResult pr;
  check_painter(ptrs(open), ortho("1", "1.3", "1.7"), 12, 1, &pr);
  check_views(open, P("2", "2", "1"));
}

TEST(PriorityList, NumbersWithManyDigitsAndFarOutsideDoubles) {
  // The three-stick cycle scaled by 10^-400 and 10^400 (doubles hold neither) and moved by a
  // number of 40 digits: the same cuts and the same order as the sticks themselves (a
  // similarity changes no decision), the oracle agrees.
  PriorityResult base;
  auto sticks = three_sticks();
  check_painter(ptrs(sticks), ortho("0", "0", "1"), 4, 1, &base);
  auto faces_of = [](const PriorityResult& r) {
    std::vector<std::pair<int, int>> out;
    for (int i : r.order) out.emplace_back(r.polygons[i].body, r.polygons[i].face);
    return out;
  };
  for (const char* k : {"1e-400", "1e400", "1234567890123456789012345678901234567891/1000000000000000000000000000000000000000"}) {
    Rational s = Q(k);
    std::vector<Polyhedron> b;
    for (const Polyhedron& p : three_sticks()) {
      std::vector<Point3> vs;
      for (const Point3& v : p.vertices()) vs.emplace_back(v.x() * s + s, v.y() * s, v.z() * s);
      b.emplace_back(std::move(vs), p.faces());
    }
    PriorityResult pr;
    check_painter(ptrs(b), ortho("0", "0", "1"), 12, 1, &pr);
    EXPECT_EQ(pr.splits, base.splits) << k;
    EXPECT_EQ(faces_of(pr), faces_of(base)) << k;
    check_painter(ptrs(b), ortho("1", "1.3", "1.7"), 8);
  }
}

TEST(PriorityList, GridAndFullScanPaintTheSameList) {
  // 80 random triangles: the grid (doubles hold the scene) and the full scan (scaled by 10^400,
  // where doubles cannot: the grid turns itself off) must paint the same list, cut for cut.
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> c(0, 1024), e(-200, 200);
  std::vector<Polyhedron> b, big;
  const Rational s = Q("1e400");
  for (int i = 0; i < 80; ++i) {
    int x = c(rng), y = c(rng), z = c(rng);
    std::array<std::array<int, 3>, 3> d{{{0, 0, 0}, {e(rng), e(rng), e(rng)}, {e(rng), e(rng), e(rng)}}};
    std::vector<Point3> vs, ws;
    for (const auto& k : d) {
      Point3 p(rational(x + k[0], 1024), rational(y + k[1], 1024), rational(z + k[2], 1024));
      vs.push_back(p);
      ws.emplace_back(p.x() * s, p.y() * s, p.z() * s);
    }
    b.emplace_back(std::move(vs), std::vector<Face>{{0, 1, 2}});
    big.emplace_back(std::move(ws), std::vector<Face>{{0, 1, 2}});
  }
  for (const Camera& cam : {ortho("1", "1.3", "1.7"), ortho("0", "0", "1")}) {
    PriorityResult small_r, big_r;
    check_painter(ptrs(b), cam, 3, 1, &small_r, 400);
    check_painter(ptrs(big), cam, 3, 1, &big_r, 150);
    ASSERT_EQ(small_r.order.size(), big_r.order.size());
    EXPECT_GT(small_r.splits, 0u);
    EXPECT_EQ(small_r.splits, big_r.splits);
    EXPECT_LT(small_r.pairs, big_r.pairs);  // the grid skipped pairs whose boxes are apart
    for (std::size_t i = 0; i < small_r.order.size(); ++i) {
      const PriorityPolygon &p = small_r.polygons[small_r.order[i]], &q = big_r.polygons[big_r.order[i]];
      ASSERT_EQ(p.corners.size(), q.corners.size());
      for (std::size_t k = 0; k < p.corners.size(); ++k) EXPECT_EQ(p.corners[k].x() * s, q.corners[k].x());
    }
  }
}

TEST(PriorityList, PerspectiveNeedsBodiesInFrontOfTheEye) {
  // A wall that reaches behind the eye: the line drawing takes it, the painter does not.
  std::vector<Polyhedron> b{quad(P("3", "0", "0"), P("3", "2", "0"), P("3", "2", "10"), P("3", "0", "10"))};
  Camera c = persp("1", "1", "5", P("1", "1", "0"));
  LineDrawing lines = face_occluders(ptrs(b), c, {EdgeSelection::All});
  EXPECT_THROW(priority_list(ptrs(b), c, lines), std::invalid_argument);
}
