// The `hlr` command-line tool: exact hidden-line drawings of polyhedra.
// Exit codes: 0 success, 1 bad input or a failed requirement, 2 bad usage.
#include <iostream>

#include "cli/commands.hpp"
#include "io/input_error.hpp"
#include "kernel/number.hpp"

int main(int argc, char** argv) {
  CLI::App app{"hlr: exact hidden-line removal for polyhedra"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "hlr 0.1.0");
  int exit_code = 0;
  hlr::cli::add_info_command(app, exit_code);
  try {
    app.parse(argc, argv);
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
  } catch (const std::bad_alloc&) {
    std::cerr << "hlr: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "hlr: error: " << e.what() << "\n";
    return 1;
  }
  return exit_code;
}
