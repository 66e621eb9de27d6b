// The bodies of scene-graph formats (glTF, 3MF) made exact (docs/design.md, "Models"): a
// body's triangles in the file's float coordinates and the transform that places it, welded at
// exactly equal positions, transformed exactly (a float is an exact dyadic rational, so is
// every product and sum of them), and split into smooth regions by the file's normals.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "io/models/model.hpp"
#include "kernel/matrix.hpp"
#include "kernel/transform.hpp"

namespace hlr {

/// A body as a scene-graph file stores it.
struct FloatBody {
  std::string name;
  std::vector<std::array<float, 3>> positions;
  /// Per position (empty: the file gives none).
  std::vector<std::array<float, 3>> normals;
  std::vector<std::array<int, 3>> triangles;  // indices into positions
  /// Row-vector convention, [x y z 1]·M (the course notes' section 20); affine.
  Matrix4 transform = identity_transform();
  std::optional<Rgb> colour;
};

/// The exact body: corners at exactly equal positions are one vertex, coordinates are
/// [x y z 1]·transform exactly, a mirroring transform turns every triangle round (so the faces
/// keep facing outward), triangles with a repeated corner are dropped (added to `dropped`). Where
/// the file has normals, faces that meet at an edge with the same normals at both its ends are
/// one smooth surface (never a crease there); edges between surfaces go by the crease angle.
ModelBody assemble_body(const FloatBody& body, long& dropped);

/// The note for the triangles assemble_body dropped in a file (none when there were none).
void note_dropped(long dropped, std::vector<std::string>& notes);

/// The rotation of the unit quaternion (x, y, z, w), in row-vector convention, computed exactly
/// from the given numbers (as glTF defines it: a quaternion a little off unit length gives the
/// matrix of the formula, not a rescaled one).
Matrix4 quaternion_rotation(double x, double y, double z, double w);

}  // namespace hlr
