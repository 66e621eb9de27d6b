// A point light among the bodies (course notes section 40, the shadows' first pass, for a light
// that no single view sees: docs/design.md "Lights among the bodies"). Space around the light is
// split into the six pyramids of a cube centred on it (apex the light, each through one face of
// the cube, which no body meets). A segment from the light to a point of pyramid k leaves the
// cube through its face k, so view k needs only the bodies beyond the plane of that face, cut
// there exactly (section_cut.hpp): a perspective from the light with every part in front; its
// lit polygons count inside pyramid k only, and the six pieces of a face tile its lit part.
#pragma once

#include <vector>

#include "algorithms/model/camera.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr {

/// One of the six views: a perspective from the light along one axis, the bodies' parts beyond
/// the cube's face, and the pyramid its lit polygons are clipped to (value <= 0 inside).
struct LightCubeView {
  Camera camera;
  std::vector<Polyhedron> parts;
  std::vector<int> body;               // per part: the body it is part of
  std::vector<std::vector<int>> face;  // per part, per face: the body's face it is part of (-1: a cap)
  std::vector<Plane> pyramid;          // four planes through the light
};

/// The six views of a point light at `light` among `bodies`. The cube's half-size is the
/// largest power of two (at most the scene's size) whose cube no body meets; a light on or
/// inside a body gives std::invalid_argument (it lights nothing there, or its cube never clears).
std::vector<LightCubeView> light_cube(const std::vector<const Polyhedron*>& bodies, const Point3& light);

}  // namespace hlr
