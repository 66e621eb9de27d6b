// The sheet as PNG through cairo (see plot_output.hpp), drawn in millimetres: the same
// strokes, weights and dashes as the SVG; and the glyph outlines of the PDF's labels
// (cairo_text.hpp).
#include <dlfcn.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "io/cairo_text.hpp"
#include "io/plot_output.hpp"

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
  X(cairo_paint) X(cairo_path_destroy) X(cairo_recording_surface_create) X(cairo_scale) X(cairo_set_font_options) X(cairo_text_path) \
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

const Cairo& lib() {
  static const Cairo c = load_cairo();
  return c;
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

void draw_fills(cairo_t* cr, const Sheet& sheet) {
  lib().cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  lib().cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  lib().cairo_set_line_width(cr, 0.08);  // edged in its own colour: no seams between regions
  for (const SheetView& v : sheet.views)
    for (const PlotFill& fl : v.plot->fills) {
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
      lib().cairo_set_line_width(cr, fl.edge_mm);
      lib().cairo_fill_preserve(cr);
      lib().cairo_stroke(cr);
    }
}

void draw_sheet(cairo_t* cr, const Sheet& sheet, const PlotStyle& style) {
  draw_fills(cr, sheet);
  lib().cairo_set_source_rgb(cr, 0, 0, 0);
  lib().cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  lib().cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const std::string& name : sheet_layer_names(sheet))
    for (const SheetView& v : sheet.views)
      for (const PlotLayer& l : v.plot->layers) {
        if (l.name() != name) continue;
        lib().cairo_set_line_width(cr, style.weight(l));
        auto pat = style.dash_pattern(l);
        if (l.through) lib().cairo_set_source_rgb(cr, 0.5, 0.5, 0.5);  // seen through transparent faces: grey
        else lib().cairo_set_source_rgb(cr, 0, 0, 0);
        const bool dashed = !l.visible && !l.through && style.hidden_dashed && style.dashes == DashMode::Pattern;
        lib().cairo_set_dash(cr, pat.data(), dashed ? 2 : 0, 0);
        std::vector<char> closed;
        auto strokes = page_strokes(v, l, style, &closed);
        for (std::size_t s = 0; s < strokes.size(); ++s) {
          lib().cairo_move_to(cr, strokes[s][0][0], strokes[s][0][1]);
          for (std::size_t i = 1; i < strokes[s].size(); ++i) lib().cairo_line_to(cr, strokes[s][i][0], strokes[s][i][1]);
          if (closed[s]) lib().cairo_close_path(cr);
          lib().cairo_stroke(cr);
        }
      }
  lib().cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  lib().cairo_set_font_size(cr, 3.5);
  auto text = [&](const std::string& t, double x, double y, double anchor) {
    cairo_text_extents_t e;
    lib().cairo_text_extents(cr, t.c_str(), &e);
    lib().cairo_move_to(cr, x - anchor * e.x_advance, y);
    lib().cairo_show_text(cr, t.c_str());
  };
  for (const SheetView& v : sheet.views) {
    if (v.label.empty() || v.plot->empty()) continue;
    const auto& b = v.plot->bounds;
    Point2 at = v.page({(b[0] + b[2]) / 2, b[1]});
    text(v.label, at[0], at[1] + 6, 0.5);
  }
  if (!sheet.caption.empty()) text(sheet.caption, sheet.width_mm - 5, sheet.height_mm - 5, 1);
}

void check(cairo_status_t st) {
  if (st != CAIRO_STATUS_SUCCESS) throw std::runtime_error(std::string("cairo: ") + lib().cairo_status_to_string(st));
}

}  // namespace

std::string sheet_to_png(const Sheet& sheet, const PlotStyle& style, double dpi) {
  const double px = dpi / 25.4;
  int w = std::max(1, static_cast<int>(std::lround(sheet.width_mm * px))), h = std::max(1, static_cast<int>(std::lround(sheet.height_mm * px)));
  if (static_cast<double>(w) * h > 4e8) throw std::invalid_argument("the PNG would have over 400 million pixels: lower --dpi");
  cairo_surface_t* surface = lib().cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
  cairo_t* cr = lib().cairo_create(surface);
  lib().cairo_set_source_rgb(cr, 1, 1, 1);
  lib().cairo_paint(cr);
  lib().cairo_scale(cr, px, px);
  draw_sheet(cr, sheet, style);
  cairo_status_t st = lib().cairo_status(cr);
  lib().cairo_destroy(cr);
  std::string out;
  if (st == CAIRO_STATUS_SUCCESS) st = lib().cairo_surface_write_to_png_stream(surface, append, &out);
  lib().cairo_surface_destroy(surface);
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
