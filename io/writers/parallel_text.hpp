// Text made on all cores (the SVG, DXF and JSON writers): parts made by the cores
// and joined in order, so that the text does not depend on their number. Strokes are cut into
// pieces of kPiecePoints points: one long stroke (a sphere's edges chain into a few strokes of
// hundreds of thousands of points) is shared by all cores.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "algorithms/support/parallel.hpp"
#include "io/writers/plot_output.hpp"

namespace hlr {

inline constexpr std::size_t kPiecePoints = 4096;

/// Appends `parts` to `out` in order, copied on all cores into storage reserved once (a string
/// grown part by part on one core zeroed and copied hundreds of megabytes of fresh pages
/// alone); each part is freed once copied.
inline void append_parts(std::string& out, std::vector<std::string>& parts) {
  std::vector<std::size_t> at(parts.size() + 1, out.size());
  for (std::size_t k = 0; k < parts.size(); ++k) at[k + 1] = at[k] + parts[k].size();
  out.resize(at.back());
  ParallelLoop().for_each(parts.size(), 1, [&](std::size_t k) {
    std::copy(parts[k].begin(), parts[k].end(), out.begin() + static_cast<std::ptrdiff_t>(at[k]));
    std::string().swap(parts[k]);
  });
}

/// Appends to `out`, in order, the text of `strokes` strokes, stroke s having size(s) points:
/// piece(text, s, begin, end) appends the text of points [begin, end) of stroke s (its head
/// when begin is 0, its tail when end is size(s); a stroke without points is one piece
/// [0, 0)). On all cores (ParallelLoop's limit).
template <class Size, class Piece>
void append_stroke_text(std::string& out, std::size_t strokes, const Size& size, const Piece& piece) {
  struct Range {
    std::size_t stroke, begin, end;
  };
  std::vector<Range> ranges;
  for (std::size_t s = 0; s < strokes; ++s) {
    const std::size_t n = size(s);
    for (std::size_t b = 0; b == 0 || b < n; b += kPiecePoints) ranges.push_back({s, b, std::min(n, b + kPiecePoints)});
  }
  std::vector<std::string> text(ranges.size());
  ParallelLoop().for_each(ranges.size(), 1, [&](std::size_t k) { piece(text[k], ranges[k].stroke, ranges[k].begin, ranges[k].end); });
  append_parts(out, text);
}

/// A layer's strokes on the page of a view: the plot's own strokes mapped point by point, or,
/// when hidden lines are cut into dashes, the dashes page_strokes makes.
class PageStrokes {
 public:
  PageStrokes(const SheetView& v, const PlotLayer& l, const PlotStyle& style) : view_(v), strokes_(l.strokes) {
    if ((style.dashed(l) && style.dashes == DashMode::Geometry) || style.min_length_mm > 0) {  // cut dashes, specks dropped
      cut_ = true;
      dashes_ = page_strokes(v, l, style, &closed_);
    }
  }
  std::size_t size() const { return cut_ ? dashes_.size() : strokes_.size(); }
  std::size_t size(std::size_t s) const { return cut_ ? dashes_[s].size() : strokes_[s].points.size(); }
  Point2 point(std::size_t s, std::size_t i) const { return cut_ ? dashes_[s][i] : view_.page(strokes_[s].points[i]); }
  bool closed(std::size_t s) const { return cut_ ? closed_[s] != 0 : strokes_[s].closed; }

 private:
  const SheetView& view_;
  const std::vector<Stroke>& strokes_;
  bool cut_ = false;
  std::vector<std::vector<Point2>> dashes_;
  std::vector<char> closed_;
};

}  // namespace hlr
