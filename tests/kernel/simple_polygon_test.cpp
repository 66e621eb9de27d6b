// Simple polygons (kernel/simple_polygon.hpp): the exact simplicity test on each way a polygon
// can fail to be simple, and triangulations checked by exact area and orientation.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "algorithms/solids/face_triangles.hpp"
#include "kernel/simple_polygon.hpp"

namespace hlr {
namespace {

struct Poly {
  std::vector<Point3> pts;
  std::vector<int> idx;
  explicit Poly(const std::vector<std::pair<Rational, Rational>>& xy) {
    for (const auto& [x, y] : xy) {
      idx.push_back(static_cast<int>(pts.size()));
      pts.emplace_back(x, y, Rational(0));
    }
  }
};

const PolygonView kUp = polygon_view(Vector3(Rational(0), Rational(0), Rational(1)));

bool simple(const std::vector<std::pair<Rational, Rational>>& xy) {
  Poly p(xy);
  return polygon_is_simple(p.pts, p.idx, kUp);
}

// Twice the signed area in the view (shoelace), exact.
Rational area2(const std::vector<Point3>& pts, const std::vector<int>& idx) {
  Rational a = 0;
  for (std::size_t k = 0; k < idx.size(); ++k) {
    const Point3 &p = pts[idx[k]], &q = pts[idx[(k + 1) % idx.size()]];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return a;
}

// Every triangle counter-clockwise with positive area, areas adding up to the polygon's, the
// edge flags true exactly on polygon edges, n - 2 triangles.
void check_triangulation(const Poly& p) {
  auto tris = triangulate_simple_polygon(p.pts, p.idx, kUp);
  const int n = static_cast<int>(p.idx.size());
  EXPECT_EQ(static_cast<int>(tris.size()), n - 2);
  Rational sum = 0;
  for (const auto& t : tris) {
    std::vector<int> tri = {p.idx[t.v[0]], p.idx[t.v[1]], p.idx[t.v[2]]};
    Rational a = area2(p.pts, tri);
    EXPECT_GT(a, 0);
    sum += a;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(t.edge[k], (t.v[k] + 1) % n == t.v[(k + 1) % 3]);
  }
  EXPECT_EQ(sum, area2(p.pts, p.idx));
}

TEST(SimplePolygon, ConvexAndNonConvexAreSimple) {
  EXPECT_TRUE(simple({{0, 0}, {3, 0}, {3, 2}, {0, 2}}));
  EXPECT_TRUE(simple({{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}));                // an arrow (reflex vertex)
  EXPECT_TRUE(simple({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}));                // a vertex on a straight side
}

TEST(SimplePolygon, CrossingEdgesAreNot) {
  EXPECT_FALSE(simple({{0, 0}, {2, 2}, {2, 0}, {0, 2}}));                       // symmetric bow-tie
  EXPECT_FALSE(simple({{0, 0}, {5, 3}, {5, 0}, {0, 1}}));                       // asymmetric bow-tie
  EXPECT_FALSE(simple({{0, 0}, {3, 0}, {3, 2}, {1, -1}, {0, 2}}));              // data/bad/self_intersecting_face.off
}

TEST(SimplePolygon, StarWithEveryTurnOneWayIsNot) {
  // A pentagram: every turn to the left, but the edges go round twice.
  std::vector<std::pair<Rational, Rational>> star;
  const int order[5] = {0, 2, 4, 1, 3};
  const Rational xs[5] = {Rational(0), Rational(95, 100), Rational(59, 100), Rational(-59, 100), Rational(-95, 100)};
  const Rational ys[5] = {Rational(1), Rational(31, 100), Rational(-81, 100), Rational(-81, 100), Rational(31, 100)};
  for (int k : order) star.push_back({xs[k], ys[k]});
  EXPECT_FALSE(simple(star));
  Poly p(star);
  EXPECT_FALSE(polygon_is_convex(p.pts, p.idx, kUp));
}

TEST(SimplePolygon, TouchingIsNot) {
  EXPECT_FALSE(simple({{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}));               // a vertex on another edge
  EXPECT_FALSE(simple({{0, 0}, {4, 0}, {2, 2}, {4, 4}, {0, 4}, {2, 2}}));       // a repeated point
  EXPECT_FALSE(simple({{0, 0}, {4, 0}, {2, 0}, {2, 3}}));                       // a spike back along its edge
}

TEST(SimplePolygon, TriangulationsAddUpExactly) {
  check_triangulation(Poly({{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}));
  check_triangulation(Poly({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}));
  // A comb: many reflex vertices.
  std::vector<std::pair<Rational, Rational>> comb = {{0, 0}, {20, 0}};
  for (int k = 9; k >= 0; --k) {
    comb.push_back({2 * k + 2, 5});
    comb.push_back({2 * k + 1, 1});
  }
  comb.push_back({0, 5});
  check_triangulation(Poly(comb));
  // A star of 400 points with rational radii, and a regular-ish convex 200-gon (halving).
  std::vector<std::pair<Rational, Rational>> star, round;
  for (int k = 0; k < 400; ++k) {
    double a = 2 * M_PI * k / 400, r = k % 2 ? 600 : 1000;
    star.push_back({rational_from_double(std::round(r * std::cos(a))), rational_from_double(std::round(r * std::sin(a)))});
  }
  for (int k = 0; k < 200; ++k) {
    // Rational points on the unit circle: ((1 - t^2)/(1 + t^2), 2t/(1 + t^2)), t = tan(a/2).
    Rational t = rational_from_double(std::tan(M_PI * (k + 0.5) / 200 - M_PI / 2));
    round.push_back({(1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)});
  }
  check_triangulation(Poly(star));
  Poly r(round);
  EXPECT_TRUE(polygon_is_convex(r.pts, r.idx, kUp));
  check_triangulation(r);
}

TEST(SimplePolygon, ClockwiseFacesKeepTheirOrientation) {
  // Seen from -z the same square is counter-clockwise: triangles come back clockwise in (x, y).
  Poly p({{0, 0}, {0, 2}, {3, 2}, {3, 0}});
  const PolygonView down = polygon_view(Vector3(Rational(0), Rational(0), Rational(-1)));
  for (const auto& t : triangulate_simple_polygon(p.pts, p.idx, down)) {
    std::vector<int> tri = {t.v[0], t.v[1], t.v[2]};
    EXPECT_LT(area2(p.pts, tri), 0);
  }
}

}  // namespace
}  // namespace hlr

// face_triangles' 128-bit route (planar, strictly convex faces of 4 to 12 vertices with decimal
// coordinates) gives the rational route's verdict and triangles: random faces on random planes,
// convex (points on an ellipse), with a straight corner, reflex, star-shaped (winding twice),
// bent out of the plane, and with coordinates too large for 128 bits.
namespace {

hlr::FaceTriangles rational_route(const hlr::Polyhedron& p, int f) {
  using namespace hlr;
  FaceTriangles out;
  const Face& face = p.faces()[f];
  std::vector<const Point3*> pts;
  for (int v : face) pts.push_back(&p.vertices()[v]);
  Plane h = plane_of_polygon(pts.data(), pts.size());
  if (h.is_degenerate()) {
    const ZeroAreaKind k = zero_area_kind(pts.data(), pts.size());
    out.status = k == ZeroAreaKind::Collinear ? FaceTriangles::Status::Degenerate
                 : k == ZeroAreaKind::Crossing ? FaceTriangles::Status::SelfIntersecting
                                               : FaceTriangles::Status::NonPlanar;
    return out;
  }
  for (std::size_t k = 0; k < face.size(); ++k)
    if (h.value(*pts[k]) != 0) {
      out.status = FaceTriangles::Status::NonPlanar;
      return out;
    }
  out.triangles = triangulate_face(p.vertices(), face, h.normal());
  if (out.triangles.empty()) out.status = FaceTriangles::Status::SelfIntersecting;
  return out;
}

}  // namespace

TEST(FaceTriangles, IntegerRouteEqualsTheRationalRoute) {
  using namespace hlr;
  std::mt19937 rng(29);
  auto dec = [&](int range) { return Rational(static_cast<long>(rng() % (2 * range + 1)) - range, 1000); };
  int fast = 0;
  for (int it = 0; it < 3000; ++it) {
    const int n = 4 + static_cast<int>(rng() % 10);  // 4..13: 13 is past the fan limit
    const int kind = static_cast<int>(rng() % 6);
    // A plane through o spanned by integer-ish vectors a, b; the polygon's points o + x·a + y·b.
    const Rational o[3] = {dec(5000), dec(5000), dec(5000)};
    Rational a[3] = {dec(3), dec(3), dec(3)}, b[3] = {dec(3), dec(3), dec(3)};
    std::vector<std::array<Rational, 2>> uv;
    for (int k = 0; k < n; ++k) {
      const double t = 2 * M_PI * k / n * (kind == 4 ? 2 : 1);  // kind 4: a star winding twice
      long r = kind == 2 && k == 1 ? 300 : 1000;                // kind 2: a reflex corner
      uv.push_back({Rational(std::lround(r * std::cos(t)), 100), Rational(std::lround(r * std::sin(t) * 0.7), 100)});
    }
    if (kind == 3) uv[1] = {(uv[0][0] + uv[2][0]) / 2, (uv[0][1] + uv[2][1]) / 2};  // a corner on a straight side
    std::vector<Point3> v;
    for (int k = 0; k < n; ++k) {
      Rational c[3];
      for (int i = 0; i < 3; ++i) c[i] = o[i] + uv[k][0] * a[i] + uv[k][1] * b[i];
      if (kind == 5 && k == 2) c[2] += Rational(1, 1000);  // bent out of the plane
      v.push_back(Point3(c[0], c[1], c[2]));
    }
    if (it % 50 == 0) v[0] = Point3(v[0].x() + Rational(mpz_class(1) << 80, 1), v[0].y(), v[0].z());  // too large
    std::vector<int> face(n);
    for (int k = 0; k < n; ++k) face[k] = k;
    Polyhedron p(v, {face});
    const FaceTriangles got = face_triangles(p, 0), want = rational_route(p, 0);
    fast += proven_convex_face(p, 0);
    ASSERT_EQ(got.status, want.status) << "face " << it << " kind " << kind;
    ASSERT_EQ(got.triangles.size(), want.triangles.size()) << it;
    for (std::size_t t = 0; t < got.triangles.size(); ++t) {
      EXPECT_EQ(got.triangles[t].v, want.triangles[t].v) << it;
      EXPECT_EQ(got.triangles[t].edge, want.triangles[t].edge) << it;
    }
  }
  EXPECT_GT(fast, 500) << "the integer route was taken";
}
