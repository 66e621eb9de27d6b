// The user's own 3D lines hidden by the bodies (see polylines.hpp).
#include "io/pipeline/polylines.hpp"

#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/hlr/see_through_lines.hpp"
#include "io/pipeline/render_steps.hpp"

namespace hlr {

void add_polylines(RenderResult& r, const std::vector<Polyline3>& lines, const RenderOptions& o) {
  FaceRouteHooks hooks;
  for (const Polyline3& l : lines)
    for (std::size_t k = 0; k + 1 < l.size(); ++k)
      if (l[k] != l[k + 1]) hooks.extra_lines.push_back({-1, -1, l[k], l[k + 1], LineKind::Polyline});
  if (hooks.extra_lines.empty()) return;
  std::vector<const Polyhedron*> polys;
  for (const SceneBody* b : r.bodies) polys.push_back(&b->body);
  LineOptions lo = o.lines;
  lo.edges = EdgeSelection::Feature;
  lo.intersections = false;
  hooks.extra_only = true;
  LineDrawing d = face_occluders(polys, r.camera, lo, hooks);
  const std::vector<char> glass = see_through_bodies(r);
  bool any_glass = false;
  for (char g : glass) any_glass = any_glass || g;
  if (any_glass && o.through_lines) mark_see_through(d, polys, r.camera, lo, glass, hooks);
  r.drawing.segments.reserve(r.drawing.segments.size() + d.segments.size());
  for (Segment& s : d.segments)
    if (s.line == LineKind::Polyline) r.drawing.segments.push_back(std::move(s));
}

}  // namespace hlr
