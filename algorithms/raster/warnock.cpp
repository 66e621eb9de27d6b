// Warnock's window subdivision, exact (course notes sections 29-30). See warnock.hpp.
#include "algorithms/raster/warnock.hpp"

#include <algorithm>
#include <mutex>

#include "algorithms/support/parallel.hpp"
#include "algorithms/raster/zbuffer.hpp"

namespace hlr {
namespace {

enum class Kind { Disjoint, Surrounding, Other };

struct Window {
  int i0, j0, i1, j1;  // pixels [i0, i1) x [j0, j1)
};

class Subdivision {
 public:
  Subdivision(const RasterScene& s, std::vector<int>& frame, std::vector<WarnockWindow>* trace)
      : s_(s), g_(s.grid), frame_(frame), trace_(trace) {}
  WarnockStats stats;

  void run(const Window& w, const std::vector<int>& parent, int level = 0) {
    ++stats.windows;
    // The trace's entry by index: the recursion below grows the vector.
    const std::size_t tw = trace_ ? trace_->size() : 0;
    if (trace_) trace_->push_back(WarnockWindow{w.i0, w.j0, w.i1, w.j1, level, {}, WarnockWindow::Decision::Split, -1});
    auto decide = [&](WarnockWindow::Decision d, int p) {
      if (trace_) (*trace_)[tw].decision = d, (*trace_)[tw].polygon = p;
    };
    const int ci[2] = {w.i0, w.i1 - 1}, cj[2] = {w.j0, w.j1 - 1};
    std::vector<int> meet;  // polygons not disjoint from the window
    std::vector<int> surrounding;
    for (int p : parent) {
      Kind k = classify(s_.polygons[p], w, ci, cj);
      if (k == Kind::Disjoint) continue;
      meet.push_back(p);
      if (k == Kind::Surrounding) surrounding.push_back(p);
      if (trace_) (*trace_)[tw].polygons.push_back({p, k == Kind::Surrounding});
    }
    if (meet.empty()) {  // background (the frame starts as background)
      ++stats.empty;
      decide(WarnockWindow::Decision::Empty, -1);
      return;
    }
    if (w.i1 - w.i0 == 1 && w.j1 - w.j0 == 1) {
      ++stats.pixels;
      frame_[index(w.i0, w.j0)] = seen_among(s_, meet, w.i0, w.j0);
      decide(WarnockWindow::Decision::Pixel, frame_[index(w.i0, w.j0)]);
      return;
    }
    for (int sp : surrounding)
      if (in_front_of_all(sp, meet, ci, cj)) {
        ++stats.surrounded;
        decide(WarnockWindow::Decision::Surrounded, sp);
        for (int j = w.j0; j < w.j1; ++j)
          for (int i = w.i0; i < w.i1; ++i) frame_[index(i, j)] = sp;
        return;
      }
    if (meet.size() == 1) {  // one polygon, contained or intersecting: scan-converted
      ++stats.single;
      decide(WarnockWindow::Decision::Single, meet[0]);
      for (int j = w.j0; j < w.j1; ++j)
        for (int i = w.i0; i < w.i1; ++i)
          if (s_.covers(s_.polygons[meet[0]], i, j)) frame_[index(i, j)] = meet[0];
      return;
    }
    const int im = (w.i0 + w.i1 + 1) / 2, jm = (w.j0 + w.j1 + 1) / 2;
    for (const Window& q : {Window{w.i0, w.j0, im, jm}, Window{im, w.j0, w.i1, jm}, Window{w.i0, jm, im, w.j1},
                            Window{im, jm, w.i1, w.j1}})
      if (q.i0 < q.i1 && q.j0 < q.j1) run(q, meet, level + 1);
  }

 private:
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * g_.width + i; }

  // Disjoint when the polygon's box misses the rectangle of centres or one side has all four
  // corners strictly outside; surrounding when all four corners are inside (convex polygon).
  Kind classify(const RasterPolygon& p, const Window& w, const int ci[2], const int cj[2]) const {
    const double x0 = g_.cx(w.i0), x1 = g_.cx(w.i1 - 1), y1 = g_.cy(w.j0), y0 = g_.cy(w.j1 - 1);
    if (p.box[0] > x1 || p.box[2] < x0 || p.box[1] > y1 || p.box[3] < y0) return Kind::Disjoint;
    bool all_in = true;
    for (int k = 0; k < p.count; ++k) {
      int outside = 0;
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) {
          int sg = s_.side_sign(p, k, g_.cx(ci[a]), g_.cy(cj[b]));
          outside += sg < 0;
        }
      if (outside == 4) return Kind::Disjoint;
      if (outside > 0) all_in = false;
    }
    return all_in ? Kind::Surrounding : Kind::Other;
  }

  // Strictly nearer than every other polygon at the four corners, with the depth difference's
  // sign fixed over the window: orthographic depths are linear in the picture point;
  // perspective ones are num/den with den linear, so the difference's sign is fixed once both
  // denominators keep one strict sign at the corners.
  bool in_front_of_all(int sp, const std::vector<int>& meet, const int ci[2], const int cj[2]) const {
    const RasterPolygon& a = s_.polygons[sp];
    for (int p : meet) {
      if (p == sp) continue;
      const RasterPolygon& b = s_.polygons[p];
      if (b.id == a.id) continue;
      for (int u = 0; u < 2; ++u)
        for (int v = 0; v < 2; ++v)
          if (s_.depth_order(a, b, g_.cx(ci[u]), g_.cy(cj[v])) >= 0) return false;
      if (s_.camera.perspective && !(steady_den(a, ci, cj) && steady_den(b, ci, cj))) return false;
    }
    return true;
  }

  bool steady_den(const RasterPolygon& p, const int ci[2], const int cj[2]) const {
    int first = 0;
    for (int u = 0; u < 2; ++u)
      for (int v = 0; v < 2; ++v) {
        const int sg = s_.denominator_sign(p, g_.cx(ci[u]), g_.cy(cj[v]));
        if (sg == 0 || (first != 0 && sg != first)) return false;
        first = sg;
      }
    return true;
  }

  const RasterScene& s_;
  const RasterGrid& g_;
  std::vector<int>& frame_;
  std::vector<WarnockWindow>* trace_;
};

}  // namespace

FaceIdBuffer warnock(const RasterScene& s, const WarnockOptions& o, WarnockStats* stats) {
  const RasterGrid& g = s.grid;
  std::vector<int> frame(static_cast<std::size_t>(g.width) * g.height, -1);
  constexpr int kTile = 64;
  const int tx = (g.width + kTile - 1) / kTile, ty = (g.height + kTile - 1) / kTile;
  // Each tile starts with the polygons whose boxes meet it.
  std::vector<std::vector<int>> in_tile(static_cast<std::size_t>(tx) * ty);
  for (std::size_t p = 0; p < s.polygons.size(); ++p) {
    auto rows = g.rows(s.polygons[p].box[1], s.polygons[p].box[3]);
    auto cols = g.columns(s.polygons[p].box[0], s.polygons[p].box[2]);
    if (rows[0] >= rows[1] || cols[0] >= cols[1]) continue;
    for (int b = rows[0] / kTile; b <= (rows[1] - 1) / kTile; ++b)
      for (int a = cols[0] / kTile; a <= (cols[1] - 1) / kTile; ++a) in_tile[static_cast<std::size_t>(b) * tx + a].push_back(static_cast<int>(p));
  }
  std::mutex m;
  WarnockStats total;
  ParallelLoop(o.trace ? 1 : o.threads).for_each(in_tile.size(), 1, [&](std::size_t t) {
    const int a = static_cast<int>(t % tx), b = static_cast<int>(t / tx);
    Subdivision sub(s, frame, o.trace);
    sub.run(Window{a * kTile, b * kTile, std::min(g.width, (a + 1) * kTile), std::min(g.height, (b + 1) * kTile)}, in_tile[t]);
    std::lock_guard<std::mutex> lock(m);
    total.windows += sub.stats.windows, total.empty += sub.stats.empty, total.surrounded += sub.stats.surrounded;
    total.single += sub.stats.single, total.pixels += sub.stats.pixels;
  });
  if (stats) *stats = total;
  return face_ids(s, frame);
}

}  // namespace hlr
