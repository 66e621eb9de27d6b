// The exact z-buffer (course notes section 32). See zbuffer.hpp.
#include "algorithms/raster/zbuffer.hpp"

#include <algorithm>

#include "algorithms/support/parallel.hpp"

namespace hlr {

FaceIdBuffer face_ids(const RasterScene& s, const std::vector<int>& at) {
  FaceIdBuffer out;
  out.width = s.grid.width, out.height = s.grid.height;
  out.ids.resize(at.size());
  for (std::size_t k = 0; k < at.size(); ++k) out.ids[k] = at[k] < 0 ? -1 : s.polygons[at[k]].id;
  out.polygons.assign(at.begin(), at.end());
  return out;
}

FaceIdBuffer zbuffer(const RasterScene& s, const ZBufferOptions& o) {
  const RasterGrid& g = s.grid;
  std::vector<int> frame(static_cast<std::size_t>(g.width) * g.height, -1);  // the polygon kept per pixel
  constexpr int kBand = 16;                                                   // rows per band
  const int bands = (g.height + kBand - 1) / kBand;
  // Each polygon goes to the bands its rows meet, in input order (the order does not matter:
  // `nearer` is a total order, so the buffer ends with the same polygon whatever the order).
  std::vector<std::vector<int>> in_band(bands);
  for (std::size_t p = 0; p < s.polygons.size(); ++p) {
    auto rows = g.rows(s.polygons[p].box[1], s.polygons[p].box[3]);
    for (int b = rows[0] / kBand; b < bands && b * kBand < rows[1]; ++b) in_band[b].push_back(static_cast<int>(p));
  }
  ParallelLoop(o.threads).for_each(bands, 1, [&](std::size_t b) {
    const int j0 = static_cast<int>(b) * kBand, j1 = std::min(g.height, j0 + kBand);
    for (int p : in_band[b]) {
      const RasterPolygon& poly = s.polygons[p];
      auto rows = g.rows(poly.box[1], poly.box[3]);
      auto cols = g.columns(poly.box[0], poly.box[2]);
      for (int j = std::max(j0, rows[0]); j < std::min(j1, rows[1]); ++j)
        for (int i = cols[0]; i < cols[1]; ++i) {
          if (!s.covers(poly, i, j)) continue;
          int& cur = frame[static_cast<std::size_t>(j) * g.width + i];
          if (cur < 0 || s.nearer(poly, s.polygons[cur], g.cx(i), g.cy(j))) cur = p;
        }
    }
  });
  return face_ids(s, frame);
}

}  // namespace hlr
