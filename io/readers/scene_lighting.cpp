// Lights and materials in scene files (see scene_lighting.hpp, docs/scene-format.md).
#include "io/readers/scene_lighting.hpp"

#include <png.h>

#include <cmath>
#include <filesystem>
#include <memory>

namespace hlr {
namespace {

double real(const YamlContext& c, const YAML::Node& n, const std::string& what, double lo, double hi) {
  double v = to_double(c.number(n, what));
  if (!(v >= lo && v <= hi)) c.fail(n, what + " must be between " + to_string(rational_from_double(lo)) + " and " + to_string(rational_from_double(hi)));
  return v;
}

Vec3d vec(const YamlContext& c, const YAML::Node& n, const std::string& what, bool nonzero) {
  auto t = c.triple(n, what);
  if (nonzero && t[0] == 0 && t[1] == 0 && t[2] == 0) c.fail(n, what + " has zero length");
  return {to_double(t[0]), to_double(t[1]), to_double(t[2])};
}

// [r, g, b] from 0 to 1, or "#rrggbb".
Rgb colour(const YamlContext& c, const YAML::Node& n, const std::string& what) {
  if (n.IsScalar()) {
    const std::string& s = n.Scalar();
    bool ok = s.size() == 7 && s[0] == '#';
    for (std::size_t i = 1; ok && i < 7; ++i) ok = std::isxdigit(static_cast<unsigned char>(s[i])) != 0;
    if (!ok) c.fail(n, what + " must be [r, g, b] from 0 to 1 or #rrggbb");
    Rgb out;
    for (int i = 0; i < 3; ++i) out[i] = std::stoi(s.substr(1 + 2 * i, 2), nullptr, 16) / 255.0;
    return out;
  }
  if (!n.IsSequence() || n.size() != 3) c.fail(n, what + " must be [r, g, b] from 0 to 1 or #rrggbb");
  return {real(c, n[0], what, 0, 1), real(c, n[1], what, 0, 1), real(c, n[2], what, 0, 1)};
}

// An 8-bit RGB texture from a PNG file (libpng's simplified API converts any PNG).
std::shared_ptr<const TextureImage> read_texture(const YamlContext& c, const YAML::Node& n, const std::string& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) c.fail(n, "texture '" + path + "' cannot be read as PNG");
  image.format = PNG_FORMAT_RGB;
  auto t = std::make_shared<TextureImage>();
  t->width = static_cast<int>(image.width), t->height = static_cast<int>(image.height);
  t->rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, t->rgb.data(), 0, nullptr)) {
    png_image_free(&image);
    c.fail(n, "texture '" + path + "' cannot be read as PNG");
  }
  return t;
}

Light parse_light(const YamlContext& c, const YAML::Node& n) {
  c.check_keys(n, "a light", {"type", "direction", "position", "colour", "color", "intensity", "attenuation", "cone", "exponent"});
  if (!n["type"]) c.fail(n, "a light needs a 'type' (directional, point or spot)");
  std::string type = c.text(n["type"], "light type");
  Light l;
  if (type == "directional") l.type = Light::Type::Directional;
  else if (type == "point") l.type = Light::Type::Point;
  else if (type == "spot") l.type = Light::Type::Spot;
  else c.fail(n["type"], "light type must be directional, point or spot");
  bool needs_dir = l.type != Light::Type::Point, needs_pos = l.type != Light::Type::Directional;
  if (needs_dir != static_cast<bool>(n["direction"]))
    c.fail(n, needs_dir ? "a " + type + " light needs a 'direction'" : "a point light has no 'direction'");
  if (needs_pos != static_cast<bool>(n["position"]))
    c.fail(n, needs_pos ? "a " + type + " light needs a 'position'" : "a directional light has no 'position' (it is at infinity)");
  if (n["direction"]) l.direction = vec(c, n["direction"], "light direction", true);
  if (n["position"]) l.position = vec(c, n["position"], "light position", false);
  l.exact = true;
  if (n["direction"]) l.exact_direction = c.triple(n["direction"], "light direction");
  if (n["position"]) l.exact_position = c.triple(n["position"], "light position");
  if (n["colour"] && n["color"]) c.fail(n, "give 'colour' or 'color', not both");
  if (n["colour"]) l.colour = colour(c, n["colour"], "light colour");
  if (n["color"]) l.colour = colour(c, n["color"], "light colour");
  if (n["intensity"]) l.intensity = real(c, n["intensity"], "light intensity", 0, 1e6);
  if (n["attenuation"]) {
    if (l.type == Light::Type::Directional) c.fail(n["attenuation"], "a directional light has no attenuation (it is at infinity)");
    auto a = vec(c, n["attenuation"], "attenuation", true);
    if (a[0] < 0 || a[1] < 0 || a[2] < 0) c.fail(n["attenuation"], "attenuation [a0, a1, a2] must not be negative");
    l.attenuation = a;
  }
  if ((n["cone"] || n["exponent"]) && l.type != Light::Type::Spot) c.fail(n, "'cone' and 'exponent' belong to a spot light");
  if (n["cone"]) l.cone_degrees = real(c, n["cone"], "cone", 0, 90);
  if (n["exponent"]) l.exponent = real(c, n["exponent"], "exponent", 0, 1e4);
  return l;
}

}  // namespace

Lighting parse_lighting(const YamlContext& c, const YAML::Node& n) {
  c.check_keys(n, "lighting", {"ambient", "specular", "lights"});
  Lighting l;
  if (n["ambient"]) l.ambient = colour(c, n["ambient"], "ambient");
  if (n["specular"]) {
    std::string s = c.text(n["specular"], "specular");
    if (s != "phong" && s != "blinn") c.fail(n["specular"], "specular must be phong or blinn");
    l.blinn = s == "blinn";
  }
  if (n["lights"]) {
    if (!n["lights"].IsSequence()) c.fail(n["lights"], "lights must be a list");
    for (const auto& li : n["lights"]) l.lights.push_back(parse_light(c, li));
  }
  return l;
}

Material parse_material(const YamlContext& c, const YAML::Node& n, int body) {
  c.check_keys(n, "a material", {"colour", "color", "ka", "kd", "ks", "shininess", "transparency", "transparency_model",
                                 "transparency_min", "transparency_power", "reflection", "ior", "checker", "colour2", "color2", "bump", "bump_size", "texture"});
  Material m;
  m.colour = palette_colour(body);
  if (n["colour"] && n["color"]) c.fail(n, "give 'colour' or 'color', not both");
  if (n["colour"]) m.colour = colour(c, n["colour"], "colour");
  if (n["color"]) m.colour = colour(c, n["color"], "colour");
  if (n["ka"]) m.ka = real(c, n["ka"], "ka", 0, 1);
  if (n["kd"]) m.kd = real(c, n["kd"], "kd", 0, 1);
  if (n["ks"]) m.ks = real(c, n["ks"], "ks", 0, 1);
  if (n["shininess"]) m.shininess = real(c, n["shininess"], "shininess", 0, 1e4);
  if (n["transparency"]) m.transparency = real(c, n["transparency"], "transparency", 0, 1);
  if (n["transparency_min"]) m.transparency_min = real(c, n["transparency_min"], "transparency_min", 0, 1);
  if (n["transparency_power"]) m.transparency_power = real(c, n["transparency_power"], "transparency_power", 0, 100);
  if (n["reflection"]) m.reflection = real(c, n["reflection"], "reflection", 0, 1);
  if (n["ior"]) {
    m.ior_exact = c.number(n["ior"], "ior");
    m.ior = to_double(m.ior_exact);
    if (!(m.ior >= 0.1 && m.ior <= 10)) c.fail(n["ior"], "ior must be between 1/10 and 10");
  }
  if (m.reflection + m.transparency > 1) c.fail(n, "reflection + transparency must not exceed 1");
  if (n["texture"]) {
    std::filesystem::path tp = c.text(n["texture"], "texture");
    if (tp.is_relative()) tp = std::filesystem::path(c.file).parent_path() / tp;
    m.texture = read_texture(c, n["texture"], tp.string());
  }
  if (n["bump"]) m.bump = real(c, n["bump"], "bump", 0, 1e300);
  if (n["bump_size"]) m.bump_size = real(c, n["bump_size"], "bump_size", 1e-300, 1e300);
  if (n["checker"]) m.checker = real(c, n["checker"], "checker", 0, 1e300);
  if (n["colour2"] && n["color2"]) c.fail(n, "give 'colour2' or 'color2', not both");
  if (n["colour2"]) m.colour2 = colour(c, n["colour2"], "colour2");
  if (n["color2"]) m.colour2 = colour(c, n["color2"], "colour2");
  if (n["transparency_model"]) {
    const std::string t = c.text(n["transparency_model"], "transparency_model");
    if (t == "linear") m.transparency_model = Material::TransparencyModel::Linear;
    else if (t == "kay") m.transparency_model = Material::TransparencyModel::Kay;
    else if (t == "path") m.transparency_model = Material::TransparencyModel::PathLength;
    else c.fail(n["transparency_model"], "transparency_model must be linear, kay or path");
  }
  return m;
}

}  // namespace hlr
