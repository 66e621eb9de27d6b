// A model read from a CAD or scene-graph file (STEP, IGES, glTF, 3MF): bodies with their names,
// exact vertices (the file's or the tessellation's numbers, exactly), the surface each face is
// part of, colours, and what the file says about units and the up axis (docs/design.md,
// "Models").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "algorithms/shading/lighting.hpp"
#include "algorithms/solids/face_surfaces.hpp"
#include "io/readers/mesh_reader.hpp"

namespace hlr {

struct ModelBody {
  std::string name;
  MeshData mesh;
  FaceSurfaces surfaces;  // empty: none
  std::optional<Rgb> colour;
};

struct Model {
  std::vector<ModelBody> bodies;
  /// The length unit of the coordinates: "mm", "cm", "m", "in", "ft" or "um".
  std::string units = "mm";
  /// The file's convention: Z up (CAD, 3D printing) or Y up (glTF).
  bool z_up = true;
  /// What reading did that the drawing should say (the tessellation's deflection, sewing).
  std::vector<std::string> notes;
};

/// How a B-rep model is made into triangles.
struct TessellationOptions {
  /// Largest distance in mm between a triangle and the surface; 0: a thousandth of the model's
  /// bounding-box diagonal.
  double deflection = 0;
  /// Largest angle in degrees between the normals of neighbouring triangles of one surface.
  double angle_degrees = 15;
};

}  // namespace hlr
