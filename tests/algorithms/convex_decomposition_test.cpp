// Convex decomposition (algorithms/solids/convex_decomposition.hpp, course notes section 23) and
// Roberts' algorithm through the pieces (algorithms/hlr/roberts_pieces.hpp): pieces convex and
// exactly as large as the body, both methods; the pieces route draws exactly what the
// per-face route draws; the cut-plane trap.
#include "algorithms/solids/convex_decomposition.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/hlr/roberts_pieces.hpp"
#include "algorithms/solids/convexity.hpp"
#include "io/readers/mesh_reader.hpp"
#include "support/numbers.hpp"

using namespace hlr;

namespace {
const std::string kData = HLR_DATA_DIR;
using hlr::test::Q;
Point3 P(const char* x, const char* y, const char* z) { return Point3(Q(x), Q(y), Q(z)); }

std::string pieces(const Segment& s) {
  std::string out = "0";
  for (const Piece& p : s.pieces) out += std::string(p.visible ? " v " : p.behind_eye ? " b " : " h ") + to_string(p.t1);
  return out;
}

std::vector<std::string> bodies() {
  std::vector<std::string> out = {kData + "/l_prism.off", kData + "/u_prism.off", kData + "/star_prism.off", kData + "/frame.off"};
  std::string cross = std::string(HLR_CORPUS_DIR) + "/cross.off";
  if (std::filesystem::exists(cross)) out.push_back(cross);
  return out;
}
}  // namespace

TEST(ConvexDecomposition, PiecesAreConvexAndFillTheBodyExactly) {
  for (const std::string& path : bodies()) {
    Polyhedron body = load_mesh(path);
    Rational volume = six_volume(body);
    for (DecompositionMethod m : {DecompositionMethod::FacePlanes, DecompositionMethod::Nef}) {
      Decomposition d = convex_decomposition(body, m);
      EXPECT_GE(d.pieces.size(), 2u) << path;
      Rational total = 0;
      std::size_t cut = 0, surface = 0;
      for (const ConvexPiece& p : d.pieces) {
        EXPECT_TRUE(p.body.report().valid_solid()) << path;
        EXPECT_TRUE(convexity(p.body).convex()) << path;
        EXPECT_GT(six_volume(p.body), 0) << path;
        total += six_volume(p.body);
        ASSERT_EQ(p.faces.size(), p.body.num_faces());
        for (FaceOrigin o : p.faces) {
          cut += o != FaceOrigin::Surface;
          surface += o != FaceOrigin::Cut;
        }
      }
      EXPECT_EQ(total, volume) << path;  // the union's volume, exactly (pieces do not overlap)
      EXPECT_GT(cut, 0u) << path;
      EXPECT_GT(surface, 0u) << path;
      if (m == DecompositionMethod::FacePlanes) {
        EXPECT_FALSE(d.cuts.empty());
        for (const Plane& h : d.cuts) {  // every cut is the plane of a face of the body
          bool found = false;
          for (const Plane& f : body.planes()) found = found || f == h;
          EXPECT_TRUE(found) << path;
        }
      }
    }
  }
  // The L-prism by hand: cut by y = 1 (the plane of face 4) into [0,1]x[1,2] and [0,2]x[0,1].
  Decomposition l = convex_decomposition(load_mesh(kData + "/l_prism.off"));
  ASSERT_EQ(l.pieces.size(), 2u);
  EXPECT_EQ(to_string(l.cuts[0]), "[0 1 0 -1]");
  std::vector<Rational> v = {six_volume(l.pieces[0].body) / 6, six_volume(l.pieces[1].body) / 6};
  std::sort(v.begin(), v.end());
  EXPECT_EQ(v, (std::vector<Rational>{1, 2}));
  // A convex body is its own single piece, all of it on the surface.
  Decomposition c = convex_decomposition(load_mesh(kData + "/cube.off"));
  ASSERT_EQ(c.pieces.size(), 1u);
  for (FaceOrigin o : c.pieces[0].faces) EXPECT_EQ(o, FaceOrigin::Surface);
  // Not a solid: refused with a message.
  EXPECT_THROW(convex_decomposition(load_mesh(kData + "/bad/open_box.off")), std::invalid_argument);
}

// Both routes give the same drawing for closed solids, edge by edge, exactly.
TEST(ConvexDecomposition, PiecesRouteDrawsWhatThePerFaceRouteDraws) {
  std::vector<Camera> cams = {make_orthographic(Vector3(1, Q("1.3"), Q("1.7"))), make_orthographic(Vector3(0, 0, 1)),
                              make_orthographic(Vector3(1, 0, 0)), make_orthographic(Vector3(0, 1, 0)),
                              make_orthographic(Vector3(1, 1, 0)), make_orthographic(Vector3(-1, 2, -3)),
                              make_perspective(P("7", "9", "5"), P("1", "1", "1/2")), make_perspective(P("1/2", "1", "6"), P("1/2", "1", "0"))};
  std::size_t compared = 0, hidden = 0;
  for (const std::string& path : bodies()) {
    Polyhedron body = load_mesh(path);
    for (const Camera& cam : cams)
      for (EdgeSelection e : {EdgeSelection::All, EdgeSelection::Feature}) {
        LineOptions ro;
        ro.edges = e;
        LineOptions lo;
        lo.edges = e;
        LineDrawing a = roberts_pieces({&body}, cam, ro), b = face_occluders({&body}, cam, lo);
        ASSERT_EQ(a.segments.size(), b.segments.size()) << path;
        for (std::size_t i = 0; i < a.segments.size(); ++i) {
          const Segment &x = a.segments[i], &y = b.segments[i];
          ASSERT_EQ(x.v0, y.v0);
          ASSERT_EQ(x.v1, y.v1);
          EXPECT_EQ(x.line, y.line);
          EXPECT_EQ(pieces(x), pieces(y)) << path << " edge " << x.from() << "-" << x.to();
          ++compared;
          for (const Piece& p : x.pieces) hidden += !p.visible;
        }
      }
  }
  EXPECT_GT(compared, 1000u);
  EXPECT_GT(hidden, 300u);
}

// The trap: a sight ray running exactly along a cut plane inside the union is inside the solid.
// The L-prism is cut by y = 1; seen along +x (a direction in that plane), the rod's edges in
// y = 1 behind the L are hidden by the L's interior, which only the cut face separates.
TEST(ConvexDecomposition, RayAlongTheCutPlaneIsInsideTheSolid) {
  Polyhedron l = load_mesh(kData + "/l_prism.off");
  Polyhedron rod = make_box(P("-3", "1", "1/4"), P("-2", "3/2", "3/4"));
  for (const Camera& cam : {make_orthographic(Vector3(1, 0, 0)), make_orthographic(Vector3(5, 0, 0)),
                            make_perspective(P("6", "1", "1/2"), P("0", "1", "1/2"))}) {
    LineDrawing a = roberts_pieces({&l, &rod}, cam, {});
    LineDrawing b = face_occluders({&l, &rod}, cam, {});
    for (const LineDrawing* r : {&a, &b}) {
      const Segment* e = nullptr;
      for (const Segment& s : r->segments)
        if (s.body == 1 && s.v0 == 1 && s.v1 == 5) e = &s;  // x = -2, y = 1, z from 1/4 to 3/4
      ASSERT_NE(e, nullptr);
      EXPECT_EQ(pieces(*e), "0 h 1") << to_string(r->stats.method);
    }
  }
}
