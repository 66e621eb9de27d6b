// The exact floating horizon (see floating_horizon.hpp; course notes section 24).
#include "algorithms/horizon/floating_horizon.hpp"

#include "algorithms/horizon/floating_horizon_filtered.hpp"
#include "algorithms/support/parallel.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <map>
#include <optional>
#include <stdexcept>

namespace hlr {
namespace {

// A line of the picture, y = s·x + c, exact: the line of a projected edge. Pieces of the
// horizons keep the line they lie on, so values and crossings are always computed from the
// original edges' numbers (their size does not grow with the number of cuts).
struct Line {
  Rational s, c;
  Rational at(const Rational& x) const { return s * x + c; }
};

// A piece of a horizon: its line over x0 < x < x1.
struct Seg {
  Rational x0, x1;
  const Line* line;
  Rational at(const Rational& x) const { return line->at(x); }
};

// A horizon: pieces in increasing x, not overlapping (they may touch, or leave gaps where no
// geometry is). `upper`: the maximum of the geometry; else the minimum.
using Env = std::vector<Seg>;

// The lines of one run (stable addresses).
class Lines {
 public:
  const Line* through(const Rational& ax, const Rational& ay, const Rational& bx, const Rational& by) {
    Rational s = (by - ay) / (bx - ax);
    Rational c = ay - s * ax;
    pool_.push_back(Line{std::move(s), std::move(c)});
    return &pool_.back();
  }

 private:
  std::deque<Line> pool_;
};

bool same_line(const Line* a, const Line* b) { return a == b || (a->s == b->s && a->c == b->c); }

// Appends a piece, joined to the last one when it continues it on the same line.
void push(Env& e, const Rational& x0, const Rational& x1, const Line* line) {
  if (!(x0 < x1)) return;
  if (!e.empty() && e.back().x1 == x0 && same_line(e.back().line, line)) {
    e.back().x1 = x1;
    return;
  }
  e.push_back(Seg{x0, x1, line});
}

// The pointwise maximum (upper) or minimum of two horizons: cut at every breakpoint of both and
// at every crossing, exactly.
Env merge(const Env& A, const Env& B, bool upper) {
  // The breakpoints of each horizon are already in order: merge the two lists.
  auto points = [](const Env& e) {
    std::vector<const Rational*> p;
    p.reserve(2 * e.size());
    for (const Seg& s : e) {
      if (p.empty() || *p.back() != s.x0) p.push_back(&s.x0);
      p.push_back(&s.x1);
    }
    return p;
  };
  std::vector<const Rational*> pa = points(A), pb = points(B);
  std::vector<Rational> xs;
  xs.reserve(pa.size() + pb.size());
  std::size_t i = 0, j = 0;
  while (i < pa.size() || j < pb.size()) {
    const Rational* next;
    if (j == pb.size() || (i < pa.size() && *pa[i] < *pb[j])) next = pa[i++];
    else if (i == pa.size() || *pb[j] < *pa[i]) next = pb[j++];
    else next = pa[i++], ++j;  // equal
    if (xs.empty() || xs.back() != *next) xs.push_back(*next);
  }
  Env out;
  out.reserve(A.size() + B.size());
  std::size_t ia = 0, ib = 0;
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const Rational &a = xs[k], &b = xs[k + 1];
    while (ia < A.size() && A[ia].x1 <= a) ++ia;
    while (ib < B.size() && B[ib].x1 <= a) ++ib;
    const Seg* sa = ia < A.size() && A[ia].x0 <= a ? &A[ia] : nullptr;
    const Seg* sb = ib < B.size() && B[ib].x0 <= a ? &B[ib] : nullptr;
    if (!sa && !sb) continue;
    if (!sa || !sb || same_line(sa->line, sb->line)) {
      push(out, a, b, (sa ? sa : sb)->line);
      continue;
    }
    const Line &la = *sa->line, &lb = *sb->line;
    int d0 = sgn(la.at(a) - lb.at(a)), d1 = sgn(la.at(b) - lb.at(b));
    if (!upper) d0 = -d0, d1 = -d1;  // d > 0: A is the better one
    if (d0 >= 0 && d1 >= 0) {
      push(out, a, b, &la);
    } else if (d0 <= 0 && d1 <= 0) {
      push(out, a, b, &lb);
    } else {  // they cross inside (a, b)
      Rational xc = (lb.c - la.c) / (la.s - lb.s);
      push(out, a, xc, d0 > 0 ? &la : &lb);
      push(out, xc, b, d0 > 0 ? &lb : &la);
    }
  }
  return out;
}

struct P2 {
  Rational x, y;
};

// The upper (or lower) boundary of a projected triangle as a horizon.
Env triangle_side(P2 a, P2 b, P2 c, bool upper, Lines& lines) {
  if (b.x < a.x) std::swap(a, b);
  if (c.x < b.x) std::swap(b, c);
  if (b.x < a.x) std::swap(a, b);
  Env e;
  if (!(a.x < c.x)) return e;  // seen edge-on: no area in the picture
  // b above the line a-c (orientation) puts it on the upper chain.
  int side = sgn((c.x - a.x) * (b.y - a.y) - (c.y - a.y) * (b.x - a.x));
  bool via_b = upper ? side > 0 : side < 0;
  if (via_b) {
    if (a.x < b.x) push(e, a.x, b.x, lines.through(a.x, a.y, b.x, b.y));
    if (b.x < c.x) push(e, b.x, c.x, lines.through(b.x, b.y, c.x, c.y));
  } else {
    push(e, a.x, c.x, lines.through(a.x, a.y, c.x, c.y));
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

// Hidden open intervals of the cut's segment on `line` over (x0, x1) against the horizons:
// where L < segment < U.
std::vector<std::pair<Rational, Rational>> hidden_parts(const Line& line, const Rational& x0, const Rational& x1, const Env& U,
                                                         const Env& L) {
  std::vector<Rational> xs{x0, x1};
  for (const Env* e : {&U, &L}) {
    auto first = std::upper_bound(e->begin(), e->end(), x0, [](const Rational& v, const Seg& p) { return v < p.x1; });
    for (auto it = first; it != e->end() && it->x0 < x1; ++it) {
      if (it->x0 > x0) xs.push_back(it->x0);
      if (it->x1 < x1) xs.push_back(it->x1);
    }
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
    // On (a, b): where the line `hi` is above the line `lo`: an open interval of (a, b).
    auto where_above = [&](const Line& hi, const Line& lo, Rational& from, Rational& to) {
      int s0 = sgn(hi.at(a) - lo.at(a)), s1 = sgn(hi.at(b) - lo.at(b));
      if (s0 <= 0 && s1 <= 0) return false;
      from = a, to = b;
      if (s0 != s1 && s0 != 0 && s1 != 0) {
        Rational xc = (lo.c - hi.c) / (hi.s - lo.s);
        (s0 > 0 ? to : from) = xc;
      }
      return true;
    };
    Rational lo1, hi1, lo2, hi2;
    if (!where_above(*u->line, line, lo1, hi1)) continue;
    if (!where_above(line, *l->line, lo2, hi2)) continue;
    Rational lo = std::max(lo1, lo2), hi = std::min(hi1, hi2);
    if (!(lo < hi)) continue;
    if (!out.empty() && out.back().second == lo) out.back().second = hi;  // a single point between is hidden too
    else out.emplace_back(lo, hi);
  }
  return out;
}

// A sample's verdict against the horizons at its abscissa (at a breakpoint the horizon's value
// is the largest, or smallest, of the pieces there).
std::string verdict(const P2& p, const Env& U, const Env& L) {
  std::optional<Rational> u, l;
  for (const Seg& s : U)
    if (s.x0 <= p.x && p.x <= s.x1) {
      Rational v = s.at(p.x);
      if (!u || v > *u) u = v;
    }
  for (const Seg& s : L)
    if (s.x0 <= p.x && p.x <= s.x1) {
      Rational v = s.at(p.x);
      if (!l || v < *l) l = v;
    }
  if (!u || !l) return "free";  // nothing in front at this abscissa: visible
  if (p.y > *u) return "above";
  if (p.y < *l) return "below";
  if (p.y == *u || p.y == *l) return "on";
  return "between";
}

// The visible runs of the segment from sample a (t = 0) to sample b (t = 1) of the picture: the
// segment minus its hidden open intervals (in picture x), as parameter ranges.
void emit_runs(const P2& a, const P2& b, const std::vector<std::pair<Rational, Rational>>& hidden, int curve, int segment,
               std::vector<HorizonPiece>& out) {
  const bool forward = a.x < b.x;
  const P2 &p = forward ? a : b, &q = forward ? b : a;
  auto t_of = [&](const Rational& x) {
    Rational t = (x - p.x) / (q.x - p.x);
    return forward ? t : Rational(1 - t);
  };
  auto emit = [&](const Rational& x0, const Rational& x1) {
    if (!(x0 < x1)) return;
    Rational t0 = t_of(x0), t1 = t_of(x1);
    if (t1 < t0) std::swap(t0, t1);
    out.push_back({curve, segment, t0, t1});
  };
  Rational at = p.x;
  for (const auto& [h0, h1] : hidden) {
    emit(at, h0);
    at = h1;
  }
  emit(at, q.x);
}

}  // namespace

HorizonResult floating_horizon(const HeightGrid& g, const Camera& cam, std::vector<HorizonStep>* trace) {
  return trace ? floating_horizon_exact(g, cam, trace) : floating_horizon_filtered(g, cam);
}

std::array<Vector3, 2> horizon_axes(const HeightGrid& g, const Camera& cam) {
  const std::size_t nx = g.xs.size(), nz = g.zs.size();
  if (nx < 2 || nz < 1 || g.heights() != nx * nz) throw std::invalid_argument("the grid needs at least 2 x samples and one cut");
  if (nx * nz > 2'000'000'000ull) throw std::invalid_argument("the grid has too many samples");
  for (std::size_t i = 1; i < nx; ++i)
    if (!(g.xs[i - 1] < g.xs[i])) throw std::invalid_argument("grid x values must increase");
  for (std::size_t j = 1; j < nz; ++j)
    if (!(g.zs[j - 1] < g.zs[j])) throw std::invalid_argument("grid z values must increase");
  if (cam.perspective) throw std::invalid_argument("the floating horizon takes an orthographic view");
  const Vector3& v = cam.direction;
  if (v.z() == 0) throw std::invalid_argument("the view direction lies in the cutting planes z = const: give it a z component");
  Vector3 r = cross(cam.up, v), u = cross(v, r);
  if (r.y() != 0 || r.x() == 0)
    throw std::invalid_argument("the cuts must run left to right in the picture: choose up in the plane of y and the view direction");
  return {r, u};
}

HorizonResult floating_horizon_exact(const HeightGrid& g, const Camera& cam, std::vector<HorizonStep>* trace, HorizonRule rule) {
  const std::size_t nx = g.xs.size(), nz = g.zs.size();
  const Vector3& v = cam.direction;
  // Picture axes as the exact clean-up's (unnormalised): X = P·r, Y = P·u.
  const std::array<Vector3, 2> axes = horizon_axes(g, cam);
  const Vector3 &r = axes[0], &u = axes[1];
  auto project = [&](std::size_t i, std::size_t j) {
    const Rational &x = g.xs[i], &y = g.y(i, j), &z = g.zs[j];
    return P2{x * r.x() + z * r.z(), x * u.x() + y * u.y() + z * u.z()};
  };
  HorizonResult res;
  for (std::size_t k = 0; k < nz; ++k) res.order.push_back(static_cast<int>(v.z() > 0 ? nz - 1 - k : k));
  Env U, L;
  Lines lines;
  // The strips' own envelopes do not depend on each other: all of them first, on every core
  // (each strip with its own lines), then the sweep in order.
  std::vector<Lines> strip_lines(nz);
  std::vector<Env> strip_up(nz), strip_lo(nz);
  ParallelLoop loop;
  const bool strips = rule == HorizonRule::Strips;
  loop.for_each(nz > 0 && strips ? nz - 1 : 0, 1, [&](std::size_t km1) {
    const std::size_t k = km1 + 1;
    const std::size_t j = static_cast<std::size_t>(res.order[k]), jp = static_cast<std::size_t>(res.order[k - 1]);
    const std::size_t j0 = std::min(j, jp), j1 = std::max(j, jp);
    std::vector<Env> up, lo;
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      P2 a = project(i, j0), b = project(i + 1, j0), cc = project(i + 1, j1), d = project(i, j1);
      for (auto [p, q, s] : {std::array<P2*, 3>{&a, &b, &cc}, std::array<P2*, 3>{&a, &cc, &d}}) {
        up.push_back(triangle_side(*p, *q, *s, true, strip_lines[k]));
        lo.push_back(triangle_side(*p, *q, *s, false, strip_lines[k]));
      }
    }
    strip_up[k] = envelope(std::move(up), true);
    strip_lo[k] = envelope(std::move(lo), false);
  });
  for (std::size_t k = 0; k < nz; ++k) {
    const std::size_t j = static_cast<std::size_t>(res.order[k]);
    std::vector<P2> c(nx);
    for (std::size_t i = 0; i < nx; ++i) c[i] = project(i, j);
    if (k > 0 && strips) {  // the strip between this cut and the previous one, in front of this cut
      U = merge(U, strip_up[k], true);
      L = merge(L, strip_lo[k], false);
      Env().swap(strip_up[k]);
      Env().swap(strip_lo[k]);
    }
    HorizonStep* step = nullptr;
    if (trace) {
      trace->push_back(HorizonStep{});
      step = &trace->back();
      step->curve = static_cast<int>(j);
      for (const P2& p : c) step->points.push_back({p.x, p.y});
      if (k > 0) {
        for (const Seg& p : U) step->upper.push_back({p.x0, p.x1, {p.line->s, p.line->c}});
        for (const Seg& p : L) step->lower.push_back({p.x0, p.x1, {p.line->s, p.line->c}});
      }
      for (const P2& p : c) step->verdicts.push_back(k == 0 ? "first" : verdict(p, U, L));
    }
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      const bool forward = c[i].x < c[i + 1].x;
      const P2 &p = forward ? c[i] : c[i + 1], &q = forward ? c[i + 1] : c[i];
      const Line* cut = lines.through(p.x, p.y, q.x, q.y);
      std::vector<std::pair<Rational, Rational>> hidden;
      if (k > 0) hidden = hidden_parts(*cut, p.x, q.x, U, L);
      emit_runs(c[i], c[i + 1], hidden, static_cast<int>(j), static_cast<int>(i), res.visible);
      if (step)  // the ends of a hidden run inside the segment are crossings with a horizon
        for (const auto& [h0, h1] : hidden)
          for (const Rational* x : {&h0, &h1}) {
            if (*x == p.x || *x == q.x) continue;
            Rational y = cut->at(*x);
            bool done = false;
            for (bool up : {true, false})
              for (const Seg& h : up ? U : L)
                if (!done && h.x0 <= *x && *x <= h.x1 && h.line->at(*x) == y && !same_line(h.line, cut)) {
                  step->crossings.push_back({static_cast<int>(i), *x, y, {cut->s, cut->c}, {h.line->s, h.line->c}, up});
                  done = true;
                }
          }
    }
    if (k == 0 || !strips) {  // the nearest cut is the first geometry: a strip of zero width
      Env cut;
      std::vector<std::size_t> idx(nx - 1);
      for (std::size_t i = 0; i + 1 < nx; ++i) idx[i] = c[0].x < c[1].x ? i : nx - 2 - i;
      for (std::size_t i : idx) {
        const P2 &p = c[i].x < c[i + 1].x ? c[i] : c[i + 1], &q = c[i].x < c[i + 1].x ? c[i + 1] : c[i];
        push(cut, p.x, q.x, lines.through(p.x, p.y, q.x, q.y));
      }
      if (k == 0) U = cut, L = cut;
      else U = merge(U, cut, true), L = merge(L, cut, false);  // the notes' rule: the cut joins the horizons
    }
    res.horizon_breakpoints = std::max({res.horizon_breakpoints, U.size(), L.size()});
  }
  // The side edges (see HorizonResult::side).
  if (nz >= 2) {
    const Rational& vx = v.x();
    const std::size_t far = vx > 0 ? 0 : nx - 1, near = vx > 0 ? nx - 1 : 0;
    for (std::size_t j = 0; j + 1 < nz; ++j) {
      if (vx == 0 || nx == 1) {
        res.side.push_back({0, static_cast<int>(j), Rational(0), Rational(1)});
        res.side.push_back({static_cast<int>(nx - 1), static_cast<int>(j), Rational(0), Rational(1)});
        continue;
      }
      res.side.push_back({static_cast<int>(near), static_cast<int>(j), Rational(0), Rational(1)});
      P2 a = project(far, j), b = project(far, j + 1);
      const P2 &p = a.x < b.x ? a : b, &q = a.x < b.x ? b : a;
      const Line* edge = lines.through(p.x, p.y, q.x, q.y);
      emit_runs(a, b, hidden_parts(*edge, p.x, q.x, U, L), static_cast<int>(far), static_cast<int>(j), res.side);
    }
    std::stable_sort(res.side.begin(), res.side.end(), [](const HorizonPiece& a, const HorizonPiece& b) {
      if (a.curve != b.curve) return a.curve < b.curve;
      if (a.segment != b.segment) return a.segment < b.segment;
      return a.t0 < b.t0;
    });
  }
  sort_visible(res);
  return res;
}

void sort_visible(HorizonResult& res) {
  int top = 0;
  for (int c : res.order) top = std::max(top, c + 1);
  std::vector<int> rank(static_cast<std::size_t>(top), 0);
  for (std::size_t k = 0; k < res.order.size(); ++k) rank[static_cast<std::size_t>(res.order[k])] = static_cast<int>(k);
  std::stable_sort(res.visible.begin(), res.visible.end(), [&](const HorizonPiece& a, const HorizonPiece& b) {
    if (a.curve != b.curve) return rank[static_cast<std::size_t>(a.curve)] < rank[static_cast<std::size_t>(b.curve)];
    if (a.segment != b.segment) return a.segment < b.segment;
    return a.t0 < b.t0;
  });
}

HorizonResult floating_horizon_x(const HeightGrid& g, const Camera& cam, unsigned threads, bool flat) {
  HeightGrid t;
  t.xs = g.zs;
  t.zs = g.xs;
  if (!g.yd.empty()) t.yd.resize(g.yd.size());
  else t.ys.resize(g.ys.size());
  const std::size_t nx = g.xs.size(), nz = g.zs.size();
  for (std::size_t j = 0; j < nz; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      if (!g.yd.empty()) t.yd[i * nz + j] = g.yd[j * nx + i];
      else t.ys[i * nz + j] = g.ys[j * nx + i];
    }
  auto swap_xz = [](const Vector3& v) { return Vector3(v.z(), v.y(), v.x()); };
  Camera c = cam;
  c.direction = swap_xz(cam.direction);
  c.up = swap_xz(cam.up);
  return floating_horizon_filtered(t, c, threads, nullptr, flat);
}

bool x_cuts_edge_on(const Camera& camera) { return !camera.perspective && camera.direction.x() == 0; }

}  // namespace hlr
