// `hlr render [options] INPUT...`: parses the options into the library's RenderOptions, calls
// render() (io/render.hpp) and writes SVG or exact JSON (atomically: no partial output on
// failure).
#include <chrono>
#include <filesystem>
#include <iostream>

#include "cli/arguments.hpp"
#include "cli/clipper_spec.hpp"
#include "cli/commands.hpp"
#include "io/atomic_file.hpp"
#include "io/json_writer.hpp"
#include "io/render.hpp"
#include "io/svg_writer.hpp"

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

RenderOptions render_options(const RenderArgs& a) {
  RenderOptions o;
  o.method = a.method == "roberts" ? RenderMethod::Roberts : RenderMethod::Faces;
  o.lines.edges = a.edges == "all" ? EdgeSelection::All : EdgeSelection::Feature;
  o.lines.threads = a.threads;
  try {
    o.lines.crease_degrees = parse_rational(a.crease);
  } catch (const NumberError& e) {
    throw std::invalid_argument(std::string("--crease: ") + e.what());
  }
  if (o.lines.crease_degrees < 0 || o.lines.crease_degrees > 180)
    throw std::invalid_argument("--crease must be an angle in degrees from 0 to 180");
  if (!a.view.empty()) o.view.direction = parse_vector3("--view", a.view);
  if (!a.eye.empty()) o.view.eye = as_point(parse_vector3("--eye", a.eye));
  if (!a.target.empty()) o.view.target = as_point(parse_vector3("--target", a.target));
  if (!a.up.empty()) o.view.up = parse_vector3("--up", a.up);
  try {
    o.near = parse_rational(a.near);
  } catch (const NumberError& e) {
    throw std::invalid_argument(std::string("--near: ") + e.what());
  }
  if (!a.clip.empty()) o.clip = parse_clipper("--clip", a.clip).clipper;
  return o;
}

int run_render(const RenderArgs& a) {
  if (!a.view.empty() && !a.eye.empty()) throw std::invalid_argument("give --view (orthographic) or --eye (perspective), not both");
  if (!(a.width > 0) || !std::isfinite(a.width) || a.width > 1e6) throw std::invalid_argument("--width must be a positive size in millimetres");
  if (!(a.stroke > 0) || !std::isfinite(a.stroke) || a.stroke > 1e3) throw std::invalid_argument("--stroke must be a positive width in millimetres");
  const std::string format = output_format(a.format, a.output, {{".svg", "svg"}, {".json", "json"}}, "svg");
  using Clock = std::chrono::steady_clock;
  auto t_start = Clock::now();
  std::vector<Scene> scenes;
  for (const auto& in : a.inputs) scenes.push_back(is_scene_file(in) ? load_scene(in) : scene_from_mesh(in));
  auto t_loaded = Clock::now();
  RenderOptions options = render_options(a);
  RenderResult r;
  try {
    r = render(std::move(scenes), options);
  } catch (const RenderBodyError& e) {
    std::cerr << "hlr render: " << e.what() << "\n";
    return 1;
  }
  for (const std::string& note : r.notes) std::cerr << "hlr render: note: " << note << "\n";
  auto t_solved = Clock::now();
  SvgOptions so;
  so.hidden_dashed = a.hidden == "dashed";
  so.width_mm = a.width;
  so.stroke_mm = a.stroke;
  std::string text = format == "json" ? to_json(r.names, r.drawing, r.camera) : to_svg(r.names, r.drawing, r.camera, so);
  write_output(a.output, text);
  if (a.timings) {
    auto t_end = Clock::now();
    auto sec = [](auto d) { return std::chrono::duration<double>(d).count(); };
    std::size_t tris = 0;
    for (const SceneBody* b : r.bodies) tris += b->body.num_faces();
    const DrawingStats& st = r.drawing.stats;
    FaceRouteStats fs = st.faces.value_or(FaceRouteStats{});
    std::cerr << std::fixed;
    std::cerr.precision(3);
    std::cerr << "timings: faces " << tris << ", load " << sec(t_loaded - t_start) << " s, setup " << st.setup_seconds
              << " s, intersections " << st.intersections_seconds << " s, visibility " << st.visibility_seconds
              << " s, solve total " << sec(t_solved - t_loaded) << " s, output " << sec(t_end - t_solved) << " s, segments "
              << r.drawing.segments.size() << ", comparisons " << fs.comparisons << " (identical "
              << fs.comparisons_identical << ", exact fallback " << fs.comparisons_exact << ")"
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
