// The options of `hlr render` on the command line: the library's RenderRequest (io/request/
// render_request.hpp) with what only a command has (output file, progress, tiles, polyline
// files). The Python package parses its keywords with the same table, so both take the same
// options with the same defaults and the same messages.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

#include "cli/drawing_output.hpp"
#include "io/request/render_request.hpp"

namespace hlr::cli {

struct RenderArgs : RenderRequest, OutputFlags {
  std::vector<std::string> inputs;
  bool timings = false;
  std::string tile;                    // "I/N"
  std::vector<std::string> lines;      // polyline files
  std::vector<std::string> each_view;  // every --view, in order: more than one is a batch of drawings
};

/// Adds every option of `hlr render` (inputs, output options, views, methods, sections, ...) to `cmd`.
void add_render_options(CLI::App* cmd, const std::shared_ptr<RenderArgs>& a);

}  // namespace hlr::cli
