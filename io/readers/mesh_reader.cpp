// Mesh files by extension, and their polyhedra (see mesh_reader.hpp).
#include "io/readers/mesh_reader.hpp"

#include "algorithms/support/parallel.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "io/readers/text_reader.hpp"

namespace hlr {

MeshData read_mesh_file(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  MeshData (*reader)(std::string_view, const std::string&) = nullptr;
  if (ext == ".off") reader = read_off;
  else if (ext == ".obj") reader = read_obj;
  else if (ext == ".stl") reader = read_stl;
  else if (ext == ".ply") reader = read_ply;
  else
    throw InputError(path, 0, "unknown mesh file extension '" + ext + "' (expected .off, .obj, .stl or .ply)");
  std::string bytes = read_file_bytes(path);
  MeshData m = reader(bytes, path);
  if (m.vertices.empty()) throw InputError(path, 0, "empty mesh: no vertices");
  if (m.faces.empty()) throw InputError(path, 0, "empty mesh: no faces");
  return m;
}

Polyhedron make_polyhedron(MeshData data, const std::string& file) {
  std::vector<int> lines = std::move(data.face_lines);
  try {
    const ParallelLoop loop;
    return Polyhedron(std::move(data.vertices), std::move(data.faces),
                      [&](std::size_t n, const std::function<void(std::size_t)>& body) { loop.for_each(n, 4096, body); });
  } catch (const FaceError& e) {
    int line = e.face() >= 0 && e.face() < static_cast<int>(lines.size()) ? lines[e.face()] : 0;
    throw InputError(file, line, e.what());
  }
}

Polyhedron load_mesh(const std::string& path) { return make_polyhedron(read_mesh_file(path), path); }

}  // namespace hlr
