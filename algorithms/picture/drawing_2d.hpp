// The 2D stage (course notes section 20: projection onto the picture plane): the exact line
// drawing projected into drawing coordinates, as its own value. Each polyline keeps its class
// (line kind, visible or hidden, body) and a link back to the exact 3D pieces it comes from,
// so later stages (chaining into strokes, removing duplicates, pen order, page layout) work
// here and writers (SVG now, PDF/DXF later) only format. Coordinates are doubles: drawing
// only; every visibility decision was taken exactly before.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/model/camera.hpp"
#include "algorithms/model/line_drawing.hpp"

namespace hlr {

/// Which exact piece a polyline edge comes from: segments[segment].pieces[piece].
struct PieceRef {
  int segment = -1, piece = -1;
};

/// A polyline: points [first, first + count) of Drawing2D::points, its edges coming from the
/// pieces [first_edge, first_edge + count - 1) of Drawing2D::sources. Flat storage: a million
/// pieces cost no allocation each.
struct Polyline2D {
  std::uint32_t first = 0, count = 0, first_edge = 0;
  LineKind kind = LineKind::Edge;
  bool visible = true;
  bool through = false;       // hidden only by see-through faces (Piece::through)
  bool intersection = false;  // an intersection line of bodies `body` and `body2`
  bool pulled = false;        // perspective: an end pulled to the drawing's near depth (not the exact projection)
  int body = -1, body2 = -1;
};

/// A text placed at a point of the drawing (vertex numbers on the exam page's drawing).
struct Label2D {
  std::array<double, 2> at;
  std::string text;
};

struct Drawing2D {
  std::vector<Polyline2D> lines;               // in order of segment, then piece
  std::vector<Label2D> labels;                 // vertex numbers when asked (Project2DOptions)
  std::vector<std::array<double, 2>> points;   // x to the right, y up, scene units (frame)
  std::vector<PieceRef> sources;               // per polyline edge
  const std::array<double, 2>& point(const Polyline2D& l, std::uint32_t k) const { return points[l.first + k]; }
};

struct Project2DOptions {
  bool hidden = true;  // include hidden pieces
  bool through = true; // include pieces seen through transparent faces (Piece::through)
  /// Label every vertex that ends a drawn edge with its number (plus `label_base`: 1 for the
  /// notes' numbering from 1), in front of the eye.
  bool vertex_labels = false;
  int label_base = 0;
};

/// Projects every drawn piece (not behind the eye, not clipped; hidden ones if asked) to a
/// two-point polyline. Perspective: piece ends nearer than 1e-4 of the farthest segment end's
/// depth are pulled to that depth (drawing only).
Drawing2D project_drawing(const LineDrawing& drawing, const Camera& camera, const Project2DOptions& options = {});

/// The projector of project_drawing() for `drawing` (its frame chosen from the segments' ends):
/// anything drawn with the lines (filled surfaces) goes through it to stay on them.
Projector drawing_projector(const LineDrawing& drawing, const Camera& camera);

/// Bounds [x0, x1] x [y0, y1] of the polylines; false when there are none.
bool drawing_bounds(const Drawing2D& d, double& x0, double& y0, double& x1, double& y1);

}  // namespace hlr
