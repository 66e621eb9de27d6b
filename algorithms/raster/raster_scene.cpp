// The exact image-space model of the raster algorithms (course notes sections 25, 29-35). See
// raster_scene.hpp.
#include "algorithms/raster/raster_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "algorithms/solids/face_triangles.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/picture/scene_polygons.hpp"

namespace hlr {
namespace {

// Interval arithmetic: kernel/error_bounds.hpp.
using namespace interval;
double up(double v) { return next_up(v); }
Interval of(const Rational& q) { return bounds_of(q); }
Interval linear(Interval c0, Interval cx, Interval cy, double x, double y) { return add(add(c0, scale(cx, x)), scale(cy, y)); }

FilteredLinear filtered(Interval c0, Interval cx, Interval cy) {
  FilteredLinear f;
  const Interval c[3] = {c0, cx, cy};
  for (int k = 0; k < 3; ++k) f.m[k] = c[k].lo, f.r[k] = up(c[k].hi - c[k].lo);
  return f;
}

}  // namespace

int FilteredLinear::sign(double x, double y) const {
  // |exact - (m0 + m1·x + m2·y)| <= r0 + r1·|x| + r2·|y|; evaluating the three terms in doubles
  // errs by at most γ3 = 3u/(1 - 3u) < 4u of the sum of their magnitudes; the bound's own
  // rounding (a sum of non-negative terms, 8 operations) is covered by the factor 1 + 2^-40,
  // underflow by 2^-1000. Not finite: undecided.
  const double ax = std::fabs(x), ay = std::fabs(y);
  const double v = m[0] + m[1] * x + m[2] * y;
  const double e = ((r[0] + r[1] * ax + r[2] * ay) + 8 * kUnitRoundoff * (std::fabs(m[0]) + std::fabs(m[1]) * ax + std::fabs(m[2]) * ay)) *
                       kBoundSafety + 0x1p-1000;
  if (!(e < INFINITY)) return 2;
  if (v > e) return 1;
  if (v < -e) return -1;
  return 2;
}

std::array<int, 2> RasterGrid::columns(double lo, double hi) const {
  double a = std::floor((lo - dx0) / dxstep - 0.5) - 1, b = std::ceil((hi - dx0) / dxstep - 0.5) + 1;
  return {static_cast<int>(std::clamp(a, 0.0, static_cast<double>(width))), static_cast<int>(std::clamp(b + 1, 0.0, static_cast<double>(width)))};
}

std::array<int, 2> RasterGrid::rows(double lo, double hi) const {
  double a = std::floor((dy1 - hi) / dystep - 0.5) - 1, b = std::ceil((dy1 - lo) / dystep - 0.5) + 1;
  return {static_cast<int>(std::clamp(a, 0.0, static_cast<double>(height))), static_cast<int>(std::clamp(b + 1, 0.0, static_cast<double>(height)))};
}

namespace {

// A short dyadic number m·2^k >= raw (2^19 <= m < 2^20) and its k.
double dyadic_up(double raw, int& k) {
  k = static_cast<int>(std::floor(std::log2(raw))) - 19;
  return std::ldexp(std::ceil(std::ldexp(raw, -k)), k);
}

}  // namespace

RasterGrid raster_grid(const std::array<double, 4>& extent, int width, int height, double x_unit, double y_unit, double margin) {
  if (width < 1 || height < 1 || width > 65536 || height > 65536)
    throw std::invalid_argument("--size: the image must be 1 to 65536 pixels each way");
  double x0 = extent[0], y0 = extent[1], x1 = extent[2], y1 = extent[3];
  if (!(x0 <= x1 && y0 <= y1)) x0 = y0 = -1, x1 = y1 = 1;  // no polygon
  const double big = std::ldexp(1.0, 500), small = std::ldexp(1.0, -500);
  for (double v : {x0, x1, y0, y1})
    if (!std::isfinite(v) || std::fabs(v) > big)
      throw std::invalid_argument("raster: the picture's coordinates lie beyond 2^500 (scale the scene: the pixel grid is exact in doubles)");
  // The pixel's true size, then its steps in picture units along x and y.
  double size = std::max((x1 - x0) * x_unit / width, (y1 - y0) * y_unit / height) * margin;
  if (!(size > 0)) size = std::max({std::fabs(x0) * x_unit, std::fabs(y0) * y_unit, 1e-300}) * 1e-3 / std::max(width, height);
  const double rx = size / x_unit, ry = size / y_unit;
  if (!(rx > small && ry > small && std::isfinite(rx) && std::isfinite(ry)))
    throw std::invalid_argument("raster: the picture is smaller than 2^-500 (scale the scene)");
  RasterGrid g;
  g.width = width, g.height = height;
  int kx = 0, ky = 0;
  g.dxstep = dyadic_up(rx, kx), g.dystep = dyadic_up(ry, ky);
  const double ux = std::ldexp(1.0, kx), uy = std::ldexp(1.0, ky);  // x0 and y1 on multiples of these
  g.dx0 = std::floor(((x0 + x1) / 2 - width * g.dxstep / 2) / ux) * ux;
  g.dy1 = std::ceil(((y0 + y1) / 2 + height * g.dystep / 2) / uy) * uy;
  g.x0 = Rational(g.dx0), g.y1 = Rational(g.dy1), g.xstep = Rational(g.dxstep), g.ystep = Rational(g.dystep);
  return g;
}

bool RasterScene::covers(const RasterPolygon& p, int i, int j) const {
  const double x = grid.cx(i), y = grid.cy(j);
  if (x < p.box[0] || x > p.box[2] || y < p.box[1] || y > p.box[3]) return false;
  for (int k = 0; k < p.count; ++k)
    if (side_sign(p, k, x, y) < 0) return false;
  return true;
}

int RasterScene::side_sign(const RasterPolygon& p, int k, double x, double y) const {
  const int sg = side(p, k).sign(x, y);
  if (sg != 2) return sg;
  counters.inside_exact.fetch_add(1, std::memory_order_relaxed);
  return orient2d(point(p, k), point(p, (k + 1) % p.count), Exact2{Rational(x), Rational(y)});
}

Exact2 RasterScene::point(const RasterPolygon& p, int k) const { return plane->project(corner(p, k)); }

std::vector<Exact2> RasterScene::points(const RasterPolygon& p) const {
  std::vector<Exact2> out;
  for (int k = 0; k < p.count; ++k) out.push_back(point(p, k));
  return out;
}

// The face's exact plane, computed here: a body of triangles has no planes computed
// (raster_scene needs none), and Polyhedron::planes() must not start from parallel loops.
Plane face_plane(const Polyhedron& body, int f) {
  std::vector<const Point3*> pts;
  for (int v : body.faces()[f]) pts.push_back(&body.vertices()[v]);
  return primitive_plane_of_polygon(pts.data(), pts.size());
}

const std::array<Rational, 6>& RasterScene::depth(const RasterPolygon& p) const {
  std::atomic<const std::array<Rational, 6>*>& slot = depth_cache->slot[static_cast<std::size_t>(p.id)];
  if (const auto* z = slot.load(std::memory_order_acquire)) return *z;
  auto [num, den] = plane->ray_parameter(face_plane(*bodies[p.body], p.face));
  auto* fresh = camera.perspective
                    ? new std::array<Rational, 6>{num.c0, num.cx, num.cy, den.c0, den.cx, den.cy}  // z = l = num / den, num constant
                    : new std::array<Rational, 6>{Rational(-num.c0 / den.c0), Rational(-num.cx / den.c0), Rational(-num.cy / den.c0),
                                                  Rational(1), Rational(0), Rational(0)};  // z = -s = -num / den, den constant
  const std::array<Rational, 6>* kept = nullptr;
  if (slot.compare_exchange_strong(kept, fresh, std::memory_order_acq_rel)) return *fresh;
  delete fresh;  // another thread was first: the same value
  return *kept;
}

int RasterScene::denominator_sign(const RasterPolygon& p, double x, double y) const {
  if (!camera.perspective) return 1;
  const int sg = p.zden.sign(x, y);
  if (sg != 2) return sg;
  const std::array<Rational, 6>& z = depth(p);
  return sgn(Rational(z[3] + z[4] * Rational(x) + z[5] * Rational(y)));
}

int RasterScene::depth_order(const RasterPolygon& a, const RasterPolygon& b, double x, double y) const {
  if (a.id == b.id) return 0;  // pieces of one face: one plane
  Interval za, zb;
  if (!camera.perspective) {  // linear depths: the filter on each, then the difference
    const double va = a.zlin.m[0] + a.zlin.m[1] * x + a.zlin.m[2] * y, vb = b.zlin.m[0] + b.zlin.m[1] * x + b.zlin.m[2] * y;
    const double ax = std::fabs(x), ay = std::fabs(y);
    auto err = [&](const FilteredLinear& f) {
      return (f.r[0] + f.r[1] * ax + f.r[2] * ay) + 8 * kUnitRoundoff * (std::fabs(f.m[0]) + std::fabs(f.m[1]) * ax + std::fabs(f.m[2]) * ay);
    };
    // The difference's own rounding: at most u·|va - vb| <= u·(|va| + |vb|).
    const double e = (err(a.zlin) + err(b.zlin) + kToDoubleError * (std::fabs(va) + std::fabs(vb))) * kBoundSafety + 0x1p-1000;
    const double d = va - vb;
    if (e < INFINITY && d < -e) return -1;
    if (e < INFINITY && d > e) return 1;
  } else if (divide(linear(a.zi[0], a.zi[1], a.zi[2], x, y), linear(a.zi[3], a.zi[4], a.zi[5], x, y), za) &&
      divide(linear(b.zi[0], b.zi[1], b.zi[2], x, y), linear(b.zi[3], b.zi[4], b.zi[5], x, y), zb)) {
    if (za.hi < zb.lo) return -1;
    if (za.lo > zb.hi) return 1;
  }
  counters.depth_exact.fetch_add(1, std::memory_order_relaxed);
  const Rational qx(x), qy(y);
  auto z = [&](const RasterPolygon& p) -> Rational {
    const std::array<Rational, 6>& c = depth(p);
    if (!camera.perspective) return c[0] + c[1] * qx + c[2] * qy;  // the denominator is 1
    return (c[0] + c[1] * qx + c[2] * qy) / (c[3] + c[4] * qx + c[5] * qy);
  };
  return cmp(z(a), z(b));
}

bool RasterScene::nearer(const RasterPolygon& a, const RasterPolygon& b, double x, double y) const {
  int d = depth_order(a, b, x, y);
  if (d != 0) return d < 0;
  if (a.rank != b.rank) return a.rank < b.rank;
  return a.id < b.id;
}

int seen_among(const RasterScene& s, const std::vector<int>& candidates, int i, int j) {
  int best = -1;
  const double x = s.grid.cx(i), y = s.grid.cy(j);
  for (int c : candidates)
    if (s.covers(s.polygons[c], i, j) && (best < 0 || s.nearer(s.polygons[c], s.polygons[best], x, y))) best = c;
  return best;
}

namespace {

Interval iv(const Bounds& b) { return b; }
Interval dot3(const Interval a[3], const Interval b[3]) { return add(add(mul(a[0], b[0]), mul(a[1], b[1])), mul(a[2], b[2])); }
// Intervals this small keep every product and sum below in the finite range (2^400·2^400
// times a few), so no infinity and no NaN arise on the way.
bool small(Interval a) { return std::fabs(a.lo) <= 0x1p400 && std::fabs(a.hi) <= 0x1p400; }

using Pic = Interval2;  // certified intervals of a picture point

// The picture plane's vectors as certified intervals (PicturePlane's exact ones).
struct FrameIntervals {
  bool persp = false, usable = true;
  Interval r[3], u[3], d[3], e[3];
  Interval rr, uu, dd;
  FrameIntervals(const PicturePlane& pp, const Camera& c) : persp(c.perspective) {
    for (int i = 0; i < 3; ++i) {
      r[i] = iv(pp.r().approx(i)), u[i] = iv(pp.u().approx(i)), d[i] = iv(pp.d().approx(i)), e[i] = iv(c.eye.approx(i));
      usable = usable && small(r[i]) && small(u[i]) && small(d[i]) && small(e[i]);
    }
    rr = of(dot(pp.r(), pp.r())), uu = of(dot(pp.u(), pp.u())), dd = of(dot(pp.d(), pp.d()));
    usable = usable && small(rr) && small(uu) && small(dd);
  }
};

// Certified intervals of v's picture point: interval doubles from v's bounds, or the bounds of
// the exact projection where the doubles cannot hold the numbers (PicturePlane::project).
Pic picture_of(const FrameIntervals& f, const PicturePlane& pp, const Point3& v) {
  if (f.usable && small(v.approx(0)) && small(v.approx(1)) && small(v.approx(2))) {
    const Interval p[3] = {iv(v.approx(0)), iv(v.approx(1)), iv(v.approx(2))};
    if (!f.persp) return {dot3(p, f.r), dot3(p, f.u)};
    const Interval q[3] = {sub(p[0], f.e[0]), sub(p[1], f.e[1]), sub(p[2], f.e[2])};
    const Interval w = dot3(q, f.d);
    Pic out;
    if (divide(dot3(q, f.r), w, out[0]) && divide(dot3(q, f.u), w, out[1])) return out;
  }
  const Exact2 x = pp.project(v);
  return {of(x[0]), of(x[1])};
}

// Certified intervals of a face's depth coefficients (RasterScene::depth) from the plane's
// bounds; the bounds of the exact ones where the doubles cannot hold the numbers.
std::array<Interval, 6> exact_depth_intervals(const RasterScene& s, const RasterPolygon& p) {
  const std::array<Rational, 6>& z = s.depth(p);
  std::array<Interval, 6> out;
  for (int k = 0; k < 6; ++k) out[k] = of(z[k]);
  return out;
}

// A triangle's plane: n = (b - a) x (c - a), d = -n·a, a positive multiple of its exact plane
// (the depth functions are fractions: a common factor changes no value and no sign).
// A strictly convex face's first three corners give a positive multiple of its plane too (the
// turn at the second corner is strictly positive about its normal).
bool triangle_plane(const Polyhedron& body, int f, Interval n[3], Interval& d) {
  const Face& face = body.faces()[f];
  Interval x[3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      const Bounds& b = body.vertices()[face[i]].approx(k);
      if (!small(b) || std::fabs(b.lo) > 0x1p200 || std::fabs(b.hi) > 0x1p200) return false;
      x[i][k] = iv(b);
    }
  Interval u[3], v[3];
  for (int k = 0; k < 3; ++k) u[k] = sub(x[1][k], x[0][k]), v[k] = sub(x[2][k], x[0][k]);
  n[0] = sub(mul(u[1], v[2]), mul(u[2], v[1]));
  n[1] = sub(mul(u[2], v[0]), mul(u[0], v[2]));
  n[2] = sub(mul(u[0], v[1]), mul(u[1], v[0]));
  const Interval dot_na = dot3(n, x[0]);
  d = {-dot_na.hi, -dot_na.lo};
  return true;
}

std::array<Interval, 6> depth_intervals(const FrameIntervals& f, const Polyhedron& body, bool convex, const RasterScene& s,
                                        const RasterPolygon& p) {
  Interval n[3], hd;
  bool ok = f.usable;
  if (body.faces()[p.face].size() == 3 || convex) {
    ok = ok && triangle_plane(body, p.face, n, hd);
  } else {  // the body's planes are computed (raster_scene)
    const Plane& h = body.planes()[p.face];
    for (int i = 0; i < 4; ++i) ok = ok && small(h.approx(i));
    for (int i = 0; i < 3; ++i) n[i] = iv(h.approx(i));
    hd = iv(h.approx(3));
  }
  if (ok) {
    const Interval nr = dot3(n, f.r), nu = dot3(n, f.u), nd = dot3(n, f.d);
    Interval a, b, c;
    if (!(small(nr) && small(nu) && small(nd) && small(hd))) return exact_depth_intervals(s, p);
    if (!f.persp) {  // z = (d + x·n·r/|r|² + y·n·u/|u|²) / n·v
      if (divide(hd, nd, a) && divide(nr, mul(f.rr, nd), b) && divide(nu, mul(f.uu, nd), c))
        return {a, b, c, Interval{1, 1}, Interval{0, 0}, Interval{0, 0}};
    } else {  // z = -(n·E + d) / (n·d + x·n·r·|d|²/|r|² + y·n·u·|d|²/|u|²)
      const Interval ne = add(dot3(n, f.e), hd);
      if (divide(mul(nr, f.dd), f.rr, b) && divide(mul(nu, f.dd), f.uu, c) && finite(ne) && finite(nd))
        return {Interval{-ne.hi, -ne.lo}, Interval{0, 0}, Interval{0, 0}, nd, b, c};
    }
  }
  return exact_depth_intervals(s, p);
}

// The polygons of a run of faces, in face order (one per chunk, joined in chunk order).
struct Chunk {
  std::vector<RasterPolygon> polygons;
  std::vector<int> verts;
};

// Face f of body b as convex picture polygons: a triangle, or a face proven strictly convex
// and planar (its picture is convex with every corner, or of zero area when seen edge-on), by
// the interval filter on its first three corners (exact when the filter cannot tell); any other
// face exactly (face_pieces).
void add_face(const Polyhedron& p, int b, int f, bool convex, const std::vector<Pic>& pic, const PicturePlane& pp, Chunk& out) {
  const Face& face = p.faces()[f];
  auto push = [&](int piece, const std::vector<int>& at) {
    RasterPolygon rp;
    rp.body = b, rp.face = f, rp.piece = piece;
    rp.first = static_cast<int>(out.verts.size()), rp.count = static_cast<int>(at.size());
    for (int i : at) out.verts.push_back(face[i]);
    out.polygons.push_back(rp);
  };
  if (face.size() == 3 || convex) {
    int o = orient2d_interval(pic[face[0]], pic[face[1]], pic[face[2]]);
    if (o == 2) o = orient2d(pp.project(p.vertices()[face[0]]), pp.project(p.vertices()[face[1]]), pp.project(p.vertices()[face[2]]));
    if (o == 0) return;
    std::vector<int> at(face.size());
    for (std::size_t k = 0; k < at.size(); ++k) at[k] = static_cast<int>(o > 0 ? k : at.size() - 1 - k);
    push(0, at);
    return;
  }
  std::vector<Exact2> fp;
  for (int v : face) fp.push_back(pp.project(p.vertices()[v]));
  int piece = 0;
  for (const std::vector<int>& q : face_pieces(p, f, fp)) push(piece++, q);
}

// The nearest doubles (mpq_get_d) of the exact extremes of the corners' picture points,
// {x0, y0, x1, y1}: the intervals find the few corners that may be extreme, their exact
// projections decide. Empty scene: {1, 1, -1, -1}.
// The true length of a picture unit along x and y: 1/|r| (perspective: |d|/|r|, the picture at
// the target's distance), from the exact ratio so that no square overflows the doubles.
std::array<double, 2> picture_units(const PicturePlane& pp, const Camera& camera) {
  const Rational rr = dot(pp.r(), pp.r()), uu = dot(pp.u(), pp.u()), k2 = camera.perspective ? dot(pp.d(), pp.d()) : Rational(1);
  return {std::sqrt(to_double(Rational(k2 / rr))), std::sqrt(to_double(Rational(k2 / uu)))};
}

std::array<double, 4> picture_extent(const RasterScene& s, const std::vector<std::vector<Pic>>& pic) {
  std::array<double, 4> lo_hi{INFINITY, INFINITY, -INFINITY, -INFINITY};  // the extremes' intervals meet these
  for (const RasterPolygon& p : s.polygons)
    for (int k = 0; k < p.count; ++k) {
      const Pic& q = pic[p.body][s.vert(p, k)];
      lo_hi = {std::min(lo_hi[0], q[0].hi), std::min(lo_hi[1], q[1].hi), std::max(lo_hi[2], q[0].lo), std::max(lo_hi[3], q[1].lo)};
    }
  std::array<double, 4> out{INFINITY, INFINITY, -INFINITY, -INFINITY};
  if (s.polygons.empty()) return {1, 1, -1, -1};
  for (const RasterPolygon& p : s.polygons)
    for (int k = 0; k < p.count; ++k) {
      const Pic& q = pic[p.body][s.vert(p, k)];
      if (q[0].lo > lo_hi[0] && q[1].lo > lo_hi[1] && q[0].hi < lo_hi[2] && q[1].hi < lo_hi[3]) continue;
      const Exact2 x = s.point(p, k);
      const double dx = x[0].get_d(), dy = x[1].get_d();
      out = {std::min(out[0], dx), std::min(out[1], dy), std::max(out[2], dx), std::max(out[3], dy)};
    }
  return out;
}

}  // namespace

RasterScene raster_scene(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineDrawing& lines,
                         int width, int height, unsigned threads, const RasterGrid* grid) {
  RasterScene s;
  s.camera = camera;
  s.bodies = bodies;
  auto plane = std::make_shared<PicturePlane>(camera);
  s.plane = plane;
  const PicturePlane& pp = *plane;
  const FrameIntervals fi(pp, camera);
  ParallelLoop loop(threads);
  // Faces proven strictly convex and planar in integers (proven_convex_face) are treated like
  // triangles; a body with any other face that is not a triangle gets its planes computed once,
  // before the parallel loops. Triangles need none (the interval filters, then face_plane on
  // demand).
  std::vector<std::vector<char>> convex(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Polyhedron& p = *bodies[b];
    convex[b].assign(p.num_faces(), 0);
    if (std::all_of(p.faces().begin(), p.faces().end(), [](const Face& f) { return f.size() == 3; })) continue;
    loop.for_each(p.num_faces(), 1024, [&](std::size_t f) { convex[b][f] = p.faces()[f].size() > 3 && proven_convex_face(p, static_cast<int>(f)); });
    bool other = false;
    for (std::size_t f = 0; f < p.num_faces(); ++f) other = other || (p.faces()[f].size() != 3 && !convex[b][f]);
    if (other) plane_all_faces(p, threads);
  }
  std::vector<int> offset(bodies.size() + 1, 0);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    offset[b + 1] = offset[b] + static_cast<int>(bodies[b]->num_faces());
    for (std::size_t f = 0; f < bodies[b]->num_faces(); ++f) s.faces.push_back({static_cast<int>(b), static_cast<int>(f)});
  }
  s.depth_cache = std::make_shared<RasterScene::DepthCache>(s.faces.size());
  // Every vertex's picture as intervals, then the faces seen as polygons, on all cores in
  // chunks of faces joined in order.
  std::vector<std::vector<Pic>> pic(bodies.size());
  constexpr std::size_t kChunk = 4096;
  std::vector<Chunk> chunks;
  std::vector<std::array<std::size_t, 3>> runs;  // body, first face, end
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Polyhedron& p = *bodies[b];
    pic[b].resize(p.num_vertices());
    loop.for_each(p.num_vertices(), 2048, [&](std::size_t v) { pic[b][v] = picture_of(fi, pp, p.vertices()[v]); });
    for (std::size_t f = 0; f < p.num_faces(); f += kChunk) runs.push_back({b, f, std::min(p.num_faces(), f + kChunk)});
  }
  chunks.resize(runs.size());
  loop.for_each(runs.size(), 1, [&](std::size_t c) {
    const auto [b, f0, f1] = runs[c];
    const Polyhedron& p = *bodies[b];
    const bool cull = b < lines.back_faces_unseen.size() && lines.back_faces_unseen[b];
    for (std::size_t f = f0; f < f1; ++f) {
      if (cull && lines.facing[b][f] < 0) continue;
      // A triangle of zero area has a picture of zero area (add_face drops it); a proven
      // convex face has an area.
      if (p.faces()[f].size() != 3 && !convex[b][f] && p.planes()[f].is_degenerate()) continue;
      add_face(p, static_cast<int>(b), static_cast<int>(f), convex[b][f], pic[b], pp, chunks[c]);
    }
  });
  std::size_t np = 0, nv = 0;
  for (const Chunk& c : chunks) np += c.polygons.size(), nv += c.verts.size();
  s.polygons.reserve(np), s.corner_verts.reserve(nv);
  for (Chunk& c : chunks) {
    const int base = static_cast<int>(s.corner_verts.size());
    for (RasterPolygon& p : c.polygons) p.first += base, s.polygons.push_back(p);
    s.corner_verts.insert(s.corner_verts.end(), c.verts.begin(), c.verts.end());
    c = Chunk{};
  }
  // Each polygon's box, sides and depth, certified.
  s.sides.resize(nv);
  loop.for_each(s.polygons.size(), 1024, [&](std::size_t i) {
    RasterPolygon& p = s.polygons[i];
    p.id = offset[p.body] + p.face;
    p.rank = lines.facing[p.body][p.face] > 0 ? 0 : 1;
    p.zi = depth_intervals(fi, *bodies[p.body], convex[p.body][p.face], s, p);
    p.zlin = filtered(p.zi[0], p.zi[1], p.zi[2]);
    p.zden = filtered(p.zi[3], p.zi[4], p.zi[5]);
    const std::vector<Pic>& c = pic[p.body];
    p.box = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (int k = 0; k < p.count; ++k) {
      const Pic& a = c[s.vert(p, k)];
      p.box = {std::min(p.box[0], a[0].lo), std::min(p.box[1], a[1].lo), std::max(p.box[2], a[0].hi), std::max(p.box[3], a[1].hi)};
    }
    bool fits = true;  // no infinity on the way (else the sides leave every decision to exact)
    for (int k = 0; k < p.count; ++k) fits = fits && small(c[s.vert(p, k)][0]) && small(c[s.vert(p, k)][1]);
    for (int k = 0; k < p.count; ++k) {
      if (!fits) {
        s.sides[static_cast<std::size_t>(p.first + k)] = FilteredLinear{{0, 0, 0}, {INFINITY, INFINITY, INFINITY}};
        continue;
      }
      const Pic &a = c[s.vert(p, k)], &b = c[s.vert(p, (k + 1) % p.count)];
      const Interval dx = sub(b[0], a[0]), dy = sub(b[1], a[1]);
      // orient(a, b, q) = dx·(qy - ay) - dy·(qx - ax) = (dy·ax - dx·ay) - dy·qx + dx·qy
      s.sides[static_cast<std::size_t>(p.first + k)] = filtered(sub(mul(dy, a[0]), mul(dx, a[1])), Interval{-dy.hi, -dy.lo}, dx);
    }
  });
  const std::array<double, 2> unit = picture_units(pp, camera);
  s.grid = grid ? *grid : raster_grid(picture_extent(s, pic), width, height, unit[0], unit[1]);
  return s;
}

RasterGrid frame_grid(const Camera& camera, const Rational& half_x, const Rational& half_y, int width, int height) {
  const std::array<double, 2> unit = picture_units(PicturePlane(camera), camera);
  const double x = to_double(half_x), y = to_double(half_y);
  return raster_grid({-x, -y, x, y}, width, height, unit[0], unit[1], 1.0);
}

}  // namespace hlr
