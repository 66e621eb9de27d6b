// The 2D stage (see drawing_2d.hpp).
#include "algorithms/drawing_2d.hpp"

#include "algorithms/parallel.hpp"

#include <algorithm>
#include <limits>
#include <set>
#include <string>

namespace hlr {
namespace {

// Drawing coordinates of a piece; false when nothing of it is in front of the eye. For
// perspective, ends closer than `near` to the eye plane are pulled to it (drawing only: the
// visibility of the piece is already decided exactly).
bool piece_line(const Segment& s, const Piece& p, const Projector& proj, bool perspective, double near,
                std::array<double, 4>& out, bool& pulled) {
  pulled = false;
  // Drawing only: the ends in doubles (in the projector's frame) and t rounded.
  std::array<double, 3> F = proj.frame().to_frame(s.from()), T = proj.frame().to_frame(s.to()), A, B;
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

}  // namespace

Projector drawing_projector(const LineDrawing& r, const Camera& camera) {
  const auto& segs = r.segments;
  return Projector(camera, drawing_frame(2 * segs.size(), [&](std::size_t i) -> const Point3& {
                     return i % 2 ? segs[i / 2].to() : segs[i / 2].from();
                   }));
}

Drawing2D project_drawing(const LineDrawing& r, const Camera& camera, const Project2DOptions& opt) {
  Projector proj = drawing_projector(r, camera);
  double near = 0;
  if (camera.perspective) {
    double far = 0;
    for (const Segment& s : r.segments)
      for (const Point3* p : {&s.from(), &s.to()}) far = std::max(far, proj.project(*p)[2]);
    near = 1e-4 * std::max(far, 1e-300);
  }
  // Runs of segments on every core, each into its own lists; joined in segment order.
  constexpr std::size_t kRun = 4096;
  std::vector<Drawing2D> runs((r.segments.size() + kRun - 1) / kRun);
  ParallelLoop().for_each(runs.size(), 1, [&](std::size_t c) {
    Drawing2D& d = runs[c];
    for (std::size_t si = c * kRun, end = std::min(r.segments.size(), si + kRun); si < end; ++si) {
      const Segment& s = r.segments[si];
      for (std::size_t pi = 0; pi < s.pieces.size(); ++pi) {
        const Piece& p = s.pieces[pi];
        if (p.behind_eye || p.clipped || (!p.visible && !(p.through ? opt.through : opt.hidden))) continue;
        std::array<double, 4> l;
        bool pulled = false;
        if (!piece_line(s, p, proj, camera.perspective, near, l, pulled)) continue;
        Polyline2D pl;
        pl.first = static_cast<std::uint32_t>(d.points.size());
        pl.count = 2;
        pl.first_edge = static_cast<std::uint32_t>(d.sources.size());
        pl.kind = s.line;
        pl.visible = p.visible;
        pl.through = p.through;
        pl.intersection = s.kind == Segment::Kind::Intersection;
        pl.body = s.body;
        pl.body2 = s.body2;
        pl.pulled = pulled;
        d.points.push_back({l[0], l[1]});
        d.points.push_back({l[2], l[3]});
        d.sources.push_back(PieceRef{static_cast<int>(si), static_cast<int>(pi)});
        d.lines.push_back(pl);
      }
    }
  });
  // The runs joined in order, each copied into its place on all cores.
  Drawing2D d;
  std::vector<std::size_t> at_line(runs.size() + 1, 0), at_point(runs.size() + 1, 0), at_source(runs.size() + 1, 0);
  for (std::size_t c = 0; c < runs.size(); ++c) {
    at_line[c + 1] = at_line[c] + runs[c].lines.size();
    at_point[c + 1] = at_point[c] + runs[c].points.size();
    at_source[c + 1] = at_source[c] + runs[c].sources.size();
  }
  const ParallelLoop loop;
  reserve_touched(d.lines, at_line.back(), loop);
  reserve_touched(d.points, at_point.back(), loop);
  reserve_touched(d.sources, at_source.back(), loop);
  d.lines.resize(at_line.back());
  d.points.resize(at_point.back());
  d.sources.resize(at_source.back());
  loop.for_each(runs.size(), 1, [&](std::size_t c) {
    Drawing2D& run = runs[c];
    const auto points = static_cast<std::uint32_t>(at_point[c]), sources = static_cast<std::uint32_t>(at_source[c]);
    for (std::size_t k = 0; k < run.lines.size(); ++k) {
      Polyline2D pl = run.lines[k];
      pl.first += points;
      pl.first_edge += sources;
      d.lines[at_line[c] + k] = pl;
    }
    std::copy(run.points.begin(), run.points.end(), d.points.begin() + static_cast<std::ptrdiff_t>(at_point[c]));
    std::copy(run.sources.begin(), run.sources.end(), d.sources.begin() + static_cast<std::ptrdiff_t>(at_source[c]));
    run = Drawing2D();
  });
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
