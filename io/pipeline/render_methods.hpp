// The method table of the render pipeline (docs/design.md, "Adding a method"): what each row
// of method_table.hpp gives the pipeline, the CLI, Python and the messages, and the two steps
// a method may fill in. The pipeline (render.cpp) prepares the scene and the camera, calls the
// method's lines step (line drawings) or, for filled products, draws every edge and calls its
// polygons step, then clips and writes through one output stage.
#pragma once

#include <string>
#include <vector>

#include "algorithms/hlr/face_occluders.hpp"
#include "io/pipeline/render.hpp"

namespace hlr {

/// What a lines step gets: the render so far (bodies, names, camera), the bodies' polyhedra,
/// the options, the per-face route's hooks (a tile's filters, the raster's facing only), and
/// the notes to add to.
struct LineStep {
  RenderResult& r;
  const std::vector<const Polyhedron*>& polys;
  const RenderOptions& o;
  const FaceRouteHooks& hooks;
  std::vector<std::string>& notes;
};

/// What a polygons step gets: the render so far (shaded faces, colour groups), the scene, the
/// options, the exact drawing of every edge (classified) and the visible-surface options.
struct PolygonStep {
  RenderResult& r;
  const std::vector<const Polyhedron*>& polys;
  const std::vector<Scene>& scenes;
  const RenderOptions& o;
  const LineDrawing& all;
  const SurfaceOptions& so;
};

using LinesFn = void (*)(LineStep&);
using PolygonsFn = void (*)(PolygonStep&);

/// What else a method takes.
enum MethodFlags : unsigned {
  kTakesShadows = 1,  ///< --shadows
  kTakesTiles = 2,    ///< --tile and merges of tiles
  kChecksSolids = 4,  ///< every body's checks run while loading (it needs valid solids)
};

/// The placeholders of the table: the method has no such step.
void no_lines(LineStep&);
void no_polygons(PolygonStep&);

#define HLR_DECLARE_METHOD_STEPS(e, name, lines, polygons, flags, help) \
  void lines(LineStep&);                                                \
  void polygons(PolygonStep&);
HLR_RENDER_METHODS(HLR_DECLARE_METHOD_STEPS)
#undef HLR_DECLARE_METHOD_STEPS

struct RenderMethodEntry {
  RenderMethod method;
  const char* name;
  LinesFn lines;
  PolygonsFn polygons;
  unsigned flags;
  const char* help;
  bool draws_lines() const { return lines != &no_lines; }
  bool makes_polygons() const { return polygons != &no_polygons; }
};

/// Every method, in the table's order.
const std::vector<RenderMethodEntry>& render_methods();
/// The row of a method.
const RenderMethodEntry& method_entry(RenderMethod m);
/// The method of a name; throws std::invalid_argument naming every method.
RenderMethod parse_render_method(const std::string& name);
/// The names, in the table's order.
std::vector<std::string> render_method_names();
/// The names of the methods with `pick`, as a list for messages: "a, b or c".
std::string method_list(bool (*pick)(const RenderMethodEntry&));

}  // namespace hlr
