// The output options on the command line (see drawing_output.hpp); the output stage itself is
// the library's (io/output/output.hpp).
#include "cli/drawing_output.hpp"

#include <unistd.h>

#include "cli/arguments.hpp"

namespace hlr::cli {

void add_output_options(CLI::App* cmd, OutputOptions& a, OutputFlags& f, bool sheets) {
  cmd->add_option("-o", f.output, "Output file (default: standard output); the extension picks the format (.svg .pdf .png .dxf .json)")
      ->each([&f](const std::string& o) { f.outputs.push_back(o); })
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  cmd->add_option("--format", a.format, "svg, pdf, png, dxf or json (default: from the output file's extension, else svg)")
      ->check(CLI::IsMember({"svg", "pdf", "png", "dxf", "json"}));
  if (sheets)
    cmd->add_option("--projection", a.projection, "Arrangement of --views: third (top above front; default) or first angle")
        ->check(CLI::IsMember({"first", "third"}));
  cmd->add_option("--hidden", a.hidden, "none, dashed or solid (default none); hidden lines go to their own layers")
      ->check(CLI::IsMember({"none", "dashed", "solid"}));
  cmd->add_option("--dashes", a.dashes, "pattern (stroke-dasharray, continuous along each stroke) or geometry (real dash strokes for plotters)")
      ->check(CLI::IsMember({"pattern", "geometry"}));
  cmd->add_option("--threads", a.threads, "Threads (default: all cores)");
  cmd->add_flag("--stats", a.stats, "Print the 2D stage's numbers (paths, pen-up and pen-down lengths in mm) to standard error");
  cmd->add_flag("--progress", f.progress, "Say what it is doing on standard error (default: when it is a terminal)");
  cmd->add_flag("--quiet", f.quiet, "No progress messages");
  cmd->add_option("--page", a.page, "Page: A0..A5, letter, legal, tabloid or WxHmm (default: the drawing's own size)");
  cmd->add_flag("--landscape", a.landscape, "Turn the page to landscape");
  cmd->add_option("--margin", a.margin, "Margin in millimetres (default 10 on a page)");
  cmd->add_option("--scale", a.scale, "True scale 1:N or N:1 (scene units are millimetres; default: fit the page)");
  cmd->add_option("--width", a.width, "Drawing width in millimetres without --page (default 150)");
  cmd->add_option("--stroke", a.stroke,
                  "Width of visible edges in millimetres (default 0.5, ISO 128's wide line; hidden, tangent and hatch lines 0.25 and "
                  "cut lines 0.7 in proportion)");
  cmd->add_option("--line-widths", a.line_widths,
                  "iso (default: one wide width for every visible edge, ISO 128) or kinds (outlines 0.5, other visible edges 0.35)")
      ->check(CLI::IsMember({"iso", "kinds"}));
  cmd->add_option("--weights", a.weights, "Line widths per kind in mm, e.g. silhouette=0.7,crease=0.35,hidden=0.18");
  cmd->add_option("--layers", a.layers,
                  "Layers to write: visible, through, hidden, visible-silhouette, through-edge, hidden-crease, ... or their numbers");
  cmd->add_option("--pens", a.pens,
                  "Layer numbers by pen, stable whatever --layers selects: e.g. visible=1,hidden=2,tone=3 (a key is a layer, "
                  "its kind or visible/hidden/through; the most particular wins; every layer needs a pen)");
  cmd->add_option("--min-length", a.min_length, "Drop strokes shorter than this many millimetres on the page (specks; after dashes are cut)");
  cmd->add_option("--merge-tolerance", a.merge_tolerance,
                  "Lines closer than this on the page (mm), nearly parallel, are drawn once, the higher class kept (visible over "
                  "hidden); 0: only the exact clean-up (default: a quarter of the thinnest pen)");
  cmd->add_option("--dpi", a.dpi, "PNG resolution (default 150)");
  cmd->add_flag("--raw", a.raw, "One line per exact piece: no clean-up, chaining or pen order");
}

std::string check_output_args(const OutputOptions& a, const OutputFlags& f, bool sheet) {
  check_output_options(a);
  if (f.outputs.size() > 1)
    throw std::invalid_argument("-o is given " + std::to_string(f.outputs.size()) +
                                " times: one output, or in hlr render one -o for each --view (a batch of drawings)");
  const std::string format =
      output_format(a.format, f.output, {{".svg", "svg"}, {".pdf", "pdf"}, {".png", "png"}, {".dxf", "dxf"}, {".json", "json"}}, "svg");
  if (format == "json" && sheet) throw std::invalid_argument("--views makes a sheet: write svg, pdf, png or dxf (JSON is one view)");
  if ((format == "pdf" || format == "png") && f.output.empty() && isatty(1))
    throw std::invalid_argument("a " + format + " file goes to -o FILE, not to the terminal");
  return format;
}

}  // namespace hlr::cli
