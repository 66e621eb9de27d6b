// The `hlr` command-line tool: exact hidden-line drawings of polyhedra.
// Exit codes: 0 success, 1 bad input or a failed requirement, 2 bad usage.
#include <algorithm>
#include <iostream>
#include <vector>

#include "cli/arguments.hpp"
#include "cli/commands.hpp"
#include "cli/process.hpp"
#include "io/writers/atomic_file.hpp"
#include "io/readers/input_error.hpp"
#include "kernel/gmp_pool.hpp"
#include "kernel/number.hpp"

int main(int argc, char** argv) {
  hlr::cli::use_huge_pages(argv);
  hlr::cli::use_number_pool();
  hlr::cli::report_arithmetic_faults();
  CLI::App app{"hlr: exact hidden-line removal for polyhedra"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "hlr " HLR_VERSION);
  int exit_code = 0;
  hlr::cli::add_info_command(app, exit_code);
  hlr::cli::add_render_command(app, exit_code);
  hlr::cli::add_clip_command(app, exit_code);
  hlr::cli::add_decompose_command(app, exit_code);
  hlr::cli::add_explain_command(app, exit_code);
  hlr::cli::add_horizon_command(app, exit_code);
  hlr::cli::add_raster_command(app, exit_code);
  // A mistyped command: name the nearest one.
  if (argc > 1 && argv[1][0] != '-') {
    std::string given = argv[1], best;
    std::size_t best_d = 99;
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands({})) {
      const std::string& name = sub->get_name();
      known = known || name == given;
      // Edit distance (Levenshtein), small strings.
      std::vector<std::size_t> row(name.size() + 1);
      for (std::size_t j = 0; j <= name.size(); ++j) row[j] = j;
      for (std::size_t i = 1; i <= given.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= name.size(); ++j) {
          std::size_t up = row[j];
          row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (given[i - 1] == name[j - 1] ? 0 : 1)});
          diag = up;
        }
      }
      if (row[name.size()] < best_d) best_d = row[name.size()], best = name;
    }
    if (!known) {
      std::cerr << "hlr: unknown command '" << given << "'";
      if (best_d <= 3) std::cerr << "; did you mean '" << best << "'?";
      std::cerr << " (commands: info, render, merge, raster, clip, decompose, explain, horizon; hlr --help)\n";
      return 2;
    }
  }
  try {
    std::vector<std::string> args = hlr::cli::join_negative_values(argc, argv);
    hlr::cli::set_command_line(args);
    std::vector<std::string> rest(args.rbegin(), args.rend() - 1);  // CLI11 takes them reversed
    app.parse(rest);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "hlr: " << e.what() << "\n";
    return 2;
  } catch (const hlr::InputError& e) {
    std::cerr << "hlr: " << e.what() << "\n";
    return 1;
  } catch (const hlr::NumberError& e) {
    std::cerr << "hlr: " << e.what() << "\n";
    return 1;
  } catch (const hlr::OutputError& e) {
    std::cerr << "hlr: " << e.what() << "\n";
    return 1;
  } catch (const std::invalid_argument& e) {
    std::cerr << "hlr: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "hlr: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "hlr: error: " << e.what() << "\n";
    return 1;
  }
  return exit_code;
}
