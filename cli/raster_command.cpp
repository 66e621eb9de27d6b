// `hlr raster [options] INPUT... -o out.png`: the course's image-space algorithms (z-buffer,
// scan-line, Warnock, ray casting; notes 29-35) with the exact face at every pixel centre,
// shaded flat, Gouraud or Phong (notes 36-39), antialiased by supersampling, written
// as PNG; optionally the face-id buffer and the exact pixel grid (io/pipeline/raster.hpp). Every file
// is written atomically.
#include <iostream>
#include <memory>

#include "algorithms/support/parallel.hpp"
#include "algorithms/support/progress.hpp"
#include "cli/arguments.hpp"
#include "cli/commands.hpp"
#include "cli/process.hpp"
#include "io/pipeline/raster.hpp"
#include "io/views/view_choice.hpp"
#include "io/writers/atomic_file.hpp"

namespace hlr::cli {
namespace {

struct RasterArgs {
  std::vector<std::string> inputs;
  std::string output, algorithm = "zbuffer", size = "512x512", view, eye, target, up, up_axis = "y";
  std::string shading = "flat", filter = "box", ids, camera, background = "#ffffff";
  double smooth = 40;
  int samples = 1, bounces = 0;
  unsigned threads = 0;
  bool timings = false, progress = false, quiet = false;
};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

RasterOptions raster_options(const RasterArgs& a) {
  RasterOptions o;
  o.algorithm = a.algorithm == "scanline"   ? RasterAlgorithm::Scanline
                : a.algorithm == "warnock"  ? RasterAlgorithm::Warnock
                : a.algorithm == "raytrace" ? RasterAlgorithm::RayCast
                                            : RasterAlgorithm::ZBuffer;
  auto x = a.size.find('x');
  try {
    std::size_t used = 0;
    o.width = std::stoi(a.size.substr(0, x), &used);
    if (used != std::min(x, a.size.size())) throw std::invalid_argument("");
    o.height = 0;  // WIDTH alone: the frame's aspect (square without a frame)
    if (x != std::string::npos) {
      o.height = std::stoi(a.size.substr(x + 1), &used);
      if (used != a.size.size() - x - 1) throw std::invalid_argument("");
    }
  } catch (const std::exception&) {
    throw std::invalid_argument("--size must be WIDTHxHEIGHT or WIDTH in pixels, e.g. 512x512 (got '" + a.size + "')");
  }
  if (o.width < 1 || o.height < 0 || (x != std::string::npos && o.height < 1) || o.width > 16384 || o.height > 16384)
    throw std::invalid_argument("--size: each side must be 1 to 16384 pixels");
  o.view = parse_view_request(a.view, a.eye, a.target, a.up, a.up_axis);
  o.shading = a.shading == "gouraud" ? RasterShading::Gouraud : a.shading == "phong" ? RasterShading::Phong : RasterShading::Flat;
  if (!(a.smooth >= 0 && a.smooth <= 180)) throw std::invalid_argument("--smooth must be an angle from 0 to 180 degrees");
  o.smooth_degrees = a.smooth;
  o.samples = a.samples;
  if (a.bounces < 0 || a.bounces > 32) throw std::invalid_argument("--bounces must be 0 to 32");
  o.bounces = a.bounces;
  o.filter = a.filter == "tent" ? RasterFilter::Tent : RasterFilter::Box;
  o.threads = a.threads;
  const std::string& b = a.background;
  if (b.size() != 7 || b[0] != '#' || b.find_first_not_of("0123456789abcdefABCDEF", 1) != std::string::npos)
    throw std::invalid_argument("--background must be #rrggbb (got '" + b + "')");
  for (int k = 0; k < 3; ++k) o.background[k] = std::stoi(b.substr(1 + 2 * k, 2), nullptr, 16) / 255.0;
  return o;
}

int run_raster(const RasterArgs& a) {
  const ThreadLimit limit(a.threads);  // every parallel stage, sorts included
  if (!a.view.empty() && !a.eye.empty()) throw std::invalid_argument("give --view (orthographic) or --eye (perspective), not both");
  if (!ends_with(a.output, ".png")) throw std::invalid_argument("-o must name a .png file");
  if (!a.ids.empty() && !ends_with(a.ids, ".png") && !ends_with(a.ids, ".json"))
    throw std::invalid_argument("--ids must name a .png (16-bit, with a FILE.json legend) or a .json file");
  RasterOptions o = raster_options(a);
  ProgressLine progress_line("raster", a.progress, a.quiet);
  RasterResult r;
  try {
    r = raster_files(a.inputs, o);
  } catch (const RenderBodyError& e) {
    std::cerr << "hlr raster: " << e.what() << "\n";
    return 1;
  }
  for (const std::string& note : r.render.notes) std::cerr << "hlr raster: note: " << note << "\n";
  // Everything is formatted before anything is written: no partial set of outputs on failure.
  std::string image = png_rgb(r.width, r.height, r.rgb), ids, legend, camera;
  if (!a.ids.empty()) {
    if (ends_with(a.ids, ".png")) ids = ids_png(r.ids), legend = ids_legend_json(r);
    else ids = ids_json(r);
  }
  if (!a.camera.empty()) camera = raster_camera_json(r);
  progress("writing");
  write_file_atomically(a.output, image);
  if (!a.ids.empty()) write_file_atomically(a.ids, ids);
  if (!legend.empty()) write_file_atomically(a.ids + ".json", legend);
  if (!a.camera.empty()) write_file_atomically(a.camera, camera);
  if (a.timings) {
    std::size_t faces = 0;
    for (const SceneBody* b : r.render.bodies) faces += b->body.num_faces();
    const RasterCounters& c = r.scene.counters;
    std::cerr << std::fixed;
    std::cerr.precision(3);
    std::cerr << "timings: faces " << faces << ", polygons " << r.scene.polygons.size() << ", load " << r.seconds.load << " s, facing " << r.seconds.setup
              << " s, raster scene " << r.seconds.scene << " s, " << to_string(o.algorithm) << " " << r.seconds.visibility
              << " s, shading " << r.seconds.shading << " s; exact fallbacks: inside " << c.inside_exact << ", depth "
              << c.depth_exact << "\n";
  }
  exit_without_teardown(0);
  return 0;
}

}  // namespace

void add_raster_command(CLI::App& app, int& exit_code) {
  auto a = std::make_shared<RasterArgs>();
  CLI::App* cmd = app.add_subcommand("raster", "Image-space algorithms (z-buffer, scan-line, Warnock, ray casting) to PNG, exact at every pixel centre");
  cmd->add_option("inputs", a->inputs, "Mesh files (.off .obj .stl .ply) and scene files (.yaml .yml .json)")->required();
  cmd->add_option("-o,--output", a->output, "The image (.png)")->required();
  cmd->add_option("--algorithm", a->algorithm,
                  "zbuffer (default), scanline, warnock or raytrace: the same exact face at every pixel centre")
      ->check(CLI::IsMember({"zbuffer", "scanline", "warnock", "raytrace"}));
  cmd->add_option("--size", a->size, "WIDTHxHEIGHT in pixels (default 512x512), or WIDTH: the height from the camera's frame");
  cmd->add_option("--view", a->view, "Orthographic view: front, top, iso, ... or a direction X,Y,Z toward the viewer");
  cmd->add_option("--up-axis", a->up_axis, "Which axis is up for the named views: y (default) or z")->check(CLI::IsMember({"y", "z"}));
  cmd->add_option("--eye", a->eye, "Perspective: the eye point X,Y,Z");
  cmd->add_option("--target", a->target, "Perspective: the point looked at (default: centre of the scene)");
  cmd->add_option("--up", a->up, "Up direction X,Y,Z");
  cmd->add_option("--shading", a->shading, "flat (default), gouraud (intensities interpolated) or phong (normals interpolated)")
      ->check(CLI::IsMember({"flat", "gouraud", "phong"}));
  cmd->add_option("--smooth", a->smooth, "Gouraud and Phong: faces within this angle share vertex normals (default 40 degrees)");
  cmd->add_option("--samples", a->samples, "Antialiasing: N x N samples per pixel (default 1, at most 16)");
  cmd->add_option("--filter", a->filter, "How samples combine: box (default) or tent")->check(CLI::IsMember({"box", "tent"}));
  cmd->add_option("--bounces", a->bounces,
                  "Whitted ray tracing from the exact first hit: levels of reflected and refracted rays, with shadow rays "
                  "(default 0: local shading only; materials: reflection, transparency, ior)");
  cmd->add_option("--background", a->background, "Background colour #rrggbb (default #ffffff)");
  cmd->add_option("--ids", a->ids, "Also write the face seen at every sample centre: .png (16-bit, face + 1; legend in FILE.json) or .json");
  cmd->add_option("--camera", a->camera, "Also write the exact sample grid as JSON (origin, right and down steps: check any pixel exactly)");
  cmd->add_option("--threads", a->threads, "Threads (default 0: all cores)");
  cmd->add_flag("--timings", a->timings, "Print the time of each stage to standard error");
  cmd->add_flag("--progress", a->progress, "Say what it is doing on standard error (default: when it is a terminal)");
  cmd->add_flag("--quiet", a->quiet, "No progress messages");
  cmd->callback([a, &exit_code] { exit_code = run_raster(*a); });
}

}  // namespace hlr::cli
