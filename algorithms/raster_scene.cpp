// The exact image-space model of the raster algorithms (course notes sections 25, 29-35). See
// raster_scene.hpp.
#include "algorithms/raster_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

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

}  // namespace

std::array<int, 2> RasterGrid::columns(double lo, double hi) const {
  double a = std::floor((lo - dx0) / dstep - 0.5) - 1, b = std::ceil((hi - dx0) / dstep - 0.5) + 1;
  return {static_cast<int>(std::clamp(a, 0.0, static_cast<double>(width))), static_cast<int>(std::clamp(b + 1, 0.0, static_cast<double>(width)))};
}

std::array<int, 2> RasterGrid::rows(double lo, double hi) const {
  double a = std::floor((dy1 - hi) / dstep - 0.5) - 1, b = std::ceil((dy1 - lo) / dstep - 0.5) + 1;
  return {static_cast<int>(std::clamp(a, 0.0, static_cast<double>(height))), static_cast<int>(std::clamp(b + 1, 0.0, static_cast<double>(height)))};
}

RasterGrid raster_grid(const std::vector<ScenePolygon>& polygons, int width, int height) {
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
  double raw = std::max((x1 - x0) / width, (y1 - y0) / height) * 1.04;
  if (!(raw > small)) raw = std::max({std::fabs(x0), std::fabs(y0), 1e-300}) * 1e-3 / std::max(width, height);
  if (!(raw > small)) throw std::invalid_argument("raster: the picture is smaller than 2^-500 (scale the scene)");
  // step = m·2^k with 512 <= m < 1024: a short dyadic number; x0 and y1 on multiples of 2^k.
  int k = static_cast<int>(std::floor(std::log2(raw))) - 9;
  double m = std::ceil(std::ldexp(raw, -k));
  RasterGrid g;
  g.width = width, g.height = height;
  g.dstep = std::ldexp(m, k);
  const double unit = std::ldexp(1.0, k);
  g.dx0 = std::floor(((x0 + x1) / 2 - width * g.dstep / 2) / unit) * unit;
  g.dy1 = std::ceil(((y0 + y1) / 2 + height * g.dstep / 2) / unit) * unit;
  g.x0 = Rational(g.dx0), g.y1 = Rational(g.dy1), g.step = Rational(g.dstep);
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
  counters.inside_tests.fetch_add(1, std::memory_order_relaxed);
  const auto& s = p.sides[k];
  Interval v = linear(s[0], s[1], s[2], x, y);
  if (finite(v) && v.lo > 0) return 1;
  if (finite(v) && v.hi < 0) return -1;
  counters.inside_exact.fetch_add(1, std::memory_order_relaxed);
  const std::vector<Exact2>& pts = source[p.poly].pts;
  return orient2d(pts[k], pts[(k + 1) % pts.size()], Exact2{Rational(x), Rational(y)});
}

int RasterScene::depth_order(const RasterPolygon& a, const RasterPolygon& b, double x, double y) const {
  if (a.id == b.id) return 0;  // pieces of one face: one plane
  counters.depth_tests.fetch_add(1, std::memory_order_relaxed);
  Interval za, zb;
  if (divide(linear(a.zi[0], a.zi[1], a.zi[2], x, y), linear(a.zi[3], a.zi[4], a.zi[5], x, y), za) &&
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
                         int width, int height) {
  RasterScene s;
  s.camera = camera;
  PicturePlane pp(camera);
  s.source = scene_polygons(bodies, pp, lines);
  s.grid = raster_grid(s.source, width, height);
  std::vector<int> offset(bodies.size() + 1, 0);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    offset[b + 1] = offset[b] + static_cast<int>(bodies[b]->num_faces());
    for (std::size_t f = 0; f < bodies[b]->num_faces(); ++f) s.faces.push_back({static_cast<int>(b), static_cast<int>(f)});
  }
  std::map<int, std::array<Rational, 6>> depth;  // per face
  s.polygons.resize(s.source.size());
  for (std::size_t i = 0; i < s.source.size(); ++i) {
    const ScenePolygon& sp = s.source[i];
    RasterPolygon& p = s.polygons[i];
    p.body = sp.body, p.face = sp.face, p.poly = static_cast<int>(i);
    p.id = offset[sp.body] + sp.face;
    p.rank = lines.facing[sp.body][sp.face] > 0 ? 0 : 1;
    auto it = depth.find(p.id);
    if (it == depth.end()) {
      auto [num, den] = pp.ray_parameter(bodies[sp.body]->planes()[sp.face]);
      std::array<Rational, 6> z;
      if (!camera.perspective) {  // z = -s = -num / den, den constant
        z = {-num.c0 / den.c0, -num.cx / den.c0, -num.cy / den.c0, Rational(1), Rational(0), Rational(0)};
      } else {  // z = l = num / den, num constant
        z = {num.c0, num.cx, num.cy, den.c0, den.cx, den.cy};
      }
      it = depth.emplace(p.id, z).first;
    }
    p.z = it->second;
    for (int k = 0; k < 6; ++k) p.zi[k] = of(p.z[k]);
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
      p.sides[k] = {sub(mul(dy, a[0]), mul(dx, a[1])), Interval{-dy.hi, -dy.lo}, dx};
    }
  }
  return s;
}

}  // namespace hlr
