// Models as scenes (see model_input.hpp; docs/design.md, "Models").
#include "io/models/model_input.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "io/models/cad_reader.hpp"
#include "io/models/gltf_reader.hpp"
#include "io/models/threemf_reader.hpp"
#include "kernel/transform.hpp"

namespace hlr {

namespace {

Model read_model(const std::string& path, const ModelOptions& o) {
  if (is_cad_file(path)) return read_cad_file(path, o.tessellation);
  if (is_gltf_file(path)) return read_gltf_file(path);
  if (is_3mf_file(path)) return read_3mf_file(path);
  throw InputError(path, 0, "not a model file (.step, .stp, .iges, .igs, .gltf, .glb, .3mf)");
}

// Every body's coordinates multiplied by `k` (exactly).
void scale_bodies(Scene& s, const Rational& k) {
  if (k == 1) return;
  for (SceneBody& b : s.bodies) {
    std::vector<Point3> v = b.body.vertices();
    for (Point3& p : v) p = Point3(p.x() * k, p.y() * k, p.z() * k);
    b.body = Polyhedron(std::move(v), b.body.faces());
  }
}

}  // namespace

Rational millimetres_per(const std::string& unit) {
  if (unit == "mm") return 1;
  if (unit == "cm") return 10;
  if (unit == "m") return 1000;
  if (unit == "in") return Rational(254, 10);
  if (unit == "ft") return Rational(3048, 10);
  if (unit == "um") return Rational(1, 1000);
  throw std::invalid_argument("--units: '" + unit + "' is not a unit (mm, cm, m, in, ft, um)");
}

bool is_model_file(const std::string& path) { return is_cad_file(path) || is_gltf_file(path) || is_3mf_file(path); }

Scene load_model(const std::string& path, const ModelOptions& options) {
  Model m = read_model(path, options);
  Scene s;
  s.file = path;
  for (ModelBody& mb : m.bodies) {
    SceneBody b{mb.name, path, make_polyhedron(std::move(mb.mesh), path), identity_transform(), {}, {}, {}};
    b.surfaces = std::move(mb.surfaces);
    if (mb.colour) {
      Material mat;
      mat.colour = *mb.colour;
      b.material = mat;
    }
    s.bodies.push_back(std::move(b));
  }
  if (m.z_up) {
    s.view.up = Vector3(Rational(0), Rational(0), Rational(1));
    s.view.up_given = true;
  }
  s.notes = std::move(m.notes);
  scale_bodies(s, millimetres_per(m.units));
  return s;
}

Scene load_any_input(const std::string& path, const std::string& format, const ModelOptions& options) {
  if (format.empty() && is_model_file(path)) return load_model(path, options);
  Scene s = load_input(path, format);
  if (!options.units.empty()) scale_bodies(s, millimetres_per(options.units));
  // STL is the 3D-printing and CAD exchange format: Z up, as its producers model.
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (format == "stl" || (format.empty() && ext == ".stl")) {
    s.view.up = Vector3(Rational(0), Rational(0), Rational(1));
    s.view.up_given = true;
  }
  return s;
}

}  // namespace hlr
