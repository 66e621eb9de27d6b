// `hlr horizon`: a surface y = f(x, z), from an expression or a CSV height grid, drawn by the
// exact floating horizon (course notes section 24), through the same 2D stage and
// writers as `hlr render`.
#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>

#include "algorithms/support/parallel.hpp"
#include "algorithms/support/progress.hpp"
#include "cli/arguments.hpp"
#include "cli/commands.hpp"
#include "cli/drawing_output.hpp"
#include "cli/process.hpp"
#include "io/pipeline/horizon.hpp"
#include "io/views/view_choice.hpp"
#include "io/writers/atomic_file.hpp"
#include "kernel/rotation.hpp"

namespace hlr::cli {
namespace {

struct HorizonArgs : OutputArgs {
  std::string expression, grid, x = "-1:1", z = "-1:1", view, angles = "30,30", up, method = "exact", height = "1/4", cuts = "z";
  double dx = 0;
  bool timings = false;
};

Vector3 view_from_angles(const std::string& text) {
  auto comma = text.find(',');
  if (comma == std::string::npos) throw std::invalid_argument("--angles: '" + text + "' is not ELEVATION,AZIMUTH in degrees");
  try {
    return horizon_view_from_angles(parse_rational(text.substr(0, comma)), parse_rational(text.substr(comma + 1)));
  } catch (const NumberError& err) {
    throw std::invalid_argument(std::string("--angles: ") + err.what());
  }
}

int run_horizon(const HorizonArgs& a) {
  const ThreadLimit limit(a.threads);  // every parallel stage, sorts included
  if (a.expression.empty() == a.grid.empty()) throw std::invalid_argument("give --expr EXPRESSION or --grid FILE.csv (one of them)");
  const std::string format = check_output_args(a, a, false);
  SampleRange x = parse_sample_range("--x", a.x, 81), z = parse_sample_range("--z", a.z, 41);
  Vector3 v = a.view.empty() ? view_from_angles(a.angles) : parse_vector3("--view", a.view);
  std::optional<Vector3> up;
  if (!a.up.empty()) up = parse_vector3("--up", a.up);
  Camera cam = make_orthographic(v, up);
  ProgressLine line("horizon", a.progress, a.quiet);
  progress("sampling");
  Rational height;
  try {
    height = parse_rational(a.height);
  } catch (const NumberError& e) {
    throw std::invalid_argument(std::string("--height: ") + e.what());
  }
  using Clock = std::chrono::steady_clock;
  auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  auto t0 = Clock::now();
  HeightGrid g = a.grid.empty() ? grid_from_expression(a.expression, x, z, a.threads) : grid_from_file(a.grid, x, z, height);
  const double t_sampling = since(t0);
  progress("floating horizon (" + std::to_string(g.zs.size()) + " cuts of " + std::to_string(g.xs.size()) + " samples)");
  std::vector<RenderResult> results;
  if (a.method == "classic" && !(a.dx > 0)) throw std::invalid_argument("--method classic needs --dx (the column width in drawing units)");
  t0 = Clock::now();
  const HorizonDrawing hd(g, cam, a.method == "classic" ? a.dx : 0, a.cuts, a.threads);
  const double t_horizon = since(t0);
  // The picture formats straight from the runs where the clean-up needs no exact decision
  // (HorizonDrawing::plot); JSON, --raw and the rest through the exact model.
  t0 = Clock::now();
  PartText text;
  double t_model = 0;
  std::optional<Plot> plot;
  if (format != "json" && !a.raw) {
    progress("strokes");
    plot = hd.plot(plot_options(a));
  }
  if (plot) {
    std::vector<Plot> plots{std::move(*plot)};
    text.add(plots_text(plots, {}, a, format, "horizon"));
  } else {
    results.push_back(hd.model(a.grid.empty() ? "y = " + a.expression : a.grid));
    t_model = since(t0);
    t0 = Clock::now();
    text = drawing_text(results, {}, a, format, "horizon");
  }
  const double t_output = since(t0);
  t0 = Clock::now();
  write_output(a.output, text);
  if (a.timings)
    std::cerr << "timings: sampling " << t_sampling << " s, horizon " << t_horizon << " s, "
              << (plot ? std::string("straight to the 2D stage") : "drawing model " + std::to_string(t_model) + " s")
              << ", 2D stage and format " << t_output << " s, write " << since(t0) << " s\n";
  exit_without_teardown(0);
  return 0;
}

}  // namespace

void add_horizon_command(CLI::App& app, int& exit_code) {
  auto a = std::make_shared<HorizonArgs>();
  CLI::App* cmd = app.add_subcommand("horizon", "A surface y = f(x, z) by the exact floating horizon (course notes section 24)");
  cmd->add_option("--expr", a->expression, "y as an expression of x and z (muparser: sin, cos, exp, sqrt, ^, ...)");
  cmd->add_option("--grid", a->grid,
                  "Heights from a file: .csv (one row per z cut, one column per x sample, exact decimals), or a grey .pgm/.png heightmap");
  cmd->add_option("--height", a->height, "Heightmaps: the height of the brightest value (default 1/4; exact)");
  cmd->add_option("--x", a->x, "x range FROM:TO[:SAMPLES] (default -1:1:81; for --grid the columns set the count)");
  cmd->add_option("--z", a->z, "z range FROM:TO[:CUTS] (default -1:1:41; for --grid the rows set the count)");
  cmd->add_option("--angles", a->angles, "View as the notes turn it: ELEVATION,AZIMUTH in degrees (about x, then y; default 30,30; each realised exactly within 0.001 degree)");
  cmd->add_option("--view", a->view, "View direction X,Y,Z toward the viewer (instead of --angles; needs a z component)");
  cmd->add_option("--up", a->up, "Up direction (default 0,1,0)");
  cmd->add_option("--cuts", a->cuts, "z (default: the cuts z = const and the side edges), x (the cuts x = const) or both (a grid)")
      ->check(CLI::IsMember({"z", "x", "both"}));
  cmd->add_option("--method", a->method, "exact (default) or classic: the notes' per-column arrays, approximate, to compare")
      ->check(CLI::IsMember({"exact", "classic"}));
  cmd->add_option("--dx", a->dx, "classic: the column width in the picture (drawing units)");
  add_output_options(cmd, *a, *a, false);
  cmd->add_flag("--timings", a->timings, "Print the time of each stage to standard error");
  cmd->callback([a, &exit_code] { exit_code = run_horizon(*a); });
}

}  // namespace hlr::cli
