// The default method (docs/design.md, "Per-face occluders"): hidden lines of any mesh by exact
// per-face occluders, with the lines seen through glass as their own class; its polygons are
// the exact visible surfaces (course notes sections 25, 31), cut by shadows (section 40) or
// into transparency regions (section 41).
#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/hlr/see_through_lines.hpp"
#include "io/pipeline/render_methods.hpp"
#include "io/pipeline/render_steps.hpp"

namespace hlr {

void faces_lines(LineStep& s) {
  s.r.drawing = face_occluders(s.polys, s.r.camera, s.o.lines, s.hooks);
  if (s.o.through_lines && !s.o.segments_only)
    s.r.through_pieces = mark_see_through(s.r.drawing, s.polys, s.r.camera, s.o.lines, see_through_bodies(s.r), s.hooks);
}

void faces_polygons(PolygonStep& s) {
  s.r.surfaces = visible_surfaces(s.polys, s.r.camera, s.all, s.so);
  if (s.o.shadows) solve_shadows(s.r, s.polys, s.scenes, s.o, s.all);
  if (!s.o.shadows) solve_transparency(s.r, s.polys, s.all);
}

}  // namespace hlr
