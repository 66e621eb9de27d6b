// `hlr render [options] INPUT...`: exact hidden-line drawing of any meshes (per-face occluders)
// or of convex bodies by Roberts' algorithm, written as SVG or exact JSON (atomically: no
// partial output on failure).
#include <chrono>
#include <filesystem>
#include <iostream>

#include "algorithms/face_occluders.hpp"
#include "algorithms/convexity.hpp"
#include "algorithms/roberts.hpp"
#include "algorithms/roberts_pieces.hpp"
#include "algorithms/cyrus_beck.hpp"
#include "cli/arguments.hpp"
#include "cli/clipper_spec.hpp"
#include "cli/commands.hpp"
#include "io/atomic_file.hpp"
#include "io/drawing.hpp"
#include "io/scene.hpp"

namespace hlr::cli {
namespace {

struct RenderArgs {
  std::vector<std::string> inputs;
  std::string output, format, view, eye, target, up, hidden = "none", edges = "feature", clip, near = "1/1000";
  std::string method = "faces", crease = "30";
  unsigned threads = 0;
  bool timings = false;
  double width = 150, stroke = 0.35;
};

Point3 as_point(const Vector3& v) { return Point3(v.x(), v.y(), v.z()); }

Camera choose_camera(const RenderArgs& a, const std::vector<Scene>& scenes, const std::vector<SceneBody*>& bodies) {
  std::optional<Vector3> up;
  if (!a.up.empty()) up = parse_vector3("--up", a.up);
  const View* sv = nullptr;
  for (const Scene& s : scenes)
    if (is_scene_file(s.file)) {
      sv = &s.view;
      break;
    }
  if (!a.eye.empty() || (a.view.empty() && sv && sv->type == View::Type::Perspective)) {
    Point3 eye = !a.eye.empty() ? as_point(parse_vector3("--eye", a.eye)) : sv->eye;
    std::optional<Point3> target;
    if (!a.target.empty()) target = as_point(parse_vector3("--target", a.target));
    else if (sv && sv->type == View::Type::Perspective && sv->target) target = sv->target;
    if (!target) {  // the centre of the scene's bounding box
      Rational lo[3], hi[3];
      bool first = true;
      for (const SceneBody* b : bodies)
        for (const Point3& p : b->body.vertices())
          for (int k = 0; k < 3; ++k) {
            if (first || p[k] < lo[k]) lo[k] = p[k];
            if (first || p[k] > hi[k]) hi[k] = p[k];
            if (k == 2) first = false;
          }
      target = Point3((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
    }
    if (!up && sv && sv->up_given) up = sv->up;
    return make_perspective(eye, *target, up);
  }
  if (!a.target.empty()) throw std::invalid_argument("--target needs --eye (a perspective view)");
  if (!up && sv && sv->up_given) up = sv->up;
  Vector3 dir = !a.view.empty() ? parse_vector3("--view", a.view) : sv ? sv->direction : Vector3(0, 0, 1);
  return make_orthographic(dir, up);
}

int run_render(const RenderArgs& a) {
  if (!a.view.empty() && !a.eye.empty()) throw std::invalid_argument("give --view (orthographic) or --eye (perspective), not both");
  if (!(a.width > 0) || !std::isfinite(a.width) || a.width > 1e6) throw std::invalid_argument("--width must be a positive size in millimetres");
  if (!(a.stroke > 0) || !std::isfinite(a.stroke) || a.stroke > 1e3) throw std::invalid_argument("--stroke must be a positive width in millimetres");
  std::string format = a.format;
  if (format.empty()) {
    std::string ext = std::filesystem::path(a.output).extension().string();
    format = ext == ".json" ? "json" : "svg";
  }
  using Clock = std::chrono::steady_clock;
  auto t_start = Clock::now();
  std::vector<Scene> scenes;
  for (const auto& in : a.inputs) scenes.push_back(is_scene_file(in) ? load_scene(in) : scene_from_mesh(in));
  std::vector<SceneBody*> bodies;
  std::vector<const Polyhedron*> polys;
  std::vector<DrawingBody> names;
  for (Scene& s : scenes)
    for (SceneBody& b : s.bodies) {
      bodies.push_back(&b);
      polys.push_back(&b.body);
      names.push_back({b.name, b.source});
    }
  if (a.method == "roberts")
    for (const Polyhedron* p : polys) p->report();  // Roberts' checks belong to loading
  auto t_loaded = Clock::now();
  Camera camera = choose_camera(a, scenes, bodies);
  Rational crease;
  try {
    crease = parse_rational(a.crease);
  } catch (const NumberError& e) {
    throw std::invalid_argument(std::string("--crease: ") + e.what());
  }
  if (crease < 0 || crease > 180) throw std::invalid_argument("--crease must be an angle in degrees from 0 to 180");
  RobertsResult result;
  try {
    if (a.method == "roberts") {
      RobertsOptions ro;
      ro.edges = a.edges == "all" ? EdgeSelection::All : EdgeSelection::Feature;
      ro.crease_degrees = crease;
      bool all_convex = true;
      for (const Polyhedron* p : polys) all_convex = all_convex && p->report().valid_solid() && convexity(*p).convex();
      result = all_convex ? roberts(polys, camera, ro) : roberts_pieces(polys, camera, ro);
    } else {
      LineOptions lo;
      lo.edges = a.edges == "all" ? EdgeSelection::All : EdgeSelection::Feature;
      lo.crease_degrees = crease;
      lo.threads = a.threads;
      result = face_occluders(polys, camera, lo);
    }
  } catch (const RobertsError& e) {
    const SceneBody* b = bodies[e.body()];
    std::string msg = e.what();
    std::string prefix = "body " + std::to_string(e.body());
    if (msg.rfind(prefix, 0) == 0) msg = "body '" + b->name + "'" + msg.substr(prefix.size());
    std::cerr << "hlr render: " << b->source << ": " << msg << "\n";
    return 1;
  }
  // Degenerate but drawable views get a note, never a wrong picture.
  for (const auto& [i, note] : result.notes) {
    std::string msg = note, prefix = "body " + std::to_string(i);
    if (msg.rfind(prefix, 0) == 0) msg = "body '" + bodies[i]->name + "'" + msg.substr(prefix.size());
    std::cerr << "hlr render: note: " << bodies[i]->source << ": " << msg << "\n";
  }
  if (camera.perspective)
    for (std::size_t i = 0; i < result.facing.size(); ++i) {
      std::size_t count = 0;
      for (std::size_t f = 0; f < result.facing[i].size(); ++f)
        if (result.facing[i][f] == 0 && ++count <= 3)
          std::cerr << "hlr render: note: the eye lies in the plane of face " << f << " of body '" << bodies[i]->name
                    << "': that face is seen edge-on\n";
      if (count > 3) std::cerr << "hlr render: note: ... and " << count - 3 << " more faces of body '" << bodies[i]->name << "'\n";
    }
  // Clipping: the near plane (perspective) and the clipping volume, exactly, in world space.
  Rational near;
  try {
    near = parse_rational(a.near);
  } catch (const NumberError& e) {
    throw std::invalid_argument(std::string("--near: ") + e.what());
  }
  if (!(near > 0)) throw std::invalid_argument("--near must be positive (a fraction of the distance from the eye to the target)");
  std::optional<ClipperSpec> clip;
  if (!a.clip.empty()) clip = parse_clipper("--clip", a.clip);
  for (Segment& s : result.segments) {
    if (camera.perspective) clip_near(s, camera, near);
    if (clip) clip_pieces(s, clip->clipper);
  }
  auto t_solved = Clock::now();
  SvgOptions so;
  so.hidden_dashed = a.hidden == "dashed";
  so.width_mm = a.width;
  so.stroke_mm = a.stroke;
  std::string text = format == "json" ? to_json(names, result, camera) : to_svg(names, result, camera, so);
  write_output(a.output, text);
  if (a.timings) {
    auto t_end = Clock::now();
    auto sec = [](auto d) { return std::chrono::duration<double>(d).count(); };
    std::size_t tris = 0;
    for (const Polyhedron* p : polys) tris += p->num_faces();
    std::cerr << std::fixed;
    std::cerr.precision(3);
    std::cerr << "timings: faces " << tris << ", load " << sec(t_loaded - t_start) << " s, setup " << result.stats.setup_seconds
              << " s, intersections " << result.stats.intersections_seconds << " s, visibility " << result.stats.visibility_seconds
              << " s, solve total " << sec(t_solved - t_loaded) << " s, output " << sec(t_end - t_solved) << " s, segments "
              << result.segments.size() << ", comparisons " << result.stats.comparisons << " (identical "
              << result.stats.comparisons_identical << ", exact fallback " << result.stats.comparisons_exact << ")"
              << "\n";
  }
  return 0;
}

}  // namespace

void add_render_command(CLI::App& app, int& exit_code) {
  auto a = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Exact hidden-line drawing (Roberts' algorithm) as SVG or JSON");
  cmd->add_option("inputs", a->inputs, "Mesh files (.off .obj .stl .ply) and scene files (.yaml .yml .json)")->required();
  cmd->add_option("-o", a->output, "Output file (default: standard output); .json selects JSON");
  cmd->add_option("--format", a->format, "svg or json (default: from the output file's extension, else svg)")
      ->check(CLI::IsMember({"svg", "json"}));
  cmd->add_option("--view", a->view, "Orthographic view direction X,Y,Z, from the scene toward the viewer (default 0,0,1)");
  cmd->add_option("--eye", a->eye, "Perspective: the eye point X,Y,Z");
  cmd->add_option("--target", a->target, "Perspective: the point looked at (default: centre of the scene's bounding box)");
  cmd->add_option("--up", a->up, "Up direction X,Y,Z (default 0,1,0, or 0,0,1 when looking along y)");
  cmd->add_option("--hidden", a->hidden, "none or dashed (default none)")->check(CLI::IsMember({"none", "dashed"}));
  cmd->add_option("--edges", a->edges,
                  "feature (default: boundaries, silhouettes, creases over --crease, intersection lines) or all (every mesh edge)")
      ->check(CLI::IsMember({"all", "feature"}));
  cmd->add_option("--crease", a->crease, "Crease threshold in degrees between face normals (default 30; 0 keeps every edge between non-coplanar faces)");
  cmd->add_option("--method", a->method,
                  "faces (default: per-face occluders, any mesh) or roberts (the course's algorithm; non-convex solids are split into convex pieces)")
      ->check(CLI::IsMember({"faces", "roberts"}));
  cmd->add_option("--threads", a->threads, "Threads for the visibility stage (default: all cores)");
  cmd->add_flag("--timings", a->timings, "Print the time of each stage to standard error");
  cmd->add_option("--clip", a->clip,
                  "Clip the drawing to box:XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX, frustum:XL,XR,YB,YT,ZNEAR,ZFAR,ZCP or a convex mesh file");
  cmd->add_option("--near", a->near,
                  "Perspective near plane at this fraction of the eye-target distance from the eye (default 1/1000)");
  cmd->add_option("--width", a->width, "Drawing width in millimetres (default 150)");
  cmd->add_option("--stroke", a->stroke, "Stroke width of visible lines in millimetres (default 0.35)");
  cmd->callback([a, &exit_code] { exit_code = run_render(*a); });
}

}  // namespace hlr::cli
