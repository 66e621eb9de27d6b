// The output options every drawing command shares (`hlr render`, `hlr horizon`):
// format by extension, hidden lines, dashes, page, scale, line weights, layers, specks, PNG
// resolution; and the step from exact line drawings to the text or bytes written (the plotting
// 2D stage, the page layout, the writers; or the exact JSON).
#pragma once

#include "io/writers/atomic_file.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "algorithms/plot/plot.hpp"
#include "io/pipeline/render.hpp"

namespace hlr::cli {

struct OutputArgs {
  std::string output, format, hidden = "none", dashes = "pattern", page, margin, scale, weights, layers, projection = "third";
  bool landscape = false, raw = false, stats = false, quiet = false, progress = false;
  double width = 150, stroke = 0.35, min_length = 0, dpi = 150;
  unsigned threads = 0;
};

/// Adds -o, --format, --hidden, --dashes, --page, --landscape, --margin, --scale, --width,
/// --stroke, --weights, --layers, --min-length, --dpi, --raw, --stats, --progress, --quiet,
/// --threads (and --projection when `sheets`).
void add_output_options(CLI::App* cmd, OutputArgs& a, bool sheets);

/// Checks the options (before any long work) and returns the format: svg, pdf, png, dxf, json.
std::string check_output_args(const OutputArgs& a, bool sheet);

/// The file's content, in parts (the JSON's segments made as they are written: `results` must
/// outlive the text): JSON of the first drawing (with the 2D stage's
/// numbers), or the sheet of all drawings (`view_names` label them and place them as standard
/// views when not empty).
PartText drawing_text(const std::vector<RenderResult>& results, const std::vector<std::string>& view_names, const OutputArgs& a,
                      const std::string& format, const std::string& command);

/// The plotting options of `a` (hidden layers, clean-up and chaining unless --raw, threads).
PlotOptions plot_options(const OutputArgs& a);

/// drawing_text()'s picture formats from plots already made (make_plot() or a faster route):
/// layers, page layout, specks, pen order, the writer.
std::string plots_text(std::vector<Plot>& plots, const std::vector<std::string>& view_names, const OutputArgs& a,
                       const std::string& format, const std::string& command, bool perspective = false);

}  // namespace hlr::cli
