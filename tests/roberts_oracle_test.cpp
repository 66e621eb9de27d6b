// An independent brute-force oracle for Roberts' algorithm: exact ray casting of sample points
// of every piece against every body's face planes, sharing no code with the algorithm (it
// builds its own planes from the triangles and solves its own one-variable inequalities).
// Random scenes of random convex bodies (convex hulls of random rational points, built with
// CGAL), orthographic and perspective: zero disagreements. The per-face route (issue 4) runs on
// the same scenes: the same oracle, and exactly the same pieces for every edge.
#include <gtest/gtest.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <map>
#include <random>
#include <tuple>

#include "algorithms/face_occluders.hpp"
#include "algorithms/roberts.hpp"
#include "io/scene.hpp"
#include "kernel/epeck_bridge.hpp"

using namespace hlr;

namespace {

struct OraclePlane {
  Rational a, b, c, d;  // inward: interior positive
  Rational at(const Rational& x, const Rational& y, const Rational& z) const { return a * x + b * y + c * z + d; }
};

std::vector<OraclePlane> oracle_planes(const Polyhedron& p) {
  Rational cx = 0, cy = 0, cz = 0;
  for (const Point3& v : p.vertices()) {
    cx += v.x();
    cy += v.y();
    cz += v.z();
  }
  Rational n(static_cast<long>(p.num_vertices()));
  cx /= n;
  cy /= n;
  cz /= n;
  std::vector<OraclePlane> out;
  for (const Face& f : p.faces()) {
    const Point3 &A = p.vertices()[f[0]], &B = p.vertices()[f[1]], &C = p.vertices()[f[2]];
    Rational ux = B.x() - A.x(), uy = B.y() - A.y(), uz = B.z() - A.z();
    Rational vx = C.x() - A.x(), vy = C.y() - A.y(), vz = C.z() - A.z();
    OraclePlane h{uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx, 0};
    h.d = -(h.a * A.x() + h.b * A.y() + h.c * A.z());
    if (h.at(cx, cy, cz) < 0) h = {-h.a, -h.b, -h.c, -h.d};
    out.push_back(h);
  }
  return out;
}

// Does the open sight ray of (x, y, z) meet the interior of the body?
bool ray_enters(const std::vector<OraclePlane>& body, const Rational& x, const Rational& y, const Rational& z,
                const Camera& cam) {
  // Orthographic: Q = P + s·v, s in (0, inf). Perspective: Q = P + s·(E - P), s in (0, 1).
  Rational lo = 0;
  std::optional<Rational> hi;
  if (cam.perspective) hi = Rational(1);
  for (const OraclePlane& h : body) {
    Rational c0 = h.at(x, y, z), c1;
    if (cam.perspective)
      c1 = h.at(cam.eye.x(), cam.eye.y(), cam.eye.z()) - c0;
    else
      c1 = h.a * cam.direction.x() + h.b * cam.direction.y() + h.c * cam.direction.z();
    if (c1 == 0) {
      if (!(c0 > 0)) return false;
    } else if (c1 > 0) {
      Rational s = -c0 / c1;
      if (s > lo) lo = s;
    } else {
      Rational s = -c0 / c1;
      if (!hi || s < *hi) hi = s;
    }
  }
  return !hi || lo < *hi;
}

Polyhedron random_hull(std::mt19937& rng, int cx, int cy, int cz) {
  std::uniform_int_distribution<int> coord(-6, 6), den(1, 3), count(5, 9);
  std::vector<Epeck::Point_3> pts;
  int n = count(rng);
  for (int i = 0; i < n; ++i) {
    Rational c[3] = {rational(coord(rng), den(rng)) + cx, rational(coord(rng), den(rng)) + cy, rational(coord(rng), den(rng)) + cz};
    for (auto& q : c) q.canonicalize();
    pts.push_back(to_epeck(Point3(c[0], c[1], c[2])));
  }
  CGAL::Surface_mesh<Epeck::Point_3> sm;
  CGAL::convex_hull_3(pts.begin(), pts.end(), sm);
  std::vector<Point3> vs;
  std::map<CGAL::Surface_mesh<Epeck::Point_3>::Vertex_index, int> index;
  for (auto v : sm.vertices()) {
    index[v] = static_cast<int>(vs.size());
    vs.push_back(from_epeck(sm.point(v)));
  }
  std::vector<Face> faces;
  for (auto f : sm.faces()) {
    Face face;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) face.push_back(index[v]);
    faces.push_back(face);
  }
  return Polyhedron(vs, faces);
}

struct Tally {
  long samples = 0, disagreements = 0, scenes = 0, junctions = 0, hidden_samples = 0, isolated_points = 0, route_mismatches = 0;
};

void sample_check(const LineDrawing& r, const std::vector<std::vector<OraclePlane>>& planes, const Camera& cam, Tally& tally,
                  const char* route) {
  for (const Segment& s : r.segments) {
    for (const Piece& p : s.pieces) {
      if (p.behind_eye) continue;
      for (Rational f : {Rational(1, 2), Rational(1, 4), Rational(3, 4)}) {
        Point3 x = s.at(p.t0 + f * (p.t1 - p.t0));
        bool hidden = false;
        for (const auto& body : planes) hidden = hidden || ray_enters(body, x.x(), x.y(), x.z(), cam);
        ++tally.samples;
        tally.hidden_samples += hidden;
        if (!hidden && !p.visible) {
          // A single visible point between hidden parts (a ray along the face shared by two
          // touching bodies) is merged into the hidden piece: a point is not a line. Accept it
          // only when the points just before and after are hidden.
          Rational t = p.t0 + f * (p.t1 - p.t0), eps = (p.t1 - p.t0) / Rational(1000000007);
          Point3 before = s.at(t - eps), after = s.at(t + eps);
          bool hb = false, ha = false;
          for (const auto& body : planes) {
            hb = hb || ray_enters(body, before.x(), before.y(), before.z(), cam);
            ha = ha || ray_enters(body, after.x(), after.y(), after.z(), cam);
          }
          if (hb && ha) {
            ++tally.isolated_points;
            continue;
          }
        }
        if (hidden == p.visible) {
          ++tally.disagreements;
          ADD_FAILURE() << route << ": piece of segment " << s.from() << "-" << s.to() << " t " << p.t0 << ".." << p.t1
                        << " says visible=" << p.visible;
        }
      }
    }
  }
}

// Roberts' route and the per-face route (issue 4) on the same convex scene: the oracle checks
// both, and every edge must come out in exactly the same pieces.
void check_scene(const std::vector<Polyhedron>& bodies, const Camera& cam, EdgeSelection edges, Tally& tally) {
  std::vector<const Polyhedron*> ptrs;
  std::vector<std::vector<OraclePlane>> planes;
  for (const auto& b : bodies) {
    ptrs.push_back(&b);
    planes.push_back(oracle_planes(b));
  }
  LineOptions opt;
  opt.edges = edges;
  RobertsResult r;
  try {
    r = roberts(ptrs, cam, opt);
  } catch (const BodyError&) {
    return;  // a degenerate hull or an eye inside: not a scene for this test
  }
  ++tally.scenes;
  for (const Segment& s : r.segments)
    if (s.kind == Segment::Kind::Intersection) ++tally.junctions;
  sample_check(r, planes, cam, tally, "roberts");
  LineOptions lo;
  lo.edges = edges;
  LineDrawing f = face_occluders(ptrs, cam, lo);
  sample_check(f, planes, cam, tally, "faces");
  std::map<std::tuple<int, int, int>, const Segment*> by_edge;
  for (const Segment& s : f.segments)
    if (s.kind == Segment::Kind::Edge) by_edge[{s.body, s.v0, s.v1}] = &s;
  std::size_t edges_r = 0;
  for (const Segment& s : r.segments) {
    if (s.kind != Segment::Kind::Edge) continue;
    ++edges_r;
    auto it = by_edge.find({s.body, s.v0, s.v1});
    if (it == by_edge.end()) {
      ++tally.route_mismatches;
      ADD_FAILURE() << "edge " << s.v0 << "-" << s.v1 << " of body " << s.body << " missing from the per-face route";
      continue;
    }
    const Segment& g = *it->second;
    bool same = g.pieces.size() == s.pieces.size();
    for (std::size_t i = 0; same && i < s.pieces.size(); ++i)
      same = g.pieces[i].t0 == s.pieces[i].t0 && g.pieces[i].t1 == s.pieces[i].t1 && g.pieces[i].visible == s.pieces[i].visible &&
             g.pieces[i].behind_eye == s.pieces[i].behind_eye;
    if (!same) {
      ++tally.route_mismatches;
      ADD_FAILURE() << "edge " << s.from() << "-" << s.to() << " of body " << s.body << ": the routes split it differently";
    }
  }
  if (edges_r != by_edge.size()) {
    ++tally.route_mismatches;
    ADD_FAILURE() << "roberts draws " << edges_r << " edges, the per-face route " << by_edge.size();
  }
}

}  // namespace

TEST(RobertsOracle, RandomConvexHullScenesAgreeWithRayCasting) {
  std::mt19937 rng(20261122);
  std::uniform_int_distribution<int> nbodies(2, 4), offset(-4, 4), dir(-2, 2), persp(0, 2);
  Tally tally;
  for (int scene = 0; scene < 300; ++scene) {
    std::vector<Polyhedron> bodies;
    int n = nbodies(rng);
    for (int i = 0; i < n; ++i) bodies.push_back(random_hull(rng, offset(rng), offset(rng), offset(rng)));
    Camera cam;
    if (persp(rng) == 0) {
      std::uniform_int_distribution<int> far(-30, 30);
      Point3 eye(far(rng), far(rng), 25 + far(rng) / 3);
      cam = make_perspective(eye, Point3(0, 0, 0));
    } else {
      Vector3 v(dir(rng), dir(rng), dir(rng));
      if (v.is_zero()) v = Vector3(0, 0, 1);
      cam = make_orthographic(v);
    }
    check_scene(bodies, cam, scene % 2 ? EdgeSelection::All : EdgeSelection::Feature, tally);
  }
  std::cout << "[oracle] " << tally.scenes << " scenes, " << tally.samples << " samples (" << tally.hidden_samples
            << " hidden), " << tally.junctions << " junction segments, " << tally.disagreements << " disagreements\n";
  EXPECT_GE(tally.scenes, 250);
  EXPECT_GT(tally.hidden_samples, tally.samples / 10);  // the scenes do hide things
  EXPECT_GT(tally.junctions, 50);                        // and interpenetrate
  EXPECT_EQ(tally.disagreements, 0);
  EXPECT_EQ(tally.route_mismatches, 0);
}

TEST(RobertsOracle, AxisViewsOfTouchingAndStackedBoxes) {
  // Degenerate on purpose: boxes sharing faces, edges and planes, seen along axes and diagonals.
  std::vector<Polyhedron> bodies = {make_box(Point3(0, 0, 0), Point3(2, 2, 2)), make_box(Point3(2, 0, 0), Point3(4, 2, 2)),
                                    make_box(Point3(1, 1, 2), Point3(3, 3, 3)), make_box(Point3(-1, 1, -1), Point3(0, 2, 3)),
                                    make_box(Point3(1, -1, 1), Point3(3, 3, Rational(3, 2)))};
  Tally tally;
  for (const Vector3& v : {Vector3(0, 0, 1), Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(1, 1, 0), Vector3(1, 1, 1),
                           Vector3(-1, 0, 0), Vector3(0, -1, -1), Vector3(1, 2, 0)})
    check_scene(bodies, make_orthographic(v), EdgeSelection::All, tally);
  check_scene(bodies, make_perspective(Point3(2, 1, 10), Point3(2, 1, 0)), EdgeSelection::All, tally);
  check_scene(bodies, make_perspective(Point3(1, 1, 6), Point3(1, 1, 0)), EdgeSelection::All, tally);
  std::cout << "[oracle] axis views: " << tally.samples << " samples, " << tally.isolated_points
            << " isolated visible points merged into hidden pieces\n";
  EXPECT_EQ(tally.scenes, 10);
  EXPECT_GT(tally.isolated_points, 0);  // the scene is built to have them
  EXPECT_EQ(tally.disagreements, 0);
  EXPECT_EQ(tally.route_mismatches, 0);
}
