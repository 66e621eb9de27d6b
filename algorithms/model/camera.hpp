// The viewer: orthographic along a direction v (from the scene toward the viewer) or
// perspective from an eye point, in exact form for visibility (the homogeneous viewpoint
// g = [v 0] or [E 1] of the course notes, section 28) and in doubles for drawing coordinates
// and conservative pre-filters. Never used for a visibility decision in doubles.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "kernel/point_store.hpp"
#include "kernel/predicates.hpp"
#include "kernel/transform.hpp"

namespace hlr {

struct Camera {
  bool perspective = false;
  Vector3 direction{Rational(0), Rational(0), Rational(1)};  // orthographic, toward the viewer
  Point3 eye;                                                // perspective
  Point3 target;                                             // perspective: looked-at point
  Vector3 up{Rational(0), Rational(1), Rational(0)};

  /// The homogeneous viewpoint g: [v 0] (a point at infinity) or [E 1].
  RowVector4 viewpoint() const;
  /// Exact depth sign along the viewing axis for perspective: sign of (P - E)·(target - E);
  /// positive in front of the eye. Orthographic cameras see everything: Positive.
  Sign in_front(const Point3& p) const;
  /// (P - E)·(target - E), exactly (perspective only).
  Rational depth(const Point3& p) const;
  /// Perspective, `a` strictly in front of the eye and `b` not: the exact signs of the screen x
  /// and y (Projector's axes) of the point where segment ab meets the plane through the eye,
  /// taken from the eye. Where such a sign is positive the projection of the part of ab in
  /// front of the eye is unbounded toward +x (or +y); where no crossing point of a convex
  /// polygon has a positive sign, its projection is bounded on that side by its front vertices
  /// (docs/design.md, "Occluders that reach behind the eye").
  std::array<int, 2> eye_plane_signs(const Point3& a, const Point3& b) const;
};

/// Where drawing doubles are taken: the identity for ordinary scenes, else the exact similarity
/// p -> (p - centre)·scale that brings the scene to unit size (coordinates like 1e300 or
/// 1e-400, or a tiny scene far from the origin, which doubles cannot hold). A picture does not
/// change under a similarity, so the drawing is the same; visibility never uses doubles.
struct DrawingFrame {
  bool identity = true;
  Point3 centre;
  Rational scale = 1;
  /// Doubles of the point in this frame (identity: the midpoint of its certified bounds).
  std::array<double, 3> to_frame(const Point3& p) const;
  /// The same for point i of a store, from its bounds (identity: no exact point made).
  std::array<double, 3> to_frame(const PointStore& s, std::size_t i) const;
};

/// The points of a vertex store whose mark is set (every point when `marks` is null).
struct StorePoints {
  const PointStore* store = nullptr;
  const std::vector<char>* marks = nullptr;
};

/// The frame for `n` points (point(i), i < n): identity unless their doubles would lose them
/// (largest coordinate above 2^100, extent below 2^-100 or below 2^-30 of the largest
/// coordinate; the screen boxes of the filters are floats); then the exact bounding box's centre and 1 / its largest side.
/// point() is called from several threads at once.
DrawingFrame drawing_frame(std::size_t n, const std::function<const Point3&(std::size_t)>& point);
/// The same for points of vertex stores and `n` more points: the stores' exact points are made
/// only when the frame is not the identity.
DrawingFrame drawing_frame(const std::vector<StorePoints>& stores, std::size_t n = 0, const std::function<const Point3&(std::size_t)>& point = {});

/// Drawing coordinates: screen x to the right, y up, and a depth that grows away from the
/// viewer (orthographic: -P·v̂; perspective: distance along the viewing axis). Directions are
/// scaled exactly by a power of two before they become doubles, so any exact input works.
struct Projector {
  explicit Projector(const Camera& c, DrawingFrame frame = {});
  /// Screen (x, y) and depth of a point, in doubles. For perspective points at depth <= 0
  /// the screen coordinates are meaningless (the caller clips those first).
  std::array<double, 3> project(const Point3& p) const;
  /// The same for point i of a store (its exact point not made for the identity frame).
  std::array<double, 3> project(const PointStore& s, std::size_t i) const;
  /// The same for a point given in frame coordinates (DrawingFrame::to_frame).
  std::array<double, 3> project(double x, double y, double z) const;
  const DrawingFrame& frame() const { return frame_; }
  /// The screen's right and up axes and the viewing axis (unit vectors in doubles): what a
  /// caller needs to place its own lines on the page (hatching).
  std::array<std::array<double, 3>, 3> axes() const { return {right_, up_, forward_}; }

 private:
  bool perspective_;
  DrawingFrame frame_;
  std::array<double, 3> right_, up_, forward_, eye_;
};

/// Builds a camera; throws std::invalid_argument for a zero view direction, an eye equal to
/// the target, or an up vector parallel to the viewing axis (then a default is chosen only
/// when up was not given explicitly: `up_given = false`).
Camera make_orthographic(const Vector3& direction, std::optional<Vector3> up = std::nullopt);
Camera make_perspective(const Point3& eye, const Point3& target, std::optional<Vector3> up = std::nullopt);

}  // namespace hlr
