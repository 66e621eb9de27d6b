// `hlr render [options] INPUT...`: parses the options into the library's RenderOptions, calls
// render() (io/pipeline/render.hpp), runs the plotting 2D stage (algorithms/plot/plot.hpp: exact clean-up,
// strokes, pen order), lays the view or views out on a page (io/writers/plot_output.hpp) and writes
// SVG, PDF, PNG, DXF or exact JSON (atomically: no partial output on failure).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>

#include "algorithms/support/parallel.hpp"
#include "algorithms/support/progress.hpp"
#include "cli/arguments.hpp"
#include "cli/commands.hpp"
#include "cli/drawing_output.hpp"
#include "cli/process.hpp"
#include "io/models/model_input.hpp"
#include "io/output/section_views.hpp"
#include "io/pipeline/render.hpp"
#include "io/pipeline/render_methods.hpp"
#include "io/readers/clipper_spec.hpp"
#include "io/readers/input_error.hpp"
#include "io/readers/tile_file.hpp"
#include "io/views/standard_views.hpp"
#include "io/writers/atomic_file.hpp"
#include "io/writers/json_writer.hpp"
#include "io/writers/plot_output.hpp"
#include "io/writers/svg_writer.hpp"

namespace hlr::cli {
namespace {

struct RenderArgs : OutputArgs {
  std::vector<std::string> inputs;
  std::string view, eye, target, up, edges = "feature", clip, near = "1/1000";
  std::string method = "faces", crease = "30";
  bool timings = false, surfaces = false, shadows = false, no_through = false;
  std::string views, up_axis;
  std::string tile;  // "I/N"
  std::vector<std::string> section, cutaway;
  std::string plan;  // a height: a floor plan
  std::string plan_depth;
  bool no_overhead = false;
  std::vector<std::string> section_views;        // "A=PLANE"
  std::vector<std::string> lines;                // polyline files
  std::string input_format;                      // the inputs' format whatever their names ("-": standard input)
  double deflection = 0, deflection_angle = 15;  // a STEP or IGES model's tessellation
  std::string tangent_edges = "thin", units;
};

ModelOptions model_options(const RenderArgs& a) {
  ModelOptions m;
  m.tessellation.deflection = a.deflection;
  m.tessellation.angle_degrees = a.deflection_angle;
  m.units = a.units;
  return m;
}

// A merge of tile files (hlr merge): the tiles and their paths.
struct MergeInput {
  std::vector<TileFile> tiles;
  std::vector<std::string> paths;
};

// "I/N" with 1 <= I <= N.
RenderOptions::Tile parse_tile(const std::string& text) {
  const std::size_t slash = text.find('/');
  try {
    std::size_t used = 0, used2 = 0;
    const std::string a = text.substr(0, slash), b = slash == std::string::npos ? "" : text.substr(slash + 1);
    const long i = std::stol(a, &used), n = std::stol(b, &used2);
    if (used == a.size() && used2 == b.size() && n >= 1 && n <= kMaxTiles && i >= 1 && i <= n)
      return RenderOptions::Tile{static_cast<int>(i - 1), static_cast<int>(n)};
  } catch (const std::exception&) {
  }
  throw std::invalid_argument("--tile: '" + text + "' is not I/N with 1 <= I <= N (e.g. 3/9: the third of nine tiles)");
}

// The render command's arguments for a tile file: without the ones a merge gives itself.
std::vector<std::string> tile_args() {
  const std::vector<std::string>& all = command_line();
  std::vector<std::string> out;
  const std::vector<std::string> with_value = {"--tile", "-o", "--format", "--threads"}, flags = {"--progress", "--quiet", "--timings"};
  for (std::size_t i = 2; i < all.size(); ++i) {
    const std::string& x = all[i];
    if (std::find(flags.begin(), flags.end(), x) != flags.end()) continue;
    if (std::find(with_value.begin(), with_value.end(), x) != with_value.end()) {
      ++i;
      continue;
    }
    bool joined = false;
    for (const std::string& w : with_value) joined = joined || x.rfind(w + "=", 0) == 0;
    if (!joined) out.push_back(x);
  }
  return out;
}


RenderOptions render_options(const RenderArgs& a) {
  RenderOptions o;
  o.method = parse_render_method(a.method);
  o.lines.edges = a.edges == "all" ? EdgeSelection::All : EdgeSelection::Feature;
  o.tangent_edges = a.tangent_edges == "none" ? TangentEdges::None : a.tangent_edges == "visible" ? TangentEdges::Visible : TangentEdges::Thin;
  o.lines.threads = a.threads;
  try {
    o.lines.crease_degrees = parse_rational(a.crease);
  } catch (const NumberError& e) {
    throw std::invalid_argument(std::string("--crease: ") + e.what());
  }
  if (o.lines.crease_degrees < 0 || o.lines.crease_degrees > 180)
    throw std::invalid_argument("--crease must be an angle in degrees from 0 to 180");
  o.view = parse_view_request(a.view, a.eye, a.target, a.up, a.up_axis);
  try {
    o.near = parse_rational(a.near);
  } catch (const NumberError& e) {
    throw std::invalid_argument(std::string("--near: ") + e.what());
  }
  if (!a.clip.empty()) o.clip = parse_clipper("--clip", a.clip).clipper;
  for (const std::string& s : a.section)
    for (Plane& h : parse_section("--section", s)) o.section.push_back(std::move(h));
  for (const std::string& s : a.cutaway)
    for (Plane& h : parse_section("--cutaway", s)) o.cutaway.push_back(std::move(h));
  if (!a.plan.empty()) {  // a horizontal section at the height along the up axis, kept below
    const std::string axis = a.up_axis == "z" ? "z" : "y";
    for (Plane& h : parse_section("--plan", axis + "<" + a.plan)) o.section.push_back(std::move(h));
    o.overhead = !a.no_overhead;
    if (!a.plan_depth.empty()) {  // lines drawn down to HEIGHT - DEPTH
      const std::vector<Rational> d = parse_numbers("--plan-depth", a.plan_depth, 1);
      if (d[0] <= 0) throw std::invalid_argument("--plan-depth must be a positive length below the cut");
      const int k = a.up_axis == "z" ? 2 : 1;
      const Plane& cut = o.section.back();  // cut[k]·axis + cut[3] <= 0 kept: HEIGHT = -cut[3] / cut[k]
      const Rational bottom = -cut[3] / cut[k] - d[0];
      o.view_depth = k == 2 ? Plane(0, 0, 1, -bottom) : Plane(0, 1, 0, -bottom);
    }
  } else if (!a.plan_depth.empty()) {
    throw std::invalid_argument("--plan-depth needs --plan");
  }
  o.surfaces = a.surfaces || a.hatch;
  o.shadows = a.shadows;
  o.through_lines = !a.no_through;
  return o;
}

// The plane of section view `name` (--section-view NAME=PLANE), if given.
std::optional<Plane> section_plane(const RenderArgs& a, const std::string& name) {
  for (const std::string& d : a.section_views) {
    const std::size_t eq = d.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::invalid_argument("--section-view: '" + d + "' is not NAME=PLANE (e.g. A=x<0: keep x <= 0, seen from +x)");
    if (d.substr(0, eq) != name) continue;
    std::vector<Plane> h = parse_section("--section-view " + name, d.substr(eq + 1));
    if (h.size() != 1) throw std::invalid_argument("--section-view " + name + ": a section view takes one plane");
    return h[0];
  }
  return std::nullopt;
}

int run_render(const RenderArgs& a, const MergeInput* merge = nullptr) {
  const ThreadLimit limit(a.threads);  // every parallel stage, sorts included
  if (!a.view.empty() && !a.eye.empty()) throw std::invalid_argument("give --view (orthographic) or --eye (perspective), not both");
  if (!a.views.empty() && (!a.view.empty() || !a.eye.empty())) throw std::invalid_argument("give --views (a sheet) or one --view/--eye, not both");
  std::optional<RenderOptions::Tile> tile;
  if (!a.tile.empty()) {
    tile = parse_tile(a.tile);
    if (!a.views.empty()) throw std::invalid_argument("--tile takes one view, not --views");
  }
  const std::string format = tile ? "tile" : check_output_args(a, !a.views.empty());  // before the long work
  ProgressLine progress_line("render", a.progress, a.quiet);
  using Clock = std::chrono::steady_clock;
  auto t_start = Clock::now();
  progress("loading");
  std::vector<Scene> scenes;
  const long stdin_uses = std::count(a.inputs.begin(), a.inputs.end(), "-") + std::count(a.lines.begin(), a.lines.end(), "-");
  if (stdin_uses > 1) throw std::invalid_argument("standard input ('-') can be read once: give it to one input or one --lines");
  for (const auto& in : a.inputs) scenes.push_back(load_any_input(in, a.input_format, model_options(a)));
  std::vector<Polyline3> polylines;  // read once: one file may be standard input
  for (const std::string& f : a.lines)
    for (Polyline3& l : read_polylines(f)) polylines.push_back(std::move(l));
  auto t_loaded = Clock::now();
  // Named views follow the scene's up axis: z when its view says up 0,0,1 (CAD, architecture).
  bool z_up = false;
  if (!scenes.empty() && scenes[0].view.up_given) {
    const Vector3& u = scenes[0].view.up;
    z_up = u.x() == 0 && u.y() == 0 && u.z() > 0;
  }
  // One render per view: --views names several standard views for one sheet.
  std::vector<std::string> view_names;
  if (!a.views.empty()) {
    for (std::size_t at = 0; at <= a.views.size();) {
      std::size_t comma = a.views.find(',', at);
      std::string v = a.views.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
      at = comma == std::string::npos ? a.views.size() + 1 : comma + 1;
      const std::string name = section_of_view_name(v);
      if (!name.empty()) {
        if (!section_plane(a, name)) throw std::invalid_argument("--views: section " + name + " is not given (--section-view " + name + "=PLANE)");
      } else if (!standard_view(v, false)) {
        throw std::invalid_argument("--views: '" + v + "' is not a standard view (" + standard_view_names() + ") or section:NAME");
      }
      view_names.push_back(v);
    }
  }
  const std::size_t n_views = std::max<std::size_t>(1, view_names.size());
  std::vector<RenderResult> results(n_views);
  for (std::size_t i = 0; i < n_views; ++i) {
    RenderArgs one = a;
    if (!view_names.empty()) one.view = view_names[i];
    if (one.up_axis.empty()) one.up_axis = z_up ? "z" : "y";
    if (!a.plan.empty() && one.view.empty() && one.eye.empty()) one.view = "top";  // a plan is seen from above
    const std::string section_name = view_names.empty() ? "" : section_of_view_name(view_names[i]);
    if (!section_name.empty()) one.view = "front";  // replaced by the section's own view below
    RenderOptions options = render_options(one);
    if (!section_name.empty()) {
      options.section_view = named_section(section_name, *section_plane(a, section_name), one.up_axis == "z");
      options.view = section_view_request(*options.section_view, one.up_axis == "z");
    }
    options.surface_corners = format == "json";  // hatching lifts what it needs itself
    options.surface_faces = format == "json" || a.hatch;
    options.surface_groups = !a.hatch;  // a hatched drawing has no fills
    options.tile = tile;
    options.polylines = polylines;
    options.segments_only = merge != nullptr;
    progress(view_names.empty() ? "hidden lines" : "hidden lines, view " + view_names[i]);
    try {
      results[i] = render(i + 1 < n_views ? scenes : std::move(scenes), options);
    } catch (const RenderBodyError& e) {
      std::cerr << "hlr render: " << e.what() << "\n";
      return 1;
    }
    if (i == 0)
      for (const std::string& note : results[i].notes) std::cerr << "hlr render: note: " << note << "\n";
  }
  if (merge) {
    progress("joining the tiles");
    merge_tiles(results[0].drawing, merge->tiles, merge->paths, a.threads);
  }
  auto t_solved = Clock::now();
  PartText text;
  if (tile) text.add(tile_text(results[0].drawing, tile->index, tile->count, tile_args()));
  else text = drawing_text(results, view_names, a, format, merge ? "merge" : "render");
  write_output(a.output, text);
  if (a.timings) {
    auto t_end = Clock::now();
    auto sec = [](auto d) { return std::chrono::duration<double>(d).count(); };
    std::size_t tris = 0;
    for (const SceneBody* b : results[0].bodies) tris += b->body.num_faces();
    const DrawingStats& st = results[0].drawing.stats;
    FaceRouteStats fs = st.faces.value_or(FaceRouteStats{});
    std::cerr << std::fixed;
    std::cerr.precision(3);
    std::cerr << "timings: faces " << tris << ", load " << sec(t_loaded - t_start) << " s, setup " << st.setup_seconds
              << " s, intersections " << st.intersections_seconds << " s, visibility " << st.visibility_seconds
              << " s, solve total " << sec(t_solved - t_loaded) << " s, output " << sec(t_end - t_solved) << " s, segments "
              << results[0].drawing.segments.size() << ", comparisons " << fs.comparisons << " (identical "
              << fs.comparisons_identical << ", exact fallback " << fs.comparisons_exact << ")"
              << "\n";
    if (const auto& sf = results[0].surfaces)
      std::cerr << "timings: surfaces " << sf->stats.seconds << " s, visible pieces " << sf->stats.segments << ", arrangement edges "
                << sf->stats.edges << ", cells " << sf->stats.cycles << ", crossings " << sf->stats.crossings << ", polygons "
                << sf->stats.polygons << ", fills " << sf->stats.fills << ", exact sign tests " << sf->stats.exact_tests << " (clean-up " << sf->stats.seconds_clean
                << " s, points " << sf->stats.seconds_points << " s, arrangement " << sf->stats.seconds_arrangement << " s, triangles " << sf->stats.seconds_triangles << " s, probes "
                << sf->stats.seconds_probe << " s, regions " << sf->stats.seconds_regions << " s)\n";
    if (const auto& sh = results[0].shadows)
      std::cerr << "timings: shadows " << sh->seconds << " s (views from the lights " << sh->seconds_lights << " s), lights "
                << sh->from_light.size() << ", faces " << sh->faces.size() << " (" << sh->whole_faces << " lit wholly or not at all)\n";
    if (const auto& pr = results[0].priority)
      std::cerr << "timings: priority list " << results[0].priority_seconds << " s, polygons " << pr->initial << ", painted "
                << pr->order.size() << ", pairs " << pr->pairs << ", swaps " << pr->swaps << ", cycles " << pr->cycles << ", cuts "
                << pr->splits << " (along outlines " << pr->outline_splits << ")\n";
  }
  exit_without_teardown(0);
  return 0;
}

void add_render_options(CLI::App* cmd, const std::shared_ptr<RenderArgs>& a) {
  cmd->add_option("inputs", a->inputs,
                  "Mesh files (.off .obj .stl .ply), models (.step .stp .iges .igs) and scene files (.yaml .yml .json); - is "
                  "standard input (with --input-format)")
      ->required();
  cmd->add_option("--deflection", a->deflection,
                  "A STEP or IGES model's tessellation: the largest distance in mm from a triangle to the surface (default: a "
                  "thousandth of the model's size)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--deflection-angle", a->deflection_angle,
                  "A STEP or IGES model's tessellation: the largest angle in degrees between neighbouring triangles of one "
                  "surface (default 15)")
      ->check(CLI::Range(0.01, 90.0));
  cmd->add_option("--tangent-edges", a->tangent_edges,
                  "Edges where two faces of a model meet tangentially: thin (default, a narrow line of their own, layer "
                  "'tangent'), none, or visible (as sharp edges)")
      ->check(CLI::IsMember({"thin", "none", "visible"}));
  cmd->add_option("--units", a->units,
                  "The length unit of mesh files (mm default, cm, m, in, ft, um): coordinates are brought to millimetres, so that "
                  "--scale 1:100 means a hundredth of the real size (models say their own unit)")
      ->check(CLI::IsMember({"mm", "cm", "m", "in", "ft", "um"}));
  cmd->add_option("--input-format", a->input_format,
                  "Read the inputs as off, obj, stl, ply, yaml or json whatever their names (needed for - , standard input)")
      ->check(CLI::IsMember({"off", "obj", "stl", "ply", "yaml", "json"}));
  add_output_options(cmd, *a, true);
  cmd->add_option("--view", a->view,
                  "Orthographic view: front, back, top, bottom, left, right, iso, dimetric, or a direction X,Y,Z from the scene "
                  "toward the viewer (default 0,0,1 = front)");
  cmd->add_option("--views", a->views,
                  "A sheet of standard views at one scale, e.g. front,top,right,iso, and section views section:NAME "
                  "(--section-view)");
  cmd->add_option("--up-axis", a->up_axis,
                  "Which axis is up for the named views: y or z (default: z when the scene's view has up 0,0,1, else y)")
      ->check(CLI::IsMember({"y", "z"}));
  cmd->add_option("--eye", a->eye, "Perspective: the eye point X,Y,Z");
  cmd->add_option("--target", a->target, "Perspective: the point looked at (default: centre of the scene's bounding box)");
  cmd->add_option("--up", a->up, "Up direction X,Y,Z (default 0,1,0, or 0,0,1 when looking along y)");
  cmd->add_option("--edges", a->edges,
                  "feature (default: boundaries, silhouettes, creases over --crease, intersection lines) or all (every mesh edge)")
      ->check(CLI::IsMember({"all", "feature"}));
  cmd->add_option("--crease", a->crease, "Crease threshold in degrees between face normals (default 30; 0 keeps every edge between non-coplanar faces)");
  std::string methods;
  for (const RenderMethodEntry& m : render_methods()) methods += std::string(methods.empty() ? "" : "; ") + m.name + " (" + m.help + ")";
  cmd->add_option("--method", a->method, methods)->check(CLI::IsMember(render_method_names()));
  cmd->add_flag("--surfaces", a->surfaces,
                "Also the visible part of every face as exact polygons, flat-shaded by the scene's lights and materials "
                "(SVG/PDF/PNG fills under the lines; JSON 'surfaces')");
  cmd->add_flag("--shadows", a->shadows,
                "Shadows of the scene's lights on the visible surfaces, as exact polygons (implies --surfaces; "
                "each region shaded by the lights that reach it; JSON 'shadows')");
  cmd->add_flag("--hatch", a->hatch,
                "Tone hatching for pen plotters: every visible region (with --shadows, lit and shadowed apart) hatched by its "
                "shade instead of filled, exact lines clipped to the exact visible polygons (implies --surfaces; layers "
                "'visible-tone-1' .. lightest to darkest)");
  cmd->add_option("--hatch-levels", a->hatch_levels, "Tone levels, 2 to 8 (default 5: white, then coverage 1/5 .. 4/5; over 1/2 cross-hatched)");
  cmd->add_option("--hatch-angle", a->hatch_angle,
                  "The hatch lines' angle on the page in degrees (default 45), or 'contour': each face's level lines");
  cmd->add_option("--hatch-pen", a->hatch_pen, "The hatching pen's width in mm (default 0.25, the 'tone' weight); spacing = pen / coverage");
  cmd->add_flag("--no-through", a->no_through,
                "Lines behind transparent bodies (material transparency > 0) count as hidden; by default they are their own "
                "class, seen through (thin grey layers 'through-*', JSON pieces with \"through\": true)");
  cmd->add_flag("--timings", a->timings, "Print the time of each stage to standard error");
  cmd->add_option("--clip", a->clip,
                  "Clip the drawing to box:XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX, frustum:XL,XR,YB,YT,ZNEAR,ZFAR,ZCP or a convex mesh file");
  cmd->add_option("--section", a->section,
                  "Cut the bodies and keep z<1.2 (or x>0, A,B,C,D for A*x+B*y+C*z+D <= 0, box:XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX); "
                  "repeat to keep the intersection. What is removed hides nothing; each cut body gets exact caps, cut lines "
                  "(layer 'visible-cut') and hatching ('visible-hatch')");
  cmd->add_option("--cutaway", a->cutaway,
                  "Remove the region where every --cutaway half-space holds (same forms as --section; 'x>0' and 'y>0': a half "
                  "section's quarter) and close the cut bodies with caps");
  cmd->add_option("--plan", a->plan,
                  "A floor plan: a section at this height along the up axis, the part below kept, seen from above (--view top "
                  "unless a view is given)");
  cmd->add_option("--plan-depth", a->plan_depth, "A plan's view depth: lines are drawn down to this far below the cut (default: all the way down)");
  cmd->add_option("--section-view", a->section_views,
                  "A named section for --views section:NAME, as NAME=PLANE (e.g. A=x<0: keep x <= 0, seen from +x, labelled "
                  "A-A); the other views that see the plane edge-on show its section line, arrows and letters");
  cmd->add_flag("--no-overhead", a->no_overhead,
                "A plan without its overhead lines (what lies above the cut, seen from below, dashed: layer 'visible-overhead')");
  cmd->add_option("--lines", a->lines,
                  "Your own 3D polylines, drawn with their hidden parts removed by the bodies (layers 'visible-polyline', "
                  "'hidden-polyline'): a text file, one polyline per line as x y z x y z ... ('-': standard input)");
  cmd->add_option("--near", a->near,
                  "Perspective near plane at this fraction of the eye-target distance from the eye (default 1/1000)");
  cmd->add_option("--tile", a->tile,
                  "Only tile I of an N-tile split of the picture, as a tile file for hlr merge (I/N, e.g. 3/9; the per-face route's "
                  "line drawings)");
}

struct MergeArgs {
  std::vector<std::string> tiles;
  std::string output, format;
  unsigned threads = 0;
  bool progress = false, quiet = false, timings = false;
};

int run_merge(const MergeArgs& m) {
  const ThreadLimit limit(m.threads);  // every parallel stage, sorts included
  MergeInput in;
  in.paths = m.tiles;
  in.tiles.resize(m.tiles.size());
  // Read on every core; the first bad file (in the order given) is the one reported.
  std::vector<std::exception_ptr> failed(m.tiles.size());
  ParallelLoop(m.threads).for_each(m.tiles.size(), 1, [&](std::size_t k) {
    try {
      in.tiles[k] = read_tile(m.tiles[k]);
    } catch (...) {
      failed[k] = std::current_exception();
    }
  });
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
  // The render the tiles came from, with this command's output.
  CLI::App again;
  auto a = std::make_shared<RenderArgs>();
  add_render_options(&again, a);
  std::vector<std::string> args(in.tiles[0].args.rbegin(), in.tiles[0].args.rend());
  try {
    again.parse(args);
  } catch (const CLI::ParseError& e) {
    throw InputError(in.paths[0], 0, std::string("its render arguments do not parse: ") + e.what());
  }
  a->output = m.output, a->format = m.format, a->threads = m.threads;
  a->progress = m.progress, a->quiet = m.quiet, a->timings = m.timings, a->tile.clear();
  return run_render(*a, &in);
}

}  // namespace

void add_render_command(CLI::App& app, int& exit_code) {
  auto a = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Exact hidden-line drawing as SVG, PDF, PNG, DXF or JSON");
  add_render_options(cmd, a);
  cmd->callback([a, &exit_code] { exit_code = run_render(*a); });
  auto m = std::make_shared<MergeArgs>();
  CLI::App* mc = app.add_subcommand("merge", "Join the tile files of hlr render --tile I/N into the whole drawing (SVG, PDF, PNG, DXF or JSON)");
  mc->add_option("tiles", m->tiles, "The tile files, every tile of the split once, any order")->required();
  mc->add_option("-o", m->output, "Output file (default: standard output); the extension picks the format");
  mc->add_option("--format", m->format, "svg, pdf, png, dxf or json (default: from the output file's extension, else svg)");
  mc->add_option("--threads", m->threads, "Threads (default: all cores)");
  mc->add_flag("--progress", m->progress, "Say what it is doing on standard error");
  mc->add_flag("--quiet", m->quiet, "No progress messages");
  mc->add_flag("--timings", m->timings, "Print the time of each stage to standard error");
  mc->callback([m, &exit_code] { exit_code = run_merge(*m); });
}

}  // namespace hlr::cli
