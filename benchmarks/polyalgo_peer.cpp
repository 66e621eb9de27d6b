// The Open CASCADE peer of the README's speed table (docs/performance.md, "Hidden lines against
// the peers"): HLRBRep_PolyAlgo, Open CASCADE's hidden-line removal on meshes, on an OFF mesh
// read as Open CASCADE reads an STL file: one planar face per triangle, every triangle side a
// BRep edge shared by its two faces (the vertices merged), each face meshed by BRepMesh. Then
// every edge with its visibility along an orthographic view direction. Prints the seconds of
// building and meshing the shape and of the hidden-line computation with the extraction of the
// visible and hidden edges (the peer's time in the table), and how many edges each holds.
// Usage: polyalgo_peer MESH.off DX DY DZ
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Builder.hxx>
#include <HLRAlgo_Projector.hxx>
#include <HLRBRep_PolyAlgo.hxx>
#include <HLRBRep_PolyHLRToShape.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Vertex.hxx>
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <gp_Ax2.hxx>
#include <gp_Pnt.hxx>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Vertices and triangles of an OFF file (doubles: the peer computes in floating point).
bool read_off(const char* path, std::vector<gp_Pnt>& vs, std::vector<std::array<int, 3>>& ts) {
  std::ifstream in(path);
  std::string head;
  int nv = 0, nf = 0, ne = 0;
  if (!(in >> head) || head != "OFF" || !(in >> nv >> nf >> ne)) return false;
  vs.resize(static_cast<std::size_t>(nv));
  for (gp_Pnt& p : vs) {
    double x, y, z;
    if (!(in >> x >> y >> z)) return false;
    p = gp_Pnt(x, y, z);
  }
  for (int i = 0; i < nf; ++i) {
    int n = 0, a = 0, b = 0, c = 0;
    if (!(in >> n >> a >> b >> c) || n != 3) return false;
    ts.push_back({a, b, c});
  }
  return true;
}

int count_edges(const TopoDS_Shape& s) {
  int n = 0;
  for (TopExp_Explorer e(s, TopAbs_EDGE); e.More(); e.Next()) ++n;
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: polyalgo_peer MESH.off DX DY DZ\n";
    return 2;
  }
  std::vector<gp_Pnt> vs;
  std::vector<std::array<int, 3>> ts;
  if (!read_off(argv[1], vs, ts)) {
    std::cerr << "polyalgo_peer: " << argv[1] << " is not a triangle OFF file\n";
    return 1;
  }
  const auto t0 = Clock::now();
  std::vector<TopoDS_Vertex> vertex(vs.size());
  BRep_Builder builder;
  for (std::size_t i = 0; i < vs.size(); ++i) builder.MakeVertex(vertex[i], vs[i], 1e-7);
  std::map<std::pair<int, int>, TopoDS_Edge> edges;  // each side once, shared by its two faces
  TopoDS_Compound shape;
  builder.MakeCompound(shape);
  for (const auto& t : ts) {
    BRepBuilderAPI_MakeWire polygon;
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      const std::pair<int, int> key = std::minmax(a, b);
      auto it = edges.find(key);
      if (it == edges.end()) {
        it = edges.emplace(key, BRepBuilderAPI_MakeEdge(vertex[key.first], vertex[key.second]).Edge()).first;
      }
      polygon.Add(a == key.first ? it->second : TopoDS::Edge(it->second.Reversed()));
    }
    if (!polygon.IsDone()) continue;  // a degenerate triangle
    BRepBuilderAPI_MakeFace face(polygon.Wire(), true);
    if (face.IsDone()) builder.Add(shape, face.Face());
  }
  BRepMesh_IncrementalMesh mesh(shape, 1e-3);
  const double build = since(t0);
  const auto t1 = Clock::now();
  const gp_Dir dir(std::atof(argv[2]), std::atof(argv[3]), std::atof(argv[4]));
  Handle(HLRBRep_PolyAlgo) algo = new HLRBRep_PolyAlgo();
  algo->Load(shape);
  algo->Projector(HLRAlgo_Projector(gp_Ax2(gp_Pnt(0, 0, 0), dir)));
  algo->Update();
  HLRBRep_PolyHLRToShape extract;
  extract.Update(algo);
  const TopoDS_Shape visible = extract.VCompound(), hidden = extract.HCompound();
  const TopoDS_Shape outline = extract.OutLineVCompound(), hidden_outline = extract.OutLineHCompound();
  const double hlr = since(t1);
  std::printf("faces %zu build %.3f s hlr %.3f s visible edges %d hidden edges %d outlines %d/%d\n", ts.size(), build, hlr, count_edges(visible),
              count_edges(hidden), count_edges(outline), count_edges(hidden_outline));
  return 0;
}
