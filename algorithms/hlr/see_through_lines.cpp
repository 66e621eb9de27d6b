// Lines seen through transparent faces (course notes section 41): see see_through_lines.hpp.
#include "algorithms/hlr/see_through_lines.hpp"

#include <algorithm>
#include <stdexcept>

#include "algorithms/hlr/face_occluders.hpp"

namespace hlr {

std::vector<Piece> refine_through(const PieceList& full, const PieceList& opaque) {
  std::vector<Piece> out;
  std::size_t j = 0;
  for (const Piece& p : full) {
    if (p.visible || p.behind_eye || p.clipped) {
      out.push_back(p);
      continue;
    }
    Rational at = p.t0;
    while (at < p.t1) {
      while (j < opaque.size() && opaque[j].t1 <= at) ++j;
      if (j == opaque.size()) throw std::logic_error("refine_through: the opaque pieces do not cover [0, 1]");
      Piece q = p;
      q.t0 = at;
      q.t1 = std::min(p.t1, opaque[j].t1);
      q.through = opaque[j].visible;
      if (!out.empty() && out.back().same_kind(q) && out.back().t1 == q.t0)
        out.back().t1 = q.t1;
      else
        out.push_back(q);
      at = q.t1;
    }
  }
  return out;
}

std::size_t mark_see_through(LineDrawing& drawing, const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineOptions& options,
                             const std::vector<char>& see_through, const FaceRouteHooks& hooks) {
  if (std::none_of(see_through.begin(), see_through.end(), [](char c) { return c != 0; })) return 0;
  FaceRouteHooks h = hooks;
  h.see_through = see_through;
  LineDrawing opaque = face_occluders(bodies, camera, options, h);
  if (opaque.segments.size() != drawing.segments.size())
    throw std::logic_error("mark_see_through: the two drawings have different segments");
  std::size_t marked = 0;
  for (std::size_t k = 0; k < drawing.segments.size(); ++k) {
    Segment& s = drawing.segments[k];
    const Segment& t = opaque.segments[k];
    if (s.kind != t.kind || s.body != t.body || s.body2 != t.body2 || s.v0 != t.v0 || s.v1 != t.v1 ||
        (s.kind == Segment::Kind::Intersection && (s.from() != t.from() || s.to() != t.to())))
      throw std::logic_error("mark_see_through: the two drawings have different segments");
    s.pieces = refine_through(s.pieces, t.pieces);
    for (const Piece& p : s.pieces) marked += p.through;
  }
  return marked;
}

}  // namespace hlr
