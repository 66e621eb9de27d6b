// Shadows as exact polygons (course notes section 40: the Atherton–Weiler–Greenberg two-pass
// method). The part of a face lit by a light is the part seen from the light: the visible
// surfaces (visible_surfaces.hpp) run from the light's position (a point or spot light: a
// perspective view from it) or from its direction (a directional light: an orthographic view).
// Those lit polygons, exact in the face's plane, are carried into the viewer's picture and laid
// over the face's visible polygons in an exact planar arrangement; every cell is labelled by
// which lights reach it (a point beside an edge, offset symbolically, tested against each
// polygon set: no epsilon), and cells of one label are merged. A face lit on the other side
// than the one seen (or turned away from a light) is in that light's shadow, as the notes'
// first step. The result per visible face: regions with the set of lights that reach them, and
// per light the lit and the shadowed polygons, all with exact 3D corners.
#pragma once

#include <array>
#include <vector>

#include "algorithms/surfaces/visible_surfaces.hpp"

namespace hlr {

/// Where a light is, exactly: at infinity toward `toward` (directional) or at `position`.
struct LightPlace {
  bool directional = true;
  Vector3 toward;   // directional: from the scene toward the light
  Point3 position;  // point (and spot) lights
};

struct ShadowRegion {
  unsigned lights = 0;  // bit i: light i reaches this region
  VisiblePolygon polygon;
};

struct ShadowFace {
  int body = -1, face = -1;
  bool front = true;                      // the side seen, as VisibleFace::front
  std::vector<ShadowRegion> regions;      // the visible part, cut by every light's shadow
  /// Per light: the visible part it lights and the visible part in its shadow.
  std::vector<std::array<std::vector<VisiblePolygon>, 2>> by_light;  // [0] lit, [1] shadow
  Rational area2, shadow_area2;           // twice the visible area; twice the part no light reaches
  bool whole = false;                     // every light lights all of it or none (no arrangement)
};

struct Shadows {
  std::vector<ShadowFace> faces;                // as the viewer's VisibleSurfaces::faces
  std::vector<VisibleSurfaces> from_light;      // what each light sees (its lit polygons)
  /// Per light among the bodies: what its six cube views see (light_cube.hpp; their bodies are
  /// the parts in each pyramid), its from_light entry empty; empty for every other light.
  std::vector<std::vector<VisibleSurfaces>> cube_views;
  double seconds = 0;
  double seconds_lights = 0;   // pass 1: the views from the lights
  std::size_t whole_faces = 0; // faces each light lights wholly or not at all (no arrangement)
};

/// The lights' bodies when they are not the bodies seen: the viewer's bodies are parts of these
/// (cut by the viewer's near plane: the eye among the bodies), which the lights see whole.
struct ShadowCasters {
  std::vector<const Polyhedron*> bodies;
  std::vector<int> body;               // per body seen: its caster
  std::vector<std::vector<int>> face;  // per body seen, per face: the caster's face it is part of (-1: none, in every light's shadow)
  Plane keep;                          // the part seen: keep.value <= 0 (the lit polygons are clipped to it)
};

struct ShadowOptions {
  unsigned threads = 0;
  const ShadowCasters* casters = nullptr;
};

/// Shadows of `lights` (at most 16) on the visible surfaces `seen` of `bodies` from `camera`
/// (made with SurfaceOptions::lift on). A point light that sees every body in front of it (a
/// plane through the light with the whole scene on one side) has one view; one among the bodies
/// six (light_cube.hpp); one on or inside a body gives std::invalid_argument.
Shadows shadows(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const VisibleSurfaces& seen,
                const std::vector<LightPlace>& lights, const ShadowOptions& options = {});

/// The light's view: orthographic toward a directional light, perspective from a point light
/// looking at the centre of the scene's box (or along an axis); std::invalid_argument for a
/// point light among the bodies, which no single view serves.
Camera light_camera(const std::vector<const Polyhedron*>& bodies, const LightPlace& light);

}  // namespace hlr
