// The inputs of hlr render and the Python module that are models (STEP, IGES, glTF, 3MF) as
// scenes, and every input by its format (docs/design.md, "Models"): a model's bodies keep their
// names, surfaces and colours, its coordinates are brought to millimetres, and its up axis
// becomes the scene's.
#pragma once

#include <string>

#include "io/models/model.hpp"
#include "io/readers/scene.hpp"

namespace hlr {

struct ModelOptions {
  TessellationOptions tessellation;
  /// The length unit of files that do not say (OFF, OBJ, STL, PLY): "mm" (default), "cm", "m" or
  /// "in"; coordinates are brought to millimetres. Empty: millimetres, as they are.
  std::string units;
};

/// True for the extensions read_model reads: .step .stp .iges .igs .gltf .glb .3mf.
bool is_model_file(const std::string& path);

/// A model file as a scene: one body per model body, each face's surface and the body's colour
/// kept, a Z-up model's view up the Z axis. Throws InputError.
Scene load_model(const std::string& path, const ModelOptions& options);

/// Any input of hlr render: a model by its extension, else load_input(path, format) (scene and
/// mesh files, standard input), its coordinates brought to millimetres by `options.units`; an
/// STL file's view is Z up (as 3MF, STEP and IGES; OFF, OBJ and PLY stay Y up).
Scene load_any_input(const std::string& path, const std::string& format, const ModelOptions& options);

/// Millimetres per unit: "mm" 1, "cm" 10, "m" 1000, "in" 25.4, "ft" 304.8, "um" 0.001; throws std::invalid_argument
/// for another name.
Rational millimetres_per(const std::string& unit);

}  // namespace hlr
