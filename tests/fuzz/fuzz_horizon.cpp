// libFuzzer target for the floating horizon: bytes become a small height grid (even
// or uneven, heights from a palette with repeats, zeros, binary doubles of many digits, and
// numbers far beyond the range of doubles) and a view (with and without an x component, from
// below, from behind, up turned over); the sweep on certified doubles must equal the sweep on
// rationals in every piece, parameter and horizon size, and the picture route of `hlr horizon`
// (runs straight to the 2D stage) must give make_plot()'s strokes on the exact model, point for
// point. A disagreement aborts (a finding).
#include <cstdint>
#include <cstdlib>

#include "algorithms/horizon/floating_horizon.hpp"
#include "algorithms/horizon/floating_horizon_filtered.hpp"
#include "algorithms/plot/plot.hpp"
#include "io/pipeline/horizon.hpp"

using namespace hlr;

namespace {

struct Bytes {
  const std::uint8_t* p;
  std::size_t n, i = 0;
  int next() { return i < n ? p[i++] : 0; }
};

bool same(const std::vector<HorizonPiece>& a, const std::vector<HorizonPiece>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k].curve != b[k].curve || a[k].segment != b[k].segment || a[k].t0 != b[k].t0 || a[k].t1 != b[k].t1) return false;
  return true;
}

bool same(const Plot& a, const Plot& b) {
  if (a.layers.size() != b.layers.size() || a.bounds != b.bounds) return false;
  for (std::size_t l = 0; l < a.layers.size(); ++l) {
    if (a.layers[l].name() != b.layers[l].name() || a.layers[l].strokes.size() != b.layers[l].strokes.size()) return false;
    for (std::size_t s = 0; s < a.layers[l].strokes.size(); ++s)
      if (a.layers[l].strokes[s].points != b.layers[l].strokes[s].points || a.layers[l].strokes[s].closed != b.layers[l].strokes[s].closed)
        return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 6) return 0;
  Bytes b{data, size};
  const int nx = 2 + b.next() % 6, nz = 1 + b.next() % 6;
  const bool uneven = b.next() % 3 == 0;
  const int scale_kind = b.next() % 8;  // 0: beyond doubles, 1: tiny, else ordinary
  const Rational scale = scale_kind == 0 ? parse_rational("1e400") : scale_kind == 1 ? parse_rational("1e-400") : Rational(1);
  HeightGrid g;
  Rational at = -1;
  for (int i = 0; i < nx; ++i) g.xs.push_back(Rational(scale * (uneven ? (at += rational(1 + b.next() % 4, 3)) : rational(2 * i - nx, 5))));
  at = -1;
  for (int j = 0; j < nz; ++j) g.zs.push_back(Rational(scale * (uneven ? (at += rational(1 + b.next() % 4, 3)) : rational(2 * j - nz, 5))));
  const Rational palette[] = {Rational(0), rational(1, 2), rational(-1, 3), rational(1, 4), rational(1, 4), Rational(1),
                              rational_from_double(0.1), rational_from_double(0.30000000000000004), rational_from_double(1e-30),
                              rational_from_double(-2.5e-7), rational(7, 8), Rational(-1)};
  for (int k = 0; k < nx * nz; ++k) g.ys.push_back(Rational(scale * palette[b.next() % 12]));
  static const int views[][3] = {{1, 2, 3}, {0, 1, 4}, {-2, 1, 5}, {3, 1, -2}, {1, -1, 3}, {5, 1, 1}, {1, 1, 1}, {-1, 3, -1},
                                 {0, -1, 2}, {2, 0, 1}, {1, 0, -1}, {7, 1, 2}};
  const int* v = views[b.next() % 12];
  const Vector3 dir(v[0], v[1], v[2]);
  const Camera cam = make_orthographic(dir, Vector3(0, b.next() % 4 == 0 ? -1 : 1, 0));
  const HorizonResult f = floating_horizon_filtered(g, cam), e = floating_horizon_exact(g, cam);
  if (f.order != e.order || f.horizon_breakpoints != e.horizon_breakpoints || !same(f.visible, e.visible) || !same(f.side, e.side)) {
    std::fprintf(stderr, "filtered and exact sweeps differ\n");
    std::abort();
  }
  const char* cuts = b.next() % 2 || v[0] == 0 ? "z" : "both";
  const HorizonDrawing hd(g, cam, 0, cuts);
  PlotOptions po;
  po.hidden = b.next() % 2;
  po.threads = 1;
  std::optional<Plot> fast = hd.plot(po);
  if (fast && !same(*fast, make_plot(hd.model("grid").drawing, cam, po))) {
    std::fprintf(stderr, "the picture route differs from the exact model's\n");
    std::abort();
  }
  return 0;
}
