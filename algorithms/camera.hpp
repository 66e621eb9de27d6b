// The viewer: orthographic along a direction v (from the scene toward the viewer) or
// perspective from an eye point, in exact form for visibility (the homogeneous viewpoint
// g = [v 0] or [E 1] of the course notes, section 28) and in doubles for drawing coordinates
// and conservative pre-filters. Never used for a visibility decision in doubles.
#pragma once

#include <array>
#include <optional>

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
};

/// Drawing coordinates: screen x to the right, y up, and a depth that grows away from the
/// viewer (orthographic: -P·v̂; perspective: distance along the viewing axis).
struct Projector {
  explicit Projector(const Camera& c);
  /// Screen (x, y) and depth of a point, in doubles. For perspective points at depth <= 0
  /// the screen coordinates are meaningless (the caller clips those first).
  std::array<double, 3> project(const Point3& p) const;
  std::array<double, 3> project(double x, double y, double z) const;

 private:
  bool perspective_;
  std::array<double, 3> right_, up_, forward_, eye_;
};

/// Builds a camera; throws std::invalid_argument for a zero view direction, an eye equal to
/// the target, or an up vector parallel to the viewing axis (then a default is chosen only
/// when up was not given explicitly: `up_given = false`).
Camera make_orthographic(const Vector3& direction, std::optional<Vector3> up = std::nullopt);
Camera make_perspective(const Point3& eye, const Point3& target, std::optional<Vector3> up = std::nullopt);

}  // namespace hlr
