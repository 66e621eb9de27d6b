// glTF 2.0 models, .gltf and .glb, through tinygltf (docs/design.md, "Models"): every mesh a
// node places is a body named by its node, at the node hierarchy's transforms applied exactly,
// with its material's base colour; the file's normals mark smooth regions. The only unit that
// includes tinygltf.
#pragma once

#include <string>

#include "io/models/model.hpp"

namespace hlr {

/// True for .gltf and .glb (any case).
bool is_gltf_file(const std::string& path);

/// Reads a glTF 2.0 file: the default scene's nodes (every root node when the file has no
/// scene), each node's mesh one body per material (its triangles, strips and fans; points and
/// lines are left out with a note). Coordinates in metres, Y up, as glTF defines them. Throws
/// InputError: unreadable file, an index out of range, a node that is its own ancestor,
/// compressed or sparse data this reader does not decode.
/// Read in the model module (model_module.hpp), loaded on first use.
Model read_gltf_file(const std::string& path);

}  // namespace hlr
