// glTF and 3MF models (io/models/gltf_reader.hpp, threemf_reader.hpp): files written here (glTF as
// JSON with its buffer inline, 3MF by lib3mf's own writer) with node and build-item transforms,
// mirrors and normals, read back and compared with the same bodies placed by independent exact
// arithmetic; the drawing checked by the exact ray-casting oracle; assimp's test models (real
// files and broken ones) where Debian's assimp-testmodels is installed.
#include <Model/COM/NMR_DLLInterfaces.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "io/models/gltf_reader.hpp"
#include "io/models/model_input.hpp"
#include "io/models/threemf_reader.hpp"
#include "io/pipeline/render.hpp"
#include "io/views/standard_views.hpp"
#include "kernel/mesh_checks.hpp"
#include "support/drawing_oracle.hpp"

namespace hlr {
namespace {

using json = nlohmann::json;

std::string temp(const std::string& name) { return (std::filesystem::temp_directory_path() / ("hlr_model_" + name)).string(); }

// A box with float corners (not short decimals: 0.1f is not 0.1), i = x + 2y + 4z, its triangles
// counter-clockwise seen from outside.
std::vector<float> box_corners() {
  std::vector<float> p;
  for (int i = 0; i < 8; ++i) {
    p.push_back(i & 1 ? 1.6f : 0.1f);
    p.push_back(i & 2 ? 1.2f : 0.2f);
    p.push_back(i & 4 ? 0.9f : 0.3f);
  }
  return p;
}
const std::vector<std::uint32_t> kBoxTriangles = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                                  2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};

std::string base64(const std::string& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t n = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) n |= static_cast<unsigned char>(bytes[i + 2]);
    out += k[(n >> 18) & 63];
    out += k[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? k[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? k[n & 63] : '=';
  }
  return out;
}

template <class T>
void append(std::string& b, const std::vector<T>& v) {
  b.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

// A glTF file of one mesh (positions, optional normals, indices) and the given nodes and scene.
std::string write_gltf(const std::string& name, const std::vector<float>& pos, const std::vector<float>& nor, const std::vector<std::uint32_t>& idx,
                       const json& nodes, const json& roots) {
  std::string buf;
  append(buf, pos);
  append(buf, nor);
  append(buf, idx);
  const std::size_t np = pos.size() * 4, nn = nor.size() * 4, ni = idx.size() * 4;
  auto view = [](std::size_t offset, std::size_t length) {
    json v = json::object();
    v["buffer"] = 0;
    v["byteOffset"] = offset;
    v["byteLength"] = length;
    return v;
  };
  auto accessor = [](int view, int type, std::size_t count, const char* shape) {
    json a = json::object();
    a["bufferView"] = view;
    a["componentType"] = type;
    a["count"] = count;
    a["type"] = shape;
    return a;
  };
  json buffer = json::object();
  buffer["byteLength"] = buf.size();
  buffer["uri"] = "data:application/octet-stream;base64," + base64(buf);
  json g = json::object();
  g["asset"] = json::object({{"version", "2.0"}});
  g["buffers"] = json::array({buffer});
  g["bufferViews"] = json::array({view(0, np), view(np + nn, ni)});
  g["accessors"] = json::array({accessor(0, 5126, pos.size() / 3, "VEC3"), accessor(1, 5125, idx.size(), "SCALAR")});
  json prim = json::object();
  prim["attributes"] = json::object({{"POSITION", 0}});
  prim["indices"] = 1;
  if (!nor.empty()) {
    g["bufferViews"].push_back(view(np, nn));
    g["accessors"].push_back(accessor(2, 5126, nor.size() / 3, "VEC3"));
    prim["attributes"]["NORMAL"] = 2;
  }
  json mesh = json::object();
  mesh["primitives"] = json::array({prim});
  g["meshes"] = json::array({mesh});
  g["nodes"] = nodes;
  json scene = json::object();
  scene["nodes"] = roots;
  g["scenes"] = json::array({scene});
  g["scene"] = 0;
  const std::string path = temp(name + ".gltf");
  std::ofstream(path) << g.dump();
  return path;
}

using Exact3 = std::array<Rational, 3>;

std::set<Exact3> vertex_set(const MeshData& m) {
  std::set<Exact3> s;
  for (const Point3& p : m.vertices) s.insert({p.x(), p.y(), p.z()});
  return s;
}

// The box placed by `place` (independent exact arithmetic on the floats' values).
template <class F>
std::set<Exact3> placed_box(F place) {
  std::set<Exact3> s;
  const std::vector<float> c = box_corners();
  for (int i = 0; i < 8; ++i) s.insert(place(Exact3{Rational(c[3 * i]), Rational(c[3 * i + 1]), Rational(c[3 * i + 2])}));
  return s;
}

// Six times the signed volume: positive for a closed mesh whose faces face outward.
Rational volume6(const MeshData& m) {
  Rational v = 0;
  for (const Face& f : m.faces) {
    const Point3 &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
    v += a.x() * (b.y() * c.z() - b.z() * c.y()) - a.y() * (b.x() * c.z() - b.z() * c.x()) + a.z() * (b.x() * c.y() - b.y() * c.x());
  }
  return v;
}

// Two boxes under a scaled, translated parent: one turned by a quaternion, one placed by a
// mirroring matrix.
std::string transformed_gltf() {
  const json nodes = json::parse(R"([
    {"name": "assembly", "translation": [10, 0, 0], "scale": [2, 2, 2], "children": [1, 2]},
    {"name": "turned", "rotation": [0, 0, 0.6, 0.8], "mesh": 0},
    {"name": "mirrored", "matrix": [-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 4, 0, 1], "mesh": 0}])");
  return write_gltf("transforms", box_corners(), {}, kBoxTriangles, nodes, json::parse("[0]"));
}

std::set<Exact3> turned_expected() {
  const Rational s(0.6), c(0.8);  // the quaternion (0, 0, s, c): a turn about z
  return placed_box([&](const Exact3& p) {
    const Rational x = (1 - 2 * s * s) * p[0] - 2 * s * c * p[1], y = 2 * s * c * p[0] + (1 - 2 * s * s) * p[1];
    return Exact3{10 + 2 * x, 2 * y, 2 * p[2]};
  });
}

std::set<Exact3> mirrored_expected() {
  return placed_box([](const Exact3& p) { return Exact3{10 - 2 * p[0], 2 * (p[1] + 4), 2 * p[2]}; });
}

TEST(GltfModel, NodeTransformsAreAppliedExactly) {
  Model m = read_gltf_file(transformed_gltf());
  EXPECT_EQ(m.units, "m");
  EXPECT_FALSE(m.z_up);
  ASSERT_EQ(m.bodies.size(), 2u);
  EXPECT_EQ(m.bodies[0].name, "turned");
  EXPECT_EQ(m.bodies[1].name, "mirrored");
  EXPECT_EQ(vertex_set(m.bodies[0].mesh), turned_expected());
  EXPECT_EQ(vertex_set(m.bodies[1].mesh), mirrored_expected());
  for (const ModelBody& b : m.bodies) {
    EXPECT_EQ(b.mesh.vertices.size(), 8u);
    EXPECT_TRUE(make_polyhedron(b.mesh, b.name).report().closed());
    EXPECT_GT(volume6(b.mesh), 0) << b.name << ": the mirror turned the triangles round";
  }
}

// The canonical text of a drawing: every segment's class, ends and pieces, sorted.
std::vector<std::string> drawing_text(const RenderResult& r) {
  std::vector<std::string> out;
  for (const Segment& s : r.drawing.segments) {
    std::ostringstream o;
    o << to_string(s.line) << " " << s.from() << " " << s.to();
    for (const Piece& p : s.pieces) o << " [" << p.t0 << "," << p.t1 << (p.visible ? " v]" : " h]");
    out.push_back(o.str());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The exact decimal of a dyadic rational (a float's products are dyadic): its digits all written.
std::string decimal(const Rational& q) {
  mpz_class num = q.get_num(), den = q.get_den();
  int k = 0;
  while (den > 1) {
    EXPECT_EQ(den % 2, 0) << "not dyadic";
    den /= 2, num *= 5, ++k;
  }
  const bool negative = num < 0;
  std::string d = mpz_class(abs(num)).get_str();
  if (k > 0) {
    if (static_cast<int>(d.size()) <= k) d = std::string(k + 1 - d.size(), '0') + d;
    d.insert(d.size() - k, ".");
  }
  return (negative ? "-" : "") + d;
}

TEST(GltfModel, SameDrawingAsTheFlattenedMesh) {
  // The flattened mesh: each box's corners placed by independent arithmetic, in millimetres (glTF
  // is in metres), as OFF files in the file's corner order.
  auto off_of = [](const std::string& name, bool flip, auto place) {
    const std::vector<float> c = box_corners();
    std::ostringstream o;
    o << "OFF\n8 12 0\n";
    for (int i = 0; i < 8; ++i) {
      const Exact3 p = place(Exact3{Rational(c[3 * i]), Rational(c[3 * i + 1]), Rational(c[3 * i + 2])});
      o << decimal(1000 * p[0]) << " " << decimal(1000 * p[1]) << " " << decimal(1000 * p[2]) << "\n";
    }
    for (std::size_t t = 0; t < kBoxTriangles.size(); t += 3)
      o << "3 " << kBoxTriangles[t] << " " << kBoxTriangles[t + (flip ? 2 : 1)] << " " << kBoxTriangles[t + (flip ? 1 : 2)] << "\n";
    const std::string path = temp(name + ".off");
    std::ofstream(path) << o.str();
    return path;
  };
  const Rational s(0.6), c(0.8);
  const std::string turned = off_of("turned", false, [&](const Exact3& p) {
    const Rational x = (1 - 2 * s * s) * p[0] - 2 * s * c * p[1], y = 2 * s * c * p[0] + (1 - 2 * s * s) * p[1];
    return Exact3{10 + 2 * x, 2 * y, 2 * p[2]};
  });
  // A mirror turns the triangles round: the flattened OFF lists them the other way round.
  const std::string mirrored = off_of("mirrored", true, [](const Exact3& p) { return Exact3{10 - 2 * p[0], 2 * (p[1] + 4), 2 * p[2]}; });
  const std::string scene = temp("flattened.yaml");
  std::ofstream(scene) << "bodies:\n  - name: turned\n    mesh: " << turned << "\n  - name: mirrored\n    mesh: " << mirrored << "\n";
  for (const char* view : {"front", "iso", "top"}) {
    RenderOptions o;
    const StandardView v = *standard_view(view, false);
    o.view.direction = v.direction;
    o.view.up = v.up;
    const RenderResult a = render({load_any_input(transformed_gltf(), "", {})}, o);
    const RenderResult b = render({load_any_input(scene, "", {})}, o);
    EXPECT_EQ(drawing_text(a), drawing_text(b)) << view;
    EXPECT_GT(test::check_visibility(a), 5) << view;
  }
}

// A hexagonal prism with smooth normals on its side (shared by neighbouring side triangles) and
// flat ones on its caps, as exporters write a shaded cylinder: the side is one smooth surface,
// so its 60-degree edges are not creases.
TEST(GltfModel, NormalsMarkSmoothRegions) {
  std::vector<float> pos, nor;
  std::vector<std::uint32_t> idx;
  auto vertex = [&](float x, float y, float z, float nx, float ny, float nz) {
    pos.insert(pos.end(), {x, y, z});
    nor.insert(nor.end(), {nx, ny, nz});
    return static_cast<std::uint32_t>(pos.size() / 3 - 1);
  };
  const int n = 6;
  const float co[6] = {1, 0.5f, -0.5f, -1, -0.5f, 0.5f}, si[6] = {0, 0.866f, 0.866f, 0, -0.866f, -0.866f};
  std::vector<std::uint32_t> lo, hi, blo, bhi;
  for (int k = 0; k < n; ++k) {
    lo.push_back(vertex(co[k], si[k], 0, co[k], si[k], 0));
    hi.push_back(vertex(co[k], si[k], 2, co[k], si[k], 0));
    blo.push_back(vertex(co[k], si[k], 0, 0, 0, -1));
    bhi.push_back(vertex(co[k], si[k], 2, 0, 0, 1));
  }
  for (int k = 0; k < n; ++k) {
    const int j = (k + 1) % n;
    idx.insert(idx.end(), {lo[k], lo[j], hi[j], lo[k], hi[j], hi[k]});
  }
  for (int k = 1; k + 1 < n; ++k) {
    idx.insert(idx.end(), {blo[0], blo[k + 1], blo[k]});
    idx.insert(idx.end(), {bhi[0], bhi[k], bhi[k + 1]});
  }
  const std::string path = write_gltf("prism", pos, nor, idx, json::parse(R"([{"name": "prism", "mesh": 0}])"), json::parse("[0]"));
  Model m = read_gltf_file(path);
  ASSERT_EQ(m.bodies.size(), 1u);
  const ModelBody& b = m.bodies[0];
  EXPECT_EQ(b.mesh.vertices.size(), 12u) << "corners welded where only their normals differ";
  EXPECT_TRUE(make_polyhedron(b.mesh, "prism").report().closed());
  std::set<int> side, caps;
  for (std::size_t f = 0; f < b.mesh.faces.size(); ++f) (f < 12 ? side : caps).insert(b.surfaces.surface[f]);
  EXPECT_EQ(side.size(), 1u) << "the side is one smooth surface";
  EXPECT_EQ(caps.size(), 2u);
  EXPECT_FALSE(b.surfaces.sharp_between) << "edges between regions still go by the crease angle";
  RenderOptions o;
  const StandardView v = *standard_view("iso", false);
  o.view.direction = v.direction;
  o.view.up = v.up;
  // Creases across the side (not horizontal) with the normals and without them.
  auto across_side = [&](const std::string& file) {
    int n = 0;
    for (const Segment& s : render({load_model(file, {})}, o).drawing.segments) n += s.line == LineKind::Crease && s.from().z() != s.to().z();
    return n;
  };
  EXPECT_EQ(across_side(path), 0);
  EXPECT_GT(across_side(write_gltf("prism_flat", pos, {}, idx, json::parse(R"([{"name": "prism", "mesh": 0}])"), json::parse("[0]"))), 0)
      << "without normals the 60-degree edges are creases";
}

TEST(GltfModel, BadFilesAreClearErrors) {
  EXPECT_THROW(read_gltf_file("/nonexistent/model.gltf"), InputError);
  const std::string junk = temp("junk.gltf");
  std::ofstream(junk) << "{ not json";
  EXPECT_THROW(read_gltf_file(junk), InputError);
  std::vector<std::uint32_t> bad = kBoxTriangles;
  bad[5] = 8;
  const json one = json::parse(R"([{"mesh": 0}])"), root = json::parse("[0]");
  try {
    read_gltf_file(write_gltf("out_of_range", box_corners(), {}, bad, one, root));
    ADD_FAILURE() << "an index out of range was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("index 8 is out of range"), std::string::npos) << e.what();
  }
  const json cycle = json::parse(R"([{"children": [1]}, {"children": [0], "mesh": 0}])");
  try {
    read_gltf_file(write_gltf("cycle", box_corners(), {}, kBoxTriangles, cycle, root));
    ADD_FAILURE() << "a node cycle was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("its own ancestor"), std::string::npos) << e.what();
  }
}

const std::string kAssimp = "/usr/share/assimp/models/";

TEST(GltfModel, AssimpTestModels) {
  if (!std::filesystem::exists(kAssimp + "glTF2")) GTEST_SKIP() << "assimp-testmodels is not installed";
  Model engine = read_gltf_file(kAssimp + "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
  EXPECT_GT(engine.bodies.size(), 20u);
  long triangles = 0;
  for (const ModelBody& b : engine.bodies) triangles += static_cast<long>(b.mesh.faces.size());
  EXPECT_GT(triangles, 50000);
  Model box = read_gltf_file(kAssimp + "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb");
  ASSERT_EQ(box.bodies.size(), 1u);
  EXPECT_TRUE(make_polyhedron(box.bodies[0].mesh, "box").report().closed()) << "welded across the texture seams";
  ASSERT_TRUE(box.bodies[0].colour.has_value());
  RenderOptions o;
  const StandardView v = *standard_view("iso", false);
  o.view.direction = v.direction;
  o.view.up = v.up;
  EXPECT_GT(test::check_visibility(render({load_model(kAssimp + "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", {})}, o)), 5);
  for (const char* broken :
       {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", "glTF2/RecursiveNodes/RecursiveNodes.gltf", "glTF2/MissingBin/BoxTextured.gltf",
        "glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "glTF2/draco/2CylinderEngine.gltf"})
    EXPECT_THROW(read_gltf_file(kAssimp + broken), InputError) << broken;
}

// ---- 3MF, written by lib3mf ----

NMR::MODELTRANSFORM transform_of(const std::array<float, 12>& rows) {  // x' = row 0 · (x, y, z, 1), ...
  NMR::MODELTRANSFORM t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) t.m_fFields[i][j] = rows[4 * i + j];
  return t;
}

// The test box's corners and triangles as a lib3mf mesh object's geometry.
void set_box_geometry(NMR::PLib3MFModelMeshObject* mesh) {
  using namespace NMR;
  const std::vector<float> c = box_corners();
  std::vector<MODELMESHVERTEX> v(8);
  for (int i = 0; i < 8; ++i) v[i] = {{c[3 * i], c[3 * i + 1], c[3 * i + 2]}};
  std::vector<MODELMESHTRIANGLE> t(12);
  for (int i = 0; i < 12; ++i) t[i] = {{kBoxTriangles[3 * i], kBoxTriangles[3 * i + 1], kBoxTriangles[3 * i + 2]}};
  EXPECT_EQ(lib3mf_meshobject_setgeometry(mesh, v.data(), 8, t.data(), 12), 0);
}

std::string write_3mf(const std::string& name, DWORD unit) {
  using namespace NMR;
  PLib3MFModel* model = nullptr;
  EXPECT_EQ(lib3mf_createmodel(&model), 0);
  lib3mf_model_setunit(model, unit);
  PLib3MFModelMeshObject* mesh = nullptr;
  EXPECT_EQ(lib3mf_model_addmeshobject(model, &mesh), 0);
  lib3mf_object_setnameutf8(mesh, "box");
  set_box_geometry(mesh);
  // A components object placing the box twice: shifted, and mirrored in x.
  PLib3MFModelComponentsObject* pair = nullptr;
  EXPECT_EQ(lib3mf_model_addcomponentsobject(model, &pair), 0);
  lib3mf_object_setnameutf8(pair, "pair");
  MODELTRANSFORM shift = transform_of({1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1, 0}), mirror = transform_of({-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});
  PLib3MFModelComponent *c1 = nullptr, *c2 = nullptr;
  EXPECT_EQ(lib3mf_componentsobject_addcomponent(pair, mesh, &shift, &c1), 0);
  EXPECT_EQ(lib3mf_componentsobject_addcomponent(pair, mesh, &mirror, &c2), 0);
  // The build: the pair scaled by 2 and moved by (10, 0, 0).
  MODELTRANSFORM place = transform_of({2, 0, 0, 10, 0, 2, 0, 0, 0, 0, 2, 0});
  PLib3MFModelBuildItem* item = nullptr;
  EXPECT_EQ(lib3mf_model_addbuilditem(model, pair, &place, &item), 0);
  PLib3MFModelWriter* writer = nullptr;
  EXPECT_EQ(lib3mf_model_querywriter(model, "3mf", &writer), 0);
  const std::string path = temp(name + ".3mf");
  EXPECT_EQ(lib3mf_writer_writetofileutf8(writer, path.c_str()), 0);
  for (PLib3MFBase* p : {writer, item, c2, c1, pair, mesh, model}) lib3mf_release(p);
  return path;
}

// A box whose triangles carry colours (8 red, 4 blue) or one base material for all.
std::string write_coloured_3mf(const std::string& name, bool base_material) {
  using namespace NMR;
  PLib3MFModel* model = nullptr;
  EXPECT_EQ(lib3mf_createmodel(&model), 0);
  PLib3MFModelMeshObject* mesh = nullptr;
  EXPECT_EQ(lib3mf_model_addmeshobject(model, &mesh), 0);
  set_box_geometry(mesh);
  PLib3MFPropertyHandler* h = nullptr;
  EXPECT_EQ(lib3mf_meshobject_createpropertyhandler(mesh, &h), 0);
  PLib3MFDefaultPropertyHandler* d = nullptr;  // lib3mf writes triangle properties with an object's default
  EXPECT_EQ(lib3mf_object_createdefaultpropertyhandler(mesh, &d), 0);
  PLib3MFModelBaseMaterial* group = nullptr;
  if (base_material) {
    EXPECT_EQ(lib3mf_model_addbasematerialgroup(model, &group), 0);
    DWORD index = 0, id = 0;
    EXPECT_EQ(lib3mf_basematerial_addmaterialutf8(group, "steel", 40, 90, 200, &index), 0);
    EXPECT_EQ(lib3mf_resource_getresourceid(group, &id), 0);
    EXPECT_EQ(lib3mf_defaultpropertyhandler_setbasematerial(d, id, index), 0);
    for (DWORD i = 0; i < 12; ++i) EXPECT_EQ(lib3mf_propertyhandler_setbasematerial(h, i, id, index), 0);
  } else {
    EXPECT_EQ(lib3mf_defaultpropertyhandler_setcolorrgb(d, 10, 20, 240), 0);  // the minority's colour
    for (DWORD i = 0; i < 12; ++i) EXPECT_EQ(lib3mf_propertyhandler_setsinglecolorrgb(h, i, i < 8 ? 220 : 10, 20, i < 8 ? 30 : 240), 0);
  }
  lib3mf_release(h);
  lib3mf_release(d);
  MODELTRANSFORM place = transform_of({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});
  PLib3MFModelBuildItem* item = nullptr;
  EXPECT_EQ(lib3mf_model_addbuilditem(model, mesh, &place, &item), 0);
  PLib3MFModelWriter* writer = nullptr;
  EXPECT_EQ(lib3mf_model_querywriter(model, "3mf", &writer), 0);
  const std::string path = temp(name + ".3mf");
  const LIB3MFRESULT written = lib3mf_writer_writetofileutf8(writer, path.c_str());
  DWORD code = 0;
  LPCSTR message = nullptr;
  if (written) lib3mf_getlasterror(writer, &code, &message);
  EXPECT_EQ(written, 0) << (message ? message : "");
  for (PLib3MFBase* p : {writer, item, mesh, model}) lib3mf_release(p);
  if (group) lib3mf_release(group);
  return path;
}

TEST(ThreeMfModel, ColoursAndBaseMaterialsColourTheBody) {
  // The colour of most triangles (sRGB bytes / 255), as glTF's base colour; none without one.
  const Model coloured = read_3mf_file(write_coloured_3mf("coloured", false));
  ASSERT_EQ(coloured.bodies.size(), 1u);
  ASSERT_TRUE(coloured.bodies[0].colour);
  EXPECT_DOUBLE_EQ(coloured.bodies[0].colour->at(0), 220 / 255.0);
  EXPECT_DOUBLE_EQ(coloured.bodies[0].colour->at(2), 30 / 255.0);
  const Model steel = read_3mf_file(write_coloured_3mf("steel", true));
  ASSERT_TRUE(steel.bodies[0].colour);
  EXPECT_DOUBLE_EQ(steel.bodies[0].colour->at(1), 90 / 255.0);
  EXPECT_DOUBLE_EQ(steel.bodies[0].colour->at(2), 200 / 255.0);
  EXPECT_FALSE(read_3mf_file(write_3mf("plain", NMR::MODELUNIT_MILLIMETER)).bodies[0].colour);
  // The scene's body takes it as its material's colour (the --surfaces fill).
  const Scene s = load_model(write_coloured_3mf("steel_scene", true), {});
  ASSERT_TRUE(s.bodies[0].material);
  EXPECT_DOUBLE_EQ(s.bodies[0].material->colour[2], 200 / 255.0);
}

TEST(ThreeMfModel, BuildItemsAndComponentsAreAppliedExactly) {
  Model m = read_3mf_file(write_3mf("pair", NMR::MODELUNIT_CENTIMETER));
  EXPECT_EQ(m.units, "cm");
  EXPECT_TRUE(m.z_up);
  ASSERT_EQ(m.bodies.size(), 2u);
  EXPECT_EQ(m.bodies[0].name, "box");
  EXPECT_EQ(vertex_set(m.bodies[0].mesh), placed_box([](const Exact3& p) { return Exact3{10 + 2 * p[0], 2 * (p[1] + 5), 2 * p[2]}; }));
  EXPECT_EQ(vertex_set(m.bodies[1].mesh), placed_box([](const Exact3& p) { return Exact3{10 - 2 * p[0], 2 * p[1], 2 * p[2]}; }));
  for (const ModelBody& b : m.bodies) EXPECT_GT(volume6(b.mesh), 0) << "faces outward after the mirror";
  // Centimetres become millimetres in the scene: the first box's lowest x is 10 + 2 * 0.1f cm.
  const Scene s = load_model(write_3mf("pair", NMR::MODELUNIT_CENTIMETER), {});
  Rational lo = s.bodies[0].body.vertices()[0].x();
  for (const Point3& p : s.bodies[0].body.vertices()) lo = std::min(lo, p.x());
  EXPECT_EQ(lo, 10 * (10 + 2 * Rational(0.1f)));
  RenderOptions o;
  const StandardView v = *standard_view("iso", true);
  o.view.direction = v.direction;
  o.view.up = v.up;
  EXPECT_GT(test::check_visibility(render({s}, o)), 10);
}

TEST(ThreeMfModel, RealAndBadFiles) {
  EXPECT_THROW(read_3mf_file("/nonexistent/part.3mf"), InputError);
  const std::string junk = temp("junk.3mf");
  std::ofstream(junk) << "PK not a zip";
  EXPECT_THROW(read_3mf_file(junk), InputError);
  if (!std::filesystem::exists(kAssimp + "3MF/box.3mf")) GTEST_SKIP() << "assimp-testmodels is not installed";
  Model m = read_3mf_file(kAssimp + "3MF/box.3mf");
  ASSERT_EQ(m.bodies.size(), 1u);
  EXPECT_TRUE(make_polyhedron(m.bodies[0].mesh, "box").report().closed());
}

}  // namespace
}  // namespace hlr
