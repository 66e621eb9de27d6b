// `hlr render [options] INPUT...`: parses the options (render_arguments.hpp) into the library's
// render request (io/request/render_request.hpp: one view or a sheet, then the 2D stage and the
// page) and writes SVG, PDF, PNG, DXF or exact JSON (atomically: no partial output on failure);
// also tiles and their merge.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <set>

#include "algorithms/support/parallel.hpp"
#include "algorithms/support/progress.hpp"
#include "cli/arguments.hpp"
#include "cli/commands.hpp"
#include "cli/drawing_output.hpp"
#include "cli/process.hpp"
#include "cli/render_arguments.hpp"
#include "io/readers/input_error.hpp"
#include "io/readers/tile_file.hpp"
#include "io/request/render_request.hpp"
#include "io/writers/atomic_file.hpp"

namespace hlr::cli {
namespace {

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

void print_timings(const std::vector<RenderResult>& results, double load, double solve, double output) {
  std::size_t tris = 0;
  for (const SceneBody* b : results[0].bodies) tris += b->body.num_faces();
  const DrawingStats& st = results[0].drawing.stats;
  FaceRouteStats fs = st.faces.value_or(FaceRouteStats{});
  std::cerr << std::fixed;
  std::cerr.precision(3);
  std::cerr << "timings: faces " << tris << ", load " << load << " s, setup " << st.setup_seconds << " s, intersections " << st.intersections_seconds
            << " s, visibility " << st.visibility_seconds << " s, solve total " << solve << " s, output " << output << " s, segments "
            << results[0].drawing.segments.size() << ", comparisons " << fs.comparisons << " (identical " << fs.comparisons_identical
            << ", exact fallback " << fs.comparisons_exact << ")"
            << "\n";
  if (const auto& sf = results[0].surfaces)
    std::cerr << "timings: surfaces " << sf->stats.seconds << " s, visible pieces " << sf->stats.segments << ", arrangement edges " << sf->stats.edges
              << ", cells " << sf->stats.cycles << ", crossings " << sf->stats.crossings << ", polygons " << sf->stats.polygons << ", fills "
              << sf->stats.fills << ", exact sign tests " << sf->stats.exact_tests << " (clean-up " << sf->stats.seconds_clean << " s, points "
              << sf->stats.seconds_points << " s, arrangement " << sf->stats.seconds_arrangement << " s, triangles " << sf->stats.seconds_triangles
              << " s, probes " << sf->stats.seconds_probe << " s, regions " << sf->stats.seconds_regions << " s)\n";
  if (const auto& sh = results[0].shadows)
    std::cerr << "timings: shadows " << sh->seconds << " s (views from the lights " << sh->seconds_lights << " s), lights " << sh->from_light.size()
              << ", faces " << sh->faces.size() << " (" << sh->whole_faces << " lit wholly or not at all)\n";
  if (const auto& pr = results[0].priority)
    std::cerr << "timings: priority list " << results[0].priority_seconds << " s, polygons " << pr->initial << ", painted " << pr->order.size()
              << ", pairs " << pr->pairs << ", swaps " << pr->swaps << ", cycles " << pr->cycles << ", cuts " << pr->splits << " (along outlines "
              << pr->outline_splits << ")\n";
}

// The drawings of one command: one (a view or a sheet), or a batch, one per --view with its -o.
std::vector<RenderArgs> drawings_of(const RenderArgs& a) {
  if (a.each_view.size() <= 1) {
    RenderArgs one = a;
    one.outputs.clear();
    if (a.outputs.size() > 1) one.outputs = a.outputs;  // refused by check_output_args
    return {one};
  }
  if (!a.views.empty() || !a.eye.empty()) throw std::invalid_argument("a batch of --view drawings takes no --views or --eye");
  if (!a.tile.empty()) throw std::invalid_argument("--tile takes one view, not a batch of --view drawings");
  if (a.outputs.size() != a.each_view.size())
    throw std::invalid_argument("a batch of drawings needs one -o for each --view, in the same order (" + std::to_string(a.each_view.size()) +
                                " --view, " + std::to_string(a.outputs.size()) + " -o)");
  std::set<std::string> seen;
  std::vector<RenderArgs> out;
  for (std::size_t i = 0; i < a.each_view.size(); ++i) {
    if (!seen.insert(a.outputs[i]).second) throw std::invalid_argument("-o " + a.outputs[i] + " is given twice: each drawing needs its own file");
    RenderArgs one = a;
    one.view = a.each_view[i], one.output = a.outputs[i];
    one.each_view = {one.view}, one.outputs.clear();
    out.push_back(std::move(one));
  }
  return out;
}

int run_render(const RenderArgs& all, const MergeInput* merge = nullptr) {
  const ThreadLimit limit(all.threads);  // every parallel stage, sorts included
  std::optional<RenderOptions::Tile> tile;
  if (!all.tile.empty()) tile = parse_tile(all.tile);
  const std::vector<RenderArgs> drawings = drawings_of(all);
  std::vector<std::string> formats;
  for (const RenderArgs& a : drawings) {  // before the long work
    check_request(a, tile.has_value());
    formats.push_back(tile ? "tile" : check_output_args(a, a, !a.views.empty()));
  }
  ProgressLine progress_line("render", all.progress, all.quiet);
  using Clock = std::chrono::steady_clock;
  auto sec = [](auto d) { return std::chrono::duration<double>(d).count(); };
  auto t_start = Clock::now();
  progress("loading");
  std::vector<Scene> scenes;  // loaded once for every drawing
  const long stdin_uses = std::count(all.inputs.begin(), all.inputs.end(), "-") + std::count(all.lines.begin(), all.lines.end(), "-");
  if (stdin_uses > 1) throw std::invalid_argument("standard input ('-') can be read once: give it to one input or one --lines");
  for (const auto& in : all.inputs) scenes.push_back(load_request_input(all, in));
  RenderExtras extras;
  extras.tile = tile;
  extras.segments_only = merge != nullptr;
  if (drawings.size() > 1) extras.share = std::make_shared<ViewShare>();
  for (const std::string& f : all.lines)  // read once: one file may be standard input
    for (Polyline3& l : read_polylines(f)) extras.polylines.push_back(std::move(l));
  const double load = sec(Clock::now() - t_start);
  // Every drawing is made before any file is written: a failure leaves no file of the batch.
  std::vector<PartText> texts(drawings.size());
  std::set<std::string> noted;
  std::vector<std::array<double, 2>> times;
  std::vector<std::unique_ptr<RenderedViews>> kept;  // the texts refer to them until written
  for (std::size_t d = 0; d < drawings.size(); ++d) {
    const RenderArgs& a = drawings[d];
    if (drawings.size() > 1) progress("drawing " + std::to_string(d + 1) + " of " + std::to_string(drawings.size()) + ", " + a.output);
    auto t_begin = Clock::now();
    kept.push_back(std::make_unique<RenderedViews>());
    RenderedViews& views = *kept.back();
    try {
      views = render_request(d + 1 < drawings.size() ? scenes : std::move(scenes), a, formats[d], extras);
    } catch (const RenderBodyError& e) {
      std::cerr << "hlr render: " << e.what() << "\n";
      return 1;
    }
    std::vector<RenderResult>& results = views.results;
    for (const std::string& note : results[0].notes)
      if (noted.insert(note).second) std::cerr << "hlr render: note: " << note << "\n";
    if (merge) {
      progress("joining the tiles");
      merge_tiles(results[0].drawing, merge->tiles, merge->paths, a.threads);
    }
    auto t_solved = Clock::now();
    if (tile) texts[d].add(tile_text(results[0].drawing, tile->index, tile->count, tile_args()));
    else texts[d] = request_text(views, a, formats[d], merge ? "merge" : "render");
    times.push_back({sec(t_solved - t_begin), sec(Clock::now() - t_solved)});
  }
  for (std::size_t d = 0; d < drawings.size(); ++d) write_output(drawings[d].output, texts[d]);
  if (all.timings)
    for (std::size_t d = 0; d < drawings.size(); ++d) print_timings(kept[d]->results, d == 0 ? load : 0.0, times[d][0], times[d][1]);
  exit_without_teardown(0);
  return 0;
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
