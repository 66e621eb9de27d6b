// The exact floating horizon (see floating_horizon.hpp; course notes section 24).
#include "algorithms/floating_horizon.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>

namespace hlr {
namespace {

// A piece of a horizon: the segment (x0, y0)-(x1, y1) of the picture, x0 < x1.
struct Seg {
  Rational x0, y0, x1, y1;
  Rational at(const Rational& x) const {
    if (x == x0) return y0;
    if (x == x1) return y1;
    return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
  }
};

// A horizon: pieces in increasing x, not overlapping (they may touch, or leave gaps where no
// geometry is). `upper`: the maximum of the geometry; else the minimum.
using Env = std::vector<Seg>;

int sgn(const Rational& q) { return q > 0 ? 1 : q < 0 ? -1 : 0; }

// Appends s to e, joined to the last piece when they continue one segment exactly.
void push(Env& e, Seg s) {
  if (!(s.x0 < s.x1)) return;
  if (!e.empty()) {
    Seg& b = e.back();
    if (b.x1 == s.x0 && b.y1 == s.y0 && (b.y1 - b.y0) * (s.x1 - s.x0) == (s.y1 - s.y0) * (b.x1 - b.x0)) {
      b.x1 = s.x1, b.y1 = s.y1;
      return;
    }
  }
  e.push_back(std::move(s));
}

// The pointwise maximum (upper) or minimum of two horizons: cut at every breakpoint of both and
// at every crossing, exactly.
Env merge(const Env& A, const Env& B, bool upper) {
  std::vector<Rational> xs;
  xs.reserve(2 * (A.size() + B.size()));
  for (const Env* e : {&A, &B})
    for (const Seg& s : *e) xs.push_back(s.x0), xs.push_back(s.x1);
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  Env out;
  std::size_t ia = 0, ib = 0;
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const Rational &a = xs[k], &b = xs[k + 1];
    while (ia < A.size() && A[ia].x1 <= a) ++ia;
    while (ib < B.size() && B[ib].x1 <= a) ++ib;
    const Seg* sa = ia < A.size() && A[ia].x0 <= a ? &A[ia] : nullptr;
    const Seg* sb = ib < B.size() && B[ib].x0 <= a ? &B[ib] : nullptr;
    if (!sa && !sb) continue;
    if (!sa || !sb) {
      const Seg* s = sa ? sa : sb;
      push(out, {a, s->at(a), b, s->at(b)});
      continue;
    }
    Rational ya = sa->at(a), yb = sa->at(b), za = sb->at(a), zb = sb->at(b);
    int d0 = sgn(ya - za), d1 = sgn(yb - zb);
    if (!upper) d0 = -d0, d1 = -d1;  // d > 0: A is the better one
    if (d0 >= 0 && d1 >= 0) {
      push(out, {a, ya, b, yb});
    } else if (d0 <= 0 && d1 <= 0) {
      push(out, {a, za, b, zb});
    } else {  // they cross inside (a, b)
      Rational u = (za - ya) / ((yb - ya) - (zb - za));  // fraction of the way from a to b
      Rational xc = a + u * (b - a), yc = ya + u * (yb - ya);
      if (d0 > 0) {
        push(out, {a, ya, xc, yc});
        push(out, {xc, yc, b, zb});
      } else {
        push(out, {a, za, xc, yc});
        push(out, {xc, yc, b, yb});
      }
    }
  }
  return out;
}

struct P2 {
  Rational x, y;
};

// The upper (or lower) boundary of a projected triangle as a horizon.
Env triangle_side(P2 a, P2 b, P2 c, bool upper) {
  if (b.x < a.x) std::swap(a, b);
  if (c.x < b.x) std::swap(b, c);
  if (b.x < a.x) std::swap(a, b);
  Env e;
  if (!(a.x < c.x)) return e;  // seen edge-on: no area in the picture
  // b above the line a-c (orientation) puts it on the upper chain.
  int side = sgn((c.x - a.x) * (b.y - a.y) - (c.y - a.y) * (b.x - a.x));
  bool via_b = upper ? side > 0 : side < 0;
  if (via_b) {
    push(e, {a.x, a.y, b.x, b.y});
    push(e, {b.x, b.y, c.x, c.y});
  } else {
    push(e, {a.x, a.y, c.x, c.y});
  }
  return e;
}

// The envelope of many horizons, by halves.
Env envelope(std::vector<Env> parts, bool upper) {
  if (parts.empty()) return {};
  while (parts.size() > 1) {
    std::vector<Env> next;
    for (std::size_t i = 0; i + 1 < parts.size(); i += 2) next.push_back(merge(parts[i], parts[i + 1], upper));
    if (parts.size() % 2) next.push_back(std::move(parts.back()));
    parts = std::move(next);
  }
  return std::move(parts[0]);
}

// Hidden open intervals of the segment s (x0 < x1) against the horizons: where L < s < U.
std::vector<std::pair<Rational, Rational>> hidden_parts(const Seg& s, const Env& U, const Env& L) {
  std::vector<Rational> xs{s.x0, s.x1};
  for (const Env* e : {&U, &L})
    for (const Seg& p : *e) {
      if (p.x1 <= s.x0 || p.x0 >= s.x1) continue;
      if (p.x0 > s.x0) xs.push_back(p.x0);
      if (p.x1 < s.x1) xs.push_back(p.x1);
    }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  auto find = [](const Env& e, const Rational& x) -> const Seg* {  // the piece over (x, next)
    auto it = std::upper_bound(e.begin(), e.end(), x, [](const Rational& v, const Seg& p) { return v < p.x1; });
    return it != e.end() && it->x0 <= x ? &*it : nullptr;
  };
  std::vector<std::pair<Rational, Rational>> out;
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const Rational &a = xs[k], &b = xs[k + 1];
    const Seg *u = find(U, a), *l = find(L, a);
    if (!u || !l) continue;
    // On (a, b): s < U where the difference U - s is positive; an interval of (a, b).
    auto open_where_positive = [&](const Rational& d0, const Rational& d1, Rational& lo, Rational& hi) {
      int s0 = sgn(d0), s1 = sgn(d1);
      if (s0 <= 0 && s1 <= 0) return false;
      lo = a, hi = b;
      if (s0 > 0 && s1 < 0) hi = a + (b - a) * d0 / (d0 - d1);
      if (s0 < 0 && s1 > 0) lo = a + (b - a) * d0 / (d0 - d1);
      return true;
    };
    Rational lo1, hi1, lo2, hi2;
    if (!open_where_positive(u->at(a) - s.at(a), u->at(b) - s.at(b), lo1, hi1)) continue;
    if (!open_where_positive(s.at(a) - l->at(a), s.at(b) - l->at(b), lo2, hi2)) continue;
    Rational lo = std::max(lo1, lo2), hi = std::min(hi1, hi2);
    if (!(lo < hi)) continue;
    if (!out.empty() && out.back().second == lo) out.back().second = hi;  // a single point between is hidden too
    else out.emplace_back(lo, hi);
  }
  return out;
}

}  // namespace

HorizonResult floating_horizon(const HeightGrid& g, const Camera& cam) {
  const std::size_t nx = g.xs.size(), nz = g.zs.size();
  if (nx < 2 || nz < 1 || g.ys.size() != nx * nz) throw std::invalid_argument("the grid needs at least 2 x samples and one cut");
  for (std::size_t i = 1; i < nx; ++i)
    if (!(g.xs[i - 1] < g.xs[i])) throw std::invalid_argument("grid x values must increase");
  for (std::size_t j = 1; j < nz; ++j)
    if (!(g.zs[j - 1] < g.zs[j])) throw std::invalid_argument("grid z values must increase");
  if (cam.perspective) throw std::invalid_argument("the floating horizon takes an orthographic view");
  const Vector3& v = cam.direction;
  if (v.z() == 0) throw std::invalid_argument("the view direction lies in the cutting planes z = const: give it a z component");
  // Picture axes as the exact clean-up's (unnormalised): X = P·r, Y = P·u.
  Vector3 r = cross(cam.up, v), u = cross(v, r);
  if (r.y() != 0 || r.x() == 0)
    throw std::invalid_argument("the cuts must run left to right in the picture: choose up in the plane of y and the view direction");
  auto project = [&](std::size_t i, std::size_t j) {
    const Rational &x = g.xs[i], &y = g.y(i, j), &z = g.zs[j];
    return P2{x * r.x() + z * r.z(), x * u.x() + y * u.y() + z * u.z()};
  };
  HorizonResult res;
  for (std::size_t k = 0; k < nz; ++k) res.order.push_back(static_cast<int>(v.z() > 0 ? nz - 1 - k : k));
  Env U, L;
  for (std::size_t k = 0; k < nz; ++k) {
    const std::size_t j = static_cast<std::size_t>(res.order[k]);
    std::vector<P2> c(nx);
    for (std::size_t i = 0; i < nx; ++i) c[i] = project(i, j);
    if (k > 0) {  // the strip between this cut and the previous one, in front of this cut
      const std::size_t jp = static_cast<std::size_t>(res.order[k - 1]), j0 = std::min(j, jp), j1 = std::max(j, jp);
      std::vector<Env> up, lo;
      for (std::size_t i = 0; i + 1 < nx; ++i) {
        P2 a = project(i, j0), b = project(i + 1, j0), cc = project(i + 1, j1), d = project(i, j1);
        for (auto [p, q, s] : {std::array<P2*, 3>{&a, &b, &cc}, std::array<P2*, 3>{&a, &cc, &d}}) {
          up.push_back(triangle_side(*p, *q, *s, true));
          lo.push_back(triangle_side(*p, *q, *s, false));
        }
      }
      U = merge(U, envelope(std::move(up), true), true);
      L = merge(L, envelope(std::move(lo), false), false);
    }
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      const bool forward = c[i].x < c[i + 1].x;
      const P2 &p = forward ? c[i] : c[i + 1], &q = forward ? c[i + 1] : c[i];
      Seg s{p.x, p.y, q.x, q.y};
      // Visible = the segment minus its hidden open intervals, as parameters t from sample i.
      auto t_of = [&](const Rational& x) {
        Rational t = (x - s.x0) / (s.x1 - s.x0);
        return forward ? t : Rational(1 - t);
      };
      Rational at = s.x0;
      auto emit = [&](const Rational& x0, const Rational& x1) {
        if (!(x0 < x1)) return;
        Rational t0 = t_of(x0), t1 = t_of(x1);
        if (t1 < t0) std::swap(t0, t1);
        res.visible.push_back({static_cast<int>(j), static_cast<int>(i), t0, t1});
      };
      for (const auto& [h0, h1] : (k == 0 ? std::vector<std::pair<Rational, Rational>>{} : hidden_parts(s, U, L))) {
        emit(at, h0);
        at = h1;
      }
      emit(at, s.x1);
    }
    if (k == 0) {  // the nearest cut is the first geometry: a strip of zero width
      Env up, lo;
      for (std::size_t i = 0; i + 1 < nx; ++i) {
        const P2 &p = c[i].x < c[i + 1].x ? c[i] : c[i + 1], &q = c[i].x < c[i + 1].x ? c[i + 1] : c[i];
        push(up, {p.x, p.y, q.x, q.y});
      }
      if (!(c[0].x < c[1].x)) std::reverse(up.begin(), up.end());
      U = up, L = up;
    }
    res.horizon_breakpoints = std::max({res.horizon_breakpoints, U.size(), L.size()});
  }
  // Curves nearest first, then segments, then t (a reversed segment emitted its runs backwards).
  std::map<int, int> rank;
  for (std::size_t k = 0; k < res.order.size(); ++k) rank[res.order[k]] = static_cast<int>(k);
  std::stable_sort(res.visible.begin(), res.visible.end(), [&](const HorizonPiece& a, const HorizonPiece& b) {
    if (a.curve != b.curve) return rank[a.curve] < rank[b.curve];
    if (a.segment != b.segment) return a.segment < b.segment;
    return a.t0 < b.t0;
  });
  return res;
}

HorizonResult floating_horizon_x(const HeightGrid& g, const Camera& cam) {
  HeightGrid t;
  t.xs = g.zs;
  t.zs = g.xs;
  t.ys.resize(g.ys.size());
  const std::size_t nx = g.xs.size(), nz = g.zs.size();
  for (std::size_t j = 0; j < nz; ++j)
    for (std::size_t i = 0; i < nx; ++i) t.ys[i * nz + j] = g.y(i, j);
  auto swap_xz = [](const Vector3& v) { return Vector3(v.z(), v.y(), v.x()); };
  Camera c = cam;
  c.direction = swap_xz(cam.direction);
  c.up = swap_xz(cam.up);
  return floating_horizon(t, c);
}

bool x_cuts_edge_on(const Camera& camera) { return !camera.perspective && camera.direction.x() == 0; }

}  // namespace hlr
