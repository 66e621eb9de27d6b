// The scene's faces as convex polygons of the picture, with their exact 3D corners (course
// notes section 31 for Weiler–Atherton's polygons, section 3.3 of the hidden-surface part for
// the priority list's): a convex face as itself (corners on a straight side of its picture
// dropped), any other face as the triangles of its exact triangulation; counter-clockwise in the
// picture. Faces seen edge-on and a closed solid's faces turned away from the viewer are left
// out. Shared by weiler_atherton.hpp and priority_list.hpp.
#pragma once

#include <vector>

#include "algorithms/model/line_drawing.hpp"
#include "algorithms/picture/picture_plane.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr {

struct ScenePolygon {
  int body = -1, face = -1;
  int piece = 0;                 // which convex piece of the face (0 for a convex face)
  std::vector<Point3> corners;   // exact, on the face
  std::vector<Exact2> pts;       // their picture points, counter-clockwise
  std::vector<int> verts;        // their vertex numbers in the body
};

/// The polygons of every body; `lines` gives the facing of each face and whether a body's
/// faces turned away are never seen (LineDrawing::back_faces_unseen).
std::vector<ScenePolygon> scene_polygons(const std::vector<const Polyhedron*>& bodies, const PicturePlane& pp,
                                         const LineDrawing& lines);

/// The convex picture pieces of face `f` of `p` whose vertices (in face order) have the exact
/// picture points `pic`: the face itself when its picture is convex (corners on a straight side
/// dropped), else the triangles of its exact triangulation with an area; each piece as
/// positions in the face, counter-clockwise in the picture. Empty when the face's picture has
/// no area (seen edge-on).
std::vector<std::vector<int>> face_pieces(const Polyhedron& p, int f, const std::vector<Exact2>& pic);

/// Twice the signed area of a picture polygon (positive counter-clockwise).
Rational picture_area2(const std::vector<Exact2>& p);

}  // namespace hlr
