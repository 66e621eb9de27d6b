// The sheet as SVG (see plot_output.hpp): one Inkscape layer per visibility and line kind
// (AxiDraw plots layers by their number), one <path> per stroke in pen order, line weights per
// layer; hidden lines dashed by the pattern (continuous along each stroke) or cut into dashes.
#include "io/writers/plot_output.hpp"
#include "io/writers/parallel_text.hpp"
#include "io/writers/svg_writer.hpp"

#include <algorithm>
#include <cstdio>

#include "algorithms/shading/lighting.hpp"
#include "algorithms/support/parallel.hpp"

namespace hlr {
namespace {

// One <path> per stroke, "  <path d=\"Mx y Lx y x y ...[Z]\"/>", appended to `out` in order,
// made on all cores.
void append_layer(std::string& out, const SheetView& v, const PlotLayer& l, const PlotStyle& style) {
  const PageStrokes st(v, l, style);
  append_stroke_text(out, st.size(), [&](std::size_t s) { return st.size(s); },
                     [&](std::string& d, std::size_t s, std::size_t begin, std::size_t end) {
                       d.reserve(16 + 20 * (end - begin));
                       if (begin == 0) d += "  <path d=\"M";
                       for (std::size_t i = begin; i < end; ++i) {
                         if (i > 1) d += ' ';
                         const Point2 p = st.point(s, i);
                         d += svg_number(p[0]);
                         d += ' ';
                         d += svg_number(p[1]);
                         if (i == 0) d += 'L';
                       }
                       if (end == st.size(s)) {
                         if (st.closed(s)) d += 'Z';
                         d += "\"/>\n";
                       }
                     });
}

}  // namespace

std::string sheet_to_svg(const Sheet& sheet, const PlotStyle& style) {
  auto f = svg_number;
  std::string out;
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" width=\"" +
         f(sheet.width_mm) + "mm\" height=\"" + f(sheet.height_mm) + "mm\" viewBox=\"0 0 " + f(sheet.width_mm) + " " +
         f(sheet.height_mm) + "\">\n";
  out += "<title>exact-hlr drawing</title>\n";
  // Shaded surfaces under the lines, each region edged in its own colour (0.08 mm) so that no
  // viewer's antialiasing shows a seam between regions of different colours.
  bool fills = false;
  for (const SheetView& v : sheet.views) fills = fills || !v.plot->fills.empty();
  if (fills) {
    out += "<g inkscape:groupmode=\"layer\" inkscape:label=\"surfaces\" id=\"surfaces\" fill-rule=\"evenodd\" "
           "stroke-width=\"0.08\" stroke-linejoin=\"round\">\n";
    for (const SheetView& v : sheet.views)
      for (const PlotFill& fl : v.plot->fills) {
        std::string d;
        for (const auto& ring : fl.rings) {
          for (std::size_t i = 0; i < ring.size(); ++i) {
            Point2 p = v.page(ring[i]);
            d += i == 0 ? 'M' : ' ';
            d += f(p[0]);
            d += ' ';
            d += f(p[1]);
          }
          d += "Z";
        }
        auto c = rgb8(fl.colour);
        char hex[8];
        std::snprintf(hex, sizeof hex, "#%02x%02x%02x", c[0], c[1], c[2]);
        std::string width = fl.edge_mm != 0.08 ? " stroke-width=\"" + f(fl.edge_mm) + "\"" : "";
        out += "  <path d=\"" + d + "\" fill=\"" + hex + "\" stroke=\"" + hex + "\"" + width + "/>\n";
      }
    out += "</g>\n";
  }
  for (const SheetLayer& sl : sheet_layers(sheet, style)) {
    const PlotLayer& any = *sl.layer;
    const auto pat = style.dash_pattern(any);
    out += "<g inkscape:groupmode=\"layer\" inkscape:label=\"" + sl.label + "\" id=\"" + sl.name +
           "\" fill=\"none\" stroke=\"" + std::string(any.through ? kThroughGrey : "#000") + "\" stroke-width=\"" + f(style.weight(any)) +
           "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"" +
           (style.pattern_dashed(any) ? " stroke-dasharray=\"" + f(pat[0]) + " " + f(pat[1]) + "\"" : std::string()) + ">\n";
    for (const SheetView& v : sheet.views)
      for (const PlotLayer& l : v.plot->layers)
        if (l.name() == sl.name) append_layer(out, v, l, style);
    out += "</g>\n";
  }
  const std::vector<SheetText> texts = sheet_texts(sheet);
  if (!texts.empty()) {
    out += "<g inkscape:groupmode=\"layer\" inkscape:label=\"labels\" id=\"labels\" font-family=\"sans-serif\" font-size=\"3.5\" "
           "fill=\"#000\">\n";
    for (const SheetText& t : texts) {
      out += "  <text x=\"" + f(t.at[0]) + "\" y=\"" + f(t.at[1]) + "\"";
      if (t.size_mm != 3.5) out += " font-size=\"" + f(t.size_mm) + "\"";
      out += t.anchor == 0.5 ? " text-anchor=\"middle\">" : t.anchor == 1 ? " text-anchor=\"end\">" : ">";
      out += svg_escape(t.text) + "</text>\n";
    }
    out += "</g>\n";
  }
  out += "</svg>\n";
  return out;
}

}  // namespace hlr
