// Visible surfaces as exact polygons (course notes sections 25 and 31). See visible_surfaces.hpp;
// why the visible lines bound the cells and why the probe is exact: docs/design.md ("Visible
// surfaces as exact polygons").
#include "algorithms/surfaces/visible_surfaces.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "algorithms/picture/drawing_2d.hpp"
#include "algorithms/picture/line_dedup.hpp"
#include "algorithms/solids/face_triangles.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/support/screen_grid.hpp"
#include "kernel/plane_int128.hpp"

namespace hlr {
namespace {

// A scene triangle as the picture sees it: its corners (vertex numbers of its body, counter-
// clockwise in the picture) and, as filters (they decide only when their error bound allows;
// docs/design.md), the corners' doubles and for orthographic views the doubles of the depth
// s(q) = c0 + cx·x + cy·y (PicturePlane::depth_doubles). The exact depth or ray parameter is
// made per face when a filter cannot decide (Prober::ray). Plain numbers only, so the
// triangles of a million faces are a few tens of megabytes and copy as bytes.
struct PictureTriangle {
  int body, face, id;  // id: global face number
  std::array<std::uint32_t, 3> v;
  bool front;
  bool pd_ok;     // every corner double in [2^-400, 2^400] or zero: the side filter may be used
  bool depth_ok;  // depth_d may be used
  std::array<std::array<double, 2>, 3> pd;
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
  Prober(const std::vector<const Polyhedron*>& bodies, const PicturePlane& pp, const LineDrawing& lines, unsigned threads)
      : pp_(pp), bodies_(bodies) {
    std::vector<int> offset(bodies.size() + 1, 0);
    for (std::size_t b = 0; b < bodies.size(); ++b) offset[b + 1] = offset[b] + static_cast<int>(bodies[b]->num_faces());
    total_faces_ = offset.back();
    front_.assign(total_faces_, 1);
    rays_ = std::make_unique<std::atomic<const Ray*>[]>(total_faces_);
    for (int i = 0; i < total_faces_; ++i) rays_[i].store(nullptr, std::memory_order_relaxed);
    ParallelLoop loop(threads);
    project_vertices(loop);
    // The faces' triangles in order of face, made on all cores in ranges of faces joined in order.
    std::mutex m;
    std::vector<std::pair<std::size_t, std::vector<PictureTriangle>>> runs;
    loop.run(total_faces_, 256, [&](unsigned, std::size_t begin, std::size_t end) {
      std::vector<PictureTriangle> run;
      std::size_t b = std::upper_bound(offset.begin(), offset.end(), static_cast<int>(begin)) - offset.begin() - 1;
      for (std::size_t id = begin; id < end; ++id) {
        while (static_cast<int>(id) >= offset[b + 1]) ++b;
        add_face(static_cast<int>(b), static_cast<int>(id) - offset[b], static_cast<int>(id), lines, run);
      }
      std::lock_guard<std::mutex> lock(m);
      runs.emplace_back(begin, std::move(run));
    });
    std::sort(runs.begin(), runs.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::size_t count = 0;
    for (const auto& r : runs) count += r.second.size();
    tris_.reserve(count);
    for (const auto& r : runs) tris_.insert(tris_.end(), r.second.begin(), r.second.end());
    runs.clear();
    build_grid(loop, threads);
  }

  ~Prober() {
    for (int i = 0; i < total_faces_; ++i) delete rays_[i].load(std::memory_order_relaxed);
  }
  Prober(const Prober&) = delete;
  Prober& operator=(const Prober&) = delete;

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
  bool contains(const PictureTriangle& tr, const Offset& off, const Near& nr) const {
    for (int k = 0; k < 3; ++k) {
      if (nr.ok && tr.pd_ok) {
        const auto &p = tr.pd[k], &q = tr.pd[(k + 1) % 3];
        const double mx = std::max({std::fabs(p[0]), std::fabs(q[0]), nr.mag_x}), my = std::max({std::fabs(p[1]), std::fabs(q[1]), nr.mag_y});
        const int o = orient2d_filter(p, q, {nr.x, nr.y}, mx, my, 2);
        if (o > 0) continue;
        if (o < 0) return false;
      }
      if (side_sign(corner(tr, k), corner(tr, (k + 1) % 3), off) <= 0) return false;
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
      if (nr.ok && x.depth_ok && y.depth_ok) {
        auto val = [&](const std::array<double, 3>& c) { return c[0] + c[1] * nr.x + c[2] * nr.y; };
        auto mag = [&](const std::array<double, 3>& c) { return std::fabs(c[0]) + std::fabs(c[1]) * nr.mag_x + std::fabs(c[2]) * nr.mag_y; };
        double d = val(x.depth_d) - val(y.depth_d), bound = 16 * kToDoubleError * (mag(x.depth_d) + mag(y.depth_d));
        if (d > bound) return true;
        if (d < -bound) return false;
      }
      const PictureLinear &dx = ray(x).depth, &dy = ray(y).depth;
      PictureLinear diff{dx.c0 - dy.c0, dx.cx - dy.cx, dx.cy - dy.cy};
      off.need();
      s = lex_sign(diff, off.m, off.n, off.t);
    } else {
      // l = num / den(q), num constant; smaller is nearer. l_x - l_y = G / (den_x den_y) with
      // G = num_x den_y - num_y den_x linear in q.
      const auto &rx = ray(x).ray, &ry = ray(y).ray;
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

  // The face's ray parameter (PicturePlane::ray_parameter) and, orthographic, its depth
  // num / den; made on first use by any thread (the first one stored is kept).
  struct Ray {
    std::array<PictureLinear, 2> ray;
    PictureLinear depth;
  };
  const Ray& ray(int id, int b, int f) const {
    if (const Ray* r = rays_[id].load(std::memory_order_acquire)) return *r;
    auto made = std::make_unique<Ray>();
    const Polyhedron& p = *bodies_[b];
    const Plane* h = p.plane_if_made(f);
    Plane own;
    if (!h) own = p.face_plane(f), h = &own;
    made->ray = pp_.ray_parameter(*h);
    if (!pp_.perspective() && sgn(made->ray[1].c0) != 0) {
      const Rational& den = made->ray[1].c0;
      made->depth = PictureLinear{made->ray[0].c0 / den, made->ray[0].cx / den, made->ray[0].cy / den};
    }
    const Ray* expected = nullptr;
    if (rays_[id].compare_exchange_strong(expected, made.get(), std::memory_order_acq_rel)) return *made.release();
    return *expected;
  }
  const Ray& ray(const PictureTriangle& t) const { return ray(t.id, t.body, t.face); }
  const Exact2& corner(const PictureTriangle& t, int k) const { return proj_[t.body][t.v[k]]; }

  void project_vertices(const ParallelLoop& loop) {
    proj_.resize(bodies_.size());
    projd_.resize(bodies_.size());
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      const Polyhedron& p = *bodies_[b];
      proj_[b].resize(p.num_vertices());
      projd_[b].resize(p.num_vertices());
      loop.for_each(p.num_vertices(), 256, [&](std::size_t v) {
        proj_[b][v] = pp_.project(p.vertices()[v]);
        const Exact2& q = proj_[b][v];
        Corner& c = projd_[b][v];
        c.d = {q[0].get_d(), q[1].get_d()};
        c.ok = trusted(c.d[0], q[0]) && trusted(c.d[1], q[1]);
      });
    }
  }

  // The triangles of face f of body b (global number id) that a sight ray can meet first.
  void add_face(int b, int f, int id, const LineDrawing& lines, std::vector<PictureTriangle>& out) {
    const Polyhedron& p = *bodies_[b];
    // A closed solid's faces turned away are never met first by a sight ray.
    if (static_cast<std::size_t>(b) < lines.back_faces_unseen.size() && lines.back_faces_unseen[b] && lines.facing[b][f] < 0) return;
    // The plane in 128-bit integers when it fits (no rationals), else the exact one.
    const Plane* h = p.plane_if_made(f);
    PlaneInt128 small;
    const bool is_small = !h && face_plane_int128(p, f, small);
    Plane own;
    if (!h && !is_small) own = p.face_plane(f), h = &own;
    if (is_small ? small.degenerate() : h->is_degenerate()) return;
    PictureTriangle pt{b, f, id, {}, true, true, false, {}, {0, 0, 0}};
    if (pp_.perspective()) {
      pt.front = sgn(ray(id, b, f).ray[0].c0) < 0;
    } else {
      const PicturePlane::DepthDoubles dd = is_small ? pp_.depth_doubles(small) : pp_.depth_doubles(*h);
      const int facing = dd.integers ? dd.facing : sgn(ray(id, b, f).ray[1].c0);
      if (facing == 0) return;  // edge-on: never the face seen at a point of a cell
      pt.front = facing > 0;
      pt.depth_ok = dd.ok;
      pt.depth_d = dd.c;
    }
    front_[id] = pt.front;
    const Face& face = p.faces()[f];
    auto add = [&](std::array<int, 3> k) {
      pt.v = {static_cast<std::uint32_t>(face[k[0]]), static_cast<std::uint32_t>(face[k[1]]), static_cast<std::uint32_t>(face[k[2]])};
      const int o = orient2d(corner(pt, 0), corner(pt, 1), corner(pt, 2));
      if (o == 0) return;  // edge-on: never the face seen at a point of a cell
      if (o < 0) std::swap(pt.v[1], pt.v[2]);
      pt.pd_ok = true;
      for (int c = 0; c < 3; ++c) {
        const Corner& cd = projd_[b][pt.v[c]];
        pt.pd[c] = cd.d;
        pt.pd_ok = pt.pd_ok && cd.ok;
      }
      out.push_back(pt);
    };
    if (face.size() == 3) return add({0, 1, 2});
    FaceTriangles ft = face_triangles(p, f);
    if (ft.status != FaceTriangles::Status::Ok) return;
    for (const FaceTriangle& t : ft.triangles) add({t.v[0], t.v[1], t.v[2]});
  }

  void build_grid(const ParallelLoop& loop, unsigned threads) {
    rects_.resize(tris_.size());
    std::vector<char> always(tris_.size(), 0);
    loop.for_each(tris_.size(), 1024, [&](std::size_t i) {
      ScreenRect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
      for (const auto& q : tris_[i].pd) {
        double x = q[0], y = q[1];
        r.x0 = std::min(r.x0, x), r.x1 = std::max(r.x1, x), r.y0 = std::min(r.y0, y), r.y1 = std::max(r.y1, y);
      }
      double pad = box_pad({r.x0, r.x1, r.y0, r.y1});
      rects_[i] = {r.x0 - pad, r.y0 - pad, r.x1 + pad, r.y1 + pad};
      always[i] = !(std::isfinite(rects_[i].x0) && std::isfinite(rects_[i].x1) && std::isfinite(rects_[i].y0) && std::isfinite(rects_[i].y1));
    });
    grid_.build(rects_, always, 4.0, 2048, threads);
  }

  struct Corner {
    std::array<double, 2> d;
    bool ok;
  };
  const PicturePlane& pp_;
  const std::vector<const Polyhedron*>& bodies_;
  std::vector<std::vector<Exact2>> proj_;            // per body and vertex
  std::vector<std::vector<Corner>> projd_;           // their doubles
  std::unique_ptr<std::atomic<const Ray*>[]> rays_;  // per global face, made on first use
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
  // (Only when lifting: a million faces' empty rays are a million GMP initialisations.)
  std::vector<std::array<PictureLinear, 2>> ray_of(options.lift && options.faces ? total_faces : 0);
  if (options.lift && options.faces) {
    std::vector<char> used(total_faces, 0);
    for (int l : label)
      if (l >= 0) used[l] = 1;
    for (const Polyhedron* b : bodies) plane_all_faces(*b, options.threads);  // before the parallel reads
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
