// Scene files (YAML, or JSON, which yaml-cpp reads as YAML): bodies from mesh files, inline
// vertices and faces, or boxes, each with its own list of transforms; a view (orthographic
// direction or perspective eye/target/up) and an optional light vector. Every number keeps
// its exact value. Unknown keys and wrong types are errors with line numbers.
// Schema and examples: docs/scene-format.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "algorithms/clip/view_pyramid.hpp"
#include "algorithms/hatching/hatch.hpp"
#include "algorithms/shading/lighting.hpp"
#include "algorithms/solids/face_surfaces.hpp"
#include "io/readers/input_error.hpp"
#include "io/readers/mesh_reader.hpp"
#include "kernel/polyhedron.hpp"
#include "kernel/transform.hpp"

namespace hlr {

struct View {
  enum class Type { Orthographic, Perspective };
  Type type = Type::Orthographic;
  /// Orthographic: from the scene toward the viewer (course notes default: +z).
  Vector3 direction{Rational(0), Rational(0), Rational(1)};
  /// Perspective: centre of projection, point looked at (unset: the scene's centre), up.
  Point3 eye;
  std::optional<Point3> target;
  Vector3 up{Rational(0), Rational(1), Rational(0)};
  bool up_given = false;
  /// Perspective: the picture's frame (fov, fov_v, aspect, frame, focal, sensor); unset: the
  /// drawing fits its lines.
  std::optional<FrameRequest> frame;
};

struct SceneBody {
  std::string name;
  std::string source;  // mesh path, or the scene file for inline bodies and boxes
  Polyhedron body;     // world coordinates: the body's transforms applied
  Matrix4 transform;   // composition of the body's transforms (row-vector convention)
  std::vector<std::pair<std::string, Matrix4>> steps;  // each transform step: its key and matrix
  std::vector<std::string> notes;  // e.g. how an inexact rotation angle was realised
  /// Inline bodies: the faces in the order typed (before they were oriented outward); the
  /// exam page shows them and says which were turned. Empty for meshes and boxes.
  std::vector<Face> typed_faces;
  /// The body's material for shaded surfaces (unset: the default, in the palette's colour).
  std::optional<Material> material = std::nullopt;
  /// OBJ texture coordinates and each face's corners' indices into them (aligned with the
  /// face's vertices; empty: none), for `material.texture` (hlr raster).
  std::vector<std::array<double, 2>> texcoords = {};
  std::vector<std::vector<int>> face_texcoords = {};
  /// Sections: false for a body no section cuts (a shaft, a fastener: drawn whole).
  bool cut = true;
  /// How its caps are hatched (unset: the defaults, hatch.hpp).
  std::optional<HatchStyle> hatch = std::nullopt;
  /// Once a section has cut it: per face, the input face it is part of (or the number of
  /// input faces + k for the cap on plane k), and the plane whose cap it is on (-1: none).
  /// Empty: not cut.
  std::vector<int> section_part = {}, section_cap = {};
  /// Which surface of the model each face is part of and which surfaces meet tangentially
  /// (a CAD model's B-rep faces, a polygon split into triangles); empty: none.
  FaceSurfaces surfaces = {};
};

struct Scene {
  std::string file;
  std::vector<SceneBody> bodies;
  View view;
  std::optional<Vector3> light;
  /// Lights for shaded surfaces (`lighting:`); unset: `light` as a directional light, else the default.
  std::optional<Lighting> lighting;
  /// `ground: z = 0`: the axis (0 x, 1 y, 2 z) and the value; a scene gets a ground body too,
  /// a problem keeps the plane only (the cast shadow on it).
  std::optional<std::pair<int, Rational>> ground;
  /// `section:` cutting half-spaces (value <= 0 kept; io/readers/clipper_spec.hpp): what they
  /// remove is gone, each cut body gets its caps.
  std::vector<Plane> section;
  /// `cutaway:` half-spaces whose common region is removed (a half section: two planes).
  std::vector<Plane> cutaway;
  /// What reading the file did that the drawing says in its notes (a model's tessellation).
  std::vector<std::string> notes = {};
};

/// True for .yaml, .yml and .json files.
bool is_scene_file(const std::string& path);

/// Loads and checks a scene file. Throws InputError with file and line.
Scene load_scene(const std::string& path);

/// The same from the file's text; `path` names it in messages and anchors relative mesh paths.
Scene load_scene_text(const std::string& text, const std::string& path);

/// The same, for files that carry more than a scene (problem files): `extra_keys` are accepted
/// at the top level (the caller reads them), and `bodies` may be missing unless required.
Scene load_scene_text(const std::string& text, const std::string& path, const std::vector<std::string>& extra_keys,
                      bool bodies_required);

/// A scene of one body from a mesh file (name: the file's stem), default view.
Scene scene_from_mesh(const std::string& path);

/// A scene of one body from a mesh's data (checked by make_polyhedron; `source` names it in
/// messages), default view: meshes read from a file or handed over in memory.
Scene scene_from_mesh_data(MeshData data, const std::string& body, const std::string& source);

/// An input of hlr render: a scene or mesh file by its extension, or, with `format` (off, obj,
/// stl, ply, yaml or json), read as that format whatever its name; "-" is standard input
/// (named <stdin> in messages, mesh paths in it relative to the working directory) and needs
/// a format. Throws InputError.
Scene load_input(const std::string& path, const std::string& format);

}  // namespace hlr
