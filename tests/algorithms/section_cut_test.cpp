// Sections (algorithms/sections): the cut solid and its caps against an independent exact
// oracle (a ray's crossings with the faces, exactly), on random tetrahedra, boxes and the L
// and U prisms cut by random planes, planes through vertices and planes holding faces; the
// hatch lines of a cap with a hole lie inside it.
#include "algorithms/sections/section_cut.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <set>

#include "algorithms/hatching/hatch.hpp"
#include "algorithms/solids/face_triangles.hpp"
#include "io/readers/mesh_reader.hpp"
#include "support/numbers.hpp"

using namespace hlr;
using hlr::test::Q;

namespace {

Point3 P(long x, long y, long z) { return Point3(Rational(x), Rational(y), Rational(z)); }

// Where x lies for the closed body p: 1 inside, 0 outside, -1 not decided along `dir` (the ray
// meets an edge or lies in a face's plane, or x is on the surface).
int ray_inside(const Polyhedron& p, const Point3& x, const Vector3& dir) {
  int count = 0;
  for (std::size_t f = 0; f < p.num_faces(); ++f) {
    const FaceTriangles ft = face_triangles(p, static_cast<int>(f));
    for (const FaceTriangle& t : ft.triangles) {
      const Point3& a = p.vertices()[p.faces()[f][t.v[0]]];
      const Point3& b = p.vertices()[p.faces()[f][t.v[1]]];
      const Point3& c = p.vertices()[p.faces()[f][t.v[2]]];
      const Vector3 n = cross(b - a, c - a);
      const Rational den = dot(n, dir), num = dot(n, a - x);
      if (den == 0) {
        if (num == 0) return -1;
        continue;
      }
      const Rational t_hit = num / den;
      if (t_hit < 0) continue;
      const Point3 h = x + t_hit * dir;
      const int s0 = sgn(dot(cross(b - a, h - a), n)), s1 = sgn(dot(cross(c - b, h - b), n)), s2 = sgn(dot(cross(a - c, h - c), n));
      const bool in = s0 >= 0 && s1 >= 0 && s2 >= 0;
      if (!in) continue;
      if (s0 == 0 || s1 == 0 || s2 == 0 || t_hit == 0) return -1;
      ++count;
    }
  }
  return count % 2;
}

// The same along +z, each triangle first rejected exactly by its x and y range (fast on
// meshes of thousands of faces); -1 when the ray meets an edge or a vertex.
int ray_inside_z(const Polyhedron& p, const Point3& x) {
  int count = 0;
  for (std::size_t f = 0; f < p.num_faces(); ++f) {
    const FaceTriangles ft = face_triangles(p, static_cast<int>(f));
    for (const FaceTriangle& t : ft.triangles) {
      const Point3* c[3] = {&p.vertices()[p.faces()[f][t.v[0]]], &p.vertices()[p.faces()[f][t.v[1]]], &p.vertices()[p.faces()[f][t.v[2]]]};
      bool left = true, right = true, below = true, above = true;
      for (const Point3* v : c)
        left = left && v->x() < x.x(), right = right && v->x() > x.x(), below = below && v->y() < x.y(), above = above && v->y() > x.y();
      if (left || right || below || above) continue;
      const int r = ray_inside(Polyhedron({*c[0], *c[1], *c[2]}, {{0, 1, 2}}), x, Vector3(0, 0, 1));
      if (r < 0) return -1;
      count += r;
    }
  }
  return count % 2;
}

// ray_inside along a few generic directions; -1 when every one is undecided.
int inside(const Polyhedron& p, const Point3& x) {
  if (p.num_faces() > 200) {
    const int r = ray_inside_z(p, x);
    if (r >= 0) return r;
  }
  for (const Vector3& d :
       {Vector3(Q("1"), Q("0.3137"), Q("0.7219")), Vector3(Q("-0.4411"), Q("1"), Q("0.1931")), Vector3(Q("0.2713"), Q("-0.5923"), Q("1"))}) {
    const int r = ray_inside(p, x, d);
    if (r >= 0) return r;
  }
  return -1;
}

Polyhedron prism(const std::vector<std::array<long, 2>>& poly, long z0, long z1) {
  std::vector<Point3> v;
  const int n = static_cast<int>(poly.size());
  for (long z : {z0, z1})
    for (const auto& q : poly) v.push_back(P(q[0], q[1], z));
  std::vector<Face> f;
  Face bottom, top;
  for (int k = n - 1; k >= 0; --k) bottom.push_back(k);
  for (int k = 0; k < n; ++k) top.push_back(n + k);
  f.push_back(bottom);
  f.push_back(top);
  for (int k = 0; k < n; ++k) f.push_back(Face{k, (k + 1) % n, n + (k + 1) % n, n + k});
  return Polyhedron(v, orient_faces(v, f));
}

Polyhedron l_prism() { return prism({{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}}, 0, 2); }
Polyhedron u_prism() { return prism({{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}, 0, 2); }

Polyhedron tetrahedron(std::mt19937& rng) {
  std::uniform_int_distribution<long> c(0, 10);
  for (;;) {
    std::vector<Point3> v;
    for (int k = 0; k < 4; ++k) v.push_back(P(c(rng), c(rng), c(rng)));
    std::vector<Face> f = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    if (six_signed_volume(v, f) == 0) continue;
    return Polyhedron(v, orient_faces(v, f));
  }
}

// A square ring: outer [0,3]^2, inner [1,2]^2, z in [0,1] (its top and bottom in four pieces).
Polyhedron ring() {
  std::vector<Point3> v;
  const long sq[2][4][2] = {{{0, 0}, {3, 0}, {3, 3}, {0, 3}}, {{1, 1}, {2, 1}, {2, 2}, {1, 2}}};
  for (long z : {0L, 1L})
    for (int s = 0; s < 2; ++s)
      for (int k = 0; k < 4; ++k) v.push_back(P(sq[s][k][0], sq[s][k][1], z));
  auto id = [](int z, int s, int k) { return z * 8 + s * 4 + (k % 4); };
  std::vector<Face> f;
  for (int k = 0; k < 4; ++k) {
    f.push_back(Face{id(0, 0, k), id(0, 0, k + 1), id(1, 0, k + 1), id(1, 0, k)});  // outer wall
    f.push_back(Face{id(0, 1, k + 1), id(0, 1, k), id(1, 1, k), id(1, 1, k + 1)});  // inner wall
    f.push_back(Face{id(1, 0, k), id(1, 0, k + 1), id(1, 1, k + 1), id(1, 1, k)});  // top
    f.push_back(Face{id(0, 0, k + 1), id(0, 0, k), id(0, 1, k), id(0, 1, k + 1)});  // bottom
  }
  return Polyhedron(v, orient_faces(v, f));
}

Rational random_q(std::mt19937& rng, long lo, long hi) {
  std::uniform_int_distribution<long> n(lo * 97, hi * 97);
  return Rational(n(rng)) / 97;  // in lowest terms (GMP's operations need canonical fractions)
}

// A point of face f's triangle t strictly inside it (barycentric weights 1..5 / sum).
Point3 inside_triangle(const Point3& a, const Point3& b, const Point3& c, std::mt19937& rng) {
  std::uniform_int_distribution<int> w(1, 5);
  const Rational wa = w(rng), wb = w(rng), wc = w(rng), s = wa + wb + wc;
  return Point3((wa * a.x() + wb * b.x() + wc * c.x()) / s, (wa * a.y() + wb * b.y() + wc * c.y()) / s, (wa * a.z() + wb * b.z() + wc * c.z()) / s);
}

bool in_triangle(const Point3& a, const Point3& b, const Point3& c, const Point3& x) {
  const Vector3 n = cross(b - a, c - a);
  return sgn(dot(cross(b - a, x - a), n)) >= 0 && sgn(dot(cross(c - b, x - b), n)) >= 0 && sgn(dot(cross(a - c, x - c), n)) >= 0;
}

struct Tally {
  int solid_points = 0, cap_points = 0, plane_points = 0;
};

// Where the random points are drawn and how many.
struct Region {
  std::array<Rational, 3> lo{Rational(-1), Rational(-1), Rational(-1)}, hi{Rational(11), Rational(11), Rational(11)};
  int solid_points = 60, plane_points = 150, cap_faces = 1 << 30;
  Point3 point(std::mt19937& rng) const {
    Rational q[3];
    for (int k = 0; k < 3; ++k) q[k] = lo[k] + (hi[k] - lo[k]) * (random_q(rng, 0, 1));
    return Point3(q[0], q[1], q[2]);
  }
};

Region box_region(const Polyhedron& p, int solid_points, int plane_points, int cap_faces) {
  Region r;
  r.lo = r.hi = {p.vertices()[0].x(), p.vertices()[0].y(), p.vertices()[0].z()};
  for (const Point3& v : p.vertices())
    for (int k = 0; k < 3; ++k) r.lo[k] = std::min(r.lo[k], v[k]), r.hi[k] = std::max(r.hi[k], v[k]);
  r.solid_points = solid_points, r.plane_points = plane_points, r.cap_faces = cap_faces;
  return r;
}

// Every oracle check of one cut.
// `away`: cut_away (the planes' region removed), else cut_solid (kept).
void check_cut(const Polyhedron& body, const std::vector<Plane>& planes, std::mt19937& rng, Tally& tally, const std::string& what, bool away = false,
               const Region& region = Region{}) {
  SCOPED_TRACE(what + (away ? ", cut away" : ""));
  const CutSolid c = away ? cut_away(body, planes) : cut_solid(body, planes);
  ASSERT_FALSE(c.open);
  auto in_region = [&](const Point3& x) {
    for (const Plane& h : planes)
      if (h.value(x) > 0) return false;
    return true;
  };
  auto in_open_region = [&](const Point3& x) {
    for (const Plane& h : planes)
      if (h.value(x) >= 0) return false;
    return true;
  };
  auto kept = [&](const Point3& x) { return away ? !in_region(x) : in_region(x); };
  if (c.state == CutSolid::State::Removed) {
    for (const Point3& v : body.vertices())
      if (away) EXPECT_TRUE(in_region(v)) << "a vertex outside the removed region of a removed body";
      else EXPECT_FALSE(in_open_region(v)) << "a vertex strictly on the kept side of a removed body";
    return;
  }
  if (c.state == CutSolid::State::Whole) {
    for (const Point3& v : body.vertices()) EXPECT_TRUE(away ? !in_open_region(v) : in_region(v));
    return;
  }
  const Polyhedron cut(c.vertices, c.faces);
  ASSERT_EQ(c.part.size(), cut.num_faces());
  ASSERT_EQ(c.cap.size(), cut.num_faces());
  // The cut solid is closed and oriented: every cap edge is in two faces.
  EXPECT_TRUE(cut.report().closed()) << cut.report().boundary_edges.size() << " boundary edges" << [&] {
    std::string t;
    for (const auto& e : cut.report().boundary_edges) t += " " + to_string(cut.vertices()[e.first]) + "-" + to_string(cut.vertices()[e.second]);
    for (const Plane& h : planes) t += " plane " + to_string(h);
    for (const Point3& v : body.vertices()) t += " v" + to_string(v);
    return t;
  }();
  EXPECT_TRUE(cut.report().oriented());
  // Faces: a cap lies in its plane facing the removed side; any other face lies in its input face's plane.
  for (std::size_t f = 0; f < cut.num_faces(); ++f) {
    const Plane& h = cut.planes()[f];
    if (c.cap[f] >= 0) {
      const Plane& k = planes[c.cap[f]];
      for (int v : cut.faces()[f]) EXPECT_EQ(k.value(cut.vertices()[v]), 0);
      EXPECT_EQ(sgn(dot(h.normal(), k.normal())), away ? -1 : 1);  // facing the removed side
    } else {
      ASSERT_LT(c.part[f], static_cast<int>(body.num_faces()));
      EXPECT_EQ(primitive_plane(h), primitive_plane(body.planes()[c.part[f]]));
    }
  }
  // Random points: inside the cut solid exactly when inside the body and on the kept side.
  for (int k = 0; k < region.solid_points; ++k) {
    const Point3 x = region.point(rng);
    bool off = false;
    for (const Plane& h : planes) off = off || h.value(x) == 0;
    if (off) continue;
    const int in_body = inside(body, x), in_cut = inside(cut, x);
    if (in_body < 0 || in_cut < 0) continue;
    EXPECT_EQ(in_cut, in_body && kept(x) ? 1 : 0) << to_string(x);
    ++tally.solid_points;
  }
  for (std::size_t p = 0; p < planes.size(); ++p) {
    std::vector<int> cap;
    for (std::size_t f = 0; f < cut.num_faces(); ++f)
      if (c.cap[f] == static_cast<int>(p)) cap.push_back(static_cast<int>(f));
    auto corner = [&](int f, int i) -> const Point3& { return cut.vertices()[cut.faces()[f][i]]; };
    // Random points of the cap: on the plane, inside the body.
    std::vector<int> sampled = cap;
    std::shuffle(sampled.begin(), sampled.end(), rng);
    if (static_cast<int>(sampled.size()) > region.cap_faces) sampled.resize(static_cast<std::size_t>(region.cap_faces));
    for (int f : sampled) {
      const Point3 x = inside_triangle(corner(f, 0), corner(f, 1), corner(f, 2), rng);
      EXPECT_EQ(planes[p].value(x), 0);
      const int r = inside(body, x);
      if (r < 0) continue;
      EXPECT_EQ(r, 1) << "a cap point outside the body: " << to_string(x);
      ++tally.cap_points;
    }
    // Random points of the plane inside the body and on the other planes' kept sides: in the cap.
    const Vector3 n = planes[p].normal();
    const int a = n.z() != 0 ? 2 : n.y() != 0 ? 1 : 0;
    for (int k = 0; k < region.plane_points; ++k) {
      const Point3 r0 = region.point(rng);
      Rational q[3] = {r0.x(), r0.y(), r0.z()};
      q[a] = 0;
      const Rational rest = planes[p].value(Point3(q[0], q[1], q[2]));
      q[a] = -rest / n[a];
      const Point3 x(q[0], q[1], q[2]);
      if (!in_region(x)) continue;
      bool strictly = true;
      for (std::size_t o = 0; o < planes.size(); ++o) strictly = strictly && (o == p || planes[o].value(x) < 0);
      if (!strictly || inside(body, x) != 1) continue;
      bool found = false;
      for (int f : cap)  // a cap face is a triangle, or a convex piece of one that a later plane cut
        for (std::size_t i = 1; i + 1 < cut.faces()[f].size(); ++i)
          found = found || in_triangle(corner(f, 0), corner(f, static_cast<int>(i)), corner(f, static_cast<int>(i) + 1), x);
      EXPECT_TRUE(found) << "a point of the plane inside the body is in no cap: " << to_string(x) << " plane " << p << " of " << [&] {
        std::string t;
        for (const Plane& h : planes) t += to_string(h) + " ";
        return t;
      }();
      ++tally.plane_points;
    }
  }
}

}  // namespace

TEST(SectionCut, BoxByAnAxisPlaneIsTheSmallerBox) {
  const Polyhedron box = make_box(P(0, 0, 0), P(2, 3, 4));
  const CutSolid c = cut_solid(box, {Plane(0, 0, 1, -1)});  // keep z <= 1
  ASSERT_EQ(c.state, CutSolid::State::Cut);
  EXPECT_EQ(six_signed_volume(c.vertices, c.faces), 36);  // 6 * 2 * 3 * 1
  std::set<Point3> corners(c.vertices.begin(), c.vertices.end());
  const Polyhedron small = make_box(P(0, 0, 0), P(2, 3, 1));
  EXPECT_EQ(corners, std::set<Point3>(small.vertices().begin(), small.vertices().end()));
  int caps = 0;
  for (std::size_t f = 0; f < c.faces.size(); ++f)
    if (c.cap[f] == 0) {
      ++caps;
      EXPECT_EQ(c.part[f], 6);  // the cap is part 6: after the box's six faces
    }
  EXPECT_EQ(caps, 2);  // the rectangle in two triangles
}

TEST(SectionCut, PlanesThatOnlyTouchLeaveTheBodyWholeOrRemoveIt) {
  const Polyhedron box = make_box(P(0, 0, 0), P(1, 1, 1));
  EXPECT_EQ(cut_solid(box, {Plane(0, 0, 1, -1)}).state, CutSolid::State::Whole);   // z <= 1: the top face lies in it
  EXPECT_EQ(cut_solid(box, {Plane(0, 0, 1, 0)}).state, CutSolid::State::Removed);  // z <= 0: only the bottom face
  EXPECT_EQ(cut_solid(box, {Plane(0, 0, 1, -5)}).state, CutSolid::State::Whole);
  // The L prism cut at its step (y = 1): the step face stays a face, the cap covers the narrow arm only.
  const CutSolid l = cut_solid(l_prism(), {Plane(0, 1, 0, -1)});
  ASSERT_EQ(l.state, CutSolid::State::Cut);
  Rational cap_area2 = 0;
  for (std::size_t f = 0; f < l.faces.size(); ++f)
    if (l.cap[f] >= 0) {
      const Point3 &a = l.vertices[l.faces[f][0]], &b = l.vertices[l.faces[f][1]], &c = l.vertices[l.faces[f][2]];
      cap_area2 += dot(cross(b - a, c - a), Vector3(0, 1, 0));
    }
  EXPECT_EQ(cap_area2, 2 * 2);                               // x in [0, 1], z in [0, 2]: area 2
  EXPECT_EQ(six_signed_volume(l.vertices, l.faces), 6 * 8);  // 4 * 1 * 2
}

TEST(SectionCut, AnOpenMeshIsCutWithoutACap) {
  const Polyhedron box = make_box(P(0, 0, 0), P(1, 1, 1));
  std::vector<Face> five(box.faces().begin(), box.faces().begin() + 5);
  const CutSolid c = cut_solid(Polyhedron(box.vertices(), five), {Plane(0, 0, 2, -1)});
  EXPECT_EQ(c.state, CutSolid::State::Cut);
  EXPECT_TRUE(c.open);
  for (int k : c.cap) EXPECT_EQ(k, -1);
}

TEST(SectionCut, OracleOnRandomBodiesAndPlanes) {
  std::mt19937 rng(20261202);
  std::uniform_int_distribution<long> nc(-3, 3);
  Tally tally;
  std::vector<std::pair<std::string, Polyhedron>> bodies = {
      {"L", l_prism()}, {"U", u_prism()}, {"ring", ring()}, {"box", make_box(P(1, 2, 0), P(7, 5, 9))}};
  for (int k = 0; k < 6; ++k) bodies.push_back({"tetrahedron " + std::to_string(k), tetrahedron(rng)});
  for (const auto& [name, body] : bodies)
    for (int trial = 0; trial < 8; ++trial) {
      std::vector<Plane> planes;
      const int count = trial < 5 ? 1 : trial < 7 ? 2 : 3;
      for (int i = 0; i < count; ++i) {
        Vector3 n;
        do n = trial % 3 == 0 ? Vector3(0, 0, nc(rng) < 0 ? -1 : 1) : Vector3(nc(rng), nc(rng), nc(rng));
        while (n.is_zero());
        // Through a vertex (a degenerate place: vertices and faces in the plane) or a random point.
        const Point3 at = trial % 2 == 0 ? body.vertices()[static_cast<std::size_t>(rng() % body.num_vertices())]
                                         : Point3(random_q(rng, 0, 6), random_q(rng, 0, 6), random_q(rng, 0, 6));
        planes.emplace_back(n.x(), n.y(), n.z(), -dot(n, at - Point3()));
      }
      check_cut(body, planes, rng, tally, name + ", trial " + std::to_string(trial));
      check_cut(body, planes, rng, tally, name + ", trial " + std::to_string(trial), true);
    }
  // The oracle decided enough points to mean something.
  EXPECT_GT(tally.solid_points, 1500);
  EXPECT_GT(tally.cap_points, 50);
  EXPECT_GT(tally.plane_points, 150);
}

// CGAL's fandisk (curved, 12,946 triangles) and couplingdown (holes through a flange): random
// planes through vertices and through random points, axis-aligned and oblique, one to three of
// them, kept and cut away; the oracle as above with fewer points (each is a ray against every face).
TEST(SectionCut, OracleOnCgalMeshes) {
  std::mt19937 rng(4040);
  std::uniform_int_distribution<long> nc(-3, 3);
  Tally tally;
  int meshes = 0;
  for (const char* name : {"fandisk.off", "couplingdown.off"}) {
    const std::string path = std::string(HLR_CORPUS_DIR) + "/" + name;
    if (!std::filesystem::exists(path)) continue;  // scripts/extract_corpus.sh makes them
    ++meshes;
    const Polyhedron body = load_mesh(path);
    const Region region = box_region(body, 12, 36, 6);
    for (int trial = 0; trial < 4; ++trial) {
      std::vector<Plane> planes;
      for (int i = 0; i < 1 + trial / 2; ++i) {
        Vector3 n;
        do n = trial == 0 ? Vector3(0, 0, 1) : Vector3(nc(rng), nc(rng), nc(rng));
        while (n.is_zero());
        const Point3 at = trial % 2 == 1 ? body.vertices()[static_cast<std::size_t>(rng() % body.num_vertices())] : region.point(rng);
        planes.emplace_back(n.x(), n.y(), n.z(), -dot(n, at - Point3()));
      }
      check_cut(body, planes, rng, tally, std::string(name) + ", trial " + std::to_string(trial), false, region);
      check_cut(body, planes, rng, tally, std::string(name) + ", trial " + std::to_string(trial), true, region);
    }
  }
  if (meshes == 0) GTEST_SKIP() << "CGAL's meshes are not extracted (scripts/extract_corpus.sh)";
  EXPECT_GT(tally.solid_points, 50 * meshes);
  EXPECT_GT(tally.cap_points, 20 * meshes);
  EXPECT_GT(tally.plane_points, 30 * meshes);
}

TEST(Hatch, LinesStayInsideACapWithAHole) {
  const CutSolid c = cut_solid(ring(), {Plane(0, 0, 2, -1)});  // z <= 1/2: the cap is the square ring
  ASSERT_EQ(c.state, CutSolid::State::Cut);
  std::vector<std::array<int, 2>> border;
  std::set<std::pair<int, int>> edges;
  for (std::size_t f = 0; f < c.faces.size(); ++f)
    if (c.cap[f] >= 0)
      for (int k = 0; k < 3; ++k) edges.insert({c.faces[f][k], c.faces[f][(k + 1) % 3]});
  for (const auto& [u, v] : edges)
    if (!edges.count({v, u})) border.push_back({u, v});
  EXPECT_EQ(border.size(), 8u);  // the outer and the inner square
  // Seen from above (page x, y = world x, y): lines (x + y) / sqrt 2 = c at 45 degrees, 0.1 apart.
  auto lift = [](double x, double y) { return std::array<double, 3>{x, y, 0.5}; };
  const auto lines = hatch_lines(c.vertices, border, Plane(0, 0, 2, -1), lift, 45, 0.05, 0.1, 4.25, {0, 0, 3, 3}, 3);
  ASSERT_FALSE(lines.empty());
  std::vector<std::array<Point3, 2>> segs;
  for (const HatchLine& l : lines) {
    EXPECT_EQ(l.p0.z(), Q("0.5"));  // the ends snapped exactly onto the plane
    EXPECT_EQ(l.p1.z(), Q("0.5"));
    for (const auto& [t0, t1] : l.inside) segs.push_back({l.p0 + t0 * (l.p1 - l.p0), l.p0 + t1 * (l.p1 - l.p0)});
  }
  ASSERT_FALSE(segs.empty());
  auto in_ring = [](const Point3& x) {
    const bool outer = x.x() >= 0 && x.x() <= 3 && x.y() >= 0 && x.y() <= 3;
    const bool hole = x.x() > 1 && x.x() < 2 && x.y() > 1 && x.y() < 2;
    return outer && !hole;
  };
  double length = 0;
  for (const auto& s : segs) {
    EXPECT_EQ(s[0].z(), Q("0.5"));
    EXPECT_EQ(s[1].z(), Q("0.5"));
    for (int t = 0; t <= 16; ++t) {  // every point of the segment in the ring (a segment over the hole fails)
      const Rational w = Rational(t) / 16;
      EXPECT_TRUE(in_ring(s[0] + w * (s[1] - s[0]))) << to_string(s[0]) << " " << to_string(s[1]);
    }
    length += std::hypot(to_double(s[1].x() - s[0].x()), to_double(s[1].y() - s[0].y()));
  }
  // Lines 0.1 apart over the ring's area 8.
  const double expected = 8 / 0.1;
  EXPECT_NEAR(length, expected, 0.03 * expected);
}
