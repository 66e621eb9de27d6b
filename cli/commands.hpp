// The subcommands of the `hlr` executable.
#pragma once

#include <CLI/CLI.hpp>

namespace hlr::cli {

/// Registers `hlr info` on the app; the callback sets `exit_code`.
void add_info_command(CLI::App& app, int& exit_code);

/// Registers `hlr render`.
void add_render_command(CLI::App& app, int& exit_code);

/// Registers `hlr decompose`.
void add_decompose_command(CLI::App& app, int& exit_code);

/// Registers `hlr explain`.
void add_explain_command(CLI::App& app, int& exit_code);

/// Registers `hlr clip`.
void add_clip_command(CLI::App& app, int& exit_code);

/// `hlr raster`: the image-space algorithms to PNG.
void add_raster_command(CLI::App& app, int& exit_code);

/// `hlr horizon`: the exact floating horizon of a surface y = f(x, z).
void add_horizon_command(CLI::App& app, int& exit_code);

}  // namespace hlr::cli
