// STEP models through Open CASCADE (io/models/cad_reader.hpp): B-rep solids made here with Open
// CASCADE's own primitives and written as STEP, read back, welded and classified. The faces'
// identity is checked against the geometry (a cylinder's caps lie in z = 0 and z = h), the
// drawing against the exact ray-casting oracle (tests/support/face_oracle.hpp), and the real
// files of Debian's occt-misc where they are installed.
#include <gtest/gtest.h>

#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <STEPControl_Writer.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "io/models/cad_reader.hpp"
#include "io/models/model_input.hpp"
#include "io/pipeline/render.hpp"
#include "io/views/standard_views.hpp"
#include "kernel/mesh_checks.hpp"
#include "support/drawing_oracle.hpp"

namespace hlr {
namespace {

void set_view(RenderOptions& o, const std::string& name) {
  const StandardView v = *standard_view(name, true);
  o.view.direction = v.direction;
  o.view.up = v.up;
}

std::string write_step(const TopoDS_Shape& s, const std::string& name) {
  const std::string path = (std::filesystem::temp_directory_path() / ("hlr_cad_" + name + ".step")).string();
  STEPControl_Writer w;
  w.Transfer(s, STEPControl_AsIs);
  EXPECT_EQ(w.Write(path.c_str()), IFSelect_RetDone);
  return path;
}

// Every mesh edge of a body: its two faces (closed meshes only).
std::vector<std::array<int, 2>> edge_faces(const MeshData& m) {
  std::map<std::pair<int, int>, std::vector<int>> faces;
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (std::size_t k = 0; k < m.faces[f].size(); ++k) {
      int a = m.faces[f][k], b = m.faces[f][(k + 1) % m.faces[f].size()];
      faces[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(f));
    }
  std::vector<std::array<int, 2>> out;
  for (const auto& [e, fs] : faces) {
    EXPECT_EQ(fs.size(), 2u) << "edge " << e.first << "-" << e.second << " is not between two faces: the weld left a gap";
    if (fs.size() == 2) out.push_back({fs[0], fs[1]});
  }
  return out;
}

TEST(CadModel, CylinderFacesAndSharpCircles) {
  const double r = 10, h = 20;
  Model m = read_cad_file(write_step(BRepPrimAPI_MakeCylinder(r, h).Shape(), "cylinder"), {});
  ASSERT_EQ(m.bodies.size(), 1u);
  const ModelBody& b = m.bodies[0];
  EXPECT_TRUE(make_polyhedron(b.mesh, "cylinder").report().closed());
  // The geometry's truth: a face with every corner at z = 0 (or h) is on a cap, else on the side.
  auto where = [&](int f) {
    int at0 = 0, ath = 0;
    for (int v : b.mesh.faces[f]) at0 += b.mesh.vertices[v].z() == 0, ath += b.mesh.vertices[v].z() == Rational(h);
    return at0 == 3 ? 0 : ath == 3 ? 1 : 2;
  };
  int inside = 0, sharp = 0;
  for (const auto& e : edge_faces(b.mesh)) {
    const SurfaceEdge got = surface_edge(b.surfaces, e[0], e[1]);
    const SurfaceEdge want = where(e[0]) == where(e[1]) ? SurfaceEdge::Inside : SurfaceEdge::Sharp;
    EXPECT_EQ(got, want) << "faces " << e[0] << " and " << e[1];
    (want == SurfaceEdge::Inside ? inside : sharp)++;
  }
  EXPECT_GT(inside, 40);     // the seam and every edge across the side and the caps
  EXPECT_GE(sharp, 2 * 24);  // two circles of at least 24 segments (15 degrees)
  EXPECT_TRUE(b.surfaces.tangent.empty());
  // Drawn: the circles and the side's two silhouettes, nothing across the faces.
  RenderOptions o;
  set_view(o, "iso");
  RenderResult d = render({load_model(write_step(BRepPrimAPI_MakeCylinder(r, h).Shape(), "cylinder"), {})}, o);
  for (const Segment& s : d.drawing.segments) {
    if (s.line == LineKind::Crease) {
      EXPECT_TRUE((s.from().z() == 0 && s.to().z() == 0) || (s.from().z() == h && s.to().z() == h)) << "a crease off the circles";
    } else {
      EXPECT_EQ(s.line, LineKind::Silhouette);
    }
  }
}

TEST(CadModel, SphereHasOnlyItsSilhouette) {
  Model m = read_cad_file(write_step(BRepPrimAPI_MakeSphere(5).Shape(), "sphere"), {});
  ASSERT_EQ(m.bodies.size(), 1u);
  const ModelBody& b = m.bodies[0];
  EXPECT_TRUE(make_polyhedron(b.mesh, "sphere").report().closed()) << "the poles and the seam are welded";
  for (const auto& e : edge_faces(b.mesh)) EXPECT_EQ(surface_edge(b.surfaces, e[0], e[1]), SurfaceEdge::Inside);
  RenderOptions o;
  set_view(o, "front");
  RenderResult d = render({load_model(write_step(BRepPrimAPI_MakeSphere(5).Shape(), "sphere"), {})}, o);
  ASSERT_FALSE(d.drawing.segments.empty());
  for (const Segment& s : d.drawing.segments) EXPECT_EQ(s.line, LineKind::Silhouette);
}

TopoDS_Shape filleted_box() {
  BRepPrimAPI_MakeBox box(30, 20, 10);
  BRepFilletAPI_MakeFillet fillet(box.Shape());
  TopExp_Explorer e(box.Shape(), TopAbs_EDGE);
  fillet.Add(3, TopoDS::Edge(e.Current()));
  return fillet.Shape();
}

TEST(CadModel, FilletMeetsItsFacesTangentially) {
  const std::string path = write_step(filleted_box(), "fillet");
  Model m = read_cad_file(path, {});
  ASSERT_EQ(m.bodies.size(), 1u);
  EXPECT_EQ(m.bodies[0].surfaces.tangent.size(), 2u) << "the fillet and each of its two neighbours";
  std::map<TangentEdges, std::map<LineKind, int>> kinds;
  for (TangentEdges t : {TangentEdges::Thin, TangentEdges::None, TangentEdges::Visible}) {
    RenderOptions o;
    set_view(o, "iso");
    o.tangent_edges = t;
    for (const Segment& s : render({load_model(path, {})}, o).drawing.segments) ++kinds[t][s.line];
  }
  EXPECT_GT(kinds[TangentEdges::Thin][LineKind::Tangent], 0);
  EXPECT_EQ(kinds[TangentEdges::None].count(LineKind::Tangent), 0u);
  EXPECT_EQ(kinds[TangentEdges::Visible].count(LineKind::Tangent), 0u);
  EXPECT_EQ(kinds[TangentEdges::Visible][LineKind::Crease],
            kinds[TangentEdges::Thin][LineKind::Crease] + kinds[TangentEdges::Thin][LineKind::Tangent]);
  EXPECT_EQ(kinds[TangentEdges::None][LineKind::Crease], kinds[TangentEdges::Thin][LineKind::Crease]);
}

TEST(CadModel, OracleAgreesOnTessellatedSolids) {
  for (const char* view : {"front", "top", "iso"}) {
    RenderOptions o;
    set_view(o, view);
    EXPECT_GT(test::check_visibility(render({load_model(write_step(filleted_box(), "fillet"), {})}, o)), 10) << view;
  }
  const char* screw = "/usr/share/opencascade/data/step/screw.step";
  if (!std::filesystem::exists(screw)) GTEST_SKIP() << "occt-misc is not installed";
  RenderOptions o;
  set_view(o, "iso");
  EXPECT_GT(test::check_visibility(render({load_model(screw, {})}, o)), 100);
}

TEST(CadModel, RealFilesAreClosedSolids) {
  const std::string dir = "/usr/share/opencascade/data/step/";
  if (!std::filesystem::exists(dir + "linkrods.step")) GTEST_SKIP() << "occt-misc is not installed";
  for (const char* f : {"linkrods.step", "screw.step"}) {
    Model m = read_cad_file(dir + f, {});
    ASSERT_EQ(m.bodies.size(), 1u) << f;
    EXPECT_TRUE(make_polyhedron(m.bodies[0].mesh, f).report().closed()) << f << ": welded along every B-rep edge";
    EXPECT_FALSE(m.bodies[0].surfaces.tangent.empty()) << f;
    ASSERT_FALSE(m.notes.empty());
    EXPECT_NE(m.notes.back().find("deflection"), std::string::npos);
  }
}

TEST(CadModel, BadFilesAreClearErrors) {
  const std::string path = (std::filesystem::temp_directory_path() / "hlr_cad_bad.step").string();
  std::ofstream(path) << "ISO-10303-21;\nthis is not a STEP file\n";
  EXPECT_THROW(read_cad_file(path, {}), InputError);
  EXPECT_THROW(read_cad_file("/nonexistent/part.step", {}), InputError);
  TessellationOptions bad;
  bad.angle_degrees = 0;
  EXPECT_THROW(read_cad_file(write_step(BRepPrimAPI_MakeSphere(5).Shape(), "sphere"), bad), std::invalid_argument);
}

}  // namespace
}  // namespace hlr
