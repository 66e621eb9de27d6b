// The plotting 2D stage (see plot.hpp).
#include "algorithms/plot/plot.hpp"

#include <array>
#include <chrono>
#include <iterator>
#include <cmath>
#include <limits>

#include "algorithms/support/parallel.hpp"
#include "algorithms/support/parallel_scan.hpp"
#include "algorithms/picture/path_chaining.hpp"

namespace hlr {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Strokes of one layer: chained edges, or one stroke per edge.
std::vector<Stroke> layer_strokes(const CleanDrawing& c, const std::vector<std::uint32_t>& edge_ids, bool chain,
                                  std::size_t& min_count) {
  std::vector<Stroke> out;
  if (!chain) {
    for (std::uint32_t e : edge_ids) out.push_back(Stroke{{c.points[c.edges[e].p], c.points[c.edges[e].q]}, false});
    min_count += edge_ids.size();
    return out;
  }
  // Local point numbering for the layer's graph.
  std::vector<std::uint32_t> local(c.points.size(), UINT32_MAX), global;
  std::vector<std::array<std::uint32_t, 2>> edges;
  auto id = [&](std::uint32_t p) {
    if (local[p] == UINT32_MAX) local[p] = static_cast<std::uint32_t>(global.size()), global.push_back(p);
    return local[p];
  };
  for (std::uint32_t e : edge_ids) edges.push_back({id(c.edges[e].p), id(c.edges[e].q)});
  std::size_t minimum = 0;
  for (const Chain& ch : chain_edges(global.size(), edges, &minimum)) {
    Stroke s;
    s.closed = ch.closed;
    s.points.reserve(ch.points.size());
    for (std::uint32_t p : ch.points) s.points.push_back(c.points[global[p]]);
    out.push_back(std::move(s));
  }
  min_count += minimum;
  return out;
}

}  // namespace

std::string PlotLayer::name() const { return std::string(visible ? "visible-" : through ? "through-" : "hidden-") + to_string(kind); }

bool Plot::empty() const {
  if (!fills.empty()) return false;
  for (const PlotLayer& l : layers)
    if (!l.strokes.empty()) return false;
  return true;
}

double stroke_length(const Stroke& s) {
  double t = 0;
  for (std::size_t i = 1; i < s.points.size(); ++i)
    t += std::hypot(s.points[i][0] - s.points[i - 1][0], s.points[i][1] - s.points[i - 1][1]);
  if (s.closed && s.points.size() > 2)
    t += std::hypot(s.points.back()[0] - s.points[0][0], s.points.back()[1] - s.points[0][1]);
  return t;
}

Plot make_plot(const LineDrawing& lines, const Camera& camera, const PlotOptions& opt) {
  // A large drawing's 2D stage and clean-up begin with the heap's free pages given back
  // (release_free_pages): their arrays do not add to the holes the engine left.
  const bool large = lines.segments.size() >= kLargeArrays;
  if (large) release_free_pages();
  Project2DOptions po;
  po.hidden = opt.hidden;
  CleanDrawing c;
  auto t0 = std::chrono::steady_clock::now();
  {  // the projected drawing is freed before the strokes are made
    Drawing2D d = project_drawing(lines, camera, po);
    t0 = std::chrono::steady_clock::now();
    DedupOptions dopt;
    dopt.overlaps = opt.dedup;
    dopt.threads = opt.threads;
    if (opt.dedup) {
      c = dedup_drawing(d, lines, camera, dopt);
    } else {  // every piece as it is, its own two points
      c.pieces_in = d.lines.size();
      for (const Polyline2D& l : d.lines) {
        auto p = static_cast<std::uint32_t>(c.points.size());
        c.points.push_back(d.point(l, 0));
        c.points.push_back(d.point(l, 1));
        c.edges.push_back(CleanEdge{p, p + 1, d.sources[l.first_edge], l.kind, l.visible, l.through, l.body});
      }
    }
  }
  if (large) release_free_pages();
  return plot_from_clean(c, opt, seconds_since(t0));
}

Plot plot_from_clean(const CleanDrawing& c, const PlotOptions& opt, double seconds_dedup) {
  Plot plot;
  plot.stats.seconds_dedup = seconds_dedup;
  plot.stats.pieces = c.pieces_in;
  plot.stats.zero_length = c.zero_length;
  plot.stats.overlap_groups = c.overlap_groups;
  plot.stats.overlapped_pieces = c.overlapped_pieces;
  plot.stats.duplicate_length = c.duplicate_length;
  plot.stats.edges = c.edges.size();
  plot.stats.exact_point_tests = c.exact_point_tests;
  plot.stats.exact_line_tests = c.exact_line_tests;
  auto t1 = std::chrono::steady_clock::now();
  // The edges of each layer (seen as visible, through or hidden, then kind), in one pass.
  constexpr std::size_t nk = std::size(kLayerKinds);
  // Each edge's layer on all cores, then each used layer's edges in order (selected).
  const ParallelLoop loop(opt.threads);
  std::vector<std::uint8_t> layer_of(c.edges.size());
  PerWorker<std::array<bool, 3 * nk>> used(loop, {});
  loop.run(c.edges.size(), 16384, [&](unsigned w, std::size_t b, std::size_t e) {
    std::array<bool, 3 * nk> u = used[w];
    for (std::size_t i = b; i < e; ++i) {
      const CleanEdge& ce = c.edges[i];
      const int seen = ce.visible && !ce.through ? 0 : (!ce.visible && ce.through ? 1 : (!ce.visible ? 2 : -1));
      std::size_t layer = 3 * nk;  // none
      if (seen >= 0)
        for (std::size_t k = 0; k < nk; ++k)
          if (ce.kind == kLayerKinds[k]) layer = seen * nk + k;
      layer_of[i] = static_cast<std::uint8_t>(layer);
      if (layer < 3 * nk) u[layer] = true;
    }
    used[w] = u;
  });
  std::array<std::vector<std::uint32_t>, 3 * nk> layer_ids;
  for (std::size_t layer = 0; layer < 3 * nk; ++layer) {
    bool any = false;
    for (unsigned w = 0; w < used.size(); ++w) any = any || used[w][layer];
    if (any) layer_ids[layer] = parallel_select(c.edges.size(), [&](std::size_t i) { return layer_of[i] == layer; }, loop);
  }
  for (int seen : {0, 1, 2})  // visible, through, hidden
    for (std::size_t ki = 0; ki < nk; ++ki) {
      const LineKind k = kLayerKinds[ki];
      const bool visible = seen == 0, through = seen == 1;
      const std::vector<std::uint32_t>& ids = layer_ids[seen * nk + ki];
      if (ids.empty()) continue;
      PlotLayer layer;
      layer.visible = visible;
      layer.through = through;
      layer.kind = k;
      layer.strokes = layer_strokes(c, ids, opt.chain, plot.stats.min_path_count);
      plot.stats.path_count += layer.strokes.size();
      plot.layers.push_back(std::move(layer));
    }
  plot.stats.seconds_chain = seconds_since(t1);
  // Each stroke's length and box on all cores; the lengths added in stroke order (the same
  // sum on any number of threads).
  std::vector<const Stroke*> all;
  for (const PlotLayer& l : plot.layers)
    for (const Stroke& s : l.strokes) all.push_back(&s);
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<double> length(all.size());
  std::vector<std::array<double, 4>> box(all.size(), {inf, inf, -inf, -inf});
  ParallelLoop(opt.threads).for_each(all.size(), 64, [&](std::size_t i) {
    length[i] = stroke_length(*all[i]);
    auto& b = box[i];
    for (const Point2& p : all[i]->points) b = {std::min(b[0], p[0]), std::min(b[1], p[1]), std::max(b[2], p[0]), std::max(b[3], p[1])};
  });
  double x0 = inf, y0 = inf, x1 = -inf, y1 = -inf;
  for (std::size_t i = 0; i < all.size(); ++i) {
    plot.stats.pen_down_length += length[i];
    x0 = std::min(x0, box[i][0]), y0 = std::min(y0, box[i][1]), x1 = std::max(x1, box[i][2]), y1 = std::max(y1, box[i][3]);
  }
  if (x1 >= x0) plot.bounds = {x0, y0, x1, y1};
  return plot;
}

void drop_short_strokes(Plot& plot, double min_length) {
  if (!(min_length > 0)) return;
  for (PlotLayer& l : plot.layers) {
    std::vector<Stroke> keep;
    for (Stroke& s : l.strokes) {
      double len = stroke_length(s);
      if (len < min_length) {
        ++plot.stats.dropped_short;
        plot.stats.pen_down_length -= len;
        --plot.stats.path_count;
      } else {
        keep.push_back(std::move(s));
      }
    }
    l.strokes = std::move(keep);
  }
}

void order_plot(Plot& plot, Point2 home, const PenOrderOptions& options) {
  auto t0 = std::chrono::steady_clock::now();
  plot.stats.pen_up_length = plot.stats.pen_up_greedy = plot.stats.pen_up_unordered = 0;
  for (PlotLayer& l : plot.layers) {
    plot.stats.pen_up_unordered += pen_up_length(l.strokes, home);
    PenOrder o = order_strokes(l.strokes, home, options);
    std::vector<Stroke> ordered;
    ordered.reserve(l.strokes.size());
    for (std::size_t i = 0; i < o.order.size(); ++i) {
      Stroke s = std::move(l.strokes[o.order[i]]);
      if (s.closed && o.start[i] != 0)
        std::rotate(s.points.begin(), s.points.begin() + o.start[i], s.points.end());
      else if (!s.closed && o.reversed[i])
        std::reverse(s.points.begin(), s.points.end());
      ordered.push_back(std::move(s));
    }
    l.strokes = std::move(ordered);
    plot.stats.pen_up_length += o.pen_up;
    plot.stats.pen_up_greedy += o.pen_up_greedy;
  }
  plot.stats.seconds_order = seconds_since(t0);
}

}  // namespace hlr
