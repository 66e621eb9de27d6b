// STEP and IGES through Open CASCADE (see cad_reader.hpp; docs/design.md, "Models").
// Open CASCADE meshes each B-rep face on its own, but it discretises every edge once and every
// face's triangulation refers to that edge's nodes (Poly_PolygonOnTriangulation): the nodes of
// one edge on its two faces are welded here into one vertex each, by their place along the edge,
// and an edge's end nodes into its B-rep vertices, so a solid's faces make one closed mesh.
#include "io/models/cad_reader.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Poly_PolygonOnTriangulation.hxx>
#include <Poly_Triangulation.hxx>
#include <Quantity_Color.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TCollection_AsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "io/models/model_module.hpp"
#include "io/readers/input_error.hpp"

namespace hlr {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Faces whose normals along a shared edge differ by less than this are tangent (BRepLib::
// EncodeRegularity): CAD files store tangency to about their modelling tolerance.
constexpr double kTangentRadians = 1e-3;

struct NamedShape {
  std::string name;
  TopoDS_Shape shape;
  std::optional<Rgb> colour;
};

std::string label_name(const TDF_Label& l) {
  Handle(TDataStd_Name) n;
  if (!l.FindAttribute(TDataStd_Name::GetID(), n)) return "";
  return TCollection_AsciiString(n->Get()).ToCString();
}

std::optional<Rgb> label_colour(const Handle(XCAFDoc_ColorTool) & ct, const TDF_Label& l) {
  Quantity_Color c;
  if (ct->GetColor(l, XCAFDoc_ColorSurf, c) || ct->GetColor(l, XCAFDoc_ColorGen, c)) {
    NCollection_Vec3<float> s = Quantity_Color::Convert_LinearRGB_To_sRGB(NCollection_Vec3<float>(c.Red(), c.Green(), c.Blue()));
    return Rgb{s.r(), s.g(), s.b()};
  }
  return std::nullopt;
}

// The shapes of an XCAF document's tree, each placed by the locations above it.
void walk(const Handle(XCAFDoc_ShapeTool) & st, const Handle(XCAFDoc_ColorTool) & ct, const TDF_Label& label, const TopLoc_Location& above,
          std::vector<NamedShape>& out) {
  const TopLoc_Location here = above * XCAFDoc_ShapeTool::GetLocation(label);
  TDF_Label ref = label;
  if (XCAFDoc_ShapeTool::IsReference(label)) XCAFDoc_ShapeTool::GetReferredShape(label, ref);
  if (XCAFDoc_ShapeTool::IsAssembly(ref)) {
    TDF_LabelSequence comps;
    XCAFDoc_ShapeTool::GetComponents(ref, comps);
    for (Standard_Integer i = 1; i <= comps.Length(); ++i) walk(st, ct, comps.Value(i), here, out);
    return;
  }
  std::string name = label_name(ref);
  if (name.empty()) name = label_name(label);
  std::optional<Rgb> colour = label_colour(ct, label);
  if (!colour) colour = label_colour(ct, ref);
  out.push_back({name, XCAFDoc_ShapeTool::GetShape(ref).Moved(here), colour});
}

std::vector<NamedShape> read_shapes(const std::string& path) {
  Handle(TDocStd_Document) doc;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
  const std::string ext = lower_extension(path);
  bool ok = false;
  if (ext == ".step" || ext == ".stp") {
    STEPCAFControl_Reader r;
    r.SetNameMode(true);
    r.SetColorMode(true);
    if (r.ReadFile(path.c_str()) != IFSelect_RetDone) throw InputError(path, 0, "not a STEP file Open CASCADE can read");
    ok = r.Transfer(doc);
  } else {
    IGESCAFControl_Reader r;
    r.SetNameMode(true);
    r.SetColorMode(true);
    if (r.ReadFile(path.c_str()) != IFSelect_RetDone) throw InputError(path, 0, "not an IGES file Open CASCADE can read");
    ok = r.Transfer(doc);
  }
  if (!ok) throw InputError(path, 0, "Open CASCADE found no shape it can transfer in the file");
  Handle(XCAFDoc_ShapeTool) st = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  Handle(XCAFDoc_ColorTool) ct = XCAFDoc_DocumentTool::ColorTool(doc->Main());
  TDF_LabelSequence free;
  st->GetFreeShapes(free);
  std::vector<NamedShape> out;
  for (Standard_Integer i = 1; i <= free.Length(); ++i) walk(st, ct, free.Value(i), TopLoc_Location(), out);
  XCAFApp_Application::GetApplication()->Close(doc);
  return out;
}

// The bodies of the shapes: every solid, then the faces in no solid sewn into shells (IGES files
// often hold loose faces), a closed shell made a solid.
std::vector<NamedShape> bodies_of(const std::vector<NamedShape>& shapes, double size, std::vector<std::string>& notes) {
  std::vector<NamedShape> bodies;
  BRep_Builder builder;
  TopoDS_Compound loose;
  builder.MakeCompound(loose);
  int n_loose = 0;
  for (const NamedShape& s : shapes) {
    TopTools_IndexedMapOfShape in_solids;
    int k = 0;
    for (TopExp_Explorer e(s.shape, TopAbs_SOLID); e.More(); e.Next(), ++k) {
      bodies.push_back({s.name, e.Current(), s.colour});
      TopExp::MapShapes(e.Current(), TopAbs_FACE, in_solids);
    }
    for (TopExp_Explorer e(s.shape, TopAbs_FACE); e.More(); e.Next())
      if (!in_solids.Contains(e.Current())) builder.Add(loose, e.Current()), ++n_loose;
  }
  if (n_loose == 0) return bodies;
  const double tolerance = size * 1e-5;
  BRepBuilderAPI_Sewing sewing(tolerance);
  sewing.Add(loose);
  sewing.Perform();
  int shells = 0, closed = 0;
  for (TopExp_Explorer e(sewing.SewedShape(), TopAbs_SHELL); e.More(); e.Next()) {
    ++shells;
    TopoDS_Shape body = e.Current();
    if (BRep_Tool::IsClosed(body)) {
      BRepBuilderAPI_MakeSolid solid(TopoDS::Shell(body));
      if (solid.IsDone()) body = solid.Solid(), ++closed;
    }
    bodies.push_back({"", body, std::nullopt});
  }
  for (TopExp_Explorer e(sewing.SewedShape(), TopAbs_FACE, TopAbs_SHELL); e.More(); e.Next()) bodies.push_back({"", e.Current(), std::nullopt});
  std::ostringstream note;
  note << n_loose << " faces in no solid were sewn (tolerance " << tolerance << " mm) into " << shells << " shells, " << closed << " of them closed";
  if (sewing.NbFreeEdges() > 0) note << " (" << sewing.NbFreeEdges() << " free edges: the file's surfaces leave gaps wider than the tolerance)";
  notes.push_back(note.str());
  return bodies;
}

// One body's mesh: its faces' triangulations welded along their shared edges.
class Welder {
 public:
  explicit Welder(const TopoDS_Shape& body) {
    TopExp::MapShapes(body, TopAbs_VERTEX, vertices_);
    TopExp::MapShapes(body, TopAbs_EDGE, edges_);
    TopExp::MapShapes(body, TopAbs_FACE, faces_);
    vertex_id_.assign(vertices_.Extent() + 1, -1);
    edge_nodes_.resize(edges_.Extent() + 1);
  }

  int add_faces(ModelBody& out) {
    int unmeshed = 0;
    for (int fi = 1; fi <= faces_.Extent(); ++fi)
      if (!add_face(TopoDS::Face(faces_(fi)), fi - 1, out)) ++unmeshed;
    return unmeshed;
  }

  const TopTools_IndexedMapOfShape& faces() const { return faces_; }

 private:
  int point(const gp_Pnt& p, MeshData& m) {
    m.vertices.emplace_back(Rational(p.X()), Rational(p.Y()), Rational(p.Z()));
    return static_cast<int>(m.vertices.size()) - 1;
  }

  int vertex(const TopoDS_Vertex& v, const gp_Pnt& at, MeshData& m) {
    const int i = vertices_.FindIndex(v);
    if (i == 0) return point(at, m);
    if (vertex_id_[i] < 0) vertex_id_[i] = point(at, m);
    return vertex_id_[i];
  }

  // The face's nodes on edge `e`, mapped to the body's vertices (the edge's, made at first use).
  void map_edge(const TopoDS_Edge& e, const Handle(Poly_Triangulation) & tri, const TopLoc_Location& loc, std::vector<int>& node_id, MeshData& m) {
    Handle(Poly_PolygonOnTriangulation) poly = BRep_Tool::PolygonOnTriangulation(e, tri, loc);
    if (poly.IsNull()) return;
    const TColStd_Array1OfInteger& nodes = poly->Nodes();
    const int n = nodes.Length();
    auto node = [&](int k) { return nodes.Value(nodes.Lower() + k); };
    auto at = [&](int k) { return tri->Node(node(k)).Transformed(loc.Transformation()); };
    TopoDS_Vertex first, last;
    TopExp::Vertices(TopoDS::Edge(e.Oriented(TopAbs_FORWARD)), first, last);
    if (BRep_Tool::Degenerated(e)) {  // a pole: every node is the vertex
      for (int k = 0; k < n; ++k) node_id[node(k)] = vertex(first, at(k), m);
      return;
    }
    // The polygon runs along the edge's parameter; reversed when its parameters fall.
    const Handle(TColStd_HArray1OfReal)& par = poly->Parameters();
    const bool reversed = !par.IsNull() && n > 1 && par->Value(par->Lower()) > par->Value(par->Upper());
    std::vector<int>& ids = edge_nodes_[edges_.FindIndex(e)];
    if (ids.empty()) {
      ids.resize(n);
      for (int k = 0; k < n; ++k) {
        const int j = reversed ? n - 1 - k : k;  // place along the edge
        ids[j] = j == 0 ? vertex(first, at(k), m) : j == n - 1 ? vertex(last, at(k), m) : point(at(k), m);
      }
    }
    if (static_cast<int>(ids.size()) != n) {
      mismatched_ = true;
      return;
    }
    for (int k = 0; k < n; ++k) node_id[node(k)] = ids[reversed ? n - 1 - k : k];
  }

  bool add_face(const TopoDS_Face& f, int surface, ModelBody& out) {
    TopLoc_Location loc;
    Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(f, loc);
    if (tri.IsNull()) return false;
    MeshData& m = out.mesh;
    std::vector<int> node_id(tri->NbNodes() + 1, -1);
    for (TopExp_Explorer e(f, TopAbs_EDGE); e.More(); e.Next()) map_edge(TopoDS::Edge(e.Current()), tri, loc, node_id, m);
    for (int i = 1; i <= tri->NbNodes(); ++i)
      if (node_id[i] < 0) node_id[i] = point(tri->Node(i).Transformed(loc.Transformation()), m);
    const bool flip = f.Orientation() == TopAbs_REVERSED;
    for (int t = 1; t <= tri->NbTriangles(); ++t) {
      int a, b, c;
      tri->Triangle(t).Get(a, b, c);
      if (flip) std::swap(b, c);
      const int u = node_id[a], v = node_id[b], w = node_id[c];
      if (u == v || v == w || u == w) continue;  // collapsed at a pole
      m.faces.push_back(Face{u, v, w});
      m.face_lines.push_back(0);
      out.surfaces.surface.push_back(surface);
    }
    return true;
  }

  TopTools_IndexedMapOfShape vertices_, edges_, faces_;
  std::vector<int> vertex_id_;
  std::vector<std::vector<int>> edge_nodes_;

 public:
  bool mismatched_ = false;
};

// The pairs of B-rep faces that meet tangentially along an edge.
std::vector<std::pair<int, int>> tangent_faces(const TopoDS_Shape& body, const TopTools_IndexedMapOfShape& faces) {
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(body, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  std::vector<std::pair<int, int>> out;
  for (int i = 1; i <= edge_faces.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edge_faces.FindKey(i));
    const TopTools_ListOfShape& fs = edge_faces.FindFromIndex(i);
    if (fs.Extent() != 2 || fs.First().IsSame(fs.Last())) continue;  // a seam lies inside one face
    const TopoDS_Face& f1 = TopoDS::Face(fs.First());
    const TopoDS_Face& f2 = TopoDS::Face(fs.Last());
    if (!BRep_Tool::HasContinuity(e, f1, f2) || BRep_Tool::Continuity(e, f1, f2) == GeomAbs_C0) continue;
    int a = faces.FindIndex(f1) - 1, b = faces.FindIndex(f2) - 1;
    if (a < 0 || b < 0) continue;
    out.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

Model models::read_cad(const std::string& path, const TessellationOptions& options) {
  if (!std::filesystem::exists(path)) throw InputError(path, 0, "cannot open file");
  if (!(options.deflection >= 0) || !(options.angle_degrees > 0 && options.angle_degrees < 180))
    throw std::invalid_argument("the tessellation's deflection must be >= 0 mm and its angle in (0, 180) degrees");
  // Open CASCADE's readers print to standard output, which may be the drawing: silenced.
  Message::DefaultMessenger()->ChangePrinters().Clear();
  Model model;
  model.units = "mm";
  model.z_up = true;
  try {
    std::vector<NamedShape> shapes = read_shapes(path);
    Bnd_Box box;
    for (const NamedShape& s : shapes) BRepBndLib::Add(s.shape, box);
    if (box.IsVoid()) throw InputError(path, 0, "the file holds no shape with faces");
    const double size = std::sqrt(box.SquareExtent());
    std::vector<NamedShape> bodies = bodies_of(shapes, size, model.notes);
    const double deflection = options.deflection > 0 ? options.deflection : size / 1000;
    std::ostringstream note;
    note << "tessellated by Open CASCADE at a deflection of " << deflection << " mm and " << options.angle_degrees
         << " degrees: the drawing is exact for these triangles";
    model.notes.push_back(note.str());
    const std::string stem = std::filesystem::path(path).stem().string();
    std::map<std::string, int> seen;
    for (NamedShape& s : bodies) {
      BRepLib::EncodeRegularity(s.shape, kTangentRadians);
      BRepMesh_IncrementalMesh mesh(s.shape, deflection, false, options.angle_degrees * kPi / 180, true);
      ModelBody b;
      const std::string base = s.name.empty() ? stem : s.name;
      const int n = ++seen[base];
      b.name = n == 1 ? base : base + " " + std::to_string(n);
      b.colour = s.colour;
      Welder w(s.shape);
      const int unmeshed = w.add_faces(b);
      if (unmeshed) model.notes.push_back("body '" + b.name + "': " + std::to_string(unmeshed) + " faces Open CASCADE could not mesh are left out");
      if (w.mismatched_)
        model.notes.push_back("body '" + b.name + "': an edge was meshed differently on its two faces; those faces are not welded there");
      if (b.mesh.faces.empty()) continue;
      b.surfaces.tangent = tangent_faces(s.shape, w.faces());
      b.surfaces.sharp_between = true;
      model.bodies.push_back(std::move(b));
    }
  } catch (const Standard_Failure& e) {
    throw InputError(path, 0, std::string("Open CASCADE: ") + e.GetMessageString());
  }
  if (model.bodies.empty()) throw InputError(path, 0, "the file holds no shape with faces");
  return model;
}

}  // namespace hlr
