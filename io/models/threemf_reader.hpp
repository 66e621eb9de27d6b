// 3MF models through lib3mf (docs/design.md, "Models"): every build item a body (a components
// object one body per mesh it places), at the build item's and components' transforms applied
// exactly, in the file's unit, Z up. The only unit that includes lib3mf.
#pragma once

#include <string>

#include "io/models/model.hpp"

namespace hlr {

/// True for .3mf (any case).
bool is_3mf_file(const std::string& path);

/// Reads a 3MF file's build. lib3mf reads coordinates and transforms as 32-bit floats (the
/// precision 3MF producers write); those floats are taken exactly. Throws InputError:
/// unreadable file, a build with no triangles.
/// Read in the model module (model_module.hpp), loaded on first use.
Model read_3mf_file(const std::string& path);

}  // namespace hlr
