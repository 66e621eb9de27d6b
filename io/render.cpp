// The render pipeline (see render.hpp).
#include "io/render.hpp"

#include "algorithms/convexity.hpp"
#include "algorithms/face_occluders.hpp"
#include "algorithms/mesh_repair.hpp"
#include "algorithms/parallel.hpp"
#include "algorithms/roberts.hpp"
#include "algorithms/roberts_pieces.hpp"

namespace hlr {

RenderBodyError::RenderBodyError(int body, std::string name, std::string source, std::string reason)
    : std::runtime_error(source + ": body '" + name + "' " + reason),
      body_(body),
      name_(std::move(name)),
      source_(std::move(source)),
      reason_(std::move(reason)) {}

namespace {

LineDrawing solve(const std::vector<const Polyhedron*>& polys, const Camera& camera, const RenderOptions& o) {
  if (o.method == RenderMethod::Faces) return face_occluders(polys, camera, o.lines);
  bool all_convex = true;
  for (const Polyhedron* p : polys) all_convex = all_convex && p->report().valid_solid() && convexity(*p).convex();
  if (all_convex) return roberts(polys, camera, o.lines);
  return roberts_pieces(polys, camera, o.lines);
}

// Degenerate but drawable views get a note, never a wrong picture.
void eye_plane_notes(const RenderResult& r, std::vector<std::string>& notes) {
  if (!r.camera.perspective) return;
  for (std::size_t i = 0; i < r.drawing.facing.size(); ++i) {
    std::size_t count = 0;
    for (std::size_t f = 0; f < r.drawing.facing[i].size(); ++f)
      if (r.drawing.facing[i][f] == 0 && ++count <= 3)
        notes.push_back("the eye lies in the plane of face " + std::to_string(f) + " of body '" + r.names[i].name +
                        "': that face is seen edge-on");
    if (count > 3) notes.push_back("... and " + std::to_string(count - 3) + " more faces of body '" + r.names[i].name + "'");
  }
}

}  // namespace

RenderResult render(std::vector<Scene> scenes, const RenderOptions& o) {
  if (!(o.near > 0)) throw std::invalid_argument("--near must be positive (a fraction of the distance from the eye to the target)");
  RenderResult r;
  auto owned = std::make_shared<std::vector<Scene>>(std::move(scenes));
  r.scenes = owned;
  std::vector<const Polyhedron*> polys;
  const View* scene_view = nullptr;
  std::vector<std::string> repairs;
  for (Scene& s : *owned) {
    if (!scene_view && is_scene_file(s.file)) scene_view = &s.view;
    for (SceneBody& b : s.bodies) {
      if (auto fixed = remove_zero_area_triangles(b.body)) {
        b.body = std::move(fixed->body);
        for (const std::string& n : fixed->notes) repairs.push_back(b.source + ": body '" + b.name + "' " + n);
      }
      r.bodies.push_back(&b);
      polys.push_back(&b.body);
      r.names.push_back({b.name, b.source});
    }
  }
  if (o.method == RenderMethod::Roberts)
    for (const Polyhedron* p : polys) p->report();  // Roberts' checks belong to loading
  r.camera = choose_camera(o.view, scene_view, polys);
  try {
    r.drawing = solve(polys, r.camera, o);
  } catch (const BodyError& e) {
    const SceneBody& b = *r.bodies[e.body()];
    throw RenderBodyError(e.body(), b.name, b.source, e.reason());
  }
  r.notes = std::move(repairs);
  for (const BodyNote& n : r.drawing.notes)
    r.notes.push_back(r.names[n.body].source + ": body '" + r.names[n.body].name + "' " + n.text);
  eye_plane_notes(r, r.notes);
  // Clipping: the near plane (perspective) and the clipping volume, exactly, in world space.
  std::optional<Plane> near;
  if (r.camera.perspective) near = near_plane(r.camera, o.near);
  if (near || o.clip)
    ParallelLoop(o.lines.threads).for_each(r.drawing.segments.size(), 1024, [&](std::size_t i) {
      Segment& s = r.drawing.segments[i];
      if (near) clip_near(s, *near);
      if (o.clip) clip_pieces(s, *o.clip);
    });
  return r;
}

RenderResult render_files(const std::vector<std::string>& inputs, const RenderOptions& o) {
  std::vector<Scene> scenes;
  for (const auto& in : inputs) scenes.push_back(is_scene_file(in) ? load_scene(in) : scene_from_mesh(in));
  return render(std::move(scenes), o);
}

}  // namespace hlr
