// Lights and materials in scene files (course notes sections 36 and 39):
// the `lighting` key (ambient, phong or blinn, directional, point and spot lights) and a body's
// `material` (colour, ka, kd, ks, shininess). Schema: docs/scene-format.md. Include only in
// .cpp files that use yaml-cpp.
#pragma once

#include "algorithms/shading/lighting.hpp"
#include "io/readers/yaml_context.hpp"

namespace hlr {

Lighting parse_lighting(const YamlContext& c, const YAML::Node& n);
Material parse_material(const YamlContext& c, const YAML::Node& n, int body);

}  // namespace hlr
