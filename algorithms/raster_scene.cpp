// The exact image-space model of the raster algorithms (course notes sections 25, 29-35). See
// raster_scene.hpp.
#include "algorithms/raster_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "algorithms/parallel.hpp"

namespace hlr {
namespace {

// Interval arithmetic: each operation rounds to nearest, then widens by one ulp each way, so
// the result contains the exact value (the rounding error is at most half an ulp of the result).
double down(double v) { return std::nextafter(v, -std::numeric_limits<double>::infinity()); }
double up(double v) { return std::nextafter(v, std::numeric_limits<double>::infinity()); }
Interval of(const Rational& q) {
  Bounds b = bounds_of(q);
  return {b.lo, b.hi};
}
Interval add(Interval a, Interval b) { return {down(a.lo + b.lo), up(a.hi + b.hi)}; }
Interval sub(Interval a, Interval b) { return {down(a.lo - b.hi), up(a.hi - b.lo)}; }
Interval mul(Interval a, Interval b) {
  double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {down(*std::min_element(p, p + 4)), up(*std::max_element(p, p + 4))};
}
Interval scale(Interval a, double x) {  // x exact
  double p = a.lo * x, q = a.hi * x;
  return {down(std::min(p, q)), up(std::max(p, q))};
}
Interval linear(Interval c0, Interval cx, Interval cy, double x, double y) { return add(add(c0, scale(cx, x)), scale(cy, y)); }
bool finite(Interval a) { return std::isfinite(a.lo) && std::isfinite(a.hi); }
// The quotient a / b when b does not contain 0 (else an empty answer: undecided).
bool divide(Interval a, Interval b, Interval& out) {
  if (!(b.lo > 0 || b.hi < 0)) return false;
  double p[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  out = {down(*std::min_element(p, p + 4)), up(*std::max_element(p, p + 4))};
  return finite(out);
}

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
  const double e = ((r[0] + r[1] * ax + r[2] * ay) + 0x1p-50 * (std::fabs(m[0]) + std::fabs(m[1]) * ax + std::fabs(m[2]) * ay)) *
                       (1 + 0x1p-40) + 0x1p-1000;
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

RasterGrid raster_grid(const std::vector<ScenePolygon>& polygons, int width, int height, double x_unit, double y_unit) {
  if (width < 1 || height < 1 || width > 65536 || height > 65536)
    throw std::invalid_argument("--size: the image must be 1 to 65536 pixels each way");
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (const ScenePolygon& p : polygons)
    for (const Exact2& q : p.pts) {
      double x = q[0].get_d(), y = q[1].get_d();
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  if (polygons.empty()) x0 = y0 = -1, x1 = y1 = 1;
  const double big = std::ldexp(1.0, 500), small = std::ldexp(1.0, -500);
  for (double v : {x0, x1, y0, y1})
    if (!std::isfinite(v) || std::fabs(v) > big)
      throw std::invalid_argument("raster: the picture's coordinates lie beyond 2^500 (scale the scene: the pixel grid is exact in doubles)");
  // The pixel's true size, then its steps in picture units along x and y.
  double size = std::max((x1 - x0) * x_unit / width, (y1 - y0) * y_unit / height) * 1.04;
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
  for (std::size_t k = 0; k < p.sides.size(); ++k)
    if (side_sign(p, k, x, y) < 0) return false;
  return true;
}

int RasterScene::side_sign(const RasterPolygon& p, std::size_t k, double x, double y) const {
  const int sg = p.sides[k].sign(x, y);
  if (sg != 2) return sg;
  counters.inside_exact.fetch_add(1, std::memory_order_relaxed);
  const std::vector<Exact2>& pts = source[p.poly].pts;
  return orient2d(pts[k], pts[(k + 1) % pts.size()], Exact2{Rational(x), Rational(y)});
}

int RasterScene::depth_order(const RasterPolygon& a, const RasterPolygon& b, double x, double y) const {
  if (a.id == b.id) return 0;  // pieces of one face: one plane
  Interval za, zb;
  if (!camera.perspective) {  // linear depths: the filter on each, then the difference
    const double va = a.zlin.m[0] + a.zlin.m[1] * x + a.zlin.m[2] * y, vb = b.zlin.m[0] + b.zlin.m[1] * x + b.zlin.m[2] * y;
    const double ax = std::fabs(x), ay = std::fabs(y);
    auto err = [&](const FilteredLinear& f) {
      return (f.r[0] + f.r[1] * ax + f.r[2] * ay) + 0x1p-50 * (std::fabs(f.m[0]) + std::fabs(f.m[1]) * ax + std::fabs(f.m[2]) * ay);
    };
    // The difference's own rounding: at most u·|va - vb| <= u·(|va| + |vb|).
    const double e = (err(a.zlin) + err(b.zlin) + 0x1p-52 * (std::fabs(va) + std::fabs(vb))) * (1 + 0x1p-40) + 0x1p-1000;
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
  auto z = [&](const RasterPolygon& p) -> Rational { return (p.z[0] + p.z[1] * qx + p.z[2] * qy) / (p.z[3] + p.z[4] * qx + p.z[5] * qy); };
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

RasterScene raster_scene(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineDrawing& lines,
                         int width, int height, unsigned threads, const RasterGrid* grid) {
  RasterScene s;
  s.camera = camera;
  PicturePlane pp(camera);
  for (const Polyhedron* b : bodies) plane_all_faces(*b, threads);  // computed once, before the parallel loops
  s.source = scene_polygons(bodies, pp, lines);
  const double rr = to_double(dot(pp.r(), pp.r())), uu = to_double(dot(pp.u(), pp.u())), dd = to_double(dot(pp.d(), pp.d()));
  const double k = camera.perspective ? std::sqrt(dd) : 1.0;  // perspective: the picture at the target's distance
  s.grid = grid ? *grid : raster_grid(s.source, width, height, k / std::sqrt(rr), k / std::sqrt(uu));
  std::vector<int> offset(bodies.size() + 1, 0);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    offset[b + 1] = offset[b] + static_cast<int>(bodies[b]->num_faces());
    for (std::size_t f = 0; f < bodies[b]->num_faces(); ++f) s.faces.push_back({static_cast<int>(b), static_cast<int>(f)});
  }
  // Each face's depth function, once per face seen (on all cores).
  std::vector<std::array<Rational, 6>> depth(s.faces.size());
  std::vector<char> used(s.faces.size(), 0);
  for (const ScenePolygon& sp : s.source) used[offset[sp.body] + sp.face] = 1;
  ParallelLoop(threads).for_each(s.faces.size(), 256, [&](std::size_t id) {
    if (!used[id]) return;
    auto [b, f] = s.faces[id];
    auto [num, den] = pp.ray_parameter(bodies[b]->planes()[f]);
    if (!camera.perspective)  // z = -s = -num / den, den constant
      depth[id] = {-num.c0 / den.c0, -num.cx / den.c0, -num.cy / den.c0, Rational(1), Rational(0), Rational(0)};
    else  // z = l = num / den, num constant
      depth[id] = {num.c0, num.cx, num.cy, den.c0, den.cx, den.cy};
  });
  s.polygons.resize(s.source.size());
  ParallelLoop(threads).for_each(s.source.size(), 256, [&](std::size_t i) {
    const ScenePolygon& sp = s.source[i];
    RasterPolygon& p = s.polygons[i];
    p.body = sp.body, p.face = sp.face, p.poly = static_cast<int>(i);
    p.id = offset[sp.body] + sp.face;
    p.rank = lines.facing[sp.body][sp.face] > 0 ? 0 : 1;
    p.z = depth[p.id];
    for (int k = 0; k < 6; ++k) p.zi[k] = of(p.z[k]);
    p.zlin = filtered(p.zi[0], p.zi[1], p.zi[2]);
    const std::size_t n = sp.pts.size();
    p.box = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    std::vector<std::array<Interval, 2>> c(n);
    for (std::size_t k = 0; k < n; ++k) {
      c[k] = {of(sp.pts[k][0]), of(sp.pts[k][1])};
      p.box = {std::min(p.box[0], c[k][0].lo), std::min(p.box[1], c[k][1].lo), std::max(p.box[2], c[k][0].hi),
               std::max(p.box[3], c[k][1].hi)};
    }
    p.sides.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const auto &a = c[k], &b = c[(k + 1) % n];
      Interval dx = sub(b[0], a[0]), dy = sub(b[1], a[1]);
      // orient(a, b, q) = dx·(qy - ay) - dy·(qx - ax) = (dy·ax - dx·ay) - dy·qx + dx·qy
      p.sides[k] = filtered(sub(mul(dy, a[0]), mul(dx, a[1])), Interval{-dy.hi, -dy.lo}, dx);
    }
  });
  return s;
}

}  // namespace hlr
