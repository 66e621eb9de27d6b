// The sheet as PNG through cairo (see plot_output.hpp), drawn in millimetres in bands of rows on
// all cores: the same strokes, weights and dashes as the SVG; and the glyph outlines of the
// PDF's labels (cairo_text.hpp).
#include <dlfcn.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>
#include <stdexcept>

#include "algorithms/support/parallel.hpp"
#include "io/writers/cairo_text.hpp"
#include "io/writers/parallel_text.hpp"
#include "io/writers/plot_output.hpp"

namespace hlr {
namespace {

// cairo is loaded when the first PNG (or PDF with labels) is made, not at every start of hlr: its library
// and the sixteen it needs took 5-6 ms of each start (a third of `hlr --version`, a twentieth
// of a small drawing). The functions are looked up once; a system without cairo gets an error
// naming it when PNG or a labelled PDF is asked for, and everything else works.
#define HLR_CAIRO_FUNCTIONS(X) \
  X(cairo_close_path) X(cairo_copy_path) X(cairo_create) X(cairo_destroy) X(cairo_fill_preserve) \
  X(cairo_font_options_create) X(cairo_font_options_destroy) X(cairo_font_options_set_hint_metrics) \
  X(cairo_font_options_set_hint_style) X(cairo_image_surface_create) X(cairo_line_to) X(cairo_move_to) \
  X(cairo_paint) X(cairo_path_destroy) X(cairo_recording_surface_create) X(cairo_scale) \
  X(cairo_image_surface_create_for_data) X(cairo_image_surface_get_data) X(cairo_image_surface_get_stride) \
  X(cairo_surface_flush) X(cairo_surface_mark_dirty) X(cairo_translate) X(cairo_set_font_options) X(cairo_text_path) \
  X(cairo_select_font_face) X(cairo_set_dash) X(cairo_set_fill_rule) X(cairo_set_font_size) \
  X(cairo_set_line_cap) X(cairo_set_line_join) X(cairo_set_line_width) X(cairo_set_source_rgb) \
  X(cairo_show_text) X(cairo_status) X(cairo_status_to_string) X(cairo_stroke) \
  X(cairo_surface_destroy) X(cairo_surface_finish) X(cairo_surface_status) \
  X(cairo_surface_write_to_png_stream) X(cairo_text_extents)

struct Cairo {
#define HLR_CAIRO_POINTER(name) decltype(&::name) name = nullptr;
  HLR_CAIRO_FUNCTIONS(HLR_CAIRO_POINTER)
#undef HLR_CAIRO_POINTER
};

Cairo load_cairo() {
  void* handle = dlopen("libcairo.so.2", RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw std::runtime_error(std::string("PNG output and PDF labels need the cairo library (Debian: apt install libcairo2): ") + (why ? why : "libcairo.so.2 not found"));
  }
  Cairo c;
#define HLR_CAIRO_LOOKUP(name)                                                                       \
  c.name = reinterpret_cast<decltype(c.name)>(dlsym(handle, #name));                                 \
  if (!c.name) throw std::runtime_error("the cairo library found has no " #name ": PNG output and PDF labels need cairo 1.16 or later");
  HLR_CAIRO_FUNCTIONS(HLR_CAIRO_LOOKUP)
#undef HLR_CAIRO_LOOKUP
  return c;  // the library stays loaded for the process
}

constexpr int kBandRows = 64;

const Cairo& lib() {
  static const Cairo c = load_cairo();
  return c;
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// A band of the picture: page y from y0 to y1 (mm), the band's rows widened on both sides by
// half the widest line and two pixels (nothing drawn outside that reaches the band's pixels).
struct Band {
  double y0, y1;
  bool meets(double lo, double hi) const { return hi >= y0 && lo <= y1; }
};

// A line layer to paint, with each stroke's vertical extent on the page.
struct PaintLayer {
  PaintLayer(const SheetView& v, const PlotLayer& l, const PlotStyle& style) : strokes(v, l, style) {
    width = style.weight(l);
    grey = l.through;
    dashed = style.pattern_dashed(l);
    pattern = style.dash_pattern(l);
    extent.resize(strokes.size());
    ParallelLoop().for_each(strokes.size(), 64, [&](std::size_t s) {
      double lo = 1e300, hi = -1e300;
      for (std::size_t i = 0; i < strokes.size(s); ++i) {
        const double y = strokes.point(s, i)[1];
        lo = std::min(lo, y), hi = std::max(hi, y);
      }
      extent[s] = {lo, hi};
    });
  }
  PageStrokes strokes;
  double width = 0;
  bool grey = false, dashed = false;
  std::array<double, 2> pattern{};
  std::vector<std::array<double, 2>> extent;
};

std::vector<std::unique_ptr<PaintLayer>> paint_layers(const Sheet& sheet, const PlotStyle& style) {
  std::vector<std::unique_ptr<PaintLayer>> out;
  for (const std::string& name : sheet_layer_names(sheet))
    for (const SheetView& v : sheet.views)
      for (const PlotLayer& l : v.plot->layers)
        if (l.name() == name) out.push_back(std::make_unique<PaintLayer>(v, l, style));
  return out;
}

// Each fill's vertical extent on the page (edge included), in the order the views hold them.
std::vector<std::array<double, 2>> fill_extents(const Sheet& sheet) {
  std::vector<std::array<double, 2>> out;
  for (const SheetView& v : sheet.views)
    for (const PlotFill& fl : v.plot->fills) {
      double lo = 1e300, hi = -1e300;
      for (const auto& ring : fl.rings)
        for (const Point2& q : ring) {
          const double y = v.page(q)[1];
          lo = std::min(lo, y), hi = std::max(hi, y);
        }
      out.push_back({lo - fl.edge_mm, hi + fl.edge_mm});
    }
  return out;
}

void draw_fills(cairo_t* cr, const Sheet& sheet, const std::vector<std::array<double, 2>>& extents, const Band& band) {
  lib().cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  lib().cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  std::size_t f = 0;
  for (const SheetView& v : sheet.views)
    for (const PlotFill& fl : v.plot->fills) {
      const auto& e = extents[f++];
      if (!band.meets(e[0], e[1])) continue;
      for (const auto& ring : fl.rings) {
        for (std::size_t i = 0; i < ring.size(); ++i) {
          Point2 p = v.page(ring[i]);
          if (i == 0)
            lib().cairo_move_to(cr, p[0], p[1]);
          else
            lib().cairo_line_to(cr, p[0], p[1]);
        }
        lib().cairo_close_path(cr);
      }
      lib().cairo_set_source_rgb(cr, fl.colour[0], fl.colour[1], fl.colour[2]);
      lib().cairo_set_line_width(cr, fl.edge_mm);  // edged in its own colour: no seams between regions
      lib().cairo_fill_preserve(cr);
      lib().cairo_stroke(cr);
    }
}

// Stroke s of `l` where it meets the band. Round caps and joins draw a stroke as its polyline
// widened by a disc, so a stroke cut at points outside the band (by more than half its width)
// covers the band's pixels as the whole stroke does; the parts that meet the band are subpaths
// of one path, painted once. cairo starts the dash pattern afresh at each subpath, so a dashed
// part starts earlier on the stroke, where its arc length from the stroke's start is a whole
// number of pattern periods (less than one period back): the pattern runs on as in the whole
// stroke.
void draw_stroke(cairo_t* cr, const PaintLayer& l, std::size_t s, const Band& band) {
  const Cairo& c = lib();
  const PageStrokes& st = l.strokes;
  const std::size_t n = st.size(s);
  if (n == 0) return;
  const bool closed = st.closed(s);
  const std::size_t segments = closed ? n : n - 1;
  auto at = [&](std::size_t i) { return st.point(s, i % n); };
  auto length = [&](std::size_t k) {
    const Point2 a = at(k), b = at(k + 1);
    return std::hypot(b[0] - a[0], b[1] - a[1]);
  };
  auto meets = [&](std::size_t k) {
    const Point2 a = at(k), b = at(k + 1);
    return band.meets(std::min(a[1], b[1]), std::max(a[1], b[1]));
  };
  std::size_t touching = 0;
  for (std::size_t k = 0; k < segments; ++k) touching += meets(k);
  if (touching == segments) {  // all of it: the stroke as it is
    for (std::size_t i = 0; i < n; ++i) {
      const Point2 p = at(i);
      if (i == 0) c.cairo_move_to(cr, p[0], p[1]);
      else c.cairo_line_to(cr, p[0], p[1]);
    }
    if (closed) c.cairo_close_path(cr);
    c.cairo_stroke(cr);
    return;
  }
  if (touching == 0) return;
  const double period = l.pattern[0] + l.pattern[1];
  double along = 0;  // arc length from the stroke's start to point k
  for (std::size_t k = 0; k < segments;) {
    if (!meets(k)) {
      along += length(k++);
      continue;
    }
    // The part's start: back to the last whole period for a dashed stroke.
    double back = l.dashed && period > 0 ? along - std::floor(along / period) * period : 0;
    std::size_t j = k;
    while (back > 0 && j > 0 && length(j - 1) < back) back -= length(--j);
    if (back > 0 && j > 0) {
      const Point2 p = at(j - 1), q = at(j);
      const double t = back / length(j - 1);
      c.cairo_move_to(cr, q[0] + (p[0] - q[0]) * t, q[1] + (p[1] - q[1]) * t);
      c.cairo_line_to(cr, q[0], q[1]);
    } else {
      c.cairo_move_to(cr, at(j)[0], at(j)[1]);
    }
    for (++j; j <= k; ++j) c.cairo_line_to(cr, at(j)[0], at(j)[1]);
    for (; k < segments && meets(k); ++k) {
      const Point2 q = at(k + 1);
      c.cairo_line_to(cr, q[0], q[1]);
      along += length(k);
    }
  }
  c.cairo_stroke(cr);
}

void draw_band(cairo_t* cr, const Sheet& sheet, const std::vector<std::array<double, 2>>& fills,
               const std::vector<std::unique_ptr<PaintLayer>>& layers, const Band& band) {
  draw_fills(cr, sheet, fills, band);
  lib().cairo_set_source_rgb(cr, 0, 0, 0);
  lib().cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  lib().cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const auto& l : layers) {
    lib().cairo_set_line_width(cr, l->width);
    if (l->grey) lib().cairo_set_source_rgb(cr, 0.5, 0.5, 0.5);  // seen through transparent faces: grey
    else lib().cairo_set_source_rgb(cr, 0, 0, 0);
    lib().cairo_set_dash(cr, l->pattern.data(), l->dashed ? 2 : 0, 0);
    for (std::size_t s = 0; s < l->extent.size(); ++s)
      if (band.meets(l->extent[s][0], l->extent[s][1])) draw_stroke(cr, *l, s, band);
  }
  lib().cairo_set_source_rgb(cr, 0, 0, 0);
  lib().cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  for (const SheetText& t : sheet_texts(sheet)) {
    lib().cairo_set_font_size(cr, t.size_mm);
    cairo_text_extents_t e;
    lib().cairo_text_extents(cr, t.text.c_str(), &e);
    lib().cairo_move_to(cr, t.at[0] - t.anchor * e.x_advance, t.at[1]);
    lib().cairo_show_text(cr, t.text.c_str());
  }
}

void check(cairo_status_t st) {
  if (st != CAIRO_STATUS_SUCCESS) throw std::runtime_error(std::string("cairo: ") + lib().cairo_status_to_string(st));
}

}  // namespace

std::string sheet_to_png(const Sheet& sheet, const PlotStyle& style, double dpi) { return png_in_bands(sheet, style, dpi, kBandRows); }

std::string png_in_bands(const Sheet& sheet, const PlotStyle& style, double dpi, int band_rows) {
  const Cairo& c = lib();
  const double px = dpi / 25.4;
  int w = std::max(1, static_cast<int>(std::lround(sheet.width_mm * px))), h = std::max(1, static_cast<int>(std::lround(sheet.height_mm * px)));
  if (static_cast<double>(w) * h > 4e8) throw std::invalid_argument("the PNG would have over 400 million pixels: lower --dpi");
  cairo_surface_t* surface = c.cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
  cairo_status_t st = c.cairo_surface_status(surface);
  // Bands of `band_rows` rows drawn on all cores, each through its own surface on the picture's
  // rows; the bands are the same on any number of cores, so are the pixels.
  if (st == CAIRO_STATUS_SUCCESS) {
    c.cairo_surface_flush(surface);
    unsigned char* data = c.cairo_image_surface_get_data(surface);
    const int stride = c.cairo_image_surface_get_stride(surface);
    const auto layers = paint_layers(sheet, style);
    const auto fills = fill_extents(sheet);
    double widest = 0.08;
    for (const auto& l : layers) widest = std::max(widest, l->width);
    for (const SheetView& v : sheet.views)
      for (const PlotFill& f : v.plot->fills) widest = std::max(widest, f.edge_mm);
    const double margin = widest / 2 + 2 / px;
    const int rows_each = std::max(1, band_rows);
    const std::size_t bands = static_cast<std::size_t>((h + rows_each - 1) / rows_each);
    std::vector<cairo_status_t> status(bands, CAIRO_STATUS_SUCCESS);
    ParallelLoop().for_each(bands, 1, [&](std::size_t b) {
      const int y0 = static_cast<int>(b) * rows_each, rows = std::min(rows_each, h - y0);
      cairo_surface_t* part = c.cairo_image_surface_create_for_data(data + static_cast<std::ptrdiff_t>(y0) * stride, CAIRO_FORMAT_RGB24, w, rows, stride);
      cairo_t* cr = c.cairo_create(part);
      c.cairo_set_source_rgb(cr, 1, 1, 1);
      c.cairo_paint(cr);
      c.cairo_translate(cr, 0, -y0);
      c.cairo_scale(cr, px, px);
      draw_band(cr, sheet, fills, layers, Band{y0 / px - margin, (y0 + rows) / px + margin});
      status[b] = c.cairo_status(cr);
      c.cairo_destroy(cr);
      c.cairo_surface_finish(part);
      c.cairo_surface_destroy(part);
    });
    c.cairo_surface_mark_dirty(surface);
    for (cairo_status_t s : status)
      if (st == CAIRO_STATUS_SUCCESS) st = s;
  }
  std::string out;
  if (st == CAIRO_STATUS_SUCCESS) st = c.cairo_surface_write_to_png_stream(surface, append, &out);
  c.cairo_surface_destroy(surface);
  check(st);
  return out;
}

std::vector<OutlineOp> text_outline(const std::string& text, double x, double y, double anchor, double size) {
  const Cairo& c = lib();
  // An unbounded surface: on an image surface cairo drops the glyphs that fall outside it.
  cairo_surface_t* surface = c.cairo_recording_surface_create(CAIRO_CONTENT_ALPHA, nullptr);
  cairo_t* cr = c.cairo_create(surface);
  // Device units of 1/100 mm: the font is scaled to 350 units, so its outline's 1/64-unit grid
  // is 0.16 micrometres; no hinting, as on cairo's own PDF surface.
  c.cairo_scale(cr, 100, 100);
  cairo_font_options_t* fo = c.cairo_font_options_create();
  c.cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
  c.cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
  c.cairo_set_font_options(cr, fo);
  c.cairo_font_options_destroy(fo);
  c.cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  c.cairo_set_font_size(cr, size);
  cairo_text_extents_t e;
  c.cairo_text_extents(cr, text.c_str(), &e);
  c.cairo_move_to(cr, x - anchor * e.x_advance, y);
  c.cairo_text_path(cr, text.c_str());
  cairo_path_t* path = c.cairo_copy_path(cr);
  std::vector<OutlineOp> out;
  const cairo_status_t st = path->status;
  for (int i = 0; st == CAIRO_STATUS_SUCCESS && i < path->num_data; i += path->data[i].header.length) {
    const cairo_path_data_t* d = &path->data[i];
    OutlineOp op{};
    const int points = d->header.type == CAIRO_PATH_CURVE_TO ? 3 : d->header.type == CAIRO_PATH_CLOSE_PATH ? 0 : 1;
    op.op = d->header.type == CAIRO_PATH_MOVE_TO ? 'm' : d->header.type == CAIRO_PATH_LINE_TO ? 'l' : d->header.type == CAIRO_PATH_CURVE_TO ? 'c' : 'h';
    for (int k = 0; k < points; ++k) op.v[2 * k] = d[1 + k].point.x, op.v[2 * k + 1] = d[1 + k].point.y;
    out.push_back(op);
  }
  c.cairo_path_destroy(path);
  c.cairo_destroy(cr);
  c.cairo_surface_destroy(surface);
  check(st);
  return out;
}

}  // namespace hlr
