// Mesh files by extension, and their polyhedra (see mesh_reader.hpp).
#include "io/readers/mesh_reader.hpp"

#include "algorithms/support/parallel.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "io/readers/text_reader.hpp"

namespace hlr {

MeshData read_mesh_bytes(std::string_view bytes, const std::string& format, const std::string& name) {
  MeshData (*reader)(std::string_view, const std::string&) = nullptr;
  if (format == "off") reader = read_off;
  else if (format == "obj") reader = read_obj;
  else if (format == "stl") reader = read_stl;
  else if (format == "ply") reader = read_ply;
  else throw InputError(name, 0, "unknown mesh format '" + format + "' (expected off, obj, stl or ply)");
  MeshData m = reader(bytes, name);
  if (m.num_vertices() == 0) throw InputError(name, 0, "empty mesh: no vertices");
  if (m.faces.empty()) throw InputError(name, 0, "empty mesh: no faces");
  return m;
}

MeshData read_mesh_file(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".off" && ext != ".obj" && ext != ".stl" && ext != ".ply")
    throw InputError(path, 0, "unknown mesh file extension '" + ext + "' (expected .off, .obj, .stl or .ply; standard input: - with --input-format)");
  const std::string bytes = read_file_bytes(path);
  return read_mesh_bytes(bytes, ext.substr(1), path);
}

Polyhedron make_polyhedron(MeshData data, const std::string& file) {
  std::vector<int> lines = std::move(data.face_lines);
  try {
    const ParallelLoop loop;
    auto on_all_cores = [&](std::size_t n, const std::function<void(std::size_t)>& body) { loop.for_each(n, 4096, body); };
    if (data.compact.compact()) return Polyhedron(std::move(data.compact), std::move(data.faces), on_all_cores);
    return Polyhedron(std::move(data.vertices), std::move(data.faces), on_all_cores);
  } catch (const FaceError& e) {
    int line = e.face() >= 0 && e.face() < static_cast<int>(lines.size()) ? lines[e.face()] : 0;
    throw InputError(file, line, e.what());
  }
}

Polyhedron load_mesh(const std::string& path) { return make_polyhedron(read_mesh_file(path), path); }

}  // namespace hlr
