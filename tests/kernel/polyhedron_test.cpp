// Polyhedron checks (kernel/polyhedron.hpp, kernel/mesh_checks.hpp), each naming indices.
#include "kernel/polyhedron.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <random>
#include <thread>

#include "io/readers/mesh_reader.hpp"
#include "kernel/openmesh_mesh.hpp"

using namespace hlr;

namespace {
const std::string kData = HLR_DATA_DIR;
}

TEST(Polyhedron, CubeIsAValidSolidAndOpenMeshAgrees) {
  Polyhedron cube = load_mesh(kData + "/cube.off");
  const MeshReport& r = cube.report();
  EXPECT_TRUE(r.valid_solid());
  EXPECT_EQ(cube.edges().size(), 12u);
  EXPECT_TRUE(cube.refused_faces().empty());
  EXPECT_EQ(cube.mesh().n_vertices(), 8u);
  EXPECT_EQ(cube.mesh().n_faces(), 6u);
  EXPECT_EQ(cube.mesh().n_edges(), 12u);
  // Double points, not OpenMesh's default float.
  static_assert(std::is_same_v<Mesh::Point, OpenMesh::Vec3d>);
  EXPECT_EQ(six_signed_volume(cube.vertices(), cube.faces()), 48);  // 6 * volume 8
}

TEST(Polyhedron, OpenBoxReportsItsBoundaryEdges) {
  Polyhedron p = load_mesh(kData + "/bad/open_box.off");
  const MeshReport& r = p.report();
  EXPECT_FALSE(r.closed());
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.oriented());
  EXPECT_EQ(r.boundary_edges, (std::vector<Edge>{{4, 5}, {4, 6}, {5, 7}, {6, 7}}));
}

TEST(Polyhedron, NonManifoldEdgeNamed) {
  Polyhedron p = load_mesh(kData + "/bad/non_manifold_edge.off");
  EXPECT_EQ(p.report().non_manifold_edges, (std::vector<Edge>{{0, 1}}));
  EXPECT_FALSE(p.report().manifold());
  EXPECT_EQ(p.refused_faces(), (std::vector<int>{2}));  // OpenMesh cannot add the third face
}

TEST(Polyhedron, NonManifoldVertexNamed) {
  // Two tetrahedra sharing only vertex 0.
  std::vector<Point3> vs = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0), Point3(0, 0, 1),
                            Point3(-1, 0, 0), Point3(0, -1, 0), Point3(0, 0, -1)};
  std::vector<Face> f = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}};
  Polyhedron p(vs, f);
  EXPECT_EQ(p.report().non_manifold_vertices, (std::vector<int>{0}));
  EXPECT_TRUE(p.report().non_manifold_edges.empty());
  EXPECT_TRUE(p.report().closed());
  EXPECT_FALSE(p.report().manifold());
}

TEST(Polyhedron, MisorientedEdgeNamedAndRefusedFaceReported) {
  Polyhedron p = load_mesh(kData + "/bad/misoriented.off");
  EXPECT_EQ(p.report().misoriented_edges, (std::vector<Edge>{{0, 1}}));
  EXPECT_EQ(p.report().refused_faces, (std::vector<int>{1}));
}

TEST(Polyhedron, NonPlanarFaceIsExact) {
  Polyhedron p = load_mesh(kData + "/bad/non_planar_face.off");
  ASSERT_EQ(p.report().non_planar_faces.size(), 1u);
  EXPECT_EQ(p.report().non_planar_faces[0].face, 0);
  // The same quad with its fourth vertex exactly in the plane (decimals) is planar.
  std::vector<Point3> vs = {Point3(0, 0, 0), Point3(parse_rational("0.1"), 0, parse_rational("0.3")),
                            Point3(parse_rational("0.1"), 1, parse_rational("0.3")), Point3(0, 1, 0)};
  Polyhedron q(vs, {{0, 1, 2, 3}});
  EXPECT_TRUE(q.report().planar());
  vs[2] = Point3(parse_rational("0.1"), 1, parse_rational("0.30000000000000000001"));
  EXPECT_FALSE(Polyhedron(vs, {{0, 1, 2, 3}}).report().planar());
}

TEST(Polyhedron, DegenerateFaces) {
  EXPECT_EQ(load_mesh(kData + "/bad/degenerate_face.off").report().degenerate_faces[0].why, "collinear vertices");
  Polyhedron rep = load_mesh(kData + "/bad/repeated_index.off");
  EXPECT_EQ(rep.report().degenerate_faces[0].why, "repeated vertex 1");
  EXPECT_EQ(rep.report().isolated_vertices, (std::vector<int>{3}));
  EXPECT_EQ(rep.refused_faces(), (std::vector<int>{0}));
}

// A symmetric bow-tie quad: its Newell normal is zero (the two lobes' areas cancel), but it is
// not degenerate: it crosses itself (it was reported "zero area" and hid nothing).
TEST(Polyhedron, SymmetricBowTieIsSelfIntersecting) {
  std::vector<Point3> vs = {Point3(0, 0, 0), Point3(1, 1, 0), Point3(1, 0, 0), Point3(0, 1, 0)};
  Polyhedron p(vs, {{0, 1, 2, 3}});
  const MeshReport& r = p.report();
  EXPECT_TRUE(r.degenerate_faces.empty());
  EXPECT_EQ(r.self_intersecting_faces, std::vector<int>{0});
  // Asymmetric: non-zero normal, still crossing.
  std::vector<Point3> ws = {Point3(0, 0, 0), Point3(5, 3, 0), Point3(5, 0, 0), Point3(0, 1, 0)};
  EXPECT_EQ(Polyhedron(ws, {{0, 1, 2, 3}}).report().self_intersecting_faces, std::vector<int>{0});
}

TEST(Polyhedron, DuplicateVerticesExactly) {
  Polyhedron p = load_mesh(kData + "/bad/duplicate_vertex.off");  // 1/2 and 0.5
  EXPECT_EQ(p.report().duplicate_vertices, (std::vector<std::pair<int, int>>{{1, 3}}));
  // Values that round to the same double are still distinct.
  std::vector<Point3> vs = {Point3(parse_rational("0.1"), 0, 0), Point3(parse_rational("0.10000000000000000001"), 0, 0),
                            Point3(0, 1, 0)};
  EXPECT_TRUE(Polyhedron(vs, {{0, 1, 2}}).report().duplicate_vertices.empty());
}

TEST(Polyhedron, BadFaceListsThrowWithFaceIndex) {
  std::vector<Point3> vs = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)};
  try {
    Polyhedron(vs, {{0, 1, 2}, {0, 1, 3}});
    FAIL();
  } catch (const FaceError& e) {
    EXPECT_EQ(e.face(), 1);
  }
  EXPECT_THROW(Polyhedron(vs, {{0, 1}}), FaceError);
}

TEST(Polyhedron, OrientFacesMakesAnyOrientationOutward) {
  Polyhedron cube = load_mesh(kData + "/cube.off");
  std::vector<Face> mixed = cube.faces();
  std::reverse(mixed[0].begin(), mixed[0].end());
  std::reverse(mixed[3].begin(), mixed[3].end());
  std::reverse(mixed[4].begin(), mixed[4].end());
  Polyhedron bad(cube.vertices(), mixed);
  EXPECT_FALSE(bad.report().oriented());
  Polyhedron fixed(cube.vertices(), orient_faces(cube.vertices(), mixed));
  EXPECT_TRUE(fixed.report().valid_solid());
  EXPECT_EQ(six_signed_volume(fixed.vertices(), fixed.faces()), 48);
  // All faces inward: flipped back to outward.
  Polyhedron inward = cube.reversed();
  EXPECT_EQ(six_signed_volume(inward.vertices(), inward.faces()), -48);
  EXPECT_EQ(six_signed_volume(cube.vertices(), orient_faces(cube.vertices(), inward.faces())), 48);
}

// The planes are made on first use; that use may come from several threads at once (the
// visible surfaces and tone hatching read them on all cores): they are made once, and every
// thread sees the same, complete list.
TEST(Polyhedron, PlanesFirstReadOnManyThreadsAreMadeOnce) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<long> c(-1000, 1000);
  std::vector<Point3> v;
  std::vector<Face> f;
  for (int i = 0; i < 20000; ++i) {
    for (int k = 0; k < 3; ++k) v.emplace_back(Rational(c(rng), 7), Rational(c(rng), 3), Rational(c(rng)));
    f.push_back(Face{3 * i, 3 * i + 1, 3 * i + 2});
  }
  std::vector<Plane> want;
  for (std::size_t k = 0; k < f.size(); k += 97) {
    const Point3* pts[3] = {&v[f[k][0]], &v[f[k][1]], &v[f[k][2]]};
    want.push_back(primitive_plane(plane_of_polygon(pts, 3)));
  }
  for (int round = 0; round < 3; ++round) {
    const Polyhedron p(v, f);
    std::atomic<int> ready{0};
    std::vector<const std::vector<Plane>*> seen(8, nullptr);
    std::vector<char> good(8, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < 8; ++t)
      threads.emplace_back([&, t] {
        ready.fetch_add(1);
        while (ready.load() < 8) {
        }
        const std::vector<Plane>& pl = p.planes();  // read at once, while others may still be making them
        bool ok = pl.size() == f.size();
        for (std::size_t k = 0; ok && k < want.size(); ++k) ok = pl[97 * k] == want[k];
        seen[t] = &pl;
        good[t] = ok;
      });
    for (auto& t : threads) t.join();
    for (int t = 0; t < 8; ++t) ASSERT_EQ(seen[t], seen[0]);
    for (int t = 0; t < 8; ++t) ASSERT_TRUE(good[t]) << "thread " << t;
    EXPECT_EQ(p.plane_if_made(5), &(*seen[0])[5]);
  }
}
