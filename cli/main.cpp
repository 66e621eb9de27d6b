// The `hlr` command-line tool: exact hidden-line drawings of polyhedra.
// Exit codes: 0 success, 1 bad input or a failed requirement, 2 bad usage.
#include <iostream>

#include "cli/arguments.hpp"
#include "cli/commands.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "kernel/number.hpp"

int main(int argc, char** argv) {
  CLI::App app{"hlr: exact hidden-line removal for polyhedra"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "hlr 0.1.0");
  int exit_code = 0;
  hlr::cli::add_info_command(app, exit_code);
  hlr::cli::add_render_command(app, exit_code);
  hlr::cli::add_clip_command(app, exit_code);
  hlr::cli::add_decompose_command(app, exit_code);
  hlr::cli::add_explain_command(app, exit_code);
  try {
    std::vector<std::string> args = hlr::cli::join_negative_values(argc, argv);
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
