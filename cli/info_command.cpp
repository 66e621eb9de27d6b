// `hlr info FILE...`: counts, checks, convexity and (with --matrix) the body matrix of every
// body in mesh and scene files; `--require` turns checks into a non-zero exit.
#include <iostream>
#include <sstream>

#include "algorithms/support/progress.hpp"
#include "cli/arguments.hpp"
#include "cli/commands.hpp"
#include "io/models/model_input.hpp"
#include "io/pipeline/info_report.hpp"
#include "io/readers/scene.hpp"

namespace hlr::cli {
namespace {

struct InfoArgs {
  std::vector<std::string> inputs;
  bool matrix = false, progress = false, quiet = false;
  std::string require;
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, sep))
    if (!item.empty()) out.push_back(item);
  return out;
}

int run_info(const InfoArgs& a) {
  std::vector<std::string> required = split(a.require, ',');
  for (const auto& r : required) {
    const auto& names = requirement_names();
    if (std::find(names.begin(), names.end(), r) == names.end()) {
      std::string known;
      for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
      std::cerr << "hlr info: unknown requirement '" << r << "' (known: " << known << ")\n";
      return 2;
    }
  }
  InfoOptions opt;
  opt.matrix = a.matrix;
  ProgressLine line("info", a.progress, a.quiet);
  int failures = 0;
  for (const auto& input : a.inputs) {
    progress("loading " + input);
    Scene scene = load_any_input(input, "", ModelOptions{});  // meshes, models (STEP, IGES, glTF, 3MF) and scenes
    if (is_scene_file(input)) {
      std::cout << "scene " << input << ": " << scene.bodies.size() << " bodies, view ";
      if (scene.view.type == View::Type::Orthographic)
        std::cout << "orthographic toward " << to_string(scene.view.direction);
      else
        std::cout << "perspective from " << to_string(scene.view.eye);
      if (scene.light) std::cout << ", light " << to_string(*scene.light);
      std::cout << "\n";
    }
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      progress("checking body " + std::to_string(i) + " (" + std::to_string(scene.bodies[i].body.num_faces()) + " faces)");
      std::cout << info_report(scene.bodies[i], static_cast<int>(i), opt);
      for (const auto& r : required) {
        std::string why = requirement_failure(scene.bodies[i], r);
        if (!why.empty()) {
          std::cerr << "hlr info: " << input << ": body '" << scene.bodies[i].name << "' " << why << "\n";
          ++failures;
        }
      }
    }
  }
  return failures ? 1 : 0;
}

}  // namespace

void add_info_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<InfoArgs>();
  CLI::App* cmd = app.add_subcommand("info", "Counts, mesh checks, convexity and body matrix of each body");
  cmd->add_option("inputs", args->inputs, "Mesh files (.off .obj .stl .ply) and scene files (.yaml .yml .json)")
      ->required();
  cmd->add_flag("--matrix", args->matrix, "Print the sign-corrected body matrix [V] of small convex bodies");
  cmd->add_flag("--progress", args->progress, "Say what it is doing on standard error (default: when it is a terminal)");
  cmd->add_flag("--quiet", args->quiet, "No progress messages");
  cmd->add_option("--require", args->require,
                  "Comma-separated checks that must hold, else exit 1: closed, manifold, oriented, planar, "
                  "nondegenerate, distinct, convex, solid");
  cmd->callback([args, &exit_code] { exit_code = run_info(*args); });
}

}  // namespace hlr::cli
