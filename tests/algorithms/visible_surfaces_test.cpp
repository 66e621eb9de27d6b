// Visible surfaces as exact polygons (algorithms/surfaces/visible_surfaces.*), checked by an
// independent exact oracle that shares no code with the route: random points on the faces,
// each cast toward the viewer against every face polygon of the scene in rationals (plane,
// parameter, point in polygon in the face's dominant plane). A point that nothing strictly
// in front hides must lie inside a visible polygon of its face, a hidden one in none, and
// every sample's picture point in exactly one visible polygon of the whole scene. On small
// scenes the visible areas add up exactly to the area of the union of the projected faces,
// computed by an exact slab sweep. Scenes by name: touching, flush, shared faces,
// interpenetrating, cyclic sticks, open and coplanar surfaces, axis views, perspective, random
// triangles, CGAL's fandisk, couplingdown and bunny00.
#include "algorithms/surfaces/visible_surfaces.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <set>

#include "algorithms/clip/weiler_atherton.hpp"
#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/solids/face_triangles.hpp"
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
Camera persp(const char* x, const char* y, const char* z, const Point3& target) {
  return make_perspective(P(x, y, z), target);
}

// ---- the oracle's own geometry

struct OracleFace {
  std::vector<Point3> v;
  std::array<double, 4> box;  // picture box, widened by 1e-6 of its size: only skips far faces
  Rational a, b, c, d;  // plane
  int drop;             // the coordinate dropped for point-in-polygon (largest normal component)
};

std::array<double, 4> widen(std::array<double, 4> b) {
  for (double x : b)
    if (!std::isfinite(x) || x == 0) return {-INFINITY, -INFINITY, INFINITY, INFINITY};  // doubles lost it: no filter
  double pad = 1e-6 * (std::fabs(b[0]) + std::fabs(b[1]) + std::fabs(b[2]) + std::fabs(b[3]) + 1e-300);
  return {b[0] - pad, b[1] - pad, b[2] + pad, b[3] + pad};
}
bool in_box(const std::array<double, 4>& b, const std::array<double, 2>& q) {
  if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || q[0] == 0 || q[1] == 0) return true;
  return b[0] <= q[0] && q[0] <= b[2] && b[1] <= q[1] && q[1] <= b[3];
}
std::array<double, 4> box_of(const std::vector<Exact2>& pts) {
  std::array<double, 4> b{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (const Exact2& p : pts) {
    double x = p[0].get_d(), y = p[1].get_d();
    b = {std::min(b[0], x), std::min(b[1], y), std::max(b[2], x), std::max(b[3], y)};
  }
  return widen(b);
}

std::vector<std::vector<OracleFace>> oracle_faces(const std::vector<const Polyhedron*>& bodies, const PicturePlane& pp) {
  std::vector<std::vector<OracleFace>> out;
  for (const Polyhedron* p : bodies) {
    out.emplace_back();
    for (const Face& f : p->faces()) {
      OracleFace of;
      std::vector<Exact2> pic;
      for (int i : f) of.v.push_back(p->vertices()[i]), pic.push_back(pp.project(p->vertices()[i]));
      of.box = box_of(pic);
      // Newell normal, exact.
      Rational nx = 0, ny = 0, nz = 0;
      for (std::size_t i = 0; i < of.v.size(); ++i) {
        const Point3 &A = of.v[i], &B = of.v[(i + 1) % of.v.size()];
        nx += (A.y() - B.y()) * (A.z() + B.z());
        ny += (A.z() - B.z()) * (A.x() + B.x());
        nz += (A.x() - B.x()) * (A.y() + B.y());
      }
      of.a = nx, of.b = ny, of.c = nz;
      of.d = -(nx * of.v[0].x() + ny * of.v[0].y() + nz * of.v[0].z());
      Rational ax = abs(nx), ay = abs(ny), az = abs(nz);
      of.drop = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
      out.back().push_back(std::move(of));
    }
  }
  return out;
}

// 1 strictly inside, 0 on the boundary, -1 outside (x lies in the face's plane).
int in_face(const OracleFace& f, const std::array<Rational, 3>& x) {
  int u = f.drop == 0 ? 1 : 0, w = f.drop == 2 ? 1 : 2;
  bool in = false;
  for (std::size_t i = 0; i < f.v.size(); ++i) {
    const Point3 &A = f.v[i], &B = f.v[(i + 1) % f.v.size()];
    Rational au = A[u], aw = A[w], bu = B[u], bw = B[w], xu = x[u], xw = x[w];
    Rational cr = (bu - au) * (xw - aw) - (bw - aw) * (xu - au);
    if (cr == 0 && std::min(au, bu) <= xu && xu <= std::max(au, bu) && std::min(aw, bw) <= xw && xw <= std::max(aw, bw)) return 0;
    bool ua = aw > xw, ub = bw > xw;
    if (ua != ub && ((cr > 0) == ub)) in = !in;
  }
  return in ? 1 : -1;
}

enum class Seen { Clear, Blocked, Tie, Unsure };

// What the open sight ray of x (on face `self` of body `sb`) meets.
Seen cast(const std::vector<std::vector<OracleFace>>& faces, const Camera& cam, const std::array<Rational, 3>& x,
          const std::array<double, 2>& q, int sb, int self) {
  std::array<Rational, 3> dir;
  if (cam.perspective)
    dir = {cam.eye.x() - x[0], cam.eye.y() - x[1], cam.eye.z() - x[2]};
  else
    dir = {cam.direction.x(), cam.direction.y(), cam.direction.z()};
  bool tie = false, unsure = false;
  for (std::size_t b = 0; b < faces.size(); ++b)
    for (std::size_t f = 0; f < faces[b].size(); ++f) {
      if (static_cast<int>(b) == sb && static_cast<int>(f) == self) continue;
      const OracleFace& g = faces[b][f];
      if (!in_box(g.box, q)) continue;  // its projection is far from the sample's picture point
      Rational hx = g.a * x[0] + g.b * x[1] + g.c * x[2] + g.d, nd = g.a * dir[0] + g.b * dir[1] + g.c * dir[2];
      if (nd == 0) continue;  // parallel (edge-on along the ray, or apart): never hides
      Rational s = -hx / nd;
      if (s < 0 || (cam.perspective && s >= 1)) continue;
      std::array<Rational, 3> h{x[0] + s * dir[0], x[1] + s * dir[1], x[2] + s * dir[2]};
      int in = in_face(g, h);
      if (in < 0) continue;
      if (s == 0) {
        (in > 0 ? tie : unsure) = true;
        continue;
      }
      if (in > 0) return Seen::Blocked;
      unsure = true;
    }
  return unsure ? Seen::Unsure : tie ? Seen::Tie : Seen::Clear;
}

// 1 inside, 0 on the boundary, -1 outside: a picture polygon with holes (face_oracle.hpp).
int in_polygon(const VisiblePolygon& p, const Exact2& q) { return test::in_rings(p.outer_2d, p.holes_2d, q); }

// Twice the area of the union of the projected faces: slabs between all x of corners and
// crossings; in a slab the covered length is linear in x, so its value at the middle times
// the width is exact.
Rational union_area2(const std::vector<std::array<Exact2, 3>>& tris) {
  std::vector<std::pair<Exact2, Exact2>> edges;
  std::set<Rational> xs;
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) {
      edges.emplace_back(t[k], t[(k + 1) % 3]);
      xs.insert(t[k][0]);
    }
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto &[a, b] = edges[i];
      const auto &[c, d] = edges[j];
      Rational ux = b[0] - a[0], uy = b[1] - a[1], vx = d[0] - c[0], vy = d[1] - c[1];
      Rational den = ux * vy - uy * vx;
      if (den == 0) continue;
      Rational t = ((c[0] - a[0]) * vy - (c[1] - a[1]) * vx) / den, s = ((c[0] - a[0]) * uy - (c[1] - a[1]) * ux) / den;
      if (t >= 0 && t <= 1 && s >= 0 && s <= 1) xs.insert(a[0] + t * ux);
    }
  std::vector<Rational> x(xs.begin(), xs.end());
  Rational total = 0;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    Rational xm = (x[i] + x[i + 1]) / 2;
    std::vector<std::pair<Rational, Rational>> iv;
    for (const auto& t : tris) {
      std::vector<Rational> ys;
      for (int k = 0; k < 3; ++k) {
        const Exact2 &a = t[k], &b = t[(k + 1) % 3];
        if ((a[0] < xm) != (b[0] < xm)) ys.push_back(a[1] + (b[1] - a[1]) * (xm - a[0]) / (b[0] - a[0]));
      }
      if (ys.size() == 2) iv.emplace_back(std::min(ys[0], ys[1]), std::max(ys[0], ys[1]));
    }
    std::sort(iv.begin(), iv.end());
    Rational len = 0, lo, hi;
    bool open = false;
    for (auto& [a, b] : iv) {
      if (!open || a > hi) {
        if (open) len += hi - lo;
        lo = a, hi = b, open = true;
      } else if (b > hi) {
        hi = b;
      }
    }
    if (open) len += hi - lo;
    total += (x[i + 1] - x[i]) * len;
  }
  return 2 * total;
}

struct Tally {
  long samples = 0, clear = 0, blocked = 0, skipped = 0, wrong = 0;
};

// Every check on one scene and view. `samples` random points per face (0: none); `area`: the
// union-area check (small scenes).
Tally check_scene(const std::vector<const Polyhedron*>& bodies, const Camera& cam, int samples, bool area, unsigned seed = 1) {
  LineOptions lo;
  lo.edges = EdgeSelection::All;
  LineDrawing lines = face_occluders(bodies, cam, lo);
  SurfaceOptions so;
  so.check_cycles = true;
  VisibleSurfaces vs = visible_surfaces(bodies, cam, lines, so);
  EXPECT_EQ(vs.stats.label_mismatches, 0u);
  PicturePlane pp(cam);
  Tally tally;
  // Lifted vertices lie in their face's plane and project back to their picture points.
  std::vector<std::vector<const VisiblePolygon*>> by_face(bodies.size());
  std::vector<std::vector<std::vector<const VisiblePolygon*>>> polys(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) polys[b].resize(bodies[b]->num_faces());
  Rational total = 0;
  for (const VisibleFace& vf : vs.faces) {
    const Plane& h = bodies[vf.body]->planes()[vf.face];
    for (const VisiblePolygon& p : vf.polygons) {
      polys[vf.body][vf.face].push_back(&p);
      EXPECT_GT(p.area2, 0);
      total += p.area2;
      for (std::size_t i = 0; i < p.outer.size(); ++i) {
        EXPECT_EQ(h.value(p.outer[i]), 0);
        EXPECT_EQ(pp.project(p.outer[i]), p.outer_2d[i]);
      }
    }
  }
  if (area) {
    std::vector<std::array<Exact2, 3>> tris;
    for (const Polyhedron* body : bodies)
      for (std::size_t f = 0; f < body->num_faces(); ++f) {
        FaceTriangles ft = face_triangles(*body, static_cast<int>(f));
        for (const FaceTriangle& t : ft.triangles) {
          std::array<Exact2, 3> q;
          for (int k = 0; k < 3; ++k) q[k] = pp.project(body->vertices()[body->faces()[f][t.v[k]]]);
          if (orient2d(q[0], q[1], q[2]) != 0) tris.push_back(q);
        }
      }
    EXPECT_EQ(total, union_area2(tris)) << "visible areas do not add up to the union of the projected faces";
  }
  if (samples == 0) return tally;
  auto faces = oracle_faces(bodies, pp);
  std::vector<std::array<double, 4>> poly_box;
  for (const VisibleFace& vf : vs.faces)
    for (const VisiblePolygon& p : vf.polygons) poly_box.push_back(box_of(p.outer_2d));
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> w(1, 997);
  for (std::size_t b = 0; b < bodies.size(); ++b)
    for (std::size_t f = 0; f < bodies[b]->num_faces(); f += std::max<std::size_t>(1, bodies[b]->num_faces() / 1500)) {
      FaceTriangles ft = face_triangles(*bodies[b], static_cast<int>(f));
      if (ft.triangles.empty()) continue;
      const Face& face = bodies[b]->faces()[f];
      for (int s = 0; s < samples; ++s) {
        const FaceTriangle& t = ft.triangles[static_cast<std::size_t>(s) % ft.triangles.size()];
        Rational w0 = w(rng), w1 = w(rng), w2 = w(rng), sum = w0 + w1 + w2;
        const Point3 &A = bodies[b]->vertices()[face[t.v[0]]], &B = bodies[b]->vertices()[face[t.v[1]]],
                     &C = bodies[b]->vertices()[face[t.v[2]]];
        std::array<Rational, 3> x;
        for (int k = 0; k < 3; ++k) x[k] = (w0 * A[k] + w1 * B[k] + w2 * C[k]) / sum;
        Point3 X(x[0], x[1], x[2]);
        ++tally.samples;
        Exact2 q = pp.project(X);
        Exact2 a = pp.project(A), bb = pp.project(B), c = pp.project(C);
        if (orient2d(a, bb, c) == 0) {  // edge-on face: not seen, nothing to check
          ++tally.skipped;
          continue;
        }
        const std::array<double, 2> qd{q[0].get_d(), q[1].get_d()};
        Seen seen = cast(faces, cam, x, qd, static_cast<int>(b), static_cast<int>(f));
        int mine = 0, others = 0, boundary = 0;
        for (const VisiblePolygon* p : polys[b][f]) {
          int i = in_polygon(*p, q);
          mine += i > 0, boundary += i == 0;
        }
        std::size_t pk = 0;
        for (const VisibleFace& vf : vs.faces)
          for (const VisiblePolygon& p : vf.polygons) {
            if (!in_box(poly_box[pk++], qd)) continue;
            if (vf.body == static_cast<int>(b) && vf.face == static_cast<int>(f)) continue;
            int i = in_polygon(p, q);
            others += i > 0, boundary += i == 0;
          }
        if (boundary) {  // on a drawn line: the polygons meet there
          ++tally.skipped;
          continue;
        }
        if (mine + others != 1) {
          ++tally.wrong;
          ADD_FAILURE() << "picture point of body " << b << " face " << f << " covered " << mine + others << " times";
          continue;
        }
        if (seen == Seen::Tie || seen == Seen::Unsure) {
          ++tally.skipped;
          continue;
        }
        bool clear = seen == Seen::Clear;
        (clear ? tally.clear : tally.blocked)++;
        if (clear != (mine == 1)) {
          ++tally.wrong;
          ADD_FAILURE() << "body " << b << " face " << f << " point " << X << ": oracle says " << (clear ? "seen" : "hidden")
                        << ", polygons say " << (mine ? "seen" : "hidden");
        }
      }
    }
  EXPECT_EQ(tally.wrong, 0);
  return tally;
}

std::vector<const Polyhedron*> ptrs(const std::vector<Polyhedron>& v) {
  std::vector<const Polyhedron*> out;
  for (const auto& p : v) out.push_back(&p);
  return out;
}

std::vector<Camera> views(const Point3& target) {
  return {ortho("1", "1.3", "1.7"), ortho("0", "0", "1"), ortho("1", "1", "0"),  ortho("-2", "1", "3"),
          ortho("1", "0", "0"),     ortho("3", "-1", "-2"), persp("9", "7", "6", target), persp("-5", "8", "3", target)};
}

void check_views(const std::vector<Polyhedron>& bodies, const Point3& target, int samples = 6, bool area = true) {
  long clear = 0, blocked = 0;
  for (const Camera& c : views(target)) {
    Tally t = check_scene(ptrs(bodies), c, samples, area);
    clear += t.clear, blocked += t.blocked;
  }
  EXPECT_GT(clear, 0);
  EXPECT_GT(blocked, 0);
}

// o + the sums of e1, e2, e3 (given as points for brevity), faces as in make_box.
Polyhedron parallelepiped(const Point3& o, const Point3& e1, const Point3& e2, const Point3& e3) {
  std::vector<Point3> vs;
  for (int k = 0; k < 8; ++k) {
    std::array<Rational, 3> c;
    for (int i = 0; i < 3; ++i) c[i] = o[i] + (k & 1 ? e1[i] : Rational(0)) + (k & 2 ? e2[i] : Rational(0)) + (k & 4 ? e3[i] : Rational(0));
    vs.emplace_back(c[0], c[1], c[2]);
  }
  return Polyhedron(std::move(vs), {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}});
}

Polyhedron quad(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  return Polyhedron({a, b, c, d}, {{0, 1, 2, 3}});
}

}  // namespace

// ---- named scenes

// orient2d's exact route (integers without gcd), and the exact dot product's sign, against the
// textbook formulas in canonical rationals: random points with small and huge denominators (10^±60), exactly
// collinear triples (c = a + t·(b - a), the T-junctions of the picture) and equal points.
TEST(VisibleSurfaces, Orient2dExactMatchesRationalDeterminant) {
  std::mt19937_64 rng(7);
  auto num = [&](int digits) {
    mpz_class z = 0;
    for (int k = 0; k < digits; ++k) z = z * 10 + static_cast<long>(rng() % 10);
    return rng() % 2 ? z : mpz_class(-z);
  };
  auto q = [&](int digits) {
    Rational r(num(digits), mpz_class(abs(num(digits))) + 1);
    r.canonicalize();
    return r;
  };
  int zeros = 0, signs[3] = {0, 0, 0};
  for (int i = 0; i < 3000; ++i) {
    const int d = i % 3 == 0 ? 2 : (i % 3 == 1 ? 12 : 60);
    Exact2 a{q(d), q(d)}, b{q(d), q(d)}, c;
    const int kind = i % 4;
    if (kind == 0) {
      c = {q(d), q(d)};
    } else if (kind == 1) {  // collinear
      Rational t = q(d);
      c = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
    } else if (kind == 2) {
      c = a;
    } else {  // nearly collinear: off the line by 10^-30 of the extent
      Rational t = q(d);
      c = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]) + Rational(1, mpz_class("1000000000000000000000000000000"))};
    }
    const int want = sgn((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    ASSERT_EQ(orient2d_exact(a, b, c), want) << i;
    ASSERT_EQ(orient2d(a, b, c), want) << i;
    ASSERT_EQ(orient2d_exact(b, a, c), -want) << i;
    const int dot = sgn((b[0] - a[0]) * (c[0] - a[0]) + (b[1] - a[1]) * (c[1] - a[1]));
    ASSERT_EQ(dot_sign_exact(a, b, a, c), dot) << i;
    zeros += want == 0;
    ++signs[want + 1];
  }
  EXPECT_GT(zeros, 1400);
  EXPECT_GT(signs[0], 300);
  EXPECT_GT(signs[2], 300);
}

TEST(VisibleSurfaces, SingleBoxFrontFacesWhole) {
  std::vector<Polyhedron> b{box("0", "0", "0", "1", "1", "1")};
  VisibleSurfaces vs = visible_surfaces(ptrs(b), ortho("1", "1", "1"), face_occluders(ptrs(b), ortho("1", "1", "1"), {EdgeSelection::All}));
  ASSERT_EQ(vs.faces.size(), 3u);  // three faces seen, each a whole square
  for (const VisibleFace& f : vs.faces) {
    ASSERT_EQ(f.polygons.size(), 1u);
    EXPECT_EQ(f.polygons[0].outer.size(), 4u);
    EXPECT_TRUE(f.polygons[0].holes.empty());
    EXPECT_TRUE(f.front);
  }
}

TEST(VisibleSurfaces, BoxOnBoxTouching) {
  std::vector<Polyhedron> b{box("0", "0", "0", "4", "4", "1"), box("1", "1", "1", "3", "3", "2")};
  check_views(b, P("2", "2", "1"));
}

TEST(VisibleSurfaces, TopFaceWithHoleUnderSmallBox) {
  // Seen from straight above, the slab's top is a square with a square hole.
  std::vector<Polyhedron> b{box("0", "0", "0", "4", "4", "1"), box("1", "1", "1", "3", "3", "2")};
  Camera c = ortho("0", "0", "1");
  VisibleSurfaces vs = visible_surfaces(ptrs(b), c, face_occluders(ptrs(b), c, {EdgeSelection::All}));
  int holes = 0;
  for (const VisibleFace& f : vs.faces)
    for (const VisiblePolygon& p : f.polygons) holes += static_cast<int>(p.holes.size());
  EXPECT_EQ(holes, 1);
  ASSERT_EQ(vs.faces.size(), 2u);
}

TEST(VisibleSurfaces, BodiesSharingAFace) {
  std::vector<Polyhedron> b{box("0", "0", "0", "2", "2", "2"), box("2", "0", "0", "4", "2", "2")};
  check_views(b, P("2", "1", "1"));
}

TEST(VisibleSurfaces, WallFlushWithSlab) {
  std::vector<Polyhedron> b{box("0", "0", "0", "6", "4", "1"), box("0", "0", "1", "6", "1", "3")};
  check_views(b, P("3", "2", "1"));
}

TEST(VisibleSurfaces, InterpenetratingBoxes) {
  std::vector<Polyhedron> b{box("0", "0", "0", "3", "3", "3"), box("1", "1", "-1", "5", "2", "2")};
  check_views(b, P("2", "2", "1"));
}

TEST(VisibleSurfaces, CyclicSticks) {
  // Three long boxes each over the next: no depth order of whole faces exists.
  // Slanted sticks: 0 over 1 over 2 over 0 where they cross in the view from above.
  std::vector<Polyhedron> b{parallelepiped(P("0", "0", "0"), P("6", "0", "2"), P("0", "1", "0"), P("0", "0", "1/2")),
                            parallelepiped(P("5", "0", "0"), P("0", "6", "2"), P("1", "0", "0"), P("0", "0", "1/2")),
                            parallelepiped(P("6", "6", "0"), P("-6", "-6", "5/2"), P("1/2", "-1/2", "0"), P("0", "0", "1/2"))};
  check_views(b, P("3", "3", "1"));
  check_scene(ptrs(b), ortho("0", "0", "1"), 8, true);
}

TEST(VisibleSurfaces, OpenSurfacesAndCoplanarQuads) {
  std::vector<Polyhedron> b{quad(P("0", "0", "0"), P("3", "0", "0"), P("3", "2", "0"), P("0", "2", "0")),
                            quad(P("1", "1", "0"), P("4", "1", "0"), P("4", "3", "0"), P("1", "3", "0")),
                            quad(P("0", "0", "1"), P("2", "0", "1"), P("2", "2", "3"), P("0", "2", "3")),
                            box("2", "-1", "-1", "3", "0", "2")};
  check_views(b, P("2", "1", "1"));
}

TEST(VisibleSurfaces, ViewAlongFacesAndEdges) {
  std::vector<Polyhedron> b{box("0", "0", "0", "2", "2", "2"), box("1", "1", "2", "3", "3", "3"), box("3", "0", "0", "4", "4", "1")};
  for (const Camera& c : {ortho("1", "0", "0"), ortho("0", "1", "0"), ortho("1", "1", "0"), ortho("0", "0", "-1")})
    check_scene(ptrs(b), c, 6, true);
}

TEST(VisibleSurfaces, EyeCloseToAFace) {
  std::vector<Polyhedron> b{box("0", "0", "0", "2", "2", "2"), box("3", "0", "0", "5", "2", "2")};
  Tally t = check_scene(ptrs(b), persp("2.5", "1", "2.001", P("2.5", "1", "0")), 8, true);
  EXPECT_GT(t.clear, 0);
}

TEST(VisibleSurfaces, DemoScene) {
  Scene s = load_scene(kData + "/demo.yaml");
  std::vector<Polyhedron> b;
  for (const auto& body : s.bodies) b.push_back(body.body);
  check_views(b, P("3", "2", "1"), 4, false);
}

TEST(VisibleSurfaces, RandomTrianglesUnionArea) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> c(0, 1024), e(-100, 100);
  for (int round = 0; round < 3; ++round) {
    std::vector<Polyhedron> b;
    for (int i = 0; i < 25; ++i) {
      int x = c(rng), y = c(rng), z = c(rng);
      auto p = [&](int dx, int dy, int dz) {
        return Point3(rational(x + dx, 1024), rational(y + dy, 1024), rational(z + dz, 1024));
      };
      b.push_back(Polyhedron({p(0, 0, 0), p(e(rng), e(rng), e(rng)), p(e(rng), e(rng), e(rng))}, {{0, 1, 2}}));
    }
    for (const Camera& cam : {ortho("1", "1.3", "1.7"), ortho("0", "0", "1"), persp("3", "2", "4", P("0.5", "0.5", "0.5"))})
      check_scene(ptrs(b), cam, 4, true, static_cast<unsigned>(round));
  }
}

TEST(VisibleSurfaces, CorpusMeshes) {
  for (const char* name : {"fandisk.off", "couplingdown.off", "bunny00.off"}) {
    std::string path = kCorpus + "/" + name;
    ASSERT_TRUE(std::filesystem::exists(path)) << path << " (scripts/extract_corpus.sh)";
    std::vector<Polyhedron> b{load_mesh(path)};
    check_scene(ptrs(b), ortho("1", "1.3", "1.7"), 1, false);
  }
}

TEST(VisibleSurfaces, InsideOutSolidAndEyeOnASurface) {
  // An inside-out box (turned by the route) beside another box; then the eye on a box's top
  // face: part of that box is behind the eye, which the surfaces refuse with a clear message.
  std::vector<Polyhedron> b{box("0", "0", "0", "2", "2", "2").reversed(), box("3", "0", "0", "5", "2", "1")};
  check_views(b, P("2", "1", "1"));
  try {
    check_scene(ptrs(b), persp("1", "1", "2", P("5", "1", "0")), 8, true);
    ADD_FAILURE() << "the eye on a surface was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("in front of the eye"), std::string::npos) << e.what();
  }
}

// ---- the course's Weiler–Atherton algorithm gives the same visible part of every face

namespace {

// Same faces, same exact area per face, and every convex piece of Weiler–Atherton inside a
// polygon of the fast route's same face (its centroid, exactly).
void expect_same_as_fast_route(const std::vector<Polyhedron>& bodies, const Camera& cam, WeilerAthertonResult* out = nullptr) {
  LineOptions lo;
  lo.edges = EdgeSelection::All;
  auto b = ptrs(bodies);
  LineDrawing lines = face_occluders(b, cam, lo);
  VisibleSurfaces fast = visible_surfaces(b, cam, lines);
  WeilerAthertonResult wa = weiler_atherton(b, cam, lines);
  std::vector<SurfacePiece> pieces;
  for (const WaPolygon& p : wa.visible) pieces.push_back({p.body, p.face, p.pts});
  SurfaceOptions so;
  so.check_cycles = true;
  VisibleSurfaces slow = surfaces_from_pieces(pieces, b, cam, so);
  EXPECT_EQ(slow.stats.label_mismatches, 0u);
  std::map<std::pair<int, int>, Rational> fa, sa;
  for (const VisibleFace& f : fast.faces)
    for (const VisiblePolygon& p : f.polygons) fa[{f.body, f.face}] += p.area2;
  for (const VisibleFace& f : slow.faces)
    for (const VisiblePolygon& p : f.polygons) sa[{f.body, f.face}] += p.area2;
  EXPECT_EQ(fa, sa) << "visible area per face differs";
  for (const WaPolygon& p : wa.visible) {
    Rational cx = 0, cy = 0;
    for (const Exact2& q : p.pts) cx += q[0], cy += q[1];
    Exact2 c{cx / static_cast<long>(p.pts.size()), cy / static_cast<long>(p.pts.size())};
    int in = 0;
    for (const VisibleFace& f : fast.faces)
      if (f.body == p.body && f.face == p.face)
        for (const VisiblePolygon& vp : f.polygons) in += in_polygon(vp, c) > 0;
    EXPECT_EQ(in, 1) << "a Weiler-Atherton piece of body " << p.body << " face " << p.face << " is not seen by the fast route";
  }
  if (out) *out = std::move(wa);
}

}  // namespace

TEST(WeilerAtherton, EqualsTheFastRoute) {
  std::vector<std::vector<Polyhedron>> scenes{
      {box("0", "0", "0", "4", "4", "1"), box("1", "1", "1", "3", "3", "2")},
      {box("0", "0", "0", "2", "2", "2"), box("2", "0", "0", "4", "2", "2")},
      {box("0", "0", "0", "6", "4", "1"), box("0", "0", "1", "6", "1", "3")},
      {quad(P("0", "0", "0"), P("3", "0", "0"), P("3", "2", "0"), P("0", "2", "0")),
       quad(P("1", "1", "0"), P("4", "1", "0"), P("4", "3", "0"), P("1", "3", "0")),
       quad(P("0", "0", "1"), P("2", "0", "1"), P("2", "2", "3"), P("0", "2", "3"))},
  };
  for (const auto& s : scenes)
    for (const Camera& c : views(P("2", "1", "1"))) expect_same_as_fast_route(s, c);
  Scene demo = load_scene(kData + "/demo.yaml");
  std::vector<Polyhedron> d;
  for (const auto& body : demo.bodies) d.push_back(body.body);
  for (const Camera& c : views(P("3", "2", "1"))) expect_same_as_fast_route(d, c);
}

TEST(WeilerAtherton, PiercingPolygonsAreSplitAlongTheirIntersection) {
  std::vector<Polyhedron> b{box("0", "0", "0", "3", "3", "3"), box("1", "1", "-1", "5", "2", "2")};
  WeilerAthertonResult wa;
  expect_same_as_fast_route(b, ortho("1", "1.3", "1.7"), &wa);
  EXPECT_GT(wa.splits, 0u);
  for (const Camera& c : views(P("2", "2", "1"))) expect_same_as_fast_route(b, c);
}

TEST(WeilerAtherton, CyclicSticksNeedNoSpecialCase) {
  std::vector<Polyhedron> b{parallelepiped(P("0", "0", "0"), P("6", "0", "2"), P("0", "1", "0"), P("0", "0", "1/2")),
                            parallelepiped(P("5", "0", "0"), P("0", "6", "2"), P("1", "0", "0"), P("0", "0", "1/2")),
                            parallelepiped(P("6", "6", "0"), P("-6", "-6", "5/2"), P("1/2", "-1/2", "0"), P("0", "0", "1/2"))};
  WeilerAthertonResult wa;
  expect_same_as_fast_route(b, ortho("0", "0", "1"), &wa);
  EXPECT_GT(wa.recursions, 0u);
  for (const Camera& c : views(P("3", "3", "1"))) expect_same_as_fast_route(b, c);
}

TEST(WeilerAtherton, RandomTriangles) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> c(0, 1024), e(-200, 200);
  std::vector<Polyhedron> b;
  for (int i = 0; i < 20; ++i) {
    int x = c(rng), y = c(rng), z = c(rng);
    auto p = [&](int dx, int dy, int dz) { return Point3(rational(x + dx, 1024), rational(y + dy, 1024), rational(z + dz, 1024)); };
    b.push_back(Polyhedron({p(0, 0, 0), p(e(rng), e(rng), e(rng)), p(e(rng), e(rng), e(rng))}, {{0, 1, 2}}));
  }
  int k = 0;
  for (const Camera& cam : {ortho("1", "1.3", "1.7"), ortho("0", "0", "1"), persp("3", "2", "4", P("0.5", "0.5", "0.5"))}) {
    SCOPED_TRACE(k++);
    expect_same_as_fast_route(b, cam);
  }
}
TEST(VisibleSurfaces, FractionsNotInLowestTermsFromTheApi) {
  // mpq_class(836, 1024) is not reduced, and GMP compares such values wrongly: a polyhedron
  // built through the API reduces its coordinates, so equal points stay equal in every route.
  auto q = [](long n, long d) { return Rational(n, d); };  // deliberately not canonical
  Polyhedron a({Point3(q(0, 1024), q(0, 1024), q(0, 1024)), Point3(q(836, 1024), q(0, 1024), q(0, 1024)),
                Point3(q(0, 1024), q(654, 1024), q(0, 1024))},
               {{0, 1, 2}});
  EXPECT_EQ(a.vertices()[1].x(), rational(209, 256));
  EXPECT_EQ(a.vertices()[1].x().get_den(), 256);
  std::vector<Polyhedron> b{a, Polyhedron({Point3(rational(209, 256), rational(327, 512), rational(-1, 2)),
                                           Point3(rational(0, 1), rational(0, 1), rational(1, 1)),
                                           Point3(rational(1, 1), rational(1, 1), rational(1, 1))},
                                          {{0, 1, 2}})};
  check_scene(ptrs(b), ortho("0", "0", "1"), 6, true);
}

TEST(VisibleSurfaces, NumbersFarOutsideDoubles) {
  // The same touching scene at 10^-400 and 10^400 (doubles underflow or overflow: every filter
  // must step aside), and a tiny triangle of size 10^-350 lying on a unit box's top face.
  auto scaled = [](const std::vector<Polyhedron>& in, const Rational& k) {
    std::vector<Polyhedron> out;
    for (const Polyhedron& p : in) {
      std::vector<Point3> vs;
      for (const Point3& v : p.vertices()) vs.emplace_back(v.x() * k, v.y() * k, v.z() * k);
      out.emplace_back(std::move(vs), p.faces());
    }
    return out;
  };
  std::vector<Polyhedron> b{box("0", "0", "0", "4", "4", "1"), box("1", "1", "1", "3", "3", "2")};
  for (const char* k : {"1e-400", "1e400"}) {
    std::vector<Polyhedron> s = scaled(b, Q(k));
    check_scene(ptrs(s), ortho("1", "1.3", "1.7"), 4, true);
    check_scene(ptrs(s), ortho("0", "0", "1"), 4, true);
  }
  std::vector<Polyhedron> mixed{box("0", "0", "0", "1", "1", "1"),
                                Polyhedron({P("0.5", "0.5", "1"), P("0.5000000000000001", "0.5", "1"), P("0.5", "0.5", "1.0000000000000000000001")}, {{0, 1, 2}}),
                                Polyhedron({P("0.25", "0.25", "1"), Point3(Q("0.25") + Q("1e-350"), Q("0.25"), Q("1")),
                                            Point3(Q("0.25"), Q("0.25") + Q("1e-350"), Q("1") + Q("1e-350"))},
                                           {{0, 1, 2}})};
  check_scene(ptrs(mixed), ortho("1", "1.3", "1.7"), 4, true);
  check_scene(ptrs(mixed), persp("3", "2", "4", P("0.5", "0.5", "0.5")), 4, true);
}
