// An independent brute-force oracle for Roberts' algorithm: exact ray casting of sample points
// of every piece against every body's face planes, sharing no code with the algorithm (it
// builds its own planes from the triangles and solves its own one-variable inequalities).
// Random scenes of random convex bodies (convex hulls of random rational points, built with
// CGAL), orthographic and perspective: zero disagreements. The per-face route runs on
// the same scenes: the same oracle, and exactly the same pieces for every edge.
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <tuple>

#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/hlr/roberts.hpp"
#include "io/readers/scene.hpp"
#include "kernel/epeck_bridge.hpp"
#include "support/ray_oracle.hpp"

using namespace hlr;
using namespace hlr::test;

namespace {

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

// Roberts' route and the per-face route on the same convex scene: the oracle checks
// both, and every edge must come out in exactly the same pieces.
void check_scene(const std::vector<Polyhedron>& bodies, const Camera& cam, EdgeSelection edges, Tally& tally) {
  OracleScene scene(bodies);
  const auto& ptrs = scene.ptrs;
  const auto& planes = scene.planes;
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
  lo.continue_creases = false;  // Roberts draws the plain crease rule: compare the routes on it
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
