// STEP and IGES models through Open CASCADE (docs/design.md, "Models"): read, tessellate at a
// deflection, weld each solid's face meshes along their shared B-rep edges into one closed mesh,
// and keep each B-rep face's identity on its triangles and which faces meet tangentially. The
// only unit that includes Open CASCADE.
#pragma once

#include <string>

#include "io/models/model.hpp"

namespace hlr {

/// True for .step, .stp, .iges and .igs (any case).
bool is_cad_file(const std::string& path);

/// Reads a STEP or IGES file (by its extension): each solid a body named from the file (its
/// product or entity name, else the file's stem and a number); faces that form no solid are
/// sewn into shells, each a body. Coordinates in millimetres (Open CASCADE converts the file's
/// unit). Throws InputError: missing or unreadable file, no shape in it.
/// Read in the model module (model_module.hpp), loaded on first use.
Model read_cad_file(const std::string& path, const TessellationOptions& options);

}  // namespace hlr
