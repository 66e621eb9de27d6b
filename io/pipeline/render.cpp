// The render pipeline (see render.hpp).
#include "io/pipeline/render.hpp"

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <map>

#include "algorithms/clip/weiler_atherton.hpp"
#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/hlr/roberts.hpp"
#include "algorithms/hlr/roberts_pieces.hpp"
#include "algorithms/hlr/see_through_lines.hpp"
#include "algorithms/picture/drawing_2d.hpp"
#include "algorithms/picture/picture_tiles.hpp"
#include "algorithms/solids/convexity.hpp"
#include "algorithms/solids/mesh_repair.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/surfaces/priority_list.hpp"
#include "algorithms/surfaces/shadows.hpp"
#include "algorithms/surfaces/transparency.hpp"
#include "io/models/model_input.hpp"
#include "io/pipeline/eye_cut.hpp"
#include "io/pipeline/polylines.hpp"
#include "io/pipeline/render_methods.hpp"
#include "io/pipeline/render_steps.hpp"
#include "io/pipeline/section.hpp"
#include "kernel/plane_int128.hpp"

namespace hlr {

RenderBodyError::RenderBodyError(int body, std::string name, std::string source, std::string reason)
    : std::runtime_error(source + ": body '" + name + "' " + reason),
      body_(body),
      name_(std::move(name)),
      source_(std::move(source)),
      reason_(std::move(reason)) {}

namespace {

// Degenerate but drawable views get a note, never a wrong picture.
// The lines a model's surfaces decide (face_surfaces.hpp) for every route: inside one surface no
// crease, between two sharp or tangent; then tangent edges as --tangent-edges says. The per-face
// route decided them already (FaceRouteHooks::surfaces); the others get the same lines here,
// except a sharp edge under the crease angle they did not make.
void surface_lines(LineDrawing& d, const std::vector<const SceneBody*>& bodies, const RenderOptions& o) {
  const bool classify = o.lines.edges == EdgeSelection::Feature || o.lines.classify_all;
  std::size_t kept = 0;  // kept in place, in order (no second array of a million segments)
  for (Segment& s : d.segments) {
    const bool edge = s.kind == Segment::Kind::Edge && s.body >= 0 && static_cast<std::size_t>(s.body) < bodies.size();
    if (classify && edge && (s.line == LineKind::Crease || s.line == LineKind::Edge || s.line == LineKind::Tangent)) {
      switch (surface_edge(bodies[s.body]->surfaces, s.face0, s.face1)) {
        case SurfaceEdge::Inside:
          s.line = LineKind::Edge;
          break;
        case SurfaceEdge::Sharp:
          s.line = LineKind::Crease;
          break;
        case SurfaceEdge::Tangent:
          s.line = LineKind::Tangent;
          break;
        case SurfaceEdge::ByAngle:
          break;
      }
      if (s.line == LineKind::Edge && o.lines.edges == EdgeSelection::Feature) continue;
    }
    if (s.line == LineKind::Tangent) {
      if (o.tangent_edges == TangentEdges::None) continue;
      if (o.tangent_edges == TangentEdges::Visible) s.line = LineKind::Crease;
    }
    if (&s != &d.segments[kept]) d.segments[kept] = std::move(s);
    ++kept;
  }
  d.segments.erase(d.segments.begin() + static_cast<std::ptrdiff_t>(kept), d.segments.end());
}

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

// The scene's lights: `lighting:`, else `light:` as one directional light, else the default.
Lighting scene_lighting(const std::vector<Scene>& scenes, const Camera& cam) {
  for (const Scene& s : scenes)
    if (s.lighting) return *s.lighting;
  for (const Scene& s : scenes)
    if (s.light) {
      Lighting l;
      Light d;
      d.direction = unit(d3(*s.light));
      d.exact = true;
      d.exact_direction = {s.light->x(), s.light->y(), s.light->z()};
      l.lights.push_back(d);
      return l;
    }
  return camera_lighting(cam);
}

// The flat colour of face f of body b under `light`, for the side the viewer sees (back: the
// back side); `n`: the face's unit normal.
Rgb face_colour(const RenderResult& r, std::size_t b, std::size_t f, const Lighting& light, bool back, std::array<double, 3> n,
                const ViewDoubles& vd) {
  Material m;
  m.colour = palette_colour(static_cast<int>(b));
  if (r.bodies[b]->material) m = *r.bodies[b]->material;
  return flat_face_colour(r.bodies[b]->body, f, m, light, back, n, r.camera.perspective, vd);
}

Rgb face_colour(const RenderResult& r, std::size_t b, std::size_t f, const Lighting& light, bool back, const ViewDoubles& vd) {
  // The plane from the stored ones when they are made, else made here for this face alone
  // (thread-safe; a plain fill of a large mesh then keeps no plane per face).
  const Polyhedron& p = r.bodies[b]->body;
  std::array<Bounds, 3> n;
  PlaneInt128 small;
  if (const Plane* stored = p.plane_if_made(f)) {
    n = {stored->approx(0), stored->approx(1), stored->approx(2)};
  } else if (face_plane_int128(p, f, small)) {
    n = normal_bounds(small);
  } else {
    const Plane h = p.face_plane(f);
    n = {h.approx(0), h.approx(1), h.approx(2)};
  }
  return face_colour(r, b, f, light, back, unit({mid(n[0]), mid(n[1]), mid(n[2])}), vd);
}

// Flat colour of every face, for the side the viewer sees (facing: 1 front, -1 back, 0 edge-on).
void shade_faces(RenderResult& r, const std::vector<Scene>& scenes, const LineDrawing& all) {
  const Lighting light = scene_lighting(scenes, r.camera);
  r.face_colours.resize(r.bodies.size());
  const ViewDoubles vd(r.camera);
  for (std::size_t b = 0; b < r.bodies.size(); ++b) {
    const Polyhedron& p = r.bodies[b]->body;
    r.face_colours[b].resize(p.num_faces());
    ParallelLoop().for_each(p.num_faces(), 256, [&](std::size_t f) {
      bool back = b < all.facing.size() && f < all.facing[b].size() && all.facing[b][f] < 0;
      r.face_colours[b][f] = face_colour(r, b, f, light, back, vd);
    });
  }
}

// Where each light is, exactly: the scene file's numbers, else the doubles' binary values.
std::vector<LightPlace> light_places(const Lighting& l) {
  std::vector<LightPlace> out;
  for (const Light& x : l.lights) {
    LightPlace p;
    p.directional = x.type == Light::Type::Directional;
    std::array<Rational, 3> d, q;
    for (int k = 0; k < 3; ++k) {
      d[k] = x.exact ? x.exact_direction[k] : rational_from_double(x.direction[k]);
      q[k] = x.exact ? x.exact_position[k] : rational_from_double(x.position[k]);
    }
    p.toward = Vector3(d[0], d[1], d[2]);
    p.position = Point3(q[0], q[1], q[2]);
    out.push_back(p);
  }
  return out;
}

// The material of body b (its own, else the palette's default).
Material material_of(const RenderResult& r, std::size_t b) {
  Material m;
  m.colour = palette_colour(static_cast<int>(b));
  if (r.bodies[b]->material) m = *r.bodies[b]->material;
  return m;
}

// Per body: its material lets light through (transparency > 0): it hides no line.
}  // namespace

std::vector<char> see_through_bodies(const RenderResult& r) {
  std::vector<char> see(r.bodies.size(), 0);
  for (std::size_t b = 0; b < r.bodies.size(); ++b) see[b] = material_of(r, b).transparency > 0;
  return see;
}

// Transparency: the regions of equal face lists, each composited back to front,
// I = (1 − τ)·I_face + τ·I_behind, from white paper behind everything.
void solve_transparency(RenderResult& r, const std::vector<const Polyhedron*>& polys, const LineDrawing& all) {
  const std::vector<char> see = see_through_bodies(r);
  if (std::find(see.begin(), see.end(), 1) == see.end()) return;
  r.transparent = transparent_regions(polys, r.camera, all, see);
  const std::array<double, 3> eye = d3(r.camera.eye), view = unit(d3(r.camera.direction));
  for (const TransparentRegion& reg : r.transparent->regions) {
    Rgb c{1, 1, 1};
    for (auto [b, f] : reg.faces) {
      const Polyhedron& p = *polys[b];
      const Plane& h = p.planes()[f];
      std::array<double, 3> n = unit({mid(h.approx(0)), mid(h.approx(1)), mid(h.approx(2))}), ctr{0, 0, 0};
      for (int v : p.faces()[f]) {
        auto q = d3(p.vertices()[v]);
        for (int k = 0; k < 3; ++k) ctr[k] += q[k] / static_cast<double>(p.faces()[f].size());
      }
      std::array<double, 3> to_viewer = r.camera.perspective ? unit({eye[0] - ctr[0], eye[1] - ctr[1], eye[2] - ctr[2]}) : view;
      const double tau = see[b] ? transparency_at(material_of(r, b), std::fabs(n[0] * to_viewer[0] + n[1] * to_viewer[1] + n[2] * to_viewer[2])) : 0;
      const Rgb& own = r.face_colours[b][f];
      for (int k = 0; k < 3; ++k) c[k] = (1 - tau) * own[k] + tau * c[k];
    }
    r.transparent_colours.push_back(c);
  }
}

// Shadows: each light's lit parts laid over the visible surfaces; every region
// shaded by the lights that reach it (the ambient term alone where none does).
void solve_shadows(RenderResult& r, const std::vector<const Polyhedron*>& polys, const std::vector<Scene>& scenes, const RenderOptions& o,
                   const LineDrawing& all) {
  const Lighting light = scene_lighting(scenes, r.camera);
  ShadowOptions so;
  so.threads = o.lines.threads;
  if (r.whole) {
    so.casters = &r.whole->casters;
    for (const Polyhedron* p : r.whole->casters.bodies) plane_all_faces(*p, o.lines.threads);
  }
  r.shadows = shadows(polys, r.camera, *r.surfaces, light_places(light), so);
  r.shadow_colours.resize(r.shadows->faces.size());
  const ViewDoubles vd(r.camera);
  ParallelLoop(o.lines.threads).for_each(r.shadows->faces.size(), 4, [&](std::size_t k) {
    const ShadowFace& f = r.shadows->faces[k];
    bool back = static_cast<std::size_t>(f.body) < all.facing.size() && all.facing[f.body][f.face] < 0;
    for (const ShadowRegion& reg : f.regions) {
      Lighting some = light;
      some.lights.clear();
      for (std::size_t i = 0; i < light.lights.size(); ++i)
        if ((reg.lights >> i) & 1u) some.lights.push_back(light.lights[i]);
      r.shadow_colours[k].push_back(face_colour(r, f.body, f.face, some, back, vd));
    }
  });
}

namespace {

// Surfaces: every edge for the cells, then the selected lines of the same solution drawn.
void solve_surfaces(RenderResult& r, const std::vector<const Polyhedron*>& polys, const std::vector<Scene>& scenes,
                    const RenderOptions& o) {
  const RenderMethodEntry& m = method_entry(o.method);
  if (!m.makes_polygons())
    throw std::invalid_argument("--surfaces works with --method " + method_list([](const RenderMethodEntry& e) { return e.makes_polygons(); }));
  if (o.clip) throw std::invalid_argument("--surfaces does not take --clip (a clipped face is not a surface of the scene)");
  if (o.shadows && !(m.flags & kTakesShadows))
    throw std::invalid_argument("--shadows works with --method " +
                                method_list([](const RenderMethodEntry& e) { return (e.flags & kTakesShadows) != 0; }));
  if (r.camera.perspective)
    for (std::size_t b = 0; b < polys.size(); ++b)
      for (const Point3& v : polys[b]->vertices())
        if (r.camera.in_front(v) != Sign::Positive)
          throw std::invalid_argument(r.names[b].source + ": body '" + r.names[b].name +
                                      "' reaches the eye's plane or behind it: filled faces (--surfaces, --method weiler-atherton or priority) need every body in front of the eye");
  LineOptions all = o.lines;
  all.edges = EdgeSelection::All;
  all.classify_all = true;
  LineDrawing d = face_occluders(polys, r.camera, all);
  if (r.camera.perspective) {
    Plane near = near_plane(r.camera, o.near);
    for (Segment& s : d.segments) clip_near(s, near);
  }
  if (o.through_lines) r.through_pieces = mark_see_through(d, polys, r.camera, all, see_through_bodies(r));
  SurfaceOptions so;
  so.threads = o.lines.threads;
  so.lift = o.surface_corners;
  so.faces = o.surface_faces || o.shadows;  // the shadows are cut from the regions of each face
  // Every face's plane made once on all cores, before the stages that read them on all cores
  // (per-face regions, tone hatching, shadows, the colours seen through glass, the course's
  // methods); a plain fill needs none: its shading and probes make each plane they need
  // alone, and no plane per face is kept (a quarter of a gigabyte at a million faces).
  const std::vector<char> see = see_through_bodies(r);
  const bool plain_fill = !so.faces && !o.shadows && std::find(see.begin(), see.end(), 1) == see.end() && o.method == RenderMethod::Faces;
  if (!plain_fill)
    for (const Polyhedron* p : polys) plane_all_faces(*p, o.lines.threads);
  shade_faces(r, scenes, d);
  so.exact_groups = false;  // the groups only feed the fills (add_surface_fills)
  std::map<std::array<int, 3>, int> group_of;
  if (o.surface_groups) so.face_group.resize(r.bodies.size());
  for (std::size_t b = 0; b < r.bodies.size() && o.surface_groups; ++b)
    for (const Rgb& c : r.face_colours[b]) {
      auto [it, fresh] = group_of.emplace(rgb8(c), static_cast<int>(r.group_colours.size()));
      if (fresh) r.group_colours.push_back(c);
      so.face_group[b].push_back(it->second);
    }
  PolygonStep step{r, polys, scenes, o, d, so};
  m.polygons(step);
  mark_cut_lines(d, r.bodies);
  surface_lines(d, r.bodies, o);
  if (o.lines.edges == EdgeSelection::Feature) {
    d.segments.erase(std::remove_if(d.segments.begin(), d.segments.end(),
                                    [](const Segment& s) { return s.kind != Segment::Kind::Intersection && s.line == LineKind::Edge; }),
                     d.segments.end());
  } else {
    for (Segment& s : d.segments)
      if (s.kind == Segment::Kind::Edge && s.line != LineKind::Cut) s.line = LineKind::Edge;
  }
  r.drawing = std::move(d);
}

// A tile of the picture (picture_tiles.hpp): its split, from every body's vertices, and the
// cut of each segment to it.
class TileCut {
 public:
  TileCut(const std::vector<const Polyhedron*>& polys, const Camera& cam, const RenderOptions::Tile& t, unsigned threads)
      : cam_(cam), pp_(cam), index_(t.index) {
    if (t.count < 1 || t.index < 0 || t.index >= t.count) throw std::invalid_argument("--tile: no tile " + std::to_string(t.index + 1) + " of " + std::to_string(t.count));
    std::vector<const Point3*> pts;
    for (const Polyhedron* p : polys)
      for (const Point3& q : p->vertices()) pts.push_back(&q);
    const DrawingFrame frame = drawing_frame(pts.size(), [&](std::size_t i) -> const Point3& { return *pts[i]; });
    proj_.emplace(cam, frame);
    split_ = split_picture(cam, *proj_, pts.size(), [&](std::size_t i) -> const Point3& { return *pts[i]; }, t.count);
    // Each vertex's sides of the tile it surely lies outside (a triangle whose three vertices
    // share one cannot reach the tile: its picture is in their convex hull).
    std::size_t at = 0;
    for (const Polyhedron* p : polys) {
      first_.push_back(at);
      at += p->num_vertices();
    }
    outside_.assign(pts.size(), 0);
    ParallelLoop(threads).for_each(pts.size(), 4096, [&](std::size_t i) {
      if (split_.count > 1) outside_[i] = static_cast<unsigned char>(tile_outside(split_, index_, locate(cam, *proj_, *pts[i])));
    });
  }
  /// False only when the triangle (body, its vertex indices) cannot reach the tile.
  bool may_occlude(int body, const std::array<int, 3>& v) const {
    const std::size_t o = first_[static_cast<std::size_t>(body)];
    return (outside_[o + v[0]] & outside_[o + v[1]] & outside_[o + v[2]]) == 0;
  }
  /// False only when no point of the segment is in the tile (a filter in doubles).
  bool may_hold(const Segment& s) const { return where(s) != 0; }
  /// The segment's pieces cut to the tile, exactly.
  void apply(Segment& s) const {
    const int w = where(s);
    if (w == 0) s.pieces.clear();
    if (w == 1) cut_to_intervals(s, tile_intervals(s, pp_, cam_, split_, index_));
  }

 private:
  // 0: no point of the segment in the tile, 2: all of it, 1: not known without exact numbers.
  int where(const Segment& s) const {
    if (split_.count == 1) return 2;
    const LocatedPoint a = locate(cam_, *proj_, s.from()), b = locate(cam_, *proj_, s.to());
    return !tile_may_hold(split_, index_, a, b) ? 0 : tile_holds_wholly(split_, index_, a, b) ? 2 : 1;
  }

  const Camera& cam_;
  PicturePlane pp_;
  int index_;
  std::optional<Projector> proj_;
  TileSplit split_;
  std::vector<std::size_t> first_;       // per body: its first vertex in outside_
  std::vector<unsigned char> outside_;   // per vertex: tile_outside()
};

// A plan's overhead lines (RenderOptions::overhead): what `plane` removed, seen from the other
// side, its visible lines put into r's drawing as owned overhead segments.
void add_overhead(RenderResult& r, std::vector<Scene> scene, const Plane& plane, const RenderOptions& o) {
  RenderOptions up;
  up.method = o.method == RenderMethod::Roberts ? o.method : RenderMethod::Faces;
  up.lines = o.lines;
  up.section = {plane.opposite()};
  up.view.direction = Rational(-1) * r.camera.direction;
  up.view.up = r.camera.up;
  RenderResult u;
  try {
    u = render(std::move(scene), up);
  } catch (const std::invalid_argument&) {
    return;  // nothing above the plane
  }
  for (const Segment& s : u.drawing.segments) {
    if (s.line == LineKind::Cut) continue;
    Segment t;
    t.kind = Segment::Kind::Intersection;
    t.line = LineKind::Overhead;
    t.set_ends(s.from(), s.to());
    std::vector<Piece> pieces = s.pieces.to_vector();
    bool any = false;
    for (Piece& p : pieces) {
      if (!p.visible) p.clipped = true;  // only what is seen from below is drawn
      any = any || (p.visible && !p.clipped && !p.behind_eye);
    }
    if (!any) continue;
    t.pieces = std::move(pieces);
    r.drawing.segments.push_back(std::move(t));
  }
}

// The mesh repairs before any route runs (algorithms/solids/mesh_repair.hpp): non-planar
// polygons split into triangles (each polygon stays one surface: its diagonals are not
// creases), then zero-area triangles removed; `name` maps the faces drawn to the input's.
void repair_body(SceneBody& b, DrawingBody& name, std::vector<std::string>& repairs) {
  const std::string who = b.source + ": body '" + b.name + "' ";
  if (auto split = split_nonplanar_faces(b.body)) {
    name.numbered = b.body.faces().size();
    if (!b.face_texcoords.empty()) {
      // Each triangle's corners take the texture corners of the same vertices in its polygon.
      std::vector<std::vector<int>> tex;
      for (std::size_t k = 0; k < split->body.faces().size(); ++k) {
        const Face& from = b.body.faces()[split->input_face[k]];
        const std::vector<int>& t = b.face_texcoords[split->input_face[k]];
        std::vector<int> corners;
        for (int v : split->body.faces()[k]) {
          const auto at = std::find(from.begin(), from.end(), v) - from.begin();
          if (!t.empty()) corners.push_back(t[at]);
        }
        tex.push_back(std::move(corners));
      }
      b.face_texcoords = std::move(tex);
    }
    b.body = std::move(split->body);
    if (b.surfaces.empty()) {
      b.surfaces.surface = split->input_face;
      b.surfaces.sharp_between = false;
    } else {
      b.surfaces = renumbered_surfaces(b.surfaces, split->input_face);
    }
    name.input_face = std::move(split->input_face);
    name.repaired_faces = std::move(split->joined);
    for (const std::string& n : split->notes) repairs.push_back(who + n);
  }
  if (auto fixed = remove_zero_area_triangles(b.body)) {
    b.body = std::move(fixed->body);
    b.surfaces = renumbered_surfaces(b.surfaces, fixed->input_face);
    auto input = [&](int f) { return name.output_face(f); };
    for (int& f : fixed->input_face) f = input(f);
    for (int& f : fixed->removed) f = input(f);
    for (int& f : fixed->joined) f = input(f);
    name.input_face = std::move(fixed->input_face);
    name.removed_faces = std::move(fixed->removed);
    name.repaired_faces.insert(name.repaired_faces.end(), fixed->joined.begin(), fixed->joined.end());
    std::sort(name.repaired_faces.begin(), name.repaired_faces.end());
    name.repaired_faces.erase(std::unique(name.repaired_faces.begin(), name.repaired_faces.end()), name.repaired_faces.end());
    for (const std::string& n : fixed->notes) repairs.push_back(who + n);
    if (!b.face_texcoords.empty()) {  // the faces changed: their texture corners no longer match
      b.face_texcoords.clear();
      repairs.push_back(who + "texture coordinates dropped with the repair");
    }
  }
}

// Whether a render uses RenderOptions::share: its views change no body and draw lines.
bool shares_views(const std::vector<Scene>& scenes, const RenderOptions& o) {
  if (!o.share || !o.section.empty() || !o.cutaway.empty() || o.section_view || o.view_depth || o.tile || o.segments_only || o.facing_only ||
      o.cut_at_near || o.surfaces || o.shadows || !method_entry(o.method).draws_lines())
    return false;
  for (const Scene& s : scenes)
    if (is_scene_file(s.file) && (!s.section.empty() || !s.cutaway.empty())) return false;
  return true;
}

}  // namespace

bool reads_shared_scenes(const RenderOptions& o) { return o.share && o.share->scenes && shares_views(*o.share->scenes, o); }

RenderResult render(std::vector<Scene> scenes, const RenderOptions& o) {
  if (!(o.near > 0)) throw std::invalid_argument("--near must be positive (a fraction of the distance from the eye to the target)");
  RenderResult r;
  const bool shared = reads_shared_scenes(o);  // repaired by a view before
  const bool sharing = shared || shares_views(scenes, o);
  auto owned = shared ? o.share->scenes : std::make_shared<std::vector<Scene>>(std::move(scenes));
  r.scenes = owned;
  std::vector<const Polyhedron*> polys;
  const View* scene_view = nullptr;
  std::vector<std::string> repairs;
  std::vector<SceneBody*> editable;
  const std::vector<Plane>* planes = o.section.empty() ? nullptr : &o.section;
  std::vector<Plane> with_view_plane;  // a section view's plane and the section's
  const std::vector<Plane>* away = o.cutaway.empty() ? nullptr : &o.cutaway;
  if (shared) r.names = o.share->names, repairs = o.share->repairs;
  for (Scene& s : *owned) {
    if (!scene_view && is_scene_file(s.file)) scene_view = &s.view;
    if (!planes && is_scene_file(s.file) && !s.section.empty()) planes = &s.section;
    if (!away && is_scene_file(s.file) && !s.cutaway.empty()) away = &s.cutaway;
    if (!shared)
      for (const std::string& n : s.notes) repairs.push_back(s.file + ": " + n);
    for (SceneBody& b : s.bodies) {
      if (!shared) {
        DrawingBody name{b.name, b.source};
        repair_body(b, name, repairs);
        r.names.push_back(std::move(name));
      }
      editable.push_back(&b);
      polys.push_back(&b.body);
    }
  }
  if (sharing && !shared) {
    o.share->scenes = owned;
    o.share->names = r.names;
    o.share->repairs = repairs;
  }
  if (o.section_view) {
    if (planes) with_view_plane = *planes;
    with_view_plane.push_back(o.section_view->plane);
    planes = &with_view_plane;
    r.section_view = o.section_view;
  }
  if (o.view_depth && (o.surfaces || o.shadows || !method_entry(o.method).draws_lines()))
    throw std::invalid_argument("a plan's depth clips lines: --surfaces and fills take the plan without a depth");
  // The camera of the whole scene: a section and the plain view line up.
  r.camera = choose_camera(o.view, scene_view, polys);
  // The request's frame, else the scene's camera's (which an orthographic --view leaves out).
  const FrameRequest* frame = o.view.frame ? &*o.view.frame : scene_view && scene_view->frame && r.camera.perspective ? &*scene_view->frame : nullptr;
  if (frame) {
    check_frame_request(*frame);
    r.pyramid = view_pyramid(r.camera, frame_tangents(*frame, r.camera));
  }
  const RenderMethodEntry& m = method_entry(o.method);
  const bool sectioned = planes || away;
  std::optional<std::vector<Scene>> above;  // the uncut scene, for the overhead lines
  if (o.overhead && planes && planes->size() == 1 && !away && !r.camera.perspective) above = *owned;
  if (sectioned) {
    static const std::vector<Plane> none;
    cut_bodies(planes ? *planes : none, away ? *away : none, editable, r.names, repairs);
    r.section_planes = planes ? *planes : none;
    if (away) r.section_planes.insert(r.section_planes.end(), away->begin(), away->end());
    r.section_cut_away = away && !away->empty();
    if (editable.empty()) throw std::invalid_argument("the section removes every body: nothing is left to draw");
    polys.clear();
    for (SceneBody* b : editable) polys.push_back(&b->body);
  }
  // Filled products with the eye among the bodies: every body cut by the near plane.
  if (o.surfaces || o.shadows || o.cut_at_near || !m.draws_lines()) cut_at_eye(r, o.near, o.shadows, editable, polys, repairs);
  r.bodies.assign(editable.begin(), editable.end());
  if (m.flags & kChecksSolids)
    for (const Polyhedron* p : polys) p->report();  // the method's checks belong to loading
  if ((o.tile || o.segments_only) && (!(m.flags & kTakesTiles) || o.surfaces || o.shadows || o.clip || !o.polylines.empty()))
    throw std::invalid_argument("tiles take line drawings of the per-face route (not --method roberts, --surfaces, --shadows, --clip or --lines)");
  FaceRouteHooks hooks;
  hooks.facing_only = o.facing_only;
  if (sharing) {
    if (!o.share->faces) o.share->faces = std::make_shared<FaceRouteShare>();
    hooks.share = o.share->faces;
  }
  if (sectioned) {
    section_hooks(r.bodies, hooks);
    // The caps' hatching draws in the same bodies from the same direction: it reads this work.
    if (!hooks.share && !r.camera.perspective) r.section_share = hooks.share = std::make_shared<FaceRouteShare>();
  }
  for (const SceneBody* b : r.bodies) hooks.surfaces.push_back(b->surfaces.empty() ? nullptr : &b->surfaces);
  // Back edges are left out only where nothing after the route reads them: no glass shows
  // them, and no clipping moves their ends (the drawing's frame counts them as they are).
  const std::vector<char> glass = see_through_bodies(r);
  hooks.back_edges = o.back_edges || (o.through_lines && std::find(glass.begin(), glass.end(), 1) != glass.end()) || r.camera.perspective || o.clip ||
                     o.view_depth || o.tile || o.segments_only || r.pyramid;
  std::optional<TileCut> cut;
  if (o.tile) {
    cut.emplace(polys, r.camera, *o.tile, o.lines.threads);
    hooks.decide = [&](const Segment& s) { return cut->may_hold(s); };
    hooks.may_occlude = [&](int body, const std::array<int, 3>& v) { return cut->may_occlude(body, v); };
  }
  if (o.segments_only) {  // no visibility: no segment is solved, no face hides
    hooks.decide = [](const Segment&) { return false; };
    hooks.may_occlude = [](int, const std::array<int, 3>&) { return false; };
  }
  try {
    if (o.surfaces || o.shadows || !m.draws_lines()) {
      solve_surfaces(r, polys, *owned, o);
    } else {
      LineStep step{r, polys, o, hooks, repairs};
      m.lines(step);
    }
  } catch (const BodyError& e) {
    const SceneBody& b = *r.bodies[e.body()];
    throw RenderBodyError(e.body(), b.name, b.source, e.reason());
  }
  if (sectioned || r.eye_cut) mark_cut_lines(r.drawing, r.bodies);
  surface_lines(r.drawing, r.bodies, o);
  if (above) add_overhead(r, std::move(*above), (*planes)[0], o);
  if (!o.polylines.empty()) add_polylines(r, o.polylines, o);
  r.notes = std::move(repairs);
  for (const BodyNote& n : r.drawing.notes)
    r.notes.push_back(r.names[n.body].source + ": body '" + r.names[n.body].name + "' " + n.text);
  eye_plane_notes(r, r.notes);
  // Clipping: the near plane (perspective) and the clipping volume, exactly, in world space.
  std::optional<Plane> near;
  if (r.camera.perspective) near = near_plane(r.camera, o.near);
  r.near_plane = near;
  r.clip = o.clip;
  if ((near || o.clip || o.view_depth) && !r.surfaces && !r.priority)
    ParallelLoop(o.lines.threads).for_each(r.drawing.segments.size(), 1024, [&](std::size_t i) {
      Segment& s = r.drawing.segments[i];
      if (near) clip_near(s, *near);
      if (o.view_depth) clip_near(s, *o.view_depth);
      if (o.clip) clip_pieces(s, *o.clip);
    });
  if (r.pyramid)  // the picture frame, exactly (the filled products' polygons stay whole: the page crops them)
    ParallelLoop(o.lines.threads).for_each(r.drawing.segments.size(), 1024, [&](std::size_t i) {
      for (const Plane& side : r.pyramid->sides) clip_near(r.drawing.segments[i], side);
    });
  if (cut)
    ParallelLoop(o.lines.threads).for_each(r.drawing.segments.size(), 256, [&](std::size_t i) { cut->apply(r.drawing.segments[i]); });
  return r;
}

Lighting render_lighting(const RenderResult& r) { return scene_lighting(*r.scenes, r.camera); }

std::vector<LightPlace> render_light_places(const RenderResult& r) { return light_places(render_lighting(r)); }

Material body_material(const RenderResult& r, std::size_t b) { return material_of(r, b); }

std::vector<std::vector<Rgb>> flat_face_colours(const RenderResult& r, const std::vector<std::vector<char>>* only) {
  const Lighting light = render_lighting(r);
  const ViewDoubles vd(r.camera);
  std::vector<std::vector<Rgb>> out(r.bodies.size());
  for (std::size_t b = 0; b < r.bodies.size(); ++b) {
    out[b].resize(r.bodies[b]->body.num_faces());
    ParallelLoop().for_each(out[b].size(), 256, [&](std::size_t f) {
      const bool back = b < r.drawing.facing.size() && f < r.drawing.facing[b].size() && r.drawing.facing[b][f] < 0;
      if (only && !(*only)[b][f]) return;
      out[b][f] = face_colour(r, b, f, light, back, face_normal(r.bodies[b]->body, f), vd);
    });
  }
  return out;
}

void add_surface_fills(Plot& plot, const RenderResult& r) {
  if (!r.surfaces && !r.priority && !r.transparent) return;
  Projector proj = drawing_projector(r.drawing, r.camera);
  PictureToDrawing to_drawing(PicturePlane(r.camera), proj.frame());
  bool had = !plot.empty();
  auto ring = [&](PlotFill& f, const auto& pts) {
    std::vector<Point2> out;
    out.reserve(pts.size());
    for (const auto& q : pts) {
      auto xy = to_drawing(q);
      out.push_back({xy[0], xy[1]});
      if (!had) plot.bounds = {xy[0], xy[1], xy[0], xy[1]}, had = true;
      plot.bounds = {std::min(plot.bounds[0], xy[0]), std::min(plot.bounds[1], xy[1]), std::max(plot.bounds[2], xy[0]),
                     std::max(plot.bounds[3], xy[1])};
    }
    f.rings.push_back(std::move(out));
  };
  if (r.transparent) {  // regions of equal face lists, composited
    for (std::size_t k = 0; k < r.transparent->regions.size(); ++k) {
      const VisiblePolygon& p = r.transparent->regions[k].polygon;
      PlotFill f;
      f.colour = r.transparent_colours[k];
      ring(f, p.outer_2d);
      for (const auto& h : p.holes_2d) ring(f, h);
      plot.fills.push_back(std::move(f));
    }
    return;
  }
  if (r.shadows) {  // every region of every face in its own colour: lit, in shadow, lit by some lights
    for (std::size_t k = 0; k < r.shadows->faces.size(); ++k)
      for (std::size_t j = 0; j < r.shadows->faces[k].regions.size(); ++j) {
        const VisiblePolygon& p = r.shadows->faces[k].regions[j].polygon;
        PlotFill f;
        f.colour = r.shadow_colours[k][j];
        f.edge_mm = 0.2;  // regions are per face, not merged per colour: a wider edge hides the seams
        ring(f, p.outer_2d);
        for (const auto& h : p.holes_2d) ring(f, h);
        plot.fills.push_back(std::move(f));
      }
    return;
  }
  if (r.priority) {  // the painter's order: later fills cover earlier ones
    for (int i : r.priority->order) {
      const PriorityPolygon& p = r.priority->polygons[i];
      PlotFill f;
      f.colour = r.face_colours[p.body][p.face];
      f.edge_mm = 0.25;
      ring(f, p.pts);
      plot.fills.push_back(std::move(f));
    }
    return;
  }
  for (const VisibleGroup& g : r.surfaces->groups)
    for (const VisiblePolygon& p : g.polygons) {
      PlotFill f;
      f.colour = r.group_colours[g.group];
      if (p.outer_2d.empty() && !p.outer_approx.empty()) {  // SurfaceOptions::exact_groups off
        ring(f, p.outer_approx);
        for (const auto& h : p.holes_approx) ring(f, h);
      } else {
        ring(f, p.outer_2d);
        for (const auto& h : p.holes_2d) ring(f, h);
      }
      plot.fills.push_back(std::move(f));
    }
}

RenderResult render_files(const std::vector<std::string>& inputs, const RenderOptions& o) {
  std::vector<Scene> scenes;
  for (const auto& in : inputs) scenes.push_back(load_any_input(in, "", {}));
  return render(std::move(scenes), o);
}

}  // namespace hlr
