// The course's Weiler–Atherton visible-surface algorithm (course notes section 31) as the
// polygons of a render; the lines are the per-face route's.
#include "algorithms/clip/weiler_atherton.hpp"

#include "io/pipeline/render_methods.hpp"

namespace hlr {

void weiler_atherton_polygons(PolygonStep& s) {
  WeilerAthertonResult wa = weiler_atherton(s.polys, s.r.camera, s.all);
  std::vector<SurfacePiece> pieces;
  for (WaPolygon& p : wa.visible) pieces.push_back({p.body, p.face, std::move(p.pts)});
  s.r.surfaces = surfaces_from_pieces(pieces, s.polys, s.r.camera, s.so);
  s.r.surfaces->stats.weiler_atherton = true;
  s.r.surfaces->stats.wa_clips = wa.clips;
  s.r.surfaces->stats.wa_splits = wa.splits;
  s.r.surfaces->stats.wa_recursions = wa.recursions;
  s.r.surfaces->stats.wa_cycles = wa.cycles;
}

}  // namespace hlr
