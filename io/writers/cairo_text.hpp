// cairo's parts inside the writers: text as glyph outlines (the PDF writer draws its
// labels as filled paths, so a PDF needs no embedded font and looks as cairo's text would), and
// the PNG in bands of a chosen height.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "io/writers/plot_output.hpp"

namespace hlr {

/// One path operation: 'm' (x y), 'l' (x y), 'c' (x1 y1 x2 y2 x3 y3) or 'h' (close).
struct OutlineOp {
  char op = 'm';
  std::array<double, 6> v{};
};

/// The outlines of `text` (UTF-8) in the sans-serif font at `size` (units of the page, y down),
/// its baseline starting at x - anchor * advance, y (anchor 0 left, 0.5 centred, 1 right); to be
/// filled with the nonzero rule. Throws when cairo cannot be loaded.
std::vector<OutlineOp> text_outline(const std::string& text, double x, double y, double anchor, double size);

/// sheet_to_png with bands of `band_rows` rows (sheet_to_png: 64); one band of the picture's
/// height draws it on one surface, as a test's reference.
std::string png_in_bands(const Sheet& sheet, const PlotStyle& style, double dpi, int band_rows);

}  // namespace hlr
