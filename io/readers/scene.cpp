// Scene file reader on yaml-cpp (see scene.hpp, docs/scene-format.md).
#include "io/readers/scene.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <set>

#include "io/readers/clipper_spec.hpp"
#include "io/readers/mesh_reader.hpp"
#include "io/readers/scene_lighting.hpp"
#include "io/readers/text_reader.hpp"
#include "io/readers/yaml_context.hpp"

namespace hlr {
namespace {

constexpr int kMaxNesting = 64;

using Ctx = YamlContext;

int depth(const YAML::Node& n, int d = 0) {
  if (d > kMaxNesting) return d;
  int best = d;
  if (n.IsSequence() || n.IsMap())
    for (auto it = n.begin(); it != n.end(); ++it) {
      best = std::max(best, depth(n.IsMap() ? it->second : *it, d + 1));
      if (best > kMaxNesting) break;
    }
  return best;
}

Matrix4 parse_rotation(const Ctx& c, const YAML::Node& n, std::vector<std::string>& notes) {
  c.check_keys(n, "rotate", {"axis", "degrees", "cos", "sin", "tan_half", "centre", "center"});
  if (!n["axis"]) c.fail(n, "rotate needs an 'axis' (x, y or z)");
  auto axis = parse_axis(c.text(n["axis"], "axis"));
  if (!axis) c.fail(n["axis"], "axis must be x, y or z");
  int given = (n["degrees"] ? 1 : 0) + (n["cos"] || n["sin"] ? 1 : 0) + (n["tan_half"] ? 1 : 0);
  if (given != 1) c.fail(n, "rotate needs exactly one of: degrees, cos + sin, tan_half");
  Rotation r;
  if (n["degrees"]) {
    r = rotation_from_degrees(c.number(n["degrees"], "degrees"));
    if (!r.exact)
      notes.push_back("line " + std::to_string(n["degrees"].Mark().line + 1) + ": rotation by " +
                      n["degrees"].Scalar() + " degrees has an irrational sine or cosine; realised as " +
                      describe(r));
  } else if (n["tan_half"]) {
    r = rotation_from_tan_half(c.number(n["tan_half"], "tan_half"));
  } else {
    if (!n["cos"] || !n["sin"]) c.fail(n, "rotate by cos and sin needs both");
    try {
      r = rotation_from_cos_sin(c.number(n["cos"], "cos"), c.number(n["sin"], "sin"));
    } catch (const std::invalid_argument& e) {
      c.fail(n, e.what());
    }
  }
  if (n["centre"] && n["center"]) c.fail(n, "give 'centre' or 'center', not both");
  Point3 centre = n["centre"] ? c.point(n["centre"], "centre") : n["center"] ? c.point(n["center"], "center") : Point3();
  return rotation(*axis, r, centre);
}

Matrix4 parse_transform_step(const Ctx& c, const YAML::Node& step, std::vector<std::string>& notes) {
  if (!step.IsMap() || step.size() != 1)
    c.fail(step, "each transform must be one of: translate, scale, rotate, reflect, matrix");
  std::string kind = step.begin()->first.Scalar();
  YAML::Node v = step.begin()->second;
  if (kind == "translate") return translation(c.vector(v, "translate"));
  if (kind == "scale") {
    Point3 centre;
    YAML::Node f = v;
    if (v.IsMap()) {
      c.check_keys(v, "scale", {"factors", "centre", "center"});
      if (!v["factors"]) c.fail(v, "scale needs 'factors'");
      f.reset(v["factors"]);  // (operator= would overwrite v's node)
      if (v["centre"]) centre = c.point(v["centre"], "centre");
      if (v["center"]) centre = c.point(v["center"], "center");
    }
    Vector3 k = f.IsScalar() ? Vector3(c.number(f, "scale"), c.number(f, "scale"), c.number(f, "scale"))
                             : c.vector(f, "scale factors");
    if (k.x() == 0 || k.y() == 0 || k.z() == 0) c.fail(f, "a scale factor of 0 flattens the body");
    return scaling(k, centre);
  }
  if (kind == "rotate") return parse_rotation(c, v, notes);
  if (kind == "reflect") {
    Point3 centre;
    YAML::Node a = v;
    if (v.IsMap()) {
      c.check_keys(v, "reflect", {"axis", "centre", "center"});
      if (!v["axis"]) c.fail(v, "reflect needs an 'axis'");
      a.reset(v["axis"]);
      if (v["centre"]) centre = c.point(v["centre"], "centre");
      if (v["center"]) centre = c.point(v["center"], "center");
    }
    auto axis = parse_axis(c.text(a, "reflect axis"));
    if (!axis) c.fail(a, "reflect axis must be x, y or z (the coordinate that changes sign)");
    return reflection(*axis, centre);
  }
  if (kind == "matrix") {
    if (!v.IsSequence() || v.size() != 4) c.fail(v, "matrix must be 4 rows of 4 numbers");
    Matrix4 m;
    for (int i = 0; i < 4; ++i) {
      if (!v[i].IsSequence() || v[i].size() != 4) c.fail(v[i], "matrix row must have 4 numbers");
      for (int j = 0; j < 4; ++j) m(i, j) = c.number(v[i][j], "matrix entry");
    }
    if (!inverse(m)) c.fail(v, "matrix is singular (it flattens the body)");
    return m;
  }
  c.fail(step.begin()->first, "unknown transform '" + kind + "' (known: translate, scale, rotate, reflect, matrix)");
}

Rational det3(const Matrix4& m) {
  return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
         m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
}

Polyhedron transformed(const Ctx& c, const YAML::Node& where, const Polyhedron& p, const Matrix4& m) {
  std::vector<Point3> vs;
  vs.reserve(p.num_vertices());
  for (std::size_t i = 0; i < p.num_vertices(); ++i) {
    try {
      if (!is_affine(m)) {
        const Point3& q = p.vertices()[i];
        Rational w = q.x() * m(0, 3) + q.y() * m(1, 3) + q.z() * m(2, 3) + m(3, 3);
        if (w <= 0) c.fail(where, "the transform sends vertex " + std::to_string(i) + " through infinity (w <= 0)");
      }
      vs.push_back(apply(m, p.vertices()[i]));
    } catch (const std::domain_error& e) {
      c.fail(where, e.what());
    }
  }
  std::vector<Face> faces = p.faces();
  if (is_affine(m) && det3(m) < 0)  // a mirror image: keep faces counter-clockwise from outside
    for (auto& f : faces) std::reverse(f.begin(), f.end());
  return Polyhedron(std::move(vs), std::move(faces));
}

Polyhedron inline_body(const Ctx& c, const YAML::Node& n, std::vector<Face>& typed) {
  const YAML::Node vn = n["vertices"], fn = n["faces"];
  if (!vn || !fn) c.fail(n, "an inline body needs both 'vertices' and 'faces'");
  if (!vn.IsSequence() || vn.size() == 0) c.fail(vn, "vertices must be a non-empty list of [x, y, z]");
  if (!fn.IsSequence() || fn.size() == 0) c.fail(fn, "faces must be a non-empty list of vertex index lists");
  std::vector<Point3> vs;
  for (const auto& v : vn) vs.push_back(c.point(v, "vertex"));
  std::vector<Face> faces;
  for (std::size_t f = 0; f < fn.size(); ++f) {
    const YAML::Node face = fn[f];
    if (!face.IsSequence()) c.fail(face, "face " + std::to_string(f) + " must be a list of vertex indices");
    Face idx;
    for (const auto& i : face) {
      long k = c.integer(i, "vertex index");
      if (k < 0 || k >= static_cast<long>(vs.size()))
        c.fail(i, "face " + std::to_string(f) + " uses vertex " + std::to_string(k) + ", but there are only " +
                      std::to_string(vs.size()) + " vertices");
      idx.push_back(static_cast<int>(k));
    }
    if (idx.size() < 3) c.fail(face, "face " + std::to_string(f) + " has fewer than 3 vertices");
    faces.push_back(std::move(idx));
  }
  typed = faces;
  faces = orient_faces(vs, std::move(faces));
  return Polyhedron(std::move(vs), std::move(faces));
}

// A perspective view's frame keys (fov, fov_v, aspect, frame, focal, sensor), as --fov etc.
std::optional<FrameRequest> parse_frame(const Ctx& c, const YAML::Node& n) {
  if (!n["fov"] && !n["fov_v"] && !n["frame"] && !n["focal"]) {
    for (const char* k : {"aspect", "sensor"})
      if (n[k]) c.fail(n[k], std::string(k) + " shapes a frame: give fov, fov_v or focal");
    return std::nullopt;
  }
  FrameRequest f;
  auto real = [&](const char* k) { return to_double(c.number(n[k], k)); };
  auto pair = [&](const char* k) {
    if (!n[k].IsSequence() || n[k].size() != 2) c.fail(n[k], std::string(k) + " must be a list of two numbers [W, H]");
    return std::array<Rational, 2>{c.number(n[k][0], k), c.number(n[k][1], k)};
  };
  if (n["fov"]) f.fov = real("fov");
  if (n["fov_v"]) f.fov_v = real("fov_v");
  if (n["focal"]) f.focal = real("focal");
  if (n["aspect"]) f.aspect = real("aspect");
  if (n["frame"]) f.frame = pair("frame");
  if (n["sensor"]) {
    const auto s = pair("sensor");
    f.sensor = {to_double(s[0]), to_double(s[1])};
  }
  try {
    check_frame_request(f);
  } catch (const std::invalid_argument& e) {
    c.fail(n, std::string("view: ") + e.what());
  }
  return f;
}

View parse_view(const Ctx& c, const YAML::Node& n) {
  c.check_keys(n, "view", {"direction", "eye", "target", "up", "fov", "fov_v", "aspect", "frame", "focal", "sensor"});
  View v;
  if (n["direction"] && n["eye"]) c.fail(n, "view has both 'direction' (orthographic) and 'eye' (perspective)");
  if (n["direction"]) {
    v.direction = c.vector(n["direction"], "view direction");
    if (v.direction.is_zero()) c.fail(n["direction"], "view direction has zero length");
    if (n["target"]) c.fail(n["target"], "'target' belongs to a perspective view (with 'eye')");
  } else if (n["eye"]) {
    v.type = View::Type::Perspective;
    v.eye = c.point(n["eye"], "eye");
    if (n["target"]) {
      v.target = c.point(n["target"], "target");
      if (*v.target == v.eye) c.fail(n["target"], "target is the eye point");
    }
  } else if (n.size() > 0) {
    c.fail(n, "view needs 'direction' or 'eye'");
  }
  if (n["up"]) {
    v.up = c.vector(n["up"], "up");
    if (v.up.is_zero()) c.fail(n["up"], "up vector has zero length");
    v.up_given = true;
  }
  v.frame = parse_frame(c, n);
  if (v.frame && v.type != View::Type::Perspective) c.fail(n, "a frame (fov, fov_v, frame, focal) belongs to a perspective view (with 'eye')");
  return v;
}

}  // namespace

bool is_scene_file(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return std::tolower(ch); });
  return ext == ".yaml" || ext == ".yml" || ext == ".json";
}

Scene scene_from_mesh_data(MeshData data, const std::string& body, const std::string& source) {
  Scene s;
  s.file = source;
  auto texcoords = std::move(data.texcoords);
  auto face_texcoords = std::move(data.face_texcoords);
  FaceSurfaces surfaces = std::move(data.surfaces);
  s.bodies.push_back(SceneBody{body,
                               source,
                               make_polyhedron(std::move(data), source),
                               identity_transform(),
                               {},
                               {},
                               {},
                               std::nullopt,
                               std::move(texcoords),
                               std::move(face_texcoords)});
  s.bodies.back().surfaces = std::move(surfaces);
  return s;
}

Scene scene_from_mesh(const std::string& path) {
  return scene_from_mesh_data(read_mesh_file(path), std::filesystem::path(path).stem().string(), path);
}

Scene load_input(const std::string& path, const std::string& format) {
  if (format.empty()) {
    if (path == "-") throw InputError("<stdin>", 0, "standard input needs --input-format (off, obj, stl, ply, yaml or json)");
    return is_scene_file(path) ? load_scene(path) : scene_from_mesh(path);
  }
  const std::string name = path == "-" ? "<stdin>" : path;
  std::string bytes;
  if (path == "-") bytes.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
  else bytes = read_file_bytes(path);
  if (format == "yaml" || format == "json") return load_scene_text(bytes, name);
  const std::string body = path == "-" ? "stdin" : std::filesystem::path(path).stem().string();
  return scene_from_mesh_data(read_mesh_bytes(bytes, format, name), body, name);
}

// `ground: z = 0` (or x, y; a map {plane: "z = 0", size: S, material: {...}}): a square open
// surface in that plane centred under the scene, S wide (default four times the scene's
// largest extent), its front toward the bodies (shadows fall on it).
void add_ground(const YamlContext& c, const YAML::Node& n, Scene& s, bool body) {
  if (n.IsMap()) {
    c.check_keys(n, "ground", {"plane", "material", "size"});
    if (!n["plane"]) c.fail(n, "ground needs a 'plane' (x = C, y = C or z = C)");
  }
  const YAML::Node plane = n.IsMap() ? n["plane"] : n;  // (a YAML::Node assigned to would change n itself)
  const std::string text = plane.IsScalar() ? plane.Scalar() : "";
  const auto eq = text.find('=');
  std::string axis = eq == std::string::npos ? "" : text.substr(0, eq), value = eq == std::string::npos ? "" : text.substr(eq + 1);
  auto trim = [](std::string& t) {
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.front()))) t.erase(t.begin());
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.pop_back();
  };
  trim(axis), trim(value);
  if (axis != "x" && axis != "y" && axis != "z") c.fail(plane, "ground must be a plane x = C, y = C or z = C");
  Rational at;
  try {
    at = parse_rational(value);
  } catch (const NumberError&) {
    c.fail(plane, "ground must be a plane x = C, y = C or z = C");
  }
  if (s.bodies.empty()) c.fail(n, "ground needs bodies to lie under");
  const int k = axis[0] - 'x', u = (k + 1) % 3, w = (k + 2) % 3;
  s.ground = std::make_pair(k, at);
  if (!body) return;
  std::array<Rational, 3> lo, hi;
  bool first = true;
  for (const SceneBody& b : s.bodies)
    for (const Point3& v : b.body.vertices())
      for (int i = 0; i < 3; ++i) {
        if (first || v[i] < lo[i]) lo[i] = v[i];
        if (first || v[i] > hi[i]) hi[i] = v[i];
        if (i == 2) first = false;
      }
  Rational size = 1;
  for (int i = 0; i < 3; ++i) size = std::max(size, Rational(hi[i] - lo[i]));
  Rational half = 2 * size;
  if (n.IsMap() && n["size"]) {
    half = c.number(n["size"], "ground size") / 2;
    if (half <= 0) c.fail(n["size"], "ground size must be positive");
  }
  const Rational cu = (lo[u] + hi[u]) / 2, cw = (lo[w] + hi[w]) / 2;
  auto corner = [&](const Rational& a, const Rational& b) {
    std::array<Rational, 3> p;
    p[k] = at, p[u] = a, p[w] = b;
    return Point3(p[0], p[1], p[2]);
  };
  std::vector<Point3> vs{corner(cu - half, cw - half), corner(cu + half, cw - half), corner(cu + half, cw + half), corner(cu - half, cw + half)};
  Face f{0, 1, 2, 3};
  if (hi[k] <= at) f = {3, 2, 1, 0};  // the bodies below: the front faces down
  SceneBody g{"ground", s.file, Polyhedron(std::move(vs), {f}), identity_transform(), {}, {}, {}, std::nullopt};
  Material m;
  m.colour = {0.86, 0.86, 0.84};
  m.ks = 0;
  g.material = n.IsMap() && n["material"] ? parse_material(c, n["material"], static_cast<int>(s.bodies.size())) : m;
  s.bodies.push_back(std::move(g));
}

Scene load_scene(const std::string& path) { return load_scene_text(read_file_bytes(path), path); }

Scene load_scene_text(const std::string& bytes, const std::string& path) { return load_scene_text(bytes, path, {}, true); }

namespace {

// `hatch: none`, or a mapping of pattern (single, cross, solid, none), angle (degrees) and
// spacing (mm on the page).
HatchStyle parse_hatch(const Ctx& c, const YAML::Node& n) {
  HatchStyle h;
  auto pattern = [&](const YAML::Node& p) {
    const std::string t = c.text(p, "hatch pattern");
    if (t == "single") return HatchStyle::Pattern::Single;
    if (t == "cross") return HatchStyle::Pattern::Cross;
    if (t == "solid") return HatchStyle::Pattern::Solid;
    if (t == "none") return HatchStyle::Pattern::None;
    c.fail(p, "hatch pattern must be single, cross, solid or none, not '" + t + "'");
  };
  if (n.IsScalar()) {
    h.pattern = pattern(n);
    return h;
  }
  c.check_keys(n, "hatch", {"pattern", "angle", "spacing"});
  if (n["pattern"]) h.pattern = pattern(n["pattern"]);
  if (n["angle"]) h.angle = to_double(c.number(n["angle"], "hatch angle"));
  if (n["spacing"]) {
    h.spacing = to_double(c.number(n["spacing"], "hatch spacing"));
    if (!(*h.spacing >= 0.05 && *h.spacing <= 1000)) c.fail(n["spacing"], "hatch spacing must be between 0.05 and 1000 mm");
  }
  return h;
}

// `section:` one plane or a list (clipper_spec.hpp's forms, as text).
std::vector<Plane> parse_scene_section(const Ctx& c, const YAML::Node& n) {
  std::vector<Plane> out;
  auto one = [&](const YAML::Node& p) {
    try {
      for (Plane& h : parse_section("section", c.text(p, "a section plane"))) out.push_back(std::move(h));
    } catch (const std::invalid_argument& e) {
      c.fail(p, e.what());
    }
  };
  if (n.IsSequence()) {
    if (n.size() == 0) c.fail(n, "section must name at least one plane");
    for (const auto& p : n) one(p);
  } else {
    one(n);
  }
  return out;
}

}  // namespace

Scene load_scene_text(const std::string& bytes, const std::string& path, const std::vector<std::string>& extra_keys,
                      bool bodies_required) {
  Ctx c{path};
  YAML::Node root;
  try {
    root = YAML::Load(bytes);
  } catch (const YAML::Exception& e) {
    throw InputError(path, e.mark.is_null() ? 0 : e.mark.line + 1, "not valid YAML/JSON: " + e.msg);
  }
  if (!root || root.IsNull()) throw InputError(path, 0, "empty scene file");
  if (depth(root) > kMaxNesting) throw InputError(path, 0, "nesting deeper than " + std::to_string(kMaxNesting) + " levels");
  std::vector<std::string> known = {"bodies", "view", "camera", "light", "lighting", "ground", "section", "cutaway"};
  known.insert(known.end(), extra_keys.begin(), extra_keys.end());
  // A problem file (docs/problem-format.md) is a scene too: `hlr render` draws its bodies.
  if (extra_keys.empty() && root.IsMap() && root["problem"])
    known.insert(known.end(), {"problem", "title", "edges", "clipper", "segments", "eps"});
  c.check_keys(root, extra_keys.empty() ? "the scene" : "the problem", known);
  Scene s;
  s.file = path;
  const YAML::Node bodies = root["bodies"];
  if (!bodies && !bodies_required) {
    if (root["view"]) s.view = parse_view(c, root["view"]);
    return s;
  }
  if (!bodies) c.fail(root, "the scene needs a 'bodies' list");
  if (!bodies.IsSequence() || bodies.size() == 0) c.fail(bodies, "'bodies' must be a non-empty list");
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const YAML::Node b = bodies[i];
    c.check_keys(b, "a body", {"name", "mesh", "vertices", "faces", "box", "transform", "material", "cut", "hatch"});
    int kinds = (b["mesh"] ? 1 : 0) + (b["vertices"] || b["faces"] ? 1 : 0) + (b["box"] ? 1 : 0);
    if (kinds != 1) c.fail(b, "a body needs exactly one of: mesh, vertices + faces, box");
    std::string name = b["name"] ? c.text(b["name"], "name") : "body " + std::to_string(i);
    std::string source = path;
    std::optional<Polyhedron> poly;
    std::vector<Face> typed;
    std::vector<std::array<double, 2>> texcoords;
    std::vector<std::vector<int>> face_texcoords;
    FaceSurfaces surfaces;
    if (b["mesh"]) {
      std::string rel = c.text(b["mesh"], "mesh");
      std::filesystem::path mp = rel;
      if (mp.is_relative()) mp = dir / mp;
      source = mp.string();
      try {
        MeshData data = read_mesh_file(source);
        texcoords = std::move(data.texcoords);
        face_texcoords = std::move(data.face_texcoords);
        surfaces = std::move(data.surfaces);
        poly.emplace(make_polyhedron(std::move(data), source));
      } catch (const InputError& e) {
        c.fail(b["mesh"], "mesh '" + rel + "': " + e.what());
      }
      if (!b["name"]) name = mp.stem().string();
    } else if (b["box"]) {
      c.check_keys(b["box"], "box", {"min", "max"});
      if (!b["box"]["min"] || !b["box"]["max"]) c.fail(b["box"], "box needs 'min' and 'max' corners");
      try {
        poly.emplace(make_box(c.point(b["box"]["min"], "box min"), c.point(b["box"]["max"], "box max")));
      } catch (const std::invalid_argument& e) {
        c.fail(b["box"], e.what());
      }
    } else {
      poly.emplace(inline_body(c, b, typed));
    }
    Matrix4 m = identity_transform();
    std::vector<std::string> notes;
    std::vector<std::pair<std::string, Matrix4>> steps;
    if (b["transform"]) {
      if (!b["transform"].IsSequence()) c.fail(b["transform"], "transform must be a list of steps");
      for (const auto& step : b["transform"]) {
        Matrix4 one = parse_transform_step(c, step, notes);
        steps.push_back({step.IsMap() && step.size() > 0 ? step.begin()->first.Scalar() : std::string("step"), one});
        m = compose(m, one);
      }
      poly.emplace(transformed(c, b["transform"], *poly, m));
      if (is_affine(m) && det3(m) < 0)  // the faces were turned: their corners' texture indices too
        for (auto& t : face_texcoords) std::reverse(t.begin(), t.end());
    }
    s.bodies.push_back(SceneBody{name, source, std::move(*poly), m, std::move(steps), std::move(notes), std::move(typed), std::nullopt,
                                 std::move(texcoords), std::move(face_texcoords)});
    s.bodies.back().surfaces = std::move(surfaces);
    if (b["material"]) s.bodies.back().material = parse_material(c, b["material"], static_cast<int>(i));
    if (b["cut"]) {
      const std::string t = c.text(b["cut"], "cut");
      if (t != "true" && t != "false") c.fail(b["cut"], "cut must be true or false");
      s.bodies.back().cut = t == "true";
    }
    if (b["hatch"]) s.bodies.back().hatch = parse_hatch(c, b["hatch"]);
  }
  if (root["view"] && root["camera"]) c.fail(root["camera"], "give 'view' or 'camera' (the same keys), not both");
  if (root["view"]) s.view = parse_view(c, root["view"]);
  if (root["camera"]) s.view = parse_view(c, root["camera"]);
  if (root["light"]) {
    s.light = c.vector(root["light"], "light");
    if (s.light->is_zero()) c.fail(root["light"], "light vector has zero length");
  }
  if (root["lighting"]) s.lighting = parse_lighting(c, root["lighting"]);
  if (root["ground"]) add_ground(c, root["ground"], s, extra_keys.empty());
  if (root["section"]) s.section = parse_scene_section(c, root["section"]);
  if (root["cutaway"]) s.cutaway = parse_scene_section(c, root["cutaway"]);
  return s;
}

}  // namespace hlr
