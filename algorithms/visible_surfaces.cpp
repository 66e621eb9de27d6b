// Visible surfaces as exact polygons (course notes sections 25 and 31). See visible_surfaces.hpp;
// why the visible lines bound the cells and why the probe is exact: docs/design.md ("Visible
// surfaces as exact polygons").
#include "algorithms/visible_surfaces.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "algorithms/drawing_2d.hpp"
#include "algorithms/face_triangles.hpp"
#include "algorithms/line_dedup.hpp"
#include "algorithms/parallel.hpp"
#include "algorithms/screen_grid.hpp"

namespace hlr {
namespace {

// A scene triangle as the picture sees it: exact projected corners counter-clockwise, the
// face's ray parameter num(q) / den(q) (PicturePlane::ray_parameter).
struct PictureTriangle {
  int body, face, id;  // id: global face number
  bool front;
  std::array<Exact2, 3> p;
  std::array<PictureLinear, 2> ray;
};

// Lexicographic sign of f at m + e·n + e²·t.
int lex_sign(const PictureLinear& f, const Exact2& m, const Exact2& n, const Exact2& t) {
  int s = sgn(f.at(m));
  if (s) return s;
  s = sgn(f.along(n));
  if (s) return s;
  return sgn(f.along(t));
}

PictureLinear scaled_minus(const PictureLinear& f, const Rational& a, const PictureLinear& g, const Rational& b) {
  // a·f - b·g
  return {a * f.c0 - b * g.c0, a * f.cx - b * g.cx, a * f.cy - b * g.cy};
}

class Prober {
 public:
  Prober(const std::vector<const Polyhedron*>& bodies, const PicturePlane& pp, unsigned threads) : pp_(pp) {
    std::vector<int> offset(bodies.size() + 1, 0);
    for (std::size_t b = 0; b < bodies.size(); ++b) offset[b + 1] = offset[b] + static_cast<int>(bodies[b]->num_faces());
    total_faces_ = offset.back();
    std::vector<std::vector<PictureTriangle>> per_face(total_faces_);
    front_.assign(total_faces_, 1);
    ParallelLoop loop(threads);
    std::vector<std::vector<Exact2>> proj(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      bodies[b]->planes();  // computed on first use, not thread-safe then
      proj[b].resize(bodies[b]->num_vertices());
      loop.for_each(proj[b].size(), 256, [&](std::size_t v) { proj[b][v] = pp_.project(bodies[b]->vertices()[v]); });
    }
    std::vector<std::pair<int, int>> faces;
    for (std::size_t b = 0; b < bodies.size(); ++b)
      for (std::size_t f = 0; f < bodies[b]->num_faces(); ++f) faces.emplace_back(static_cast<int>(b), static_cast<int>(f));
    loop.for_each(faces.size(), 64, [&](std::size_t i) {
      auto [b, f] = faces[i];
      const Polyhedron& p = *bodies[b];
      const Plane& h = p.planes()[f];
      if (h.is_degenerate()) return;
      FaceTriangles ft = face_triangles(p, f);
      if (ft.status != FaceTriangles::Status::Ok) return;
      auto ray = pp_.ray_parameter(h);
      const Face& face = p.faces()[f];
      for (const FaceTriangle& t : ft.triangles) {
        PictureTriangle pt{b, f, offset[b] + f, true, {}, ray};
        for (int k = 0; k < 3; ++k) pt.p[k] = proj[b][face[t.v[k]]];
        int o = orient2d(pt.p[0], pt.p[1], pt.p[2]);
        if (o == 0) continue;  // edge-on: never the face seen at a point of a cell
        if (o < 0) std::swap(pt.p[1], pt.p[2]);
        pt.front = front_facing(h);
        front_[pt.id] = pt.front;
        per_face[i].push_back(std::move(pt));
      }
    });
    for (auto& v : per_face)
      for (auto& t : v) tris_.push_back(std::move(t));
    std::vector<ScreenRect> rects;
    rects.reserve(tris_.size());
    for (const auto& t : tris_) {
      ScreenRect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
      for (const auto& q : t.p) {
        double x = q[0].get_d(), y = q[1].get_d();
        r.x0 = std::min(r.x0, x), r.x1 = std::max(r.x1, x), r.y0 = std::min(r.y0, y), r.y1 = std::max(r.y1, y);
      }
      double pad = 1e-9 * std::max({std::fabs(r.x0), std::fabs(r.x1), std::fabs(r.y0), std::fabs(r.y1), 1e-300});
      rects.push_back({r.x0 - pad, r.y0 - pad, r.x1 + pad, r.y1 + pad});
    }
    grid_.build(rects, std::vector<char>(rects.size(), 0), 4.0, 2048);
    rects_ = std::move(rects);
  }

  std::size_t triangles() const { return tris_.size(); }
  int total_faces() const { return total_faces_; }

  /// The global face seen just left of the middle of a -> b, or -1.
  int probe(const Exact2& a, const Exact2& b, std::vector<int>& scratch) const {
    Exact2 m{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2};
    Exact2 t{b[0] - a[0], b[1] - a[1]};
    Exact2 n{-t[1], t[0]};
    double mx = m[0].get_d(), my = m[1].get_d();
    double pad = 1e-9 * std::max({std::fabs(mx), std::fabs(my), 1e-300});
    scratch.clear();
    grid_.visit(ScreenRect{mx - pad, my - pad, mx + pad, my + pad}, [&](int i) {
      const ScreenRect& r = rects_[i];
      if (r.x0 <= mx && mx <= r.x1 && r.y0 <= my && my <= r.y1) scratch.push_back(i);
    });
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
    int best = -1;
    for (int i : scratch) {
      if (!contains(tris_[i], m, n, t)) continue;
      if (best < 0 || nearer(tris_[i], tris_[best], m, n, t)) best = i;
    }
    return best < 0 ? -1 : tris_[best].id;
  }

  bool front(int id) const { return front_[id]; }

 private:
  bool front_facing(const Plane& h) const {
    auto ray = pp_.ray_parameter(h);
    // Orthographic: n·v > 0. Perspective: the eye on the positive side, h(E) > 0 (num = -h(E)).
    return pp_.perspective() ? sgn(ray[0].c0) < 0 : sgn(ray[1].c0) > 0;
  }

  // Is m + e·n + e²·t inside the (counter-clockwise) triangle?
  static bool contains(const PictureTriangle& tr, const Exact2& m, const Exact2& n, const Exact2& t) {
    for (int k = 0; k < 3; ++k) {
      const Exact2 &p = tr.p[k], &q = tr.p[(k + 1) % 3];
      // Left of p -> q: cross(q - p, X - p) > 0, linear in X.
      Rational ex = q[0] - p[0], ey = q[1] - p[1];
      PictureLinear f{-(ex * p[1] - ey * p[0]), -ey, ex};
      if (lex_sign(f, m, n, t) <= 0) return false;
    }
    return true;
  }

  // Is triangle x strictly nearer the viewer than y at the offset point? Equal depth (one
  // plane): the side facing the viewer first, then the smaller face number.
  bool nearer(const PictureTriangle& x, const PictureTriangle& y, const Exact2& m, const Exact2& n, const Exact2& t) const {
    if (x.id == y.id) return false;
    int s;
    if (!pp_.perspective()) {
      // s = num / den with den constant; larger is nearer: sign(s_x - s_y).
      const Rational &dx = x.ray[1].c0, &dy = y.ray[1].c0;
      PictureLinear diff = scaled_minus(x.ray[0], 1 / dx, y.ray[0], 1 / dy);
      s = lex_sign(diff, m, n, t);
    } else {
      // l = num / den(q), num constant; smaller is nearer. l_x - l_y = G / (den_x den_y) with
      // G = num_x den_y - num_y den_x linear in q.
      PictureLinear g = scaled_minus(y.ray[1], x.ray[0].c0, x.ray[1], y.ray[0].c0);
      int sg = lex_sign(g, m, n, t) * lex_sign(x.ray[1], m, n, t) * lex_sign(y.ray[1], m, n, t);
      s = -sg;
    }
    if (s != 0) return s > 0;
    if (x.front != y.front) return x.front;
    return x.id < y.id;
  }

  const PicturePlane& pp_;
  std::vector<PictureTriangle> tris_;
  std::vector<ScreenRect> rects_;
  ScreenGrid grid_;
  int total_faces_ = 0;
  std::vector<char> front_;  // per global face
};

void check_in_front(const std::vector<const Polyhedron*>& bodies, const Camera& cam, const LineDrawing& lines) {
  if (!cam.perspective) return;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    for (const Point3& v : bodies[b]->vertices())
      if (cam.in_front(v) != Sign::Positive)
        throw std::invalid_argument("surfaces: body " + std::to_string(b) +
                                    " reaches the eye's plane or behind it; visible surfaces need every body in front of the eye");
  for (const Segment& s : lines.segments)
    for (const Piece& p : s.pieces)
      if (p.clipped || p.behind_eye)
        throw std::invalid_argument("surfaces: a body is nearer than the near plane; move the eye back or lower --near");
}

}  // namespace

VisibleSurfaces visible_surfaces(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineDrawing& lines,
                                 const SurfaceOptions& options) {
  auto t0 = std::chrono::steady_clock::now();
  check_in_front(bodies, camera, lines);
  VisibleSurfaces out;
  PicturePlane pp(camera);
  // The visible pieces, each exact point of the picture once, collinear overlaps drawn once.
  Project2DOptions po;
  po.hidden = false;
  Drawing2D d2 = project_drawing(lines, camera, po);
  for (const Polyline2D& l : d2.lines)
    if (l.pulled) throw std::invalid_argument("surfaces: a body is too near the eye to draw exactly");
  DedupOptions dopt;
  dopt.threads = options.threads;
  CleanDrawing clean = dedup_drawing(d2, lines, camera, dopt);
  std::vector<Exact2> pts(clean.points.size());
  ParallelLoop loop(options.threads);
  loop.for_each(pts.size(), 256, [&](std::size_t i) {
    std::uint32_t e = clean.point_ends[i];
    const Polyline2D& l = d2.lines[e / 2];
    const PieceRef& ref = d2.sources[l.first_edge];
    const Segment& s = lines.segments[ref.segment];
    const Piece& p = s.pieces[ref.piece];
    pts[i] = pp.project(s.at(e & 1 ? p.t1 : p.t0));
  });
  std::vector<std::array<std::uint32_t, 2>> segs;
  segs.reserve(clean.edges.size());
  for (const CleanEdge& e : clean.edges)
    if (e.visible) segs.push_back({e.p, e.q});
  out.stats.segments = segs.size();
  ArrangementOptions ao;
  ao.threads = options.threads;
  PlanarArrangement arr = build_arrangement(std::move(pts), segs, ao);
  out.stats.edges = arr.num_edges();
  out.stats.cycles = arr.cycle_edge.size();
  out.stats.crossings = arr.crossings;
  out.stats.splits = arr.splits;
  out.stats.exact_tests = arr.exact_tests;

  // The face seen in each cycle's cell.
  Prober prober(bodies, pp, options.threads);
  out.stats.triangles = prober.triangles();
  std::vector<int> label(arr.cycle_edge.size(), -1);
  loop.run(label.size(), 64, [&](unsigned, std::size_t begin, std::size_t end) {
    std::vector<int> scratch;
    for (std::size_t c = begin; c < end; ++c) {
      std::uint32_t h = arr.cycle_edge[c];
      label[c] = prober.probe(arr.points[arr.origin[h]], arr.points[arr.head(h)], scratch);
    }
  });
  if (options.check_cycles) {
    std::vector<int> scratch;
    for (std::uint32_t h = 0; h < arr.origin.size(); ++h)
      if (prober.probe(arr.points[arr.origin[h]], arr.points[arr.head(h)], scratch) != label[arr.cycle[h]])
        ++out.stats.label_mismatches;
  }
  std::vector<LabelledRegion> regions = merge_regions(arr, label, -1);

  // Lift each region into its face's plane.
  std::vector<std::pair<int, int>> face_of(prober.total_faces());
  for (std::size_t b = 0, id = 0; b < bodies.size(); ++b)
    for (std::size_t f = 0; f < bodies[b]->num_faces(); ++f, ++id) face_of[id] = {static_cast<int>(b), static_cast<int>(f)};
  // A corner is lifted into the plane of the face on the left of its half-edge.
  auto polygon = [&](const LabelledRegion& r) {
    VisiblePolygon vp;
    auto ring = [&](const std::vector<std::uint32_t>& hs, std::vector<Point3>& p3, std::vector<Exact2>& p2) {
      for (std::uint32_t h : hs) {
        auto [b, f] = face_of[label[arr.cycle[h]]];
        p2.push_back(arr.points[arr.origin[h]]);
        p3.push_back(pp.lift(p2.back(), bodies[b]->planes()[f]));
      }
    };
    ring(r.outer, vp.outer, vp.outer_2d);
    for (const auto& hole : r.holes) {
      vp.holes.emplace_back();
      vp.holes_2d.emplace_back();
      ring(hole, vp.holes.back(), vp.holes_2d.back());
    }
    vp.area2 = r.area2;
    return vp;
  };
  std::vector<VisiblePolygon> polys(regions.size());
  loop.for_each(regions.size(), 16, [&](std::size_t i) { polys[i] = polygon(regions[i]); });
  for (std::size_t i = 0; i < regions.size(); ++i) {
    auto [b, f] = face_of[regions[i].label];
    if (out.faces.empty() || out.faces.back().body != b || out.faces.back().face != f) {
      VisibleFace vf;
      vf.body = b;
      vf.face = f;
      vf.front = prober.front(regions[i].label);
      out.faces.push_back(std::move(vf));
    }
    out.faces.back().polygons.push_back(std::move(polys[i]));
  }
  if (!options.face_group.empty()) {
    std::vector<int> group_label(label.size(), -1);
    for (std::size_t c = 0; c < label.size(); ++c)
      if (label[c] >= 0) {
        auto [b, f] = face_of[label[c]];
        group_label[c] = options.face_group.at(b).at(f);
      }
    std::vector<LabelledRegion> gr = merge_regions(arr, group_label, -1);
    std::vector<VisiblePolygon> gp(gr.size());
    loop.for_each(gr.size(), 16, [&](std::size_t i) { gp[i] = polygon(gr[i]); });
    for (std::size_t i = 0; i < gr.size(); ++i) {
      if (out.groups.empty() || out.groups.back().group != gr[i].label) out.groups.push_back(VisibleGroup{gr[i].label, {}});
      out.groups.back().polygons.push_back(std::move(gp[i]));
    }
  }
  out.stats.polygons = regions.size();
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace hlr
