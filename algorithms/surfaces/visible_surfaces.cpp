// Visible surfaces as exact polygons (course notes sections 25 and 31). See visible_surfaces.hpp;
// why the visible lines bound the cells and why the probe is exact: docs/design.md ("Visible
// surfaces as exact polygons").
#include "algorithms/surfaces/visible_surfaces.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "algorithms/picture/drawing_2d.hpp"
#include "algorithms/solids/face_triangles.hpp"
#include "algorithms/picture/line_dedup.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/support/screen_grid.hpp"

namespace hlr {
namespace {

// A scene triangle as the picture sees it: exact projected corners counter-clockwise, the
// face's ray parameter num(q) / den(q) (PicturePlane::ray_parameter).
struct PictureTriangle {
  int body, face, id;  // id: global face number
  bool front;
  std::array<const Exact2*, 3> p;  // into the projected vertices
  const std::array<PictureLinear, 2>* ray;  // the face's
  // Filters (decide only when their error bound allows; docs/design.md): the corners' doubles,
  // and for orthographic views the depth s(q) = num(q) / den exactly and in doubles.
  std::array<std::array<double, 2>, 3> pd;
  bool pd_ok;  // every corner double in [2^-400, 2^400] or zero: the side filter may be used
  PictureLinear depth;
  std::array<double, 3> depth_d;
};


// Doubles are trusted only in [2^-400, 2^400] (no underflow or overflow in products of two),
// and a zero only when the value is zero.
bool trusted(double x, const Rational& q) { return filter_usable(q, x); }

// out = a + t·(b - a) with one canonicalisation: (an·bd·td + tn·(bn·ad - an·bd)) / (ad·bd·td).
void lerp(const Rational& a, const Rational& b, const Rational& t, Rational& out) {
  thread_local mpz_class x, y, n;
  mpz_mul(x.get_mpz_t(), a.get_num_mpz_t(), b.get_den_mpz_t());  // an·bd
  mpz_mul(y.get_mpz_t(), b.get_num_mpz_t(), a.get_den_mpz_t());  // bn·ad
  mpz_sub(y.get_mpz_t(), y.get_mpz_t(), x.get_mpz_t());
  mpz_mul(n.get_mpz_t(), x.get_mpz_t(), t.get_den_mpz_t());
  mpz_addmul(n.get_mpz_t(), y.get_mpz_t(), t.get_num_mpz_t());
  mpz_mul(x.get_mpz_t(), a.get_den_mpz_t(), b.get_den_mpz_t());
  mpz_mul(x.get_mpz_t(), x.get_mpz_t(), t.get_den_mpz_t());
  mpz_swap(out.get_num_mpz_t(), n.get_mpz_t());
  mpz_swap(out.get_den_mpz_t(), x.get_mpz_t());
  out.canonicalize();
}

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

// The probe point m in doubles, bounds on |m| per axis, and whether the filters may be used.
struct Near {
  double x, y, mag_x, mag_y;
  bool ok;
};

// The probe's offset point m + e·n + e²·t of the half-edge a -> b (m the midpoint, t = b - a,
// n = t turned left), its exact parts computed on first use.
struct Offset {
  const Exact2 &a, &b;
  mutable bool ready = false;
  mutable Exact2 m, n, t;
  void need() const {
    if (ready) return;
    m = {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2};
    t = {b[0] - a[0], b[1] - a[1]};
    n = {-t[1], t[0]};
    ready = true;
  }
};

// Lexicographic sign at the probe's offset point of f(X) = cross(q - p, X - p) (X left of
// p -> q when positive). f is affine, so f(m) = (f(a) + f(b)) / 2: equal or zero signs at the
// ends decide it. Both ends on the line p q (the probe's edge lies along the side): f(m) = 0,
// and the next term, f along n, is (q - p)·t, non-zero since t is then parallel to q - p.
// Ends on opposite sides: the textbook lexicographic evaluation in rationals.
int side_sign(const Exact2& p, const Exact2& q, const Offset& off) {
  const int sa = orient2d(p, q, off.a), sb = orient2d(p, q, off.b);
  if (sa == sb && sa != 0) return sa;
  if (sa == 0 && sb != 0) return sb;
  if (sb == 0 && sa != 0) return sa;
  if (sa == 0 && sb == 0) return dot_sign_exact(p, q, off.a, off.b);
  Rational ex = q[0] - p[0], ey = q[1] - p[1];
  PictureLinear f{-(ex * p[1] - ey * p[0]), -ey, ex};
  off.need();
  return lex_sign(f, off.m, off.n, off.t);
}

class Prober {
 public:
  Prober(const std::vector<const Polyhedron*>& bodies, const PicturePlane& pp, const LineDrawing& lines, unsigned threads) : pp_(pp) {
    std::vector<int> offset(bodies.size() + 1, 0);
    for (std::size_t b = 0; b < bodies.size(); ++b) offset[b + 1] = offset[b] + static_cast<int>(bodies[b]->num_faces());
    total_faces_ = offset.back();
    std::vector<std::vector<PictureTriangle>> per_face(total_faces_);
    front_.assign(total_faces_, 1);
    ParallelLoop loop(threads);
    proj_.resize(bodies.size());
    rays_.resize(total_faces_);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      bodies[b]->planes();  // computed on first use, not thread-safe then
      proj_[b].resize(bodies[b]->num_vertices());
      loop.for_each(proj_[b].size(), 256, [&](std::size_t v) { proj_[b][v] = pp_.project(bodies[b]->vertices()[v]); });
    }
    std::vector<std::pair<int, int>> faces;
    for (std::size_t b = 0; b < bodies.size(); ++b)
      for (std::size_t f = 0; f < bodies[b]->num_faces(); ++f) faces.emplace_back(static_cast<int>(b), static_cast<int>(f));
    loop.for_each(faces.size(), 64, [&](std::size_t i) {
      auto [b, f] = faces[i];
      const Polyhedron& p = *bodies[b];
      const Plane& h = p.planes()[f];
      if (h.is_degenerate()) return;
      // A closed solid's faces turned away are never met first by a sight ray.
      if (static_cast<std::size_t>(b) < lines.back_faces_unseen.size() && lines.back_faces_unseen[b] &&
          lines.facing[b][f] < 0)
        return;
      FaceTriangles ft = face_triangles(p, f);
      if (ft.status != FaceTriangles::Status::Ok) return;
      const int id = offset[b] + f;
      rays_[id] = pp_.ray_parameter(h);
      const auto& ray = rays_[id];
      if (!pp_.perspective() && ray[1].c0 == 0) return;  // edge-on: never the face seen at a point of a cell
      const bool front = pp_.perspective() ? sgn(ray[0].c0) < 0 : sgn(ray[1].c0) > 0;
      front_[id] = front;
      PictureLinear depth;
      std::array<double, 3> depth_d{0, 0, 0};
      if (!pp_.perspective()) {
        const Rational& den = ray[1].c0;
        depth = PictureLinear{ray[0].c0 / den, ray[0].cx / den, ray[0].cy / den};
        depth_d = {depth.c0.get_d(), depth.cx.get_d(), depth.cy.get_d()};
      }
      const Face& face = p.faces()[f];
      for (const FaceTriangle& t : ft.triangles) {
        PictureTriangle pt{b, f, id, front, {}, &ray, {}, false, {}, depth_d};
        for (int k = 0; k < 3; ++k) pt.p[k] = &proj_[b][face[t.v[k]]];
        int o = orient2d(*pt.p[0], *pt.p[1], *pt.p[2]);
        if (o == 0) continue;  // edge-on: never the face seen at a point of a cell
        if (o < 0) std::swap(pt.p[1], pt.p[2]);
        for (int k = 0; k < 3; ++k) pt.pd[k] = {(*pt.p[k])[0].get_d(), (*pt.p[k])[1].get_d()};
        pt.pd_ok = true;
        for (int k = 0; k < 3; ++k) pt.pd_ok = pt.pd_ok && trusted(pt.pd[k][0], (*pt.p[k])[0]) && trusted(pt.pd[k][1], (*pt.p[k])[1]);
        if (!pp_.perspective()) pt.depth = depth;
        per_face[i].push_back(std::move(pt));
      }
    });
    std::size_t count = 0;
    for (const auto& v : per_face) count += v.size();
    tris_.reserve(count);  // growing would copy the triangles' GMP depths (mpq_class's move is not noexcept)
    for (auto& v : per_face)
      for (auto& t : v) tris_.push_back(std::move(t));
    std::vector<ScreenRect> rects;
    rects.reserve(tris_.size());
    for (const auto& t : tris_) {
      ScreenRect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
      for (const auto& q : t.pd) {
        double x = q[0], y = q[1];
        r.x0 = std::min(r.x0, x), r.x1 = std::max(r.x1, x), r.y0 = std::min(r.y0, y), r.y1 = std::max(r.y1, y);
      }
      double pad = box_pad({r.x0, r.x1, r.y0, r.y1});
      rects.push_back({r.x0 - pad, r.y0 - pad, r.x1 + pad, r.y1 + pad});
    }
    std::vector<char> always(rects.size(), 0);
    for (std::size_t i = 0; i < rects.size(); ++i)
      always[i] = !(std::isfinite(rects[i].x0) && std::isfinite(rects[i].x1) && std::isfinite(rects[i].y0) && std::isfinite(rects[i].y1));
    grid_.build(rects, always, 4.0, 2048);
    rects_ = std::move(rects);
  }

  std::size_t triangles() const { return tris_.size(); }
  int total_faces() const { return total_faces_; }

  /// The global face seen just left of the middle of a -> b, or -1. `ad`, `bd`: the ends'
  /// doubles (mpq_get_d), `filters`: they may be used (PlanarArrangement::filters).
  int probe(const Exact2& a, const Exact2& b, const std::array<double, 2>& ad, const std::array<double, 2>& bd, bool filters,
            std::vector<int>& scratch) const {
    // The probe point's double from the ends' doubles, within 1.5·kToDoubleError·mag per axis (mag = the
    // larger |end|; design.md); its exact value, direction and normal only when a filter
    // cannot decide.
    Offset off{a, b, false, {}, {}, {}};
    Near nr{0.5 * (ad[0] + bd[0]), 0.5 * (ad[1] + bd[1]), std::max(std::fabs(ad[0]), std::fabs(bd[0])) * (1 + 4 * kToDoubleError),
            std::max(std::fabs(ad[1]), std::fabs(bd[1])) * (1 + 4 * kToDoubleError), filters};
    const double mx = nr.x, my = nr.y;
    double pad = box_pad({mx, my});
    scratch.clear();
    if (!nr.ok) {  // doubles not trusted here: every triangle is a candidate
      for (std::size_t i = 0; i < tris_.size(); ++i) scratch.push_back(static_cast<int>(i));
    } else {
      grid_.visit(ScreenRect{mx - pad, my - pad, mx + pad, my + pad}, [&](int i) {
        const ScreenRect& r = rects_[i];
        if (!(std::isfinite(r.x0) && std::isfinite(r.x1) && std::isfinite(r.y0) && std::isfinite(r.y1)) ||
            (r.x0 <= mx && mx <= r.x1 && r.y0 <= my && my <= r.y1))
          scratch.push_back(i);
      });
    }
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
    int best = -1;
    for (int i : scratch) {
      if (!contains(tris_[i], off, nr)) continue;
      if (best < 0 || nearer(tris_[i], tris_[best], off, nr)) best = i;
    }
    return best < 0 ? -1 : tris_[best].id;
  }

  bool front(int id) const { return front_[id]; }

 private:
  // Is m + e·n + e²·t inside the (counter-clockwise) triangle? Each side first by the double
  // filter at m (error bound as planar_arrangement.cpp's orientation, doubled for m's own
  // rounding), then lexicographically in rationals.
  static bool contains(const PictureTriangle& tr, const Offset& off, const Near& nr) {
    for (int k = 0; k < 3; ++k) {
      if (nr.ok && tr.pd_ok) {
        const auto &p = tr.pd[k], &q = tr.pd[(k + 1) % 3];
        const double mx = std::max({std::fabs(p[0]), std::fabs(q[0]), nr.mag_x}), my = std::max({std::fabs(p[1]), std::fabs(q[1]), nr.mag_y});
        const int o = orient2d_filter(p, q, {nr.x, nr.y}, mx, my, 2);
        if (o > 0) continue;
        if (o < 0) return false;
      }
      const Exact2 &p = *tr.p[k], &q = *tr.p[(k + 1) % 3];
      if (side_sign(p, q, off) <= 0) return false;
    }
    return true;
  }

  // Is triangle x strictly nearer the viewer than y at the offset point? Equal depth (one
  // plane): the side facing the viewer first, then the smaller face number.
  bool nearer(const PictureTriangle& x, const PictureTriangle& y, const Offset& off, const Near& nr) const {
    if (x.id == y.id) return false;
    int s;
    if (!pp_.perspective()) {
      // s = num / den with den constant; larger is nearer: sign(s_x - s_y). Filter: each
      // depth's double at m is within 16·kToDoubleError·(|c0| + |cx|·|mx| + |cy|·|my|) of its value.
      if (nr.ok && std::isfinite(x.depth_d[0]) && std::isfinite(y.depth_d[0])) {
        auto val = [&](const std::array<double, 3>& c) { return c[0] + c[1] * nr.x + c[2] * nr.y; };
        auto mag = [&](const std::array<double, 3>& c) { return std::fabs(c[0]) + std::fabs(c[1]) * nr.mag_x + std::fabs(c[2]) * nr.mag_y; };
        double d = val(x.depth_d) - val(y.depth_d), bound = 16 * kToDoubleError * (mag(x.depth_d) + mag(y.depth_d));
        if (d > bound) return true;
        if (d < -bound) return false;
      }
      PictureLinear diff{x.depth.c0 - y.depth.c0, x.depth.cx - y.depth.cx, x.depth.cy - y.depth.cy};
      off.need();
      s = lex_sign(diff, off.m, off.n, off.t);
    } else {
      // l = num / den(q), num constant; smaller is nearer. l_x - l_y = G / (den_x den_y) with
      // G = num_x den_y - num_y den_x linear in q.
      const auto &rx = *x.ray, &ry = *y.ray;
      PictureLinear g = scaled_minus(ry[1], rx[0].c0, rx[1], ry[0].c0);
      off.need();
      const Exact2 &m = off.m, &n = off.n, &t = off.t;
      int sg = lex_sign(g, m, n, t) * lex_sign(rx[1], m, n, t) * lex_sign(ry[1], m, n, t);
      s = -sg;
    }
    if (s != 0) return s > 0;
    if (x.front != y.front) return x.front;
    return x.id < y.id;
  }

  const PicturePlane& pp_;
  std::vector<std::vector<Exact2>> proj_;                  // per body and vertex
  std::vector<std::array<PictureLinear, 2>> rays_;         // per global face
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

// Merges the labelled cells into each face's polygons (and each group's), lifted into the
// faces' planes when asked.
template <class Front>
void regions_to_surfaces(const PlanarArrangement& arr, const std::vector<int>& label, const std::vector<const Polyhedron*>& bodies,
                         const PicturePlane& pp, Front front, const SurfaceOptions& options, VisibleSurfaces& out) {
  ParallelLoop loop(options.threads);
  std::size_t total_faces = 0;
  for (const Polyhedron* b : bodies) total_faces += b->num_faces();
  std::vector<LabelledRegion> regions;
  if (options.faces) regions = merge_regions(arr, label, -1, options.lift);

  // Lift each region into its face's plane.
  std::vector<std::pair<int, int>> face_of(total_faces);
  for (std::size_t b = 0, id = 0; b < bodies.size(); ++b)
    for (std::size_t f = 0; f < bodies[b]->num_faces(); ++f, ++id) face_of[id] = {static_cast<int>(b), static_cast<int>(f)};
  // A corner is lifted into the plane of the face on the left of its half-edge.
  std::vector<std::array<PictureLinear, 2>> ray_of(total_faces);
  {
    std::vector<char> used(total_faces, 0);
    if (options.lift && options.faces)
      for (int l : label)
        if (l >= 0) used[l] = 1;
    loop.for_each(used.size(), 256, [&](std::size_t id) {
      if (!used[id]) return;
      auto [b, f] = face_of[id];
      ray_of[id] = pp.ray_parameter(bodies[b]->planes()[f]);
    });
  }
  auto polygon = [&](const LabelledRegion& r, bool lift) {
    VisiblePolygon vp;
    auto ring = [&](const std::vector<std::uint32_t>& hs, std::vector<Point3>& p3, std::vector<Exact2>& p2) {
      for (std::uint32_t h : hs) {
        p2.push_back(arr.points[arr.origin[h]]);
        if (lift) p3.push_back(pp.lift(p2.back(), ray_of[label[arr.cycle[h]]]));
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
  loop.for_each(regions.size(), 16, [&](std::size_t i) { polys[i] = polygon(regions[i], options.lift); });
  for (std::size_t i = 0; i < regions.size(); ++i) {
    auto [b, f] = face_of[regions[i].label];
    if (out.faces.empty() || out.faces.back().body != b || out.faces.back().face != f) {
      VisibleFace vf;
      vf.body = b;
      vf.face = f;
      vf.front = front(regions[i].label);
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
    std::vector<LabelledRegion> gr = merge_regions(arr, group_label, -1, false);
    std::vector<VisiblePolygon> gp(gr.size());
    const bool approx = !options.exact_groups && arr.filters;
    auto approx_polygon = [&](const LabelledRegion& r) {
      VisiblePolygon vp;
      auto ring = [&](const std::vector<std::uint32_t>& hs, std::vector<std::array<double, 2>>& out) {
        out.reserve(hs.size());
        for (std::uint32_t h : hs) out.push_back(arr.approx[arr.origin[h]]);
      };
      ring(r.outer, vp.outer_approx);
      for (const auto& hole : r.holes) ring(hole, vp.holes_approx.emplace_back());
      return vp;
    };
    loop.for_each(gr.size(), 16, [&](std::size_t i) { gp[i] = approx ? approx_polygon(gr[i]) : polygon(gr[i], false); });
    for (std::size_t i = 0; i < gr.size(); ++i) {
      if (out.groups.empty() || out.groups.back().group != gr[i].label) out.groups.push_back(VisibleGroup{gr[i].label, {}});
      out.groups.back().polygons.push_back(std::move(gp[i]));
    }
    out.stats.fills = gr.size();
  }
  out.stats.polygons = regions.size();
}

}  // namespace

VisibleSurfaces visible_surfaces(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineDrawing& lines,
                                 const SurfaceOptions& options) {
  auto t0 = std::chrono::steady_clock::now();
  auto lap = [t = t0]() mutable {
    auto now = std::chrono::steady_clock::now();
    double d = std::chrono::duration<double>(now - t).count();
    t = now;
    return d;
  };
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
  out.stats.seconds_clean = lap();
  std::vector<Exact2> pts(clean.points.size());
  ParallelLoop loop(options.threads);
  auto source = [&](std::size_t i) -> std::pair<std::uint32_t, const Rational*> {
    std::uint32_t e = clean.point_ends[i];
    const PieceRef& ref = d2.sources[d2.lines[e / 2].first_edge];
    const Piece& p = lines.segments[ref.segment].pieces[ref.piece];
    return {ref.segment, e & 1 ? &p.t1 : &p.t0};
  };
  // Each segment's ends projected once (orthographic projection is linear: a point at t is
  // a + t·(b - a) of its ends' picture points a, b; perspective projects the point itself).
  std::vector<std::uint32_t> slot(lines.segments.size(), UINT32_MAX), used;
  if (!camera.perspective)
    for (std::size_t i = 0; i < pts.size(); ++i) {
      auto [sg, t] = source(i);
      if (slot[sg] == UINT32_MAX) slot[sg] = static_cast<std::uint32_t>(used.size()), used.push_back(sg);
    }
  std::vector<std::array<Exact2, 2>> ends(used.size());
  loop.for_each(used.size(), 256, [&](std::size_t k) {
    const Segment& s = lines.segments[used[k]];
    ends[k] = {pp.project(s.from()), pp.project(s.to())};
  });
  loop.for_each(pts.size(), 256, [&](std::size_t i) {
    auto [sg, t] = source(i);
    const Segment& s = lines.segments[sg];
    if (camera.perspective) {
      pts[i] = pp.project(*t == 0 ? s.from() : (*t == 1 ? s.to() : s.at(*t)));
      return;
    }
    const auto& [a, b] = ends[slot[sg]];
    if (*t == 0) pts[i] = a;
    else if (*t == 1) pts[i] = b;
    else
      for (int k = 0; k < 2; ++k) lerp(a[k], b[k], *t, pts[i][k]);
  });
  std::vector<std::array<std::uint32_t, 2>> segs;
  segs.reserve(clean.edges.size());
  for (const CleanEdge& e : clean.edges)
    if (e.visible) segs.push_back({e.p, e.q});
  out.stats.segments = segs.size();
  out.stats.seconds_points = lap();
  ArrangementOptions ao;
  ao.threads = options.threads;
  PlanarArrangement arr = build_arrangement(std::move(pts), segs, ao);
  out.stats.edges = arr.num_edges();
  out.stats.cycles = arr.cycle_edge.size();
  out.stats.crossings = arr.crossings;
  out.stats.splits = arr.splits;
  out.stats.exact_tests = arr.exact_tests;
  out.stats.seconds_arrangement = lap();

  // The face seen in each cycle's cell.
  Prober prober(bodies, pp, lines, options.threads);
  out.stats.triangles = prober.triangles();
  out.stats.seconds_triangles = lap();
  std::vector<int> label(arr.cycle_edge.size(), -1);
  loop.run(label.size(), 64, [&](unsigned, std::size_t begin, std::size_t end) {
    std::vector<int> scratch;
    for (std::size_t c = begin; c < end; ++c) {
      std::uint32_t h = arr.cycle_edge[c];
      label[c] = prober.probe(arr.points[arr.origin[h]], arr.points[arr.head(h)], arr.approx[arr.origin[h]],
                              arr.approx[arr.head(h)], arr.filters, scratch);
    }
  });
  if (options.check_cycles) {
    std::vector<int> scratch;
    for (std::uint32_t h = 0; h < arr.origin.size(); ++h)
      if (prober.probe(arr.points[arr.origin[h]], arr.points[arr.head(h)], arr.approx[arr.origin[h]], arr.approx[arr.head(h)],
                       arr.filters, scratch) != label[arr.cycle[h]])
        ++out.stats.label_mismatches;
  }
  out.stats.seconds_probe = lap();
  regions_to_surfaces(arr, label, bodies, pp, [&](int id) { return prober.front(id); }, options, out);
  out.stats.seconds_regions = lap();
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

VisibleSurfaces surfaces_from_pieces(const std::vector<SurfacePiece>& pieces, const std::vector<const Polyhedron*>& bodies,
                                     const Camera& camera, const SurfaceOptions& options) {
  VisibleSurfaces out;
  PicturePlane pp(camera);
  std::vector<int> offset(bodies.size() + 1, 0);
  for (std::size_t b = 0; b < bodies.size(); ++b) offset[b + 1] = offset[b] + static_cast<int>(bodies[b]->num_faces());
  std::vector<Exact2> pts;
  std::vector<std::array<std::uint32_t, 2>> segs;
  for (const SurfacePiece& p : pieces) {
    const auto base = static_cast<std::uint32_t>(pts.size());
    for (std::size_t i = 0; i < p.pts.size(); ++i) {
      pts.push_back(p.pts[i]);
      segs.push_back({base + static_cast<std::uint32_t>(i), base + static_cast<std::uint32_t>((i + 1) % p.pts.size())});
    }
  }
  out.stats.segments = segs.size();
  ArrangementOptions ao;
  ao.threads = options.threads;
  PlanarArrangement arr = build_arrangement(std::move(pts), segs, ao);
  out.stats.edges = arr.num_edges();
  out.stats.cycles = arr.cycle_edge.size();
  // Each cell lies in at most one piece: the one holding the point just left of its edge.
  auto label_of = [&](std::uint32_t h) {
    const Exact2 &a = arr.points[arr.origin[h]], &b = arr.points[arr.head(h)];
    Exact2 m{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2}, t{b[0] - a[0], b[1] - a[1]}, n{-(b[1] - a[1]), b[0] - a[0]};
    for (const SurfacePiece& p : pieces) {
      bool in = true;
      for (std::size_t k = 0; k < p.pts.size() && in; ++k) {
        const Exact2 &u = p.pts[k], &v = p.pts[(k + 1) % p.pts.size()];
        Rational ex = v[0] - u[0], ey = v[1] - u[1];
        in = lex_sign(PictureLinear{-(ex * u[1] - ey * u[0]), -ey, ex}, m, n, t) > 0;
      }
      if (in) return offset[p.body] + p.face;
    }
    return -1;
  };
  std::vector<int> label(arr.cycle_edge.size());
  for (std::size_t c = 0; c < label.size(); ++c) label[c] = label_of(arr.cycle_edge[c]);
  if (options.check_cycles)
    for (std::uint32_t h = 0; h < arr.origin.size(); ++h)
      if (label_of(h) != label[arr.cycle[h]]) ++out.stats.label_mismatches;
  std::vector<char> front(offset.back(), 1);
  for (std::size_t b = 0; b < bodies.size(); ++b)
    for (std::size_t f = 0; f < bodies[b]->num_faces(); ++f) {
      auto r = pp.ray_parameter(bodies[b]->planes()[f]);
      front[offset[b] + f] = pp.perspective() ? sgn(r[0].c0) < 0 : sgn(r[1].c0) > 0;
    }
  regions_to_surfaces(arr, label, bodies, pp, [&](int id) { return front[id] != 0; }, options, out);
  return out;
}

}  // namespace hlr
