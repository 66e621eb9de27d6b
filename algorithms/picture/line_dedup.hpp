// The exact clean-up of the 2D stage (course notes section 20, the projection):
// which drawn piece ends are the same point of the picture, which pieces are seen end-on (a
// point), and which pieces lie on one line of the picture and overlap (an axis view draws the
// front and the back edge of a box on one line; touching bodies share edges). Every such
// decision is exact: rational screen coordinates of the exact 3D piece ends (section 20's
// projection with unnormalised rational axes), compared exactly. Doubles only pick the
// candidates, with a margin far above their error (docs/design.md, "The 2D stage's exact
// clean-up"): a pair they skip cannot be equal or collinear.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "algorithms/picture/drawing_2d.hpp"

namespace hlr {

/// One drawn edge of the picture after the clean-up: from point `p` to point `q`
/// (CleanDrawing::points, one per exact point of the picture), drawing all or part of `source`.
struct CleanEdge {
  std::uint32_t p = 0, q = 0;
  PieceRef source;
  LineKind kind = LineKind::Edge;
  bool visible = true;
  bool through = false;  // seen through transparent faces (Piece::through)
  int body = -1;
};

struct CleanDrawing {
  std::vector<std::array<double, 2>> points;  // drawing coordinates of each exact point
  /// Per point, one piece end that is that point: 2k + 0 (t0) or 2k + 1 (t1) of Drawing2D::lines[k].
  std::vector<std::uint32_t> point_ends;
  std::vector<CleanEdge> edges;
  std::size_t pieces_in = 0;         // drawn pieces of the 2D stage
  std::size_t zero_length = 0;       // seen end-on: a point in the picture (not drawn)
  std::size_t overlap_groups = 0;    // sets of collinear overlapping pieces resolved
  std::size_t overlapped_pieces = 0; // pieces in those sets
  double duplicate_length = 0;       // picture length drawn more than once before, now once
  std::size_t exact_point_tests = 0, exact_line_tests = 0;
};

struct DedupOptions {
  /// Resolve overlaps (collinear pieces drawn once: visible over seen-through over hidden, then the stronger
  /// kind: silhouette, boundary, crease, intersection, edge). Off: only points and end-on.
  bool overlaps = true;
  unsigned threads = 0;  // 0: all cores
};

/// Identifies the exact points of the picture, drops pieces seen end-on, and draws every part
/// of the picture's lines once. Pieces with a pulled end (Polyline2D::pulled) are kept as they
/// are (their drawn ends are not exact projections).
CleanDrawing dedup_drawing(const Drawing2D& drawing, const LineDrawing& lines, const Camera& camera,
                           const DedupOptions& options = {});

/// dedup_drawing() without the exact line drawing: the ends' keys (end 2k is piece k's start,
/// 2k + 1 its end; equal keys, the same exact point: a mesh vertex, or a boundary between two
/// pieces of one segment, as dedup_drawing() keys them) and each end's exact 3D point on demand
/// (asked only for the pairs the double filters cannot separate). Drawing2D::sources name the
/// pieces (segment, and piece within it). The result is dedup_drawing()'s on the same pieces.
CleanDrawing dedup_by_keys(const Drawing2D& drawing, const std::vector<std::uint64_t>& end_keys,
                           const std::function<Point3(std::uint32_t)>& end_point, const Camera& camera,
                           const DedupOptions& options = {});

/// Priority of a line kind where pieces overlap: higher wins.
int kind_priority(LineKind k);

}  // namespace hlr
