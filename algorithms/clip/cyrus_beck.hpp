// 3D Cyrus-Beck clipping of a segment against any convex polyhedron (course notes
// section 22), exact. Inner normals come from the clipper's sign-corrected body matrix; for
// each face i, with W = P1 - f_i (f_i on the face) and D = P2 - P1, the segment's points
// P(t) = P1 + t·D satisfy W·n + t·D·n >= 0 inside. D·n > 0 gives a lower limit
// t = -(W·n)/(D·n), D·n < 0 an upper limit, D·n = 0 a segment parallel to the face: outside
// (rejected) when W·n < 0, otherwise no constraint. The result is [t_lower, t_upper] in
// [0, 1], a single point when they are equal, or empty.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "algorithms/model/camera.hpp"
#include "algorithms/model/line_drawing.hpp"
#include "kernel/body_matrix.hpp"
#include "kernel/int128.hpp"

namespace hlr {

/// A convex clipper: its polyhedron and inward face planes (value >= 0 inside).
struct ConvexClipper {
  std::string name;
  Polyhedron body;
  BodyMatrix planes;  // sign-corrected: column j is face j's plane, positive inside
  std::vector<std::array<Int128, 4>> int_planes;  // the same in 128-bit integers, when they fit
};

/// Builds a clipper; throws std::invalid_argument naming the check or the face that shows the
/// body is not convex (or not a closed solid).
ConvexClipper make_clipper(Polyhedron body, std::string name = "clipper");

/// The box [xmin, xmax] x [ymin, ymax] x [zmin, zmax] (min < max each).
ConvexClipper box_clipper(const Rational& xmin, const Rational& xmax, const Rational& ymin, const Rational& ymax,
                          const Rational& zmin, const Rational& zmax);

/// The course notes' truncated viewing pyramid: centre of projection (0, 0, zcp) on the z axis,
/// the window [xl, xr] x [yb, yt] taken at the far plane z = zfar, side planes through the
/// centre, near plane z = znear; zcp > znear > zfar, xl < xr, yb < yt.
ConvexClipper frustum_clipper(const Rational& xl, const Rational& xr, const Rational& yb, const Rational& yt,
                              const Rational& znear, const Rational& zfar, const Rational& zcp);

struct CyrusBeckRow {  // one face of the notes' table
  int face;
  Vector3 n;           // inner normal
  Rational wn, dn;     // W·n and D·n
  std::optional<Rational> t;  // -(W·n)/(D·n) when D·n != 0
  enum class Kind { Lower, Upper, ParallelInside, ParallelOutside } kind;
};

struct CyrusBeckResult {
  enum class Status { Visible, Point, Outside } status = Status::Outside;
  Rational t_lower = 0, t_upper = 1;
  bool degenerate_point = false;  // P1 == P2: then `point_class` says where it is
  enum class PointClass { Inside, OnBoundary, Outside } point_class = PointClass::Outside;
  std::vector<CyrusBeckRow> table;
  bool visible() const { return status == Status::Visible; }
};

/// Clips P1P2 exactly. With `table` the notes' per-face table is filled in too; without it the
/// common case runs in 128-bit integers (exact; rationals when numbers do not fit).
CyrusBeckResult cyrus_beck(const ConvexClipper& clipper, const Point3& p1, const Point3& p2, bool table = true);

/// Clips the pieces of a drawn segment to the clipper: pieces (or parts) outside it are marked
/// clipped (never drawn); the pieces still cover [0, 1] in order.
void clip_pieces(Segment& segment, const ConvexClipper& clipper);

/// Marks the parts of the segment nearer the eye than the near plane as clipped: the near
/// plane is at distance near_fraction·|target - eye| from the eye along the viewing axis,
/// i.e. (P - eye)·(target - eye) >= near_fraction·|target - eye|^2 is kept (exact).
void clip_near(Segment& segment, const Camera& camera, const Rational& near_fraction);

/// The near plane of clip_near as a plane, positive on the kept side (perspective cameras).
Plane near_plane(const Camera& camera, const Rational& near_fraction);
/// clip_near with the plane computed once (near_plane); the sides of the two ends are decided
/// by the filtered exact predicate, the crossing parameter exactly.
void clip_near(Segment& segment, const Plane& near);

}  // namespace hlr
