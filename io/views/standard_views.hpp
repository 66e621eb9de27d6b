// Named views of technical drawing: front, back, top, bottom, left, right, and the
// pictorial iso and dimetric, as exact view directions (from the scene toward the viewer)
// with their up vectors, for y up (the default, as the course's default view 0,0,1 with up y)
// or z up (CAD and architecture).
#pragma once

#include <optional>
#include <string>

#include "kernel/geometry.hpp"

namespace hlr {

struct StandardView {
  Vector3 direction, up;
};

/// The view called `name` (case-insensitive), or nothing when it is not a name.
/// Dimetric: the ISO 5456-3 dimetric with the depth axis at half scale, direction (1, 1, 8/3)
/// for y up (foreshortening 0.94 : 0.94 : 0.47).
std::optional<StandardView> standard_view(const std::string& name, bool z_up);

/// "front, back, top, bottom, left, right, iso, dimetric".
std::string standard_view_names();

}  // namespace hlr
