// Text as glyph outlines, through cairo (issue 14: the PDF writer draws its labels as filled
// paths, so a PDF needs no embedded font and looks as cairo's text would).
#pragma once

#include <array>
#include <string>
#include <vector>

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

}  // namespace hlr
