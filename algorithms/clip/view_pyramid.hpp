// The picture frame of a perspective view and its viewing pyramid (course notes sections 21-22:
// clipping against the viewing pyramid): a field of view, a frame at the target's distance or
// a focal length on a sensor gives the picture's half-width and half-height; the pyramid is four
// exact planes through the eye whose slopes are those numbers rounded to rationals once, so the
// drawing is clipped exactly (Cyrus-Beck, clip_near per plane) to the frame the page shows.
#pragma once

#include <array>
#include <optional>

#include "algorithms/model/camera.hpp"
#include "kernel/predicates_2d.hpp"

namespace hlr {

/// How the frame of a perspective picture is asked for (at most one of fov/fov_v, frame and
/// focal; docs/usage.md "Camera").
struct FrameRequest {
  std::optional<double> fov, fov_v;              ///< degrees: the horizontal, the vertical field of view
  std::optional<std::array<Rational, 2>> frame;  ///< width and height of the frame at the target's distance
  std::optional<double> focal;                   ///< the lens's focal length in mm, on `sensor`
  std::array<double, 2> sensor{36, 24};          ///< the sensor's width and height in mm (full frame)
  std::optional<double> aspect;                  ///< width / height when one angle is given (default: the sensor's, 3:2)
};

/// Checks the numbers and the combination; throws std::invalid_argument naming the option.
void check_frame_request(const FrameRequest& f);

/// The picture's half-width and half-height at unit distance from the eye (the tangents of the
/// half angles; drawing coordinates of a perspective view).
std::array<double, 2> frame_tangents(const FrameRequest& f, const Camera& camera);

/// The viewing pyramid of a frame: `sides` (right, left, top, bottom) are planes through the eye,
/// positive inside; `rect` is the frame they cut in drawing coordinates (x0, y0, x1, y1), the
/// tangents as the planes' rational slopes realise them.
struct ViewPyramid {
  std::array<Plane, 4> sides;
  std::array<double, 4> rect{0, 0, 0, 0};
  /// The same frame in exact picture coordinates (PicturePlane::project): |X| <= half_x, |Y| <= half_y.
  Rational half_x, half_y;
};

/// The part of a picture segment a-b (exact picture coordinates) inside the frame, or none.
std::optional<std::array<Exact2, 2>> clip_to_frame(const ViewPyramid& p, const Exact2& a, const Exact2& b);

/// The pyramid of a perspective camera for `tangents` (frame_tangents()).
ViewPyramid view_pyramid(const Camera& camera, const std::array<double, 2>& tangents);

}  // namespace hlr
