// Checks of a polyhedron's face list, each naming the indices involved: closed (no boundary
// edges), manifold (edges in at most two faces, one fan of faces around each vertex),
// consistently oriented, every face exactly planar, no degenerate faces, no duplicate
// vertices. Course notes section 19 (solid models) and issue "Foundation".
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "kernel/face.hpp"
#include "kernel/geometry.hpp"

namespace hlr {

using Edge = std::pair<int, int>;

struct DegenerateFace {
  int face;
  std::string why;  // "repeated vertex 3", "zero area", "collinear vertices"
};

struct NonPlanarFace {
  int face;
  int vertex;  // a vertex of the face that is off the plane of its first three...
};

struct MeshReport {
  std::vector<Edge> boundary_edges;        // in exactly one face
  std::vector<Edge> non_manifold_edges;    // in three or more faces
  std::vector<int> non_manifold_vertices;  // faces around it form more than one fan
  std::vector<Edge> misoriented_edges;     // two faces traverse it in the same direction
  std::vector<NonPlanarFace> non_planar_faces;
  std::vector<DegenerateFace> degenerate_faces;
  std::vector<std::pair<int, int>> duplicate_vertices;  // (first, later) with equal coordinates
  std::vector<int> isolated_vertices;                   // used by no face
  std::vector<int> refused_faces;                       // refused by OpenMesh's add_face
  struct TJunction {
    int vertex;  // lies strictly inside...
    Edge edge;   // ...this boundary edge, without being one of its faces' vertices
  };
  std::vector<TJunction> t_junctions;
  std::vector<int> self_intersecting_faces;  // planar faces that are not simple polygons (edges cross or touch)
  /// Closed, oriented meshes of several components: the lowest face of each component whose
  /// signed volume is negative (inside out, or the shell of a cavity inside another one).
  std::vector<int> negative_components;
  std::vector<int> zero_area_crossing;  // internal: planar faces of zero net area, not collinear

  bool manifold() const { return non_manifold_edges.empty() && non_manifold_vertices.empty(); }
  bool closed() const { return boundary_edges.empty() && non_manifold_edges.empty(); }
  bool oriented() const { return misoriented_edges.empty(); }
  bool planar() const { return non_planar_faces.empty(); }
  bool valid_solid() const {
    return manifold() && closed() && oriented() && planar() && degenerate_faces.empty() &&
           duplicate_vertices.empty() && t_junctions.empty() && self_intersecting_faces.empty();
  }
};

/// Computes every check. `planes` are the faces' exact planes (Polyhedron::planes()).
MeshReport check_mesh(const std::vector<Point3>& vertices,
                      const std::vector<Face>& faces,
                      const std::vector<Plane>& planes);

std::string to_string(const Edge& e);

/// The first reason the mesh is not a valid solid, naming what is wrong: "edge 3-7 is in 3
/// faces (not manifold)", "face 4 crosses itself", ...; empty for a valid solid.
std::string solid_problem(const MeshReport& r);

}  // namespace hlr
