// The 2D stage (see drawing_2d.hpp).
#include "algorithms/picture/drawing_2d.hpp"

#include "algorithms/support/parallel.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <set>
#include <string>

namespace hlr {
namespace {

// A segment's end k (0: from, 1: to) in the frame's doubles; a store's without its exact point.
std::array<double, 3> end_in_frame(const Segment& s, int k, const DrawingFrame& frame) {
  if (const PointStore* store = s.store_ends()) return frame.to_frame(*store, static_cast<std::size_t>(k ? s.v1 : s.v0));
  return frame.to_frame(k ? s.to() : s.from());
}

std::array<double, 3> end_projection(const Segment& s, int k, const Projector& proj) {
  const std::array<double, 3> q = end_in_frame(s, k, proj.frame());
  return proj.project(q[0], q[1], q[2]);
}

// Drawing coordinates of a piece; false when nothing of it is in front of the eye. For
// perspective, ends closer than `near` to the eye plane are pulled to it (drawing only: the
// visibility of the piece is already decided exactly).
bool piece_line(const Segment& s, const Piece& p, const Projector& proj, bool perspective, double near,
                std::array<double, 4>& out, bool& pulled) {
  pulled = false;
  // Drawing only: the ends in doubles (in the projector's frame) and t rounded.
  std::array<double, 3> F = end_in_frame(s, 0, proj.frame()), T = end_in_frame(s, 1, proj.frame()), A, B;
  auto at = [&](const Rational& t, std::array<double, 3>& o) {
    if (t == 0) o = F;
    else if (t == 1) o = T;
    else {
      double u = to_double(t);
      for (int k = 0; k < 3; ++k) o[k] = F[k] + u * (T[k] - F[k]);
    }
  };
  at(p.t0, A);
  at(p.t1, B);
  auto pa = proj.project(A[0], A[1], A[2]), pb = proj.project(B[0], B[1], B[2]);
  if (perspective) {
    if (pa[2] < near && pb[2] < near) return false;
    if (pa[2] < near || pb[2] < near) {
      double u = (near - pa[2]) / (pb[2] - pa[2]);
      std::array<double, 3> C;
      for (int k = 0; k < 3; ++k) C[k] = A[k] + u * (B[k] - A[k]);
      auto pc = proj.project(C[0], C[1], C[2]);
      (pa[2] < near ? pa : pb) = pc;
      pulled = true;
    }
  }
  out = {pa[0], pa[1], pb[0], pb[1]};
  return true;
}

// Each (body, vertex) that ends an edge segment, once, at its projection (in front of the eye).
void add_vertex_labels(const LineDrawing& r, const Projector& proj, const Camera& camera, int base, Drawing2D& d) {
  std::set<std::pair<int, int>> seen;
  for (const Segment& s : r.segments) {
    if (s.kind != Segment::Kind::Edge) continue;
    for (auto [v, p] : {std::make_pair(s.v0, &s.from()), std::make_pair(s.v1, &s.to())}) {
      if (v < 0 || !seen.insert({s.body, v}).second) continue;
      if (camera.perspective && camera.in_front(*p) != Sign::Positive) continue;
      auto q = proj.project(*p);
      d.labels.push_back({{q[0], q[1]}, std::to_string(v + base)});
    }
  }
}

// The runs' lines moved together (run c holds kept[c] lines from at[c]), in order.
void close_gaps(const std::vector<std::size_t>& at, const std::vector<std::size_t>& kept, Drawing2D& d) {
  std::size_t w = 0;
  for (std::size_t c = 0; c + 1 < at.size(); ++c)
    for (std::size_t k = at[c]; k < at[c] + kept[c]; ++k, ++w) {
      Polyline2D pl = d.lines[k];
      pl.first = static_cast<std::uint32_t>(2 * w);
      pl.first_edge = static_cast<std::uint32_t>(w);
      d.lines[w] = pl;
      d.points[2 * w] = d.points[2 * k];
      d.points[2 * w + 1] = d.points[2 * k + 1];
      d.sources[w] = d.sources[k];
    }
  d.lines.resize(w);
  d.points.resize(2 * w);
  d.sources.resize(w);
}

}  // namespace

namespace {

// The points the segments end at, each borrowed vertex once: per worker, the vertex arrays and
// stores the ends are borrowed from with a mark per vertex used, and the owned ends; then
// every worker's marks joined. A vertex ends about six edges of a mesh, and reading the
// vertices in order is a pass through memory instead of two scattered reads per segment.
struct SegmentEnds {
  std::vector<std::pair<const void*, std::vector<char>>> bases;  // an array or a store, and its marks
  std::vector<char> is_store;                                    // per base
  std::vector<const Point3*> own;
};

SegmentEnds segment_ends(const std::vector<Segment>& segs) {
  const ParallelLoop loop;
  PerWorker<SegmentEnds> part(loop);
  loop.run(segs.size(), 65536, [&](unsigned w, std::size_t b, std::size_t e) {
    SegmentEnds& ends = part[w];
    std::size_t last = 0;  // the base of the segment before (nearly always the same)
    for (std::size_t i = b; i < e; ++i) {
      const Segment& s = segs[i];
      const PointStore* store = s.store_ends();
      const void* base = store ? static_cast<const void*>(store) : static_cast<const void*>(s.borrowed());
      if (!base) {
        ends.own.push_back(&s.from());
        ends.own.push_back(&s.to());
        continue;
      }
      if (last >= ends.bases.size() || ends.bases[last].first != base) {
        last = 0;
        while (last < ends.bases.size() && ends.bases[last].first != base) ++last;
        if (last == ends.bases.size()) {
          ends.bases.emplace_back(base, std::vector<char>());
          ends.is_store.push_back(store != nullptr);
        }
      }
      std::vector<char>& mark = ends.bases[last].second;
      const auto top = static_cast<std::size_t>(std::max(s.v0, s.v1));
      if (mark.size() <= top) mark.resize(std::max(top + 1, 2 * mark.size()), 0);
      mark[static_cast<std::size_t>(s.v0)] = mark[static_cast<std::size_t>(s.v1)] = 1;
    }
  });
  SegmentEnds all;  // every worker's marks joined
  for (unsigned w = 0; w < part.size(); ++w) {
    all.own.insert(all.own.end(), part[w].own.begin(), part[w].own.end());
    for (std::size_t k = 0; k < part[w].bases.size(); ++k) {
      const void* base = part[w].bases[k].first;
      std::vector<char>& mark = part[w].bases[k].second;
      auto it = std::find_if(all.bases.begin(), all.bases.end(), [&](const auto& x) { return x.first == base; });
      if (it == all.bases.end()) {
        all.bases.emplace_back(base, std::move(mark));
        all.is_store.push_back(part[w].is_store[k]);
        continue;
      }
      if (it->second.size() < mark.size()) it->second.resize(mark.size(), 0);
      for (std::size_t v = 0; v < mark.size(); ++v) it->second[v] |= mark[v];
    }
  }
  return all;
}

// The same with the ends of the segments the route left out (LineDrawing::frame_ends).
SegmentEnds segment_ends(const LineDrawing& r) {
  SegmentEnds all = segment_ends(r.segments);
  for (const FrameEnds& f : r.frame_ends) {
    const void* base = f.store;
    auto it = std::find_if(all.bases.begin(), all.bases.end(), [&](const auto& x) { return x.first == base; });
    if (it == all.bases.end()) {
      all.bases.emplace_back(base, f.marks);
      all.is_store.push_back(1);
      continue;
    }
    if (it->second.size() < f.marks.size()) it->second.resize(f.marks.size(), 0);
    for (std::size_t v = 0; v < f.marks.size(); ++v) it->second[v] |= f.marks[v];
  }
  return all;
}

}  // namespace

Projector drawing_projector(const LineDrawing& r, const Camera& camera) {
  // The hull of the segments' ends (drawing_frame's minima and maxima: the same in any order):
  // the stores' marked points by their bounds, then the other ends.
  const SegmentEnds ends = segment_ends(r);
  std::vector<StorePoints> stores;
  std::vector<const Point3*> pts = ends.own;
  for (std::size_t k = 0; k < ends.bases.size(); ++k) {
    if (ends.is_store[k]) {
      stores.push_back({static_cast<const PointStore*>(ends.bases[k].first), &ends.bases[k].second});
      continue;
    }
    const auto* base = static_cast<const Point3*>(ends.bases[k].first);
    const std::vector<char>& mark = ends.bases[k].second;
    for (std::size_t v = 0; v < mark.size(); ++v)
      if (mark[v]) pts.push_back(base + v);
  }
  return Projector(camera, drawing_frame(stores, pts.size(), [&](std::size_t i) -> const Point3& { return *pts[i]; }));
}

Drawing2D project_drawing(const LineDrawing& r, const Camera& camera, const Project2DOptions& opt) {
  Projector proj = drawing_projector(r, camera);
  const ParallelLoop loop;
  double near = 0;
  if (camera.perspective) {  // the farthest end's depth (a maximum: the same on any number of threads)
    PerWorker<double> most(loop, 0.0);
    loop.run(r.segments.size(), 8192, [&](unsigned w, std::size_t b, std::size_t e) {
      double far = most[w];
      for (std::size_t i = b; i < e; ++i)
        for (int k = 0; k < 2; ++k) far = std::max(far, end_projection(r.segments[i], k, proj)[2]);
      most[w] = far;
    });
    double far = 0;
    for (unsigned w = 0; w < most.size(); ++w) far = std::max(far, most[w]);
    near = 1e-4 * std::max(far, 1e-300);
  }
  // Runs of segments on every core. Each run's pieces that may be drawn are counted first, so
  // that every run writes straight into its place in the drawing's arrays (made on this
  // thread from memory already in use: a worker's own fresh allocations cost page clearing);
  // the few pieces wholly behind the near depth (perspective) leave gaps, closed afterwards.
  const std::vector<Segment>& segs = r.segments;
  auto drawn = [&](const Piece& p) { return !(p.behind_eye || p.clipped || (!p.visible && !(p.through ? opt.through : opt.hidden))); };
  constexpr std::size_t kRun = 4096;
  const std::size_t n_runs = (segs.size() + kRun - 1) / kRun;
  std::vector<std::size_t> at(n_runs + 1, 0);  // (a run per task: the scans' chunks are too coarse here)
  loop.for_each(n_runs, 1, [&](std::size_t c) {
    std::size_t k = 0;
    for (std::size_t si = c * kRun, end = std::min(segs.size(), si + kRun); si < end; ++si)
      for (const Piece& p : segs[si].pieces) k += drawn(p);
    at[c + 1] = k;
  });
  std::partial_sum(at.begin(), at.end(), at.begin());
  Drawing2D d;
  reserve_touched(d.lines, at.back(), loop);
  reserve_touched(d.points, 2 * at.back(), loop);
  reserve_touched(d.sources, at.back(), loop);
  d.lines.resize(at.back());
  d.points.resize(2 * at.back());
  d.sources.resize(at.back());
  std::vector<std::size_t> kept(n_runs);
  loop.for_each(n_runs, 1, [&](std::size_t c) {
    std::size_t w = at[c];
    for (std::size_t si = c * kRun, end = std::min(segs.size(), si + kRun); si < end; ++si) {
      const Segment& s = segs[si];
      for (std::size_t pi = 0; pi < s.pieces.size(); ++pi) {
        const Piece& p = s.pieces[pi];
        if (!drawn(p)) continue;
        std::array<double, 4> l;
        bool pulled = false;
        if (!piece_line(s, p, proj, camera.perspective, near, l, pulled)) continue;
        Polyline2D& pl = d.lines[w];
        pl.first = static_cast<std::uint32_t>(2 * w);
        pl.count = 2;
        pl.first_edge = static_cast<std::uint32_t>(w);
        pl.kind = s.line;
        pl.visible = p.visible;
        pl.through = p.through;
        pl.intersection = s.kind == Segment::Kind::Intersection;
        pl.body = s.body;
        pl.body2 = s.body2;
        pl.pulled = pulled;
        d.points[2 * w] = {l[0], l[1]};
        d.points[2 * w + 1] = {l[2], l[3]};
        d.sources[w] = PieceRef{static_cast<int>(si), static_cast<int>(pi)};
        ++w;
      }
    }
    kept[c] = w - at[c];
  });
  if (std::accumulate(kept.begin(), kept.end(), std::size_t{0}) != at.back()) close_gaps(at, kept, d);
  if (opt.vertex_labels) add_vertex_labels(r, proj, camera, opt.label_base, d);
  return d;
}

bool drawing_bounds(const Drawing2D& d, double& x0, double& y0, double& x1, double& y1) {
  x0 = y0 = std::numeric_limits<double>::infinity();
  x1 = y1 = -x0;
  for (const auto& p : d.points) {
    x0 = std::min(x0, p[0]);
    x1 = std::max(x1, p[0]);
    y0 = std::min(y0, p[1]);
    y1 = std::max(y1, p[1]);
  }
  return x1 >= x0;
}

}  // namespace hlr
