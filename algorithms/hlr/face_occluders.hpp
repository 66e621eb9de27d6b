// Hidden lines of arbitrary meshes through per-face occluders (course notes
// "Visibility semantics", sections 26-28 for the inequalities). Every face is split
// into triangles; a triangle T facing the viewer and the sight rays behind it bound a convex
// region (its "sight prism": behind T's plane and inside the three planes through T's sides
// that contain the view direction, or the eye). Roberts' inequalities apply to it unchanged:
// each of the four planes gives alpha + beta·t > 0 along an edge P(t), so the part of the
// edge hidden by T is an interval with exact rational ends, and the hidden part of the edge
// is the union over the occluders.
//
// Semantics, exactly as the notes state them: a point is hidden when its sight ray enters
// the interior of a closed solid, or crosses an open surface transversally away from its
// boundary. The open prisms alone miss rays that leave a solid exactly through an edge (a
// back edge exactly behind the edge shared by two front faces, seen along a symmetry axis).
// So a prism side is closed (>= 0) when the sight ray just behind that edge is inside the
// solid: the edge's wedge contains the direction away from the viewer, decided exactly from
// the neighbouring face (convex edge: both faces front; reflex edge: always; flat: the
// neighbour is front). For open surfaces a side is closed when the neighbouring face lies
// on the other side of the edge in the projection (the ray crosses the surface there).
// Only front faces of a closed solid are occluders; every face of an open surface is one.
//
// Exact and fast: coordinates are scaled to integers (decimal text has a common
// denominator; bounds in kernel/exact_int.hpp); when they fit in 29 bits every value is an exact 128-bit integer and split
// parameters are compared by a double filter with an exact 256-bit fallback; otherwise the
// same code runs on GMP integers. A uniform grid over the projected occluders with depth
// pruning gives each edge only the occluders that may hide it. Edges run on all cores.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "algorithms/model/camera.hpp"
#include "algorithms/model/line_drawing.hpp"
#include "algorithms/solids/face_surfaces.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr {

/// The work of the per-face route that no view changes, kept for the next view of the same
/// bodies (a sheet, a batch of views; docs/design.md, "Views that share their work"): the
/// scaled coordinates, triangles, normals, topology, which bodies are solids (and turned),
/// the feature lines' classes and the intersection lines. Give one object to every
/// orthographic view of the same, unchanged bodies; a view of other bodies, or a perspective
/// one, neither reads nor keeps it. Empty until the first view fills it.
struct FaceRouteShare {
  std::vector<const Polyhedron*> bodies;  // the bodies the work belongs to
  int policy = -1;                        // the number policy (exact_int.hpp) it was done on
  std::shared_ptr<void> prepared;         // face_route::Prepared<policy>
};

/// What callers other than a plain drawing ask of the per-face route (see-through lines,
/// tiles, the raster's facing); a plain drawing leaves them empty.
struct FaceRouteHooks {
  /// Per body, 1 when its faces hide nothing (see-through; its own lines are still drawn).
  /// Empty: every body hides. see_through_lines.hpp uses it.
  std::vector<char> see_through;
  /// Only each face's facing and which closed solids hide their back faces
  /// (LineDrawing::facing, back_faces_unseen, notes), no lines: what the raster algorithms need.
  bool facing_only = false;
  /// When set, only the segments it returns true for get their visibility decided; each of the
  /// others gets one placeholder piece over [0, 1], hidden (tiles cut those away, a merge puts
  /// the tiles' pieces in: picture_tiles.hpp).
  std::function<bool(const Segment&)> decide;
  /// When set, a face triangle (its body and the body's vertex indices) hides only when this
  /// returns true: a tile leaves out the triangles that cannot reach it, a section's hatch pass
  /// the bodies that cannot hide its caps. Called from several
  /// threads at once: it must only read.
  std::function<bool(int body, const std::array<int, 3>& vertices)> may_occlude;
  /// Per body (empty: none), per face: which face of the user's model it is part of, after a
  /// section split faces (algorithms/sections/section_cut.hpp). An edge between two faces of one
  /// part lies inside that face: it is never drawn.
  std::vector<std::vector<int>> face_part;
  /// Per body (empty: none), per face: 1 for a face of a section's cap. An edge between a cap
  /// face and a face of another part is a cut line (LineKind::Cut), always drawn.
  std::vector<std::vector<char>> cap_face;
  /// Per body (empty or null: none), the surface of the model each face is part of
  /// (face_surfaces.hpp): an edge inside one surface is never a crease, an edge between two is
  /// sharp (always a crease), tangent (LineKind::Tangent) or goes by the crease angle.
  std::vector<const FaceSurfaces*> surfaces;
  /// Lines of the caller's own lying on a face of a body (hatch lines on a cap): their visibility
  /// is decided like an intersection line's (their face does not hide them), and they come
  /// after the intersection lines as segments of kind `kind`.
  struct ExtraLine {
    int body, face;
    Point3 a, b;
    LineKind kind;
  };
  std::vector<ExtraLine> extra_lines;
  /// Only the extra lines: no edge of the bodies is drawn (and no intersection line when
  /// LineOptions::intersections is off), so only the occluders near the extra lines are built.
  bool extra_only = false;
  /// The view-independent work shared with other views of the same bodies (null: none).
  std::shared_ptr<FaceRouteShare> share;
  /// The edges that their own faces hide wholly (between two back faces of a body that hides),
  /// each a segment with one hidden piece. Off (a drawing without hidden lines): in an
  /// orthographic view they are left out, their ends kept in LineDrawing::frame_ends, and the
  /// statistics count them as before; no other segment changes.
  bool back_edges = true;
};

/// Runs the per-face hidden-line computation. Bodies may be closed solids (closed, manifold,
/// consistently oriented; inside-out solids are turned) or open/other surfaces. Segments:
/// each body's drawn edges in order of their vertex pair, then intersection lines. `facing`
/// holds per face 1, 0 or -1. Throws BodyError for a body it cannot take (a non-planar or
/// self-intersecting face) or an eye inside a solid.
LineDrawing face_occluders(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineOptions& options = {},
                           const FaceRouteHooks& hooks = {});

}  // namespace hlr
