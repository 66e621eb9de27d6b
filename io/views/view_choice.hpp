// The camera for a drawing, chosen in one place for `render`, `explain` and the library:
// explicit requests (command line or API) first, else the scene file's view, else the course
// notes' default (orthographic along +z). A perspective view without a target looks at the
// centre of the bounding box of all bodies.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "algorithms/model/camera.hpp"
#include "io/readers/scene.hpp"

namespace hlr {

/// Overrides of the scene's view; unset fields keep the scene's.
struct ViewRequest {
  std::optional<Vector3> direction;  // orthographic, from the scene toward the viewer
  std::optional<Point3> eye;         // perspective
  std::optional<Point3> target;      // perspective
  std::optional<Vector3> up;
  std::optional<FrameRequest> frame;  // perspective: the picture's frame
};

/// Parses "X,Y,Z" exactly; throws std::invalid_argument naming the option and the bad part.
Vector3 parse_vector3(const std::string& option, const std::string& text);

/// The view of `--view` (a standard view name, with `up_axis` "y" or "z", or a direction),
/// `--eye`, `--target` and `--up` (empty: not given), exactly; shared by render and raster.
ViewRequest parse_view_request(const std::string& view, const std::string& eye, const std::string& target, const std::string& up,
                               const std::string& up_axis);

/// The centre of the bounding box of the bodies' vertices, exactly.
Point3 bounding_box_centre(const std::vector<const Polyhedron*>& bodies);

/// The camera: `request` over `scene_view` (may be null) over the default. Throws
/// std::invalid_argument for a target without an eye, both a direction and an eye, or a
/// degenerate view (make_orthographic / make_perspective).
Camera choose_camera(const ViewRequest& request, const View* scene_view, const std::vector<const Polyhedron*>& bodies);

}  // namespace hlr
