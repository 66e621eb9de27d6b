// The sheet as PDF (see plot_output.hpp), written here on all cores (cairo's PDF
// surface formatted and compressed a 1M-triangle drawing on one core, 2.2 s). One page in
// millimetres (y down, through the content's `cm`), the same strokes, weights and dashes as
// the SVG, one optional-content group (a PDF layer) per SVG layer, labels as glyph outlines
// (cairo_text.hpp: no embedded font). The content stream is deflated in independent chunks of
// 1 MiB joined into one zlib stream (as pigz does), so its bytes do not depend on the number of
// cores.
#include <zlib.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/shading/lighting.hpp"
#include "algorithms/support/parallel.hpp"
#include "io/writers/cairo_text.hpp"
#include "io/writers/parallel_text.hpp"
#include "io/writers/plot_output.hpp"
#include "io/writers/svg_writer.hpp"

namespace hlr {
namespace {

constexpr double kPointsPerMm = 72.0 / 25.4;
constexpr std::size_t kDeflateChunk = std::size_t{1} << 20;
// zlib's level 4: a 1M-triangle page's 12.5 MB of content in 2.76 MB, four times as fast as the
// default level 6 (2.64 MB).
constexpr int kLevel = 4;

void point(std::string& out, const Point2& p, const char* op) {
  out += svg_number(p[0]);
  out += ' ';
  out += svg_number(p[1]);
  out += op;
}

// A colour component from 0 to 1, as the SVG's 8-bit value over 255 with 4 decimals.
std::string component(int c8) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.4f", c8 / 255.0);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

std::string rgb(const Rgb& c, const char* op) {
  const auto c8 = rgb8(c);
  return component(c8[0]) + " " + component(c8[1]) + " " + component(c8[2]) + op;
}

// A PDF literal string: ( ) and \ escaped, other bytes as they are (names here are ASCII).
std::string literal(const std::string& s) {
  std::string out = "(";
  for (char c : s) {
    if (c == '(' || c == ')' || c == '\\') out += '\\';
    out += c;
  }
  return out + ")";
}

// SOURCE_DATE_EPOCH (seconds since 1970) as a PDF date, or "" when it is not set or not a number.
std::string source_date() {
  const char* e = std::getenv("SOURCE_DATE_EPOCH");
  if (!e || !*e) return "";
  char* end = nullptr;
  const long long t = std::strtoll(e, &end, 10);
  if (*end != '\0' || t < 0) return "";
  const std::time_t tt = static_cast<std::time_t>(t);
  std::tm utc{};
  if (!gmtime_r(&tt, &utc)) return "";
  char buf[32];
  std::strftime(buf, sizeof buf, "D:%Y%m%d%H%M%SZ", &utc);
  return buf;
}

struct Layer {
  std::string name;  // the optional-content group's name, as the SVG layer's label
};

void append_fills(std::string& out, const Sheet& sheet) {
  out += "1 j\n";
  for (const SheetView& v : sheet.views)
    for (const PlotFill& fl : v.plot->fills) {
      out += rgb(fl.colour, " rg\n") + rgb(fl.colour, " RG\n") + svg_number(fl.edge_mm) + " w\n";
      for (const auto& ring : fl.rings) {
        for (std::size_t i = 0; i < ring.size(); ++i) point(out, v.page(ring[i]), i == 0 ? " m\n" : " l\n");
        out += "h\n";
      }
      out += "B*\n";  // even-odd fill, then the edge in its own colour (no seams between regions)
    }
}

// One path per stroke ("x y m", "x y l" ..., "h" when closed, "S"), made on all cores.
void append_strokes(std::string& out, const SheetView& v, const PlotLayer& l, const PlotStyle& style) {
  const PageStrokes st(v, l, style);
  append_stroke_text(out, st.size(), [&](std::size_t s) { return st.size(s); },
                     [&](std::string& d, std::size_t s, std::size_t begin, std::size_t end) {
                       d.reserve(8 + 20 * (end - begin));
                       for (std::size_t i = begin; i < end; ++i) point(d, st.point(s, i), i == 0 ? " m\n" : " l\n");
                       if (end == st.size(s)) d += st.closed(s) ? "h\nS\n" : "S\n";
                     });
}

void append_outline(std::string& out, const std::vector<OutlineOp>& ops) {
  for (const OutlineOp& o : ops) {
    if (o.op == 'h') {
      out += "h\n";
      continue;
    }
    const int n = o.op == 'c' ? 3 : 1;
    for (int k = 0; k < n; ++k) {
      if (k) out += ' ';
      out += svg_number(o.v[2 * k]) + " " + svg_number(o.v[2 * k + 1]);
    }
    out += o.op == 'm' ? " m\n" : o.op == 'l' ? " l\n" : " c\n";
  }
}

// The page's content stream (uncompressed) and its layers, in drawing order.
std::string content(const Sheet& sheet, const PlotStyle& style, std::vector<Layer>& layers) {
  // Millimetres, y down: x_pt = k x, y_pt = H - k y (H as the MediaBox writes it).
  char k[32];
  std::snprintf(k, sizeof k, "%.12f", kPointsPerMm);
  std::string out = std::string("q\n") + k + " 0 0 -" + k + " 0 " + svg_number(sheet.height_mm * kPointsPerMm) + " cm\n";
  auto begin_layer = [&](const std::string& name) {
    out += "/OC /L" + std::to_string(layers.size()) + " BDC\n";
    layers.push_back({name});
  };
  bool fills = false;
  for (const SheetView& v : sheet.views) fills = fills || !v.plot->fills.empty();
  if (fills) {
    begin_layer("surfaces");
    append_fills(out, sheet);
    out += "EMC\n";
  }
  out += "1 J 1 j\n";
  for (const SheetLayer& sl : sheet_layers(sheet, style)) {
    const PlotLayer& any = *sl.layer;
    begin_layer(sl.label);
    out += svg_number(style.weight(any));
    out += any.through ? " w\n0.502 0.502 0.502 RG\n[" : " w\n0 0 0 RG\n[";
    if (style.pattern_dashed(any)) {
      const auto pat = style.dash_pattern(any);
      out += svg_number(pat[0]) + ' ' + svg_number(pat[1]);
    }
    out += "] 0 d\n";
    for (const SheetView& v : sheet.views)
      for (const PlotLayer& l : v.plot->layers)
        if (l.name() == sl.name) append_strokes(out, v, l, style);
    out += "EMC\n";
  }
  const std::vector<SheetText> texts = sheet_texts(sheet);
  if (!texts.empty()) {
    begin_layer("labels");
    out += "0 g\n";
    for (const SheetText& t : texts) {
      append_outline(out, text_outline(t.text, t.at[0], t.at[1], t.anchor, t.size_mm));
      out += "f\n";
    }
    out += "EMC\n";
  }
  return out + "Q\n";
}

// Raw deflate of one chunk: ended by a sync flush (byte-aligned, not final) or, for the last
// chunk, by the final block.
std::string deflate_chunk(const char* data, std::size_t n, bool last) {
  z_stream z{};
  if (deflateInit2(&z, kLevel, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("PDF: zlib cannot start a stream");
  std::string out(deflateBound(&z, n) + 64, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data));
  z.avail_in = static_cast<uInt>(n);
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = deflate(&z, last ? Z_FINISH : Z_SYNC_FLUSH);
  const bool done = last ? rc == Z_STREAM_END : rc == Z_OK && z.avail_in == 0 && z.avail_out > 0;
  out.resize(out.size() - z.avail_out);
  deflateEnd(&z);
  if (!done) throw std::runtime_error("PDF: zlib could not compress the page");
  return out;
}

// A zlib stream (RFC 1950) of `text`: chunks deflated on all cores, their checksums combined.
std::string zlib_stream(const std::string& text) {
  const std::size_t chunks = text.empty() ? 1 : (text.size() + kDeflateChunk - 1) / kDeflateChunk;
  std::vector<std::string> parts(chunks + 2);
  std::vector<uLong> sums(chunks);
  ParallelLoop().for_each(chunks, 1, [&](std::size_t k) {
    const std::size_t at = k * kDeflateChunk, n = std::min(kDeflateChunk, text.size() - at);
    parts[k + 1] = deflate_chunk(text.data() + at, n, k + 1 == chunks);
    sums[k] = adler32(adler32(0, nullptr, 0), reinterpret_cast<const Bytef*>(text.data() + at), static_cast<uInt>(n));
  });
  uLong sum = sums[0];
  for (std::size_t k = 1; k < chunks; ++k)
    sum = adler32_combine(sum, sums[k], static_cast<z_off_t>(std::min(kDeflateChunk, text.size() - k * kDeflateChunk)));
  parts[0] = "\x78\x5e";  // deflate, 32 KiB window, a fast level (FLEVEL 1)
  for (int s = 24; s >= 0; s -= 8) parts[chunks + 1] += static_cast<char>((sum >> s) & 0xff);
  std::string out;
  append_parts(out, parts);
  return out;
}

}  // namespace

std::string sheet_to_pdf(const Sheet& sheet, const PlotStyle& style) {
  std::vector<Layer> layers;
  const std::string stream = zlib_stream(content(sheet, style, layers));
  const std::string w = svg_number(sheet.width_mm * kPointsPerMm), h = svg_number(sheet.height_mm * kPointsPerMm);
  // Objects: 1 catalog, 2 pages, 3 page, 4 content, 5 information, 6... layers.
  std::vector<std::string> objects;
  std::string ocgs, properties;
  for (std::size_t k = 0; k < layers.size(); ++k) {
    const std::string ref = std::to_string(6 + k) + " 0 R";
    ocgs += (k ? " " : "") + ref;
    properties += "/L" + std::to_string(k) + " " + ref + " ";
  }
  objects.push_back("<< /Type /Catalog /Pages 2 0 R" +
                    (layers.empty() ? std::string() : " /OCProperties << /OCGs [" + ocgs + "] /D << /Order [" + ocgs + "] >> >>") + " >>");
  objects.push_back("<< /Type /Pages /Kids [3 0 R] /Count 1 >>");
  objects.push_back("<< /Type /Page /Parent 2 0 R /MediaBox [0 0 " + w + " " + h + "] /Resources << /Properties << " + properties +
                    ">> >> /Contents 4 0 R >>");
  objects.push_back("<< /Length " + std::to_string(stream.size()) + " /Filter /FlateDecode >>\nstream\n" + stream + "\nendstream");
  // The same drawing gives the same bytes: no creation date from the clock, or
  // SOURCE_DATE_EPOCH's when set (reproducible builds).
  const std::string date = source_date();
  objects.push_back("<< /Title (exact-hlr drawing) /Creator (exact-hlr) /Producer (exact-hlr)" +
                    (date.empty() ? std::string() : " /CreationDate " + literal(date)) + " >>");
  for (const Layer& l : layers) objects.push_back("<< /Type /OCG /Name " + literal(l.name) + " >>");
  std::string out = "%PDF-1.5\n%\xe2\xe3\xcf\xd3\n";
  std::vector<std::size_t> offsets;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    offsets.push_back(out.size());
    out += std::to_string(k + 1) + " 0 obj\n" + objects[k] + "\nendobj\n";
    std::string().swap(objects[k]);
  }
  const std::size_t xref = out.size();
  out += "xref\n0 " + std::to_string(objects.size() + 1) + "\n0000000000 65535 f \n";
  for (std::size_t at : offsets) {
    char entry[24];
    std::snprintf(entry, sizeof entry, "%010zu 00000 n \n", at);
    out += entry;
  }
  out += "trailer\n<< /Size " + std::to_string(objects.size() + 1) + " /Root 1 0 R /Info 5 0 R >>\nstartxref\n" + std::to_string(xref) +
         "\n%%EOF\n";
  return out;
}

}  // namespace hlr
