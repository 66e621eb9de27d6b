// The picture writers read back: SVG paths, DXF and PDF strokes point by point on every thread
// count, PNG bands, PDF styles, fills and label outlines (io/writers/plot_output.hpp).
#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>
#include <gtest/gtest.h>
#include <png.h>
#include <zlib.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "algorithms/picture/path_chaining.hpp"
#include "algorithms/plot/dashes.hpp"
#include "algorithms/plot/pen_order.hpp"
#include "algorithms/plot/plot.hpp"
#include "algorithms/support/parallel.hpp"
#include "io/pipeline/render.hpp"
#include "io/views/standard_views.hpp"
#include "io/writers/cairo_text.hpp"
#include "io/writers/plot_output.hpp"
#include "io/writers/svg_writer.hpp"

namespace hlr {
namespace {

const std::string kData = HLR_DATA_DIR;

// A plot of random strokes of `sizes` points, open and closed (pieces of the writers' text
// end at 4096 points), in a visible layer, and the shorter ones scaled down in a hidden one
// (for dashes).
Plot long_stroke_plot(unsigned seed, std::initializer_list<std::size_t> sizes) {
  Plot p;
  PlotLayer vis, hid;
  hid.visible = false;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-50, 50);
  for (std::size_t n : sizes) {
    for (bool closed : {false, true}) {
      Stroke s;
      s.closed = closed && n > 2;
      for (std::size_t i = 0; i < n; ++i) s.points.push_back({u(rng), u(rng)});
      vis.strokes.push_back(s);
      if (n > 4097) continue;
      for (Point2& q : s.points) q = {q[0] / 20, q[1] / 20};  // short dashes' worth
      hid.strokes.push_back(s);
    }
  }
  p.layers = {vis, hid};
  p.bounds = {-50, -50, 50, 50};
  return p;
}

// A writer's text on 1, 2 and 8 threads, which must be the same: the one-thread text.
std::string same_on_all_thread_counts(const std::function<std::string()>& write) {
  std::string first;
  for (unsigned threads : {1u, 2u, 8u}) {
    ThreadLimit limit(threads);
    const std::string text = write();
    if (first.empty()) first = text;
    EXPECT_EQ(text, first) << threads << " threads";
  }
  return first;
}

PlotStyle hidden_cut_into_dashes() {
  PlotStyle style;
  style.hidden_dashed = true;
  style.dashes = DashMode::Geometry;
  return style;
}

// Long strokes are formatted in pieces on all cores (plot_svg.cpp): every path, whatever its
// length (pieces end at 4096 points) and whether closed, must read exactly as formatted point
// by point, with 1, 2 and 8 threads; hidden strokes cut into dashes go through the same code.
TEST(PlotOutput, SvgPathsOfLongStrokesReadPointByPoint) {
  const Plot p = long_stroke_plot(7, {1, 2, 3, 4095, 4096, 4097, 8192, 8193, 20000});
  const PlotLayer& vis = p.layers[0];
  const Sheet sheet = layout_single(p, PageOptions{});
  const SheetView& v = sheet.views.at(0);
  std::string expected;  // the visible layer's paths, point by point
  for (const Stroke& s : vis.strokes) {
    expected += "  <path d=\"M";
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const Point2 q = v.page(s.points[i]);
      if (i > 1) expected += ' ';
      expected += svg_number(q[0]) + ' ' + svg_number(q[1]);
      if (i == 0) expected += 'L';
    }
    expected += std::string(s.closed ? "Z" : "") + "\"/>\n";
  }
  const PlotStyle style = hidden_cut_into_dashes();
  const std::string svg = same_on_all_thread_counts([&] { return sheet_to_svg(sheet, style); });
  const std::size_t at = svg.find("id=\"visible-edge\"");
  ASSERT_NE(at, std::string::npos);
  const std::size_t from = svg.find('\n', at) + 1;
  EXPECT_EQ(svg.substr(from, expected.size()), expected);
  EXPECT_EQ(svg.compare(from + expected.size(), 5, "</g>\n"), 0);
  std::size_t dashes = 0;
  for (std::size_t a = svg.find("id=\"hidden-edge\""); (a = svg.find("<path ", a)) != std::string::npos; ++a) ++dashes;
  EXPECT_GT(dashes, 1000u);
}


// DXF numbers as dxflib writes them ("%.16f" with the trailing zeros cut to one after the
// point): the oracle for the entities made on all cores (plot_dxf.cpp).
std::string dxf_real(double v) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "%.16f", v);
  std::string t = buf;
  const std::size_t dot = t.find('.');
  while (dot != std::string::npos && t.size() > dot + 2 && t.back() == '0') t.pop_back();
  return t;
}

struct DxfStrokes : DL_CreationAdapter {
  std::map<std::string, std::vector<std::vector<Point2>>> strokes;
  std::map<std::string, std::vector<int>> flags;
  std::string layer;
  void addPolyline(const DL_PolylineData& d) override {
    layer = attributes.getLayer();
    strokes[layer].emplace_back();
    flags[layer].push_back(d.flags);
  }
  void addVertex(const DL_VertexData& d) override { strokes[layer].back().push_back({d.x, d.y}); }
};

// The entities are written here, not by dxflib (which flushes its file after every number):
// long strokes (pieces end at 4096 points), closed ones and cut dashes must read back point by
// point, every number in dxflib's format, every handle unique, the same text on 1, 2 and 8
// threads.
TEST(PlotOutput, DxfLongStrokesReadBackPointByPoint) {
  Plot p = long_stroke_plot(11, {1, 2, 3, 4095, 4096, 4097, 9000});
  p.layers[0].strokes.push_back(Stroke{{{0, 0}, {1e-9, -2.5e-17}, {-0.0, 12345.678}}, false});  // tiny, negative zero
  const PlotLayer& vis = p.layers[0];
  const Sheet sheet = layout_single(p, PageOptions{});
  const SheetView& v = sheet.views.at(0);
  const PlotStyle style = hidden_cut_into_dashes();
  const std::string first = same_on_all_thread_counts([&] { return sheet_to_dxf(sheet, style); });
  // Group codes and values, pair by pair: handles unique, the visible layer's x values as
  // dxflib would write them.
  std::istringstream lines(first);
  std::string code, value, layer;
  std::set<std::string> handles;
  std::vector<std::string> xs;
  while (std::getline(lines, code) && std::getline(lines, value)) {
    if (code == "  5" || code == "105") {
      EXPECT_TRUE(handles.insert(value).second) << "handle " << value << " twice";
    }
    if (code == "  8") layer = value;
    if (code == " 10" && layer == "visible-edge") xs.push_back(value);
  }
  std::vector<std::string> want;
  for (const Stroke& s : vis.strokes)
    for (const Point2& q : s.points) want.push_back(dxf_real(v.page(q)[0]));
  EXPECT_EQ(xs, want);
  auto path = std::filesystem::temp_directory_path() / "hlr_plot_long.dxf";
  std::ofstream(path, std::ios::binary) << first;
  DxfStrokes c;
  DL_Dxf reader;
  ASSERT_TRUE(reader.in(path.string(), &c));
  std::filesystem::remove(path);
  ASSERT_EQ(c.strokes["visible-edge"].size(), vis.strokes.size());
  for (std::size_t k = 0; k < vis.strokes.size(); ++k) {
    const auto& got = c.strokes["visible-edge"][k];
    ASSERT_EQ(got.size(), vis.strokes[k].points.size()) << k;
    EXPECT_EQ(c.flags["visible-edge"][k] & 1, vis.strokes[k].closed ? 1 : 0) << k;
    for (std::size_t i = 0; i < got.size(); ++i) {
      const Point2 q = v.page(vis.strokes[k].points[i]);
      ASSERT_NEAR(got[i][0], q[0], 1e-12) << k << " " << i;
      ASSERT_NEAR(got[i][1], sheet.height_mm - q[1], 1e-12) << k << " " << i;
    }
  }
  EXPECT_GT(c.strokes["hidden-edge"].size(), 1000u);  // the dashes
}

// A PDF read back as a reader would: the cross-reference table's offsets, the objects, the
// page's content stream inflated, its operators in order.
struct PdfRead {
  std::map<int, std::string> objects;  // number -> text between "N 0 obj" and "endobj"
  std::string content;                 // the page's content stream, inflated
  std::vector<std::string> layers;     // the optional-content groups' names, in /Order
};

PdfRead read_pdf(const std::string& pdf) {
  PdfRead r;
  EXPECT_EQ(pdf.rfind("%PDF-1.5\n", 0), 0u);
  EXPECT_EQ(pdf.substr(pdf.size() - 6), "%%EOF\n");
  const std::size_t sx = pdf.rfind("startxref\n");
  const std::size_t xref = std::stoul(pdf.substr(sx + 10));
  EXPECT_EQ(pdf.compare(xref, 5, "xref\n"), 0);
  std::istringstream table(pdf.substr(xref + 5));
  int first = -1, count = 0;
  table >> first >> count;
  EXPECT_EQ(first, 0);
  table.ignore(1);
  for (int k = 0; k < count; ++k) {
    std::string entry(20, ' ');
    table.read(entry.data(), 20);
    EXPECT_EQ(entry.substr(17), k == 0 ? "f \n" : "n \n") << k;
    if (k == 0) continue;
    const std::size_t at = std::stoul(entry.substr(0, 10));
    const std::string head = std::to_string(k) + " 0 obj\n";
    EXPECT_EQ(pdf.compare(at, head.size(), head), 0) << "object " << k << " is not at its offset " << at;
    const std::size_t end = pdf.find("\nendobj\n", at);
    r.objects[k] = pdf.substr(at + head.size(), end - at - head.size());
  }
  EXPECT_NE(pdf.find("trailer\n<< /Size " + std::to_string(count) + " /Root 1 0 R"), std::string::npos);
  const std::string& c = r.objects[4];
  const std::size_t length = std::stoul(c.substr(c.find("/Length ") + 8));
  const std::size_t at = c.find("stream\n") + 7;
  EXPECT_EQ(c.compare(at + length, 10, "\nendstream"), 0) << "the stream's /Length";
  z_stream z{};
  EXPECT_EQ(inflateInit(&z), Z_OK);
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(c.data() + at));
  z.avail_in = static_cast<uInt>(length);
  std::vector<char> buf(1 << 16);
  int rc = Z_OK;
  while (rc == Z_OK) {
    z.next_out = reinterpret_cast<Bytef*>(buf.data());
    z.avail_out = static_cast<uInt>(buf.size());
    rc = inflate(&z, Z_NO_FLUSH);
    r.content.append(buf.data(), buf.size() - z.avail_out);
  }
  EXPECT_EQ(rc, Z_STREAM_END) << "the content stream is not one whole zlib stream (checksum included)";
  EXPECT_EQ(z.avail_in, 0u);
  inflateEnd(&z);
  const std::string& catalog = r.objects[1];
  const std::size_t order = catalog.find("/Order [");
  if (order != std::string::npos) {
    std::istringstream refs(catalog.substr(order + 8, catalog.find(']', order) - order - 8));
    int n = 0;
    std::string zero, R;
    while (refs >> n >> zero >> R) {
      const std::string& g = r.objects[n];
      const std::size_t name = g.find("/Name (") + 7;
      r.layers.push_back(g.substr(name, g.find(") >>", name) - name));
    }
  }
  return r;
}

// The strokes of the content's layer `k` (its "/OC /Lk BDC" ... "EMC"): each "x y m", "x y l"
// ..., "h" when closed, "S", as the coordinates' text.
struct PdfStroke {
  std::vector<std::string> xy;  // "x y" per point
  bool closed = false;
};
std::vector<PdfStroke> pdf_layer_strokes(const std::string& content, std::size_t k) {
  const std::string tag = "/OC /L" + std::to_string(k) + " BDC\n";
  const std::size_t from = content.find(tag);
  EXPECT_NE(from, std::string::npos) << tag;
  std::istringstream lines(content.substr(from + tag.size(), content.find("EMC\n", from) - from - tag.size()));
  std::vector<PdfStroke> out;
  PdfStroke s;
  for (std::string line; std::getline(lines, line);) {
    const char op = line.back();
    if (line.size() > 2 && line[line.size() - 2] == ' ' && (op == 'm' || op == 'l')) {
      EXPECT_EQ(op == 'm', s.xy.empty()) << line;
      s.xy.push_back(line.substr(0, line.size() - 2));
    } else if (line == "h") {
      s.closed = true;
    } else if (line == "S") {
      out.push_back(s);
      s = PdfStroke{};
    }
  }
  EXPECT_TRUE(s.xy.empty());
  return out;
}

// A PNG's pixels as grey levels (libpng's simplified reader).
std::vector<std::uint8_t> png_grey(const std::string& png, int& w, int& h) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  EXPECT_TRUE(png_image_begin_read_from_memory(&image, png.data(), png.size()));
  image.format = PNG_FORMAT_GRAY;
  std::vector<std::uint8_t> grey(PNG_IMAGE_SIZE(image));
  EXPECT_TRUE(png_image_finish_read(&image, nullptr, grey.data(), 0, nullptr));
  w = static_cast<int>(image.width), h = static_cast<int>(image.height);
  return grey;
}

// The PNG is drawn in bands of 64 rows on all cores, each stroke cut to the parts that reach
// its band (dashed parts stroked with the dash offset of their arc length): the picture must
// be the one drawn on one surface, up to the arcs' polygon tolerance at the cuts, and the same
// bytes on 1, 2 and 8 threads. Long random strokes (every band cuts them many times), pattern
// dashes, lines seen through, fills.
TEST(PngWriter, BandsDrawAsOneSurface) {
  Plot p = long_stroke_plot(17, {2, 3, 40, 300});
  for (Stroke& s : p.layers[1].strokes)
    for (Point2& q : s.points) q = {q[0] * 20, q[1] * 20};  // hidden strokes across the page too
  PlotLayer through = p.layers[0];
  through.visible = false, through.through = true;
  through.strokes.resize(3);
  p.layers.push_back(through);
  PlotFill fill;
  fill.colour = {0.2, 0.6, 0.9};
  fill.rings = {{{-40, -40}, {40, -30}, {0, 45}}, {{-5, -5}, {5, -5}, {0, 5}}};
  p.fills.push_back(fill);
  PlotStyle style;
  style.hidden_dashed = true;  // pattern dashes
  const Sheet sheet = layout_single(p, PageOptions{});
  int w = 0, h = 0, w1 = 0, h1 = 0;
  const std::string banded = same_on_all_thread_counts([&] { return sheet_to_png(sheet, style, 120); });
  const std::vector<std::uint8_t> a = png_grey(banded, w, h);
  const std::vector<std::uint8_t> b = png_grey(png_in_bands(sheet, style, 120, 1 << 30), w1, h1);
  ASSERT_EQ(w, w1);
  ASSERT_EQ(h, h1);
  ASSERT_GT(h, 640);  // ten bands and more
  // Pixels more than 16 levels apart: the arcs' polygons at the cuts, and dash ends moved by
  // cairo's 1/256-pixel points summed along the whole stroke (the bands start each part's
  // pattern from the exact arc length).
  std::size_t apart = 0, dark = 0;
  int most = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const int d = std::abs(int(a[i]) - int(b[i]));
    apart += d > 16;
    dark += b[i] < 128;
    most = std::max(most, d);
  }
  EXPECT_GT(dark, a.size() / 20);
  EXPECT_LE(most, 64) << apart << " pixels apart";
  EXPECT_LT(apart, dark / 1000) << "most " << most;
}

// The PDF is written here (plot_pdf.cpp), its content made in pieces and deflated in chunks on
// all cores: the file must read back object by object, its stream as one zlib stream, every
// stroke point by point as formatted (1, 2 and 8 threads, the same bytes), its layers those of
// the SVG, and the content over a MiB (several chunks).
TEST(PdfWriter, StrokesReadBackPointByPoint) {
  const Plot p = long_stroke_plot(13, {1, 2, 3, 4095, 4096, 4097, 8192, 8193, 20000, 70000});
  const PlotLayer& vis = p.layers[0];
  const Sheet sheet = layout_single(p, PageOptions{});
  const SheetView& v = sheet.views.at(0);
  const PlotStyle style = hidden_cut_into_dashes();
  const PdfRead r = read_pdf(same_on_all_thread_counts([&] { return sheet_to_pdf(sheet, style); }));
  EXPECT_GT(r.content.size(), std::size_t{3} << 20);
  const std::vector<std::string> names = sheet_layer_names(sheet);
  ASSERT_EQ(r.layers.size(), names.size());
  for (std::size_t n = 0; n < names.size(); ++n) EXPECT_EQ(r.layers[n], std::to_string(n + 1) + " " + names[n]);
  EXPECT_EQ(r.content.rfind("q\n2.834645669291 0 0 -2.834645669291 0 " + svg_number(sheet.height_mm * 72 / 25.4) + " cm\n", 0), 0u);
  const std::vector<PdfStroke> got = pdf_layer_strokes(r.content, 0);
  ASSERT_EQ(got.size(), vis.strokes.size());
  for (std::size_t k = 0; k < got.size(); ++k) {
    ASSERT_EQ(got[k].xy.size(), vis.strokes[k].points.size()) << k;
    EXPECT_EQ(got[k].closed, vis.strokes[k].closed) << k;
    for (std::size_t i = 0; i < got[k].xy.size(); ++i) {
      const Point2 q = v.page(vis.strokes[k].points[i]);
      ASSERT_EQ(got[k].xy[i], svg_number(q[0]) + " " + svg_number(q[1])) << k << " " << i;
    }
  }
  // The hidden layer: the dashes page_strokes cuts, one path each.
  std::vector<char> closed;
  const auto dashes = page_strokes(v, p.layers[1], style, &closed);
  const std::vector<PdfStroke> hidden = pdf_layer_strokes(r.content, 1);
  ASSERT_EQ(hidden.size(), dashes.size());
  for (std::size_t k = 0; k < dashes.size(); ++k) {
    ASSERT_EQ(hidden[k].xy.size(), dashes[k].size()) << k;
    EXPECT_EQ(hidden[k].xy.back(), svg_number(dashes[k].back()[0]) + " " + svg_number(dashes[k].back()[1])) << k;
  }
}

// Pattern dashes, widths, the grey of lines seen through, fills and labels as the SVG has them.
TEST(PdfWriter, StylesFillsAndLabels) {
  Plot p;
  PlotLayer vis, hid, through;
  vis.kind = LineKind::Silhouette;
  vis.strokes.push_back(Stroke{{{0, 0}, {10, 0}, {10, 10}}, true});
  hid.visible = false;
  hid.kind = through.kind = LineKind::Silhouette;
  hid.strokes.push_back(Stroke{{{0, 5}, {10, 5}}, false});
  through.visible = false;
  through.through = true;
  through.strokes.push_back(Stroke{{{5, 0}, {5, 10}}, false});
  p.layers = {vis, through, hid};
  PlotFill fill;
  fill.colour = {1, 0.5, 0};
  fill.rings = {{{0, 0}, {10, 0}, {10, 10}}};
  p.fills.push_back(fill);
  p.bounds = {0, 0, 10, 10};
  Sheet sheet = layout_single(p, PageOptions{});
  sheet.views[0].label = "FRONT";
  sheet.caption = "scale (1:1)";
  const PdfRead r = read_pdf(sheet_to_pdf(sheet, PlotStyle{}));
  ASSERT_EQ(r.layers, (std::vector<std::string>{"surfaces", "1 visible-silhouette", "2 through-silhouette", "3 hidden-silhouette", "labels"}));
  EXPECT_NE(r.content.find("/OC /L0 BDC\n1 j\n1 0.502 0 rg\n1 0.502 0 RG\n0.080 w\n"), std::string::npos) << r.content.substr(0, 300);
  EXPECT_NE(r.content.find(" l\nh\nB*\nEMC\n"), std::string::npos);
  EXPECT_NE(r.content.find("/OC /L1 BDC\n0.500 w\n0 0 0 RG\n[] 0 d\n"), std::string::npos);
  EXPECT_NE(r.content.find("/OC /L2 BDC\n0.250 w\n0.502 0.502 0.502 RG\n[] 0 d\n"), std::string::npos);
  EXPECT_NE(r.content.find("/OC /L3 BDC\n0.250 w\n0 0 0 RG\n[3.000 0.750] 0 d\n"), std::string::npos);
  // Labels: glyph outlines filled, in the labels layer, nothing after it but the end.
  const std::size_t labels = r.content.find("/OC /L4 BDC\n0 g\n");
  ASSERT_NE(labels, std::string::npos);
  const std::string text = r.content.substr(labels);
  EXPECT_GT(std::count(text.begin(), text.end(), '\n'), 100);
  EXPECT_NE(text.find(" c\n"), std::string::npos);  // curves: the glyphs' outlines
  EXPECT_EQ(text.substr(text.size() - 8), "f\nEMC\nQ\n");
  EXPECT_NE(r.objects.at(1).find("/OCProperties"), std::string::npos);
  EXPECT_EQ(r.objects.at(3).find("/Font"), std::string::npos);  // no font: outlines
}

TEST(PdfWriter, LabelOutlinesAnywhereOnThePage) {
  // cairo drops glyphs outside an image surface; the outlines come from an unbounded one.
  for (double x : {0.0, 204.9, 5000.0}) {
    const std::vector<OutlineOp> ops = text_outline("FRONT", x, x / 2, 0.5, 3.5);
    ASSERT_GT(ops.size(), 20u) << x;
    double lo = 1e300, hi = -1e300;
    for (const OutlineOp& o : ops)
      if (o.op != 'h') lo = std::min(lo, o.v[0]), hi = std::max(hi, o.v[0]);
    EXPECT_NEAR((lo + hi) / 2, x, 0.5) << x;  // centred
    EXPECT_GT(hi - lo, 8.0);                    // five letters of 3.5 mm
    EXPECT_LT(hi - lo, 14.0);
  }
}

}  // namespace
}  // namespace hlr
