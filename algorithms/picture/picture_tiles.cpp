// Tiles of the picture (see picture_tiles.hpp; course notes sections 20-22).
#include "algorithms/picture/picture_tiles.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hlr {
namespace {

// A value linear in the segment's parameter t, from its values at t = 0 and t = 1.
struct Linear {
  Rational f0, f1;
};

// The closed interval of [lo, hi] where f >= 0 (strict: f > 0); a constant f keeps all of it or
// none (for a constant, >= and > differ: the tile lines' half-open rule). Returns false when
// nothing is left.
bool keep(const Linear& f, bool strict, Rational& lo, Rational& hi) {
  const int s0 = sgn(f.f0), s1 = sgn(f.f1);
  if (f.f0 == f.f1) return strict ? s0 > 0 : s0 >= 0;
  const Rational root = f.f0 / (f.f0 - f.f1);  // where f = 0
  if (f.f1 > f.f0) {                           // increasing: t >= root
    if (root > lo) lo = root;
  } else if (root < hi) {  // decreasing: t <= root
    hi = root;
  }
  (void)s1;
  return lo <= hi;
}

// X - x (orthographic) or (P - E)·r - x·w (perspective, w = (P - E)·d > 0) at the ends.
Linear line_function(const Segment& s, const PicturePlane& pp, const Camera& cam, bool vertical, const Rational& x) {
  const Vector3& axis = vertical ? pp.r() : pp.u();
  auto at = [&](const Point3& p) {
    if (!cam.perspective) return Rational(dot(Vector3(p.x(), p.y(), p.z()), axis) - x);
    const Vector3 q = p - cam.eye;
    return Rational(dot(q, axis) - x * dot(q, pp.d()));
  };
  return {at(s.from()), at(s.to())};
}

// Depth (P - E)·d at the ends (perspective).
Linear depth_function(const Segment& s, const PicturePlane& pp, const Camera& cam) {
  return {dot(s.from() - cam.eye, pp.d()), dot(s.to() - cam.eye, pp.d())};
}

}  // namespace

std::array<int, 2> tile_grid(int count) {
  if (count < 1) throw std::invalid_argument("the number of tiles must be at least 1");
  int cols = count;
  for (int c = 1; c <= count; ++c)
    if (count % c == 0 && static_cast<long>(c) * c >= count) {
      cols = c;
      break;
    }
  return {cols, count / cols};
}

TileSplit split_picture(const Camera& cam, const Projector& proj, std::size_t n, const std::function<const Point3&(std::size_t)>& point,
                        int count) {
  TileSplit t;
  const auto [cols, rows] = tile_grid(count);
  t.count = count, t.cols = cols, t.rows = rows;
  if (count == 1) return t;
  // At most ~2^17 points, every k-th: the quantiles of a large mesh do not need all of them.
  const std::size_t step = std::max<std::size_t>(1, n >> 17);
  struct Sample {
    double v;
    std::size_t i;
    bool operator<(const Sample& o) const { return v < o.v || (v == o.v && i < o.i); }
  };
  std::vector<Sample> sx, sy;
  std::vector<double> err(n > 0 ? (n - 1) / step + 1 : 0);
  for (std::size_t i = 0; i < n; i += step) {
    const LocatedPoint d = locate(cam, proj, point(i));
    if (!(d.err < HUGE_VAL) || cam.in_front(point(i)) != Sign::Positive) continue;
    err[i / step] = d.err;
    sx.push_back({d.x, i});
    sy.push_back({-d.y, i});  // rows from the top
  }
  const PicturePlane pp(cam);
  auto lines = [&](std::vector<Sample>& s, int k, bool vertical, std::vector<Rational>& exact, std::vector<double>& dr,
                   std::vector<double>& de) {
    std::sort(s.begin(), s.end());
    for (int c = 1; c < k; ++c) {
      if (s.empty()) {  // nothing in front of the eye: every line at 0, no filter
        exact.emplace_back(0);
        dr.push_back(0);
        de.push_back(HUGE_VAL);
        continue;
      }
      const Sample& q = s[std::min(s.size() - 1, s.size() * static_cast<std::size_t>(c) / static_cast<std::size_t>(k))];
      const Exact2 e = pp.project(point(q.i));
      exact.push_back(vertical ? e[0] : e[1]);
      dr.push_back(vertical ? q.v : -q.v);
      de.push_back(err[q.i / step]);
    }
  };
  lines(sx, cols, true, t.xs, t.xd, t.xe);
  lines(sy, rows, false, t.ys, t.yd, t.ye);
  return t;
}

std::vector<std::pair<Rational, Rational>> tile_intervals(const Segment& s, const PicturePlane& pp, const Camera& cam,
                                                          const TileSplit& split, int index) {
  std::vector<std::pair<Rational, Rational>> out;
  const int col = index % split.cols, row = index / split.cols;
  Rational lo(0), hi(1);
  bool any = true;
  std::optional<Linear> depth;
  if (cam.perspective) {
    depth = depth_function(s, pp, cam);
    // Behind the eye (depth <= 0): tile 0's, first in t where it comes first.
    if (index == 0) {
      Rational blo(0), bhi(1);
      Linear neg{-depth->f0, -depth->f1};
      if (keep(neg, false, blo, bhi) && blo < bhi) out.emplace_back(blo, bhi);
    }
    any = keep(*depth, true, lo, hi);
  }
  if (any && col > 0) any = keep(line_function(s, pp, cam, true, split.xs[col - 1]), false, lo, hi);
  if (any && col + 1 < split.cols) {
    Linear f = line_function(s, pp, cam, true, split.xs[col]);
    any = keep(Linear{-f.f0, -f.f1}, true, lo, hi);  // X < xs[col]
  }
  if (any && row > 0) {
    Linear f = line_function(s, pp, cam, false, split.ys[row - 1]);
    any = keep(Linear{-f.f0, -f.f1}, true, lo, hi);  // Y < ys[row - 1]
  }
  if (any && row + 1 < split.rows) any = keep(line_function(s, pp, cam, false, split.ys[row]), false, lo, hi);
  if (any && lo < hi) out.emplace_back(lo, hi);
  std::sort(out.begin(), out.end());
  return out;
}

LocatedPoint locate(const Camera& cam, const Projector& proj, const Point3& p) {
  const std::array<double, 3> q = proj.frame().to_frame(p);
  const std::array<double, 3> d = proj.project(q[0], q[1], q[2]);
  LocatedPoint out{d[0], d[1], HUGE_VAL};
  if (!std::isfinite(d[0]) || !std::isfinite(d[1])) return out;
  // The frame's doubles are within 2^-52 of the exact coordinates (relative); the projection
  // is two or three dot products with unit vectors (each component within 2^-52) and, in
  // perspective, a division: an error below 16·2^-52·m, m the sum of the magnitudes, in each
  // of screen x, y and depth, so 2^-40·m is a bound with room to spare; perspective adds the
  // division's amplification (1 + |x| + |y|) / depth where depth is clearly positive.
  double m = std::fabs(q[0]) + std::fabs(q[1]) + std::fabs(q[2]);
  if (!cam.perspective) {
    out.err = 0x1p-40 * m + 0x1p-1000;
    return out;
  }
  const std::array<double, 3> e = proj.frame().to_frame(cam.eye);
  m += std::fabs(e[0]) + std::fabs(e[1]) + std::fabs(e[2]);
  if (!(d[2] > 0x1p-30 * m)) return out;  // not clearly in front: no bound
  out.err = 0x1p-40 * m * (1 + std::fabs(d[0]) + std::fabs(d[1])) / d[2] + 0x1p-1000;
  return out;
}

namespace {

// Sure sides: a + its error before line L - its error.
bool before(double a, double ea, double l, double el) { return a + ea < l - el; }

}  // namespace

bool tile_may_hold(const TileSplit& split, int index, const LocatedPoint& a, const LocatedPoint& b) {
  if (split.count == 1) return true;
  if (!(a.err < HUGE_VAL) || !(b.err < HUGE_VAL)) return true;
  return (tile_outside(split, index, a) & tile_outside(split, index, b)) == 0;
}

bool tile_holds_wholly(const TileSplit& split, int index, const LocatedPoint& a, const LocatedPoint& b) {
  if (split.count == 1) return true;
  if (!(a.err < HUGE_VAL) || !(b.err < HUGE_VAL)) return false;
  const int col = index % split.cols, row = index / split.cols;
  for (const LocatedPoint* p : {&a, &b}) {
    if (col > 0 && !before(split.xd[col - 1], split.xe[col - 1], p->x, p->err)) return false;
    if (col + 1 < split.cols && !before(p->x, p->err, split.xd[col], split.xe[col])) return false;
    if (row > 0 && !before(p->y, p->err, split.yd[row - 1], split.ye[row - 1])) return false;
    if (row + 1 < split.rows && !before(split.yd[row], split.ye[row], p->y, p->err)) return false;
  }
  return true;
}

int tile_outside(const TileSplit& split, int index, const LocatedPoint& a) {
  if (!(a.err < HUGE_VAL)) return 0;
  const int col = index % split.cols, row = index / split.cols;
  int bits = 0;
  if (col > 0 && before(a.x, a.err, split.xd[col - 1], split.xe[col - 1])) bits |= 1;
  if (col + 1 < split.cols && !before(a.x, -a.err, split.xd[col], -split.xe[col]) ) bits |= 2;
  if (row > 0 && !before(a.y, -a.err, split.yd[row - 1], -split.ye[row - 1])) bits |= 4;
  if (row + 1 < split.rows && before(a.y, a.err, split.yd[row], split.ye[row])) bits |= 8;
  return bits;
}

void cut_to_intervals(Segment& s, const std::vector<std::pair<Rational, Rational>>& intervals) {
  std::vector<Piece> out;
  for (const auto& [lo, hi] : intervals)
    for (const Piece& p : s.pieces) {
      const Rational& a = p.t0 > lo ? p.t0 : lo;
      const Rational& b = p.t1 < hi ? p.t1 : hi;
      if (!(a < b)) continue;
      Piece q = p;
      q.t0 = a, q.t1 = b;
      out.push_back(std::move(q));
    }
  s.pieces = std::move(out);
}

std::string join_tile_pieces(std::vector<Piece>& pieces) {
  std::sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) { return a.t0 < b.t0; });
  std::vector<Piece> out;
  Rational at(0);
  for (Piece& p : pieces) {
    if (p.t0 != at) return p.t0 > at ? "no tile has the part from t = " + at.get_str() + " to " + p.t0.get_str()
                                     : "two tiles have the part from t = " + p.t0.get_str();
    at = p.t1;
    if (!out.empty() && out.back().same_kind(p)) {
      out.back().t1 = std::move(p.t1);
      continue;
    }
    out.push_back(std::move(p));
  }
  if (at != 1) return "no tile has the part from t = " + at.get_str() + " to 1";
  pieces = std::move(out);
  return "";
}

}  // namespace hlr
