// glTF 2.0 models (see gltf_reader.hpp; docs/design.md, "Models").
#include "io/models/gltf_reader.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>

#include "io/models/mesh_assembly.hpp"
#include "io/models/model_module.hpp"
#include "io/readers/input_error.hpp"

namespace hlr {

namespace {

// Images are not decoded: a drawing uses the base colour only.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) { return true; }

struct Reader {
  const std::string& path;
  const tinygltf::Model& g;
  Model& out;
  long dropped = 0;

  [[noreturn]] void fail(const std::string& what) const { throw InputError(path, 0, what); }

  // The bytes of element i of an accessor and its stride; checks that they lie in the buffer.
  const unsigned char* element(const tinygltf::Accessor& a, std::size_t i, const std::string& what) const {
    if (a.sparse.isSparse) fail(what + ": sparse accessors are not read");
    if (a.bufferView < 0 || a.bufferView >= static_cast<int>(g.bufferViews.size())) fail(what + ": accessor has no buffer view");
    const tinygltf::BufferView& v = g.bufferViews[a.bufferView];
    if (v.buffer < 0 || v.buffer >= static_cast<int>(g.buffers.size())) fail(what + ": buffer view has no buffer");
    const int stride = a.ByteStride(v);
    const int size = tinygltf::GetComponentSizeInBytes(a.componentType) * tinygltf::GetNumComponentsInType(a.type);
    if (stride <= 0 || size <= 0) fail(what + ": bad accessor layout");
    const std::size_t at = v.byteOffset + a.byteOffset + i * static_cast<std::size_t>(stride);
    const std::vector<unsigned char>& data = g.buffers[v.buffer].data;
    if (at + size > data.size() || a.byteOffset + i * static_cast<std::size_t>(stride) + size > v.byteLength)
      fail(what + ": accessor reaches past its buffer");
    return data.data() + at;
  }

  std::vector<std::array<float, 3>> vec3s(int accessor, const std::string& what) const {
    if (accessor < 0 || accessor >= static_cast<int>(g.accessors.size())) fail(what + ": no such accessor");
    const tinygltf::Accessor& a = g.accessors[accessor];
    if (a.type != TINYGLTF_TYPE_VEC3 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
      fail(what + ": only float VEC3 is read (quantized meshes are not)");
    std::vector<std::array<float, 3>> p(a.count);
    for (std::size_t i = 0; i < a.count; ++i) {
      std::memcpy(p[i].data(), element(a, i, what), 12);
      for (float c : p[i])
        if (!std::isfinite(c)) fail(what + ": value " + std::to_string(i) + " is not finite");
    }
    return p;
  }

  std::vector<long> indices(const tinygltf::Primitive& prim, std::size_t n_positions, const std::string& what) const {
    std::vector<long> ix;
    if (prim.indices < 0) {
      ix.resize(n_positions);
      for (std::size_t i = 0; i < n_positions; ++i) ix[i] = static_cast<long>(i);
      return ix;
    }
    if (prim.indices >= static_cast<int>(g.accessors.size())) fail(what + ": no such index accessor");
    const tinygltf::Accessor& a = g.accessors[prim.indices];
    ix.resize(a.count);
    for (std::size_t i = 0; i < a.count; ++i) {
      const unsigned char* e = element(a, i, what + " indices");
      if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
        ix[i] = *e;
      } else if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        std::uint16_t u;
        std::memcpy(&u, e, 2);
        ix[i] = u;
      } else if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        std::uint32_t u;
        std::memcpy(&u, e, 4);
        ix[i] = u;
      } else {
        fail(what + ": indices are not unsigned integers");
      }
      if (ix[i] >= static_cast<long>(n_positions))
        fail(what + ": index " + std::to_string(ix[i]) + " is out of range (" + std::to_string(n_positions) + " vertices)");
    }
    return ix;
  }

  // The triangles of a primitive's index list by its mode; false for points and lines.
  static bool triangles(int mode, const std::vector<long>& ix, std::vector<std::array<long, 3>>& t) {
    if (mode == TINYGLTF_MODE_TRIANGLES || mode == -1) {
      for (std::size_t i = 0; i + 2 < ix.size(); i += 3) t.push_back({ix[i], ix[i + 1], ix[i + 2]});
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (std::size_t i = 0; i + 2 < ix.size(); ++i)
        t.push_back(i % 2 == 0 ? std::array<long, 3>{ix[i], ix[i + 1], ix[i + 2]} : std::array<long, 3>{ix[i + 1], ix[i], ix[i + 2]});
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
      for (std::size_t i = 1; i + 1 < ix.size(); ++i) t.push_back({ix[0], ix[i], ix[i + 1]});
    } else {
      return false;
    }
    return true;
  }

  std::optional<Rgb> colour(int material) const {
    if (material < 0 || material >= static_cast<int>(g.materials.size())) return std::nullopt;
    const std::vector<double>& f = g.materials[material].pbrMetallicRoughness.baseColorFactor;
    if (f.size() < 3) return std::nullopt;
    // glTF's base colour is linear; the drawing's colours are sRGB.
    auto srgb = [](double c) {
      c = std::clamp(c, 0.0, 1.0);
      return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
    };
    return Rgb{srgb(f[0]), srgb(f[1]), srgb(f[2])};
  }

  static Matrix4 local_transform(const tinygltf::Node& n) {
    Matrix4 m = identity_transform();
    if (n.matrix.size() == 16) {
      // glTF stores the column-vector matrix column by column: read row by row, it is the
      // row-vector matrix.
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m(i, j) = Rational(n.matrix[4 * i + j]);
      return m;
    }
    if (n.scale.size() == 3) m = compose(m, scaling(Vector3(Rational(n.scale[0]), Rational(n.scale[1]), Rational(n.scale[2]))));
    if (n.rotation.size() == 4) m = compose(m, quaternion_rotation(n.rotation[0], n.rotation[1], n.rotation[2], n.rotation[3]));
    if (n.translation.size() == 3)
      m = compose(m, translation(Vector3(Rational(n.translation[0]), Rational(n.translation[1]), Rational(n.translation[2]))));
    return m;
  }

  void add_mesh(const tinygltf::Node& node, int node_index, const Matrix4& world) {
    if (node.mesh >= static_cast<int>(g.meshes.size())) fail("node " + std::to_string(node_index) + ": no such mesh");
    const tinygltf::Mesh& mesh = g.meshes[node.mesh];
    std::string name = !node.name.empty() ? node.name : !mesh.name.empty() ? mesh.name : "node " + std::to_string(node_index);
    // One body per node, all its primitives together (a part whose faces have several materials
    // stays one closed solid); its colour is the material of most of its triangles.
    FloatBody b;
    bool all_normals = true;
    std::map<int, std::size_t> material_triangles;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& prim = mesh.primitives[p];
      const std::string what = "mesh " + std::to_string(node.mesh) + " primitive " + std::to_string(p);
      auto pos = prim.attributes.find("POSITION");
      if (pos == prim.attributes.end()) fail(what + ": no POSITION");
      const std::vector<std::array<float, 3>> positions = vec3s(pos->second, what + " POSITION");
      std::vector<std::array<long, 3>> tris;
      if (!triangles(prim.mode, indices(prim, positions.size(), what), tris)) {
        out.notes.push_back("'" + name + "': points and lines are not drawn");
        continue;
      }
      auto nor = prim.attributes.find("NORMAL");
      std::vector<std::array<float, 3>> normals;
      if (nor != prim.attributes.end()) normals = vec3s(nor->second, what + " NORMAL");
      if (!normals.empty() && normals.size() != positions.size()) fail(what + ": NORMAL and POSITION differ in count");
      all_normals = all_normals && !normals.empty();
      const int base = static_cast<int>(b.positions.size());
      b.positions.insert(b.positions.end(), positions.begin(), positions.end());
      b.normals.insert(b.normals.end(), normals.begin(), normals.end());
      for (const auto& t : tris) b.triangles.push_back({base + static_cast<int>(t[0]), base + static_cast<int>(t[1]), base + static_cast<int>(t[2])});
      material_triangles[prim.material] += tris.size();
    }
    if (b.triangles.empty()) return;
    if (!all_normals) b.normals.clear();  // smooth regions only where every primitive has normals
    b.name = name;
    b.transform = world;
    const auto most =
        std::max_element(material_triangles.begin(), material_triangles.end(), [](const auto& x, const auto& y) { return x.second < y.second; });
    b.colour = colour(most->first);
    out.bodies.push_back(assemble_body(b, dropped));
  }

  void walk(int n, const Matrix4& above, std::vector<bool>& on_path) {
    if (n < 0 || n >= static_cast<int>(g.nodes.size())) fail("no node " + std::to_string(n));
    if (on_path[n]) fail("node " + std::to_string(n) + " is its own ancestor");
    on_path[n] = true;
    const tinygltf::Node& node = g.nodes[n];
    const Matrix4 world = compose(local_transform(node), above);
    if (node.mesh >= 0) add_mesh(node, n, world);
    for (int c : node.children) walk(c, world, on_path);
    on_path[n] = false;
  }

  std::vector<int> roots() const {
    if (!g.scenes.empty()) {
      const int s = g.defaultScene >= 0 && g.defaultScene < static_cast<int>(g.scenes.size()) ? g.defaultScene : 0;
      return g.scenes[s].nodes;
    }
    std::vector<bool> child(g.nodes.size());
    for (const tinygltf::Node& n : g.nodes)
      for (int c : n.children)
        if (c >= 0 && c < static_cast<int>(child.size())) child[c] = true;
    std::vector<int> r;
    for (std::size_t i = 0; i < child.size(); ++i)
      if (!child[i]) r.push_back(static_cast<int>(i));
    return r;
  }
};

}  // namespace

Model models::read_gltf(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, 0, "cannot open file");
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(skip_image, nullptr);
  tinygltf::Model g;
  std::string err, warn;
  const bool ok =
      lower_extension(path) == ".glb" ? loader.LoadBinaryFromFile(&g, &err, &warn, path) : loader.LoadASCIIFromFile(&g, &err, &warn, path);
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    throw InputError(path, 0, "not a glTF 2.0 file tinygltf can read: " + (err.empty() ? warn : err));
  }
  for (const std::string& e : g.extensionsRequired)
    if (e == "KHR_draco_mesh_compression" || e == "EXT_meshopt_compression" || e == "KHR_mesh_quantization")
      throw InputError(path, 0, "the file needs " + e + ", which this reader does not decode");
  Model out;
  out.units = "m";
  out.z_up = false;
  Reader r{path, g, out, 0};
  std::vector<bool> on_path(g.nodes.size());
  for (int n : r.roots()) r.walk(n, identity_transform(), on_path);
  note_dropped(r.dropped, out.notes);
  if (out.bodies.empty()) throw InputError(path, 0, "the file's scene holds no triangles");
  return out;
}

}  // namespace hlr
