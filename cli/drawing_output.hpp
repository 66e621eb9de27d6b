// The output options every drawing command shares (`hlr render`, `hlr horizon`) on the command
// line: format by extension, hidden lines, dashes, page, scale, line weights, layers, specks,
// PNG resolution. The output stage itself is the library's (io/output/output.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "io/output/output.hpp"

namespace hlr::cli {

/// What a command's output options hold besides the library's OutputOptions.
struct OutputFlags {
  std::string output;                // the last -o
  std::vector<std::string> outputs;  // every -o, in order (hlr render's batch of drawings pairs them with --view)
  bool quiet = false, progress = false;
};

struct OutputArgs : OutputOptions, OutputFlags {};

/// Adds -o, --format, --hidden, --dashes, --page, --landscape, --margin, --scale, --width,
/// --stroke, --weights, --layers, --min-length, --dpi, --raw, --stats, --progress, --quiet,
/// --threads (and --projection when `sheets`).
void add_output_options(CLI::App* cmd, OutputOptions& a, OutputFlags& f, bool sheets);

/// Checks the options (before any long work) and returns the format: svg, pdf, png, dxf, json.
std::string check_output_args(const OutputOptions& a, const OutputFlags& f, bool sheet);

}  // namespace hlr::cli
