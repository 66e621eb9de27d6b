// Reading meshes: OFF, OBJ, STL (ASCII and binary) and PLY (ASCII and binary), with exact
// coordinates. Text numbers keep their exact value (0.1 is 1/10); binary floats and doubles
// keep their stored value exactly. The face lists then go through OpenMesh (Polyhedron), and
// faces it refuses are reported by index. OpenMesh's own OFF/OBJ readers round coordinates to
// float, which is why the coordinates are read here.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "algorithms/solids/face_surfaces.hpp"
#include "io/readers/input_error.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr {

/// Raw mesh content: exact vertices, faces as 0-based index lists, and the line (or, for
/// binary files, 0) each face came from.
struct MeshData {
  std::vector<Point3> vertices;
  /// A large file's vertices when every coordinate is a short decimal: numerators over one
  /// power of ten (kernel/point_store.hpp), and `vertices` empty.
  PointStore compact;
  std::size_t num_vertices() const { return compact.compact() ? compact.size() : vertices.size(); }
  std::vector<Face> faces;
  std::vector<int> face_lines;
  /// OBJ `vt` texture coordinates (u, v; shading data, doubles) and, per face, the index of
  /// each corner's (aligned with the face's vertices; empty: the face has none).
  std::vector<std::array<double, 2>> texcoords;
  std::vector<std::vector<int>> face_texcoords;
  /// The smooth surfaces the file marks (OBJ's normals or smoothing groups); empty: none.
  FaceSurfaces surfaces;
};

/// Most vertices a single face may have.
inline constexpr long kMaxFaceVertices = 1 << 16;

MeshData read_off(std::string_view bytes, const std::string& file);
MeshData read_obj(std::string_view bytes, const std::string& file);
MeshData read_stl(std::string_view bytes, const std::string& file);
MeshData read_ply(std::string_view bytes, const std::string& file);

/// Reads a mesh file by its extension (.off, .obj, .stl, .ply, any case). Throws InputError:
/// missing file, unknown extension, parse error (with line), empty mesh.
MeshData read_mesh_file(const std::string& path);

/// Reads mesh bytes of a format ("off", "obj", "stl", "ply"); `name` names them in errors.
MeshData read_mesh_bytes(std::string_view bytes, const std::string& format, const std::string& name);

/// Builds the polyhedron of mesh data; bad faces become InputError with the face's line.
Polyhedron make_polyhedron(MeshData data, const std::string& file);

/// read_mesh_file + make_polyhedron.
Polyhedron load_mesh(const std::string& path);

}  // namespace hlr
