// The per-face engine, visibility (see face_engine.hpp; course notes sections 26-28): each
// segment against the occluders the screen grid gives it, each occluder's four inequalities
// giving an interval with exact ends; the hidden part is their union. Segments run on all
// cores (parallel.hpp); each writes only its own pieces, so the result does not depend on the
// thread count.
#include <algorithm>

#include "algorithms/face_engine.hpp"
#include "algorithms/parallel.hpp"

namespace hlr::face_route {

template <class P>
struct Engine<P>::Work {
  ComparisonCounters c;
  std::size_t pairs = 0, skipped = 0;
  StampSet stamps;
  std::vector<int> cand;
  std::vector<std::pair<Frac<P>, Frac<P>>> spans;
};

// A segment lying in two side planes of an occluder runs along the sight line through their
// common vertex (an edge seen end-on): hidden only where the ray just behind that vertex is
// inside (vertex_rules). `on_side`: bit k set when the segment lies in closed side plane k.
template <class P>
bool Engine<P>::end_on_hides(const Occluder<P>& o, int on_side) const {
  if (on_side == 6) return vertex_closed_[o.v[1]];
  if (on_side == 12) return vertex_closed_[o.v[2]];
  if (on_side == 10) return vertex_closed_[o.v[0]];
  return true;
}

template <class P>
void Engine<P>::visibility(LineDrawing& res) {
  const std::size_t n = res.segments.size();
  ParallelLoop loop(opt_.threads);
  std::vector<Work> work(loop.workers());
  std::vector<char> ready(work.size(), 0);
  loop.run(n, 512, [&](unsigned w, std::size_t b, std::size_t e) {
    Work& wk = work[w];
    if (!ready[w]) wk.stamps.reset(occ_.size()), ready[w] = 1;
    for (std::size_t i = b; i < e; ++i) solve(res.segments[i], gv_[i], wk);
  });
  FaceRouteStats& fs = *res.stats.faces;
  for (const Work& w : work) {
    res.stats.pairs_tested += w.pairs;
    res.stats.pairs_skipped += w.skipped;
    fs.comparisons += w.c.comparisons;
    fs.comparisons_exact += w.c.exact;
    fs.comparisons_identical += w.c.identical;
  }
  if (std::is_same_v<P, Big>) res.stats.pairs_rational = res.stats.pairs_tested;
}

template <class P>
std::optional<std::pair<Rational, Rational>> Engine<P>::depth_of(const Segment& s) const {
  if (!cam_.perspective) return std::nullopt;
  return std::make_pair(cam_.depth(s.from()), cam_.depth(s.to()));
}

template <class P>
void Engine<P>::candidates(const std::array<double, 3>& a, const std::array<double, 3>& b, bool front, Work& wk) const {
  wk.cand.clear();
  wk.stamps.next();
  if (!front) {
    for (std::size_t i = 0; i < occ_.size(); ++i) wk.cand.push_back(static_cast<int>(i));
    return;
  }
  double x0 = std::min(a[0], b[0]), x1 = std::max(a[0], b[0]), y0 = std::min(a[1], b[1]), y1 = std::max(a[1], b[1]);
  double dmax = std::max(a[2], b[2]) + margin_;
  grid_.visit(ScreenRect{x0 - margin_, y0 - margin_, x1 + margin_, y1 + margin_}, [&](int i) {
    if (!wk.stamps.first(i)) return;
    const Box& bx = boxes_[i];
    if (bx.x0 > x1 + margin_ || bx.x1 < x0 - margin_ || bx.y0 > y1 + margin_ || bx.y1 < y0 - margin_ || bx.dmin > dmax) return;
    wk.cand.push_back(i);
  });
}

template <class P>
void Engine<P>::solve(Segment& s, const std::array<int, 2>& gv, Work& wk) const {
  if (s.self_hidden) {
    s.pieces = pieces_from_hidden({{Rational(0), Rational(1)}}, depth_of(s));
    return;
  }
  std::array<double, 3> pa, pb;
  bool front = true;
  if (gv[0] >= 0) {
    pa = vproj_[gv[0]];
    pb = vproj_[gv[1]];
    front = vfront_[gv[0]] && vfront_[gv[1]];
  } else {
    pa = proj_.project(s.from());
    pb = proj_.project(s.to());
    front = !cam_.perspective || (cam_.in_front(s.from()) == Sign::Positive && cam_.in_front(s.to()) == Sign::Positive);
  }
  candidates(pa, pb, front, wk);
  wk.skipped += occ_.size() - wk.cand.size();
  std::vector<std::pair<Rational, Rational>> hidden;
  if (gv[0] >= 0) {
    wk.spans.clear();
    for (int i : wk.cand) test_integer(occ_[i], X_[gv[0]], X_[gv[1]], wk);
    merge(wk, hidden);
  } else {
    std::array<Rational, 3> A, B;
    for (int k = 0; k < 3; ++k) {
      A[k] = s.from()[k] * scale_;
      B[k] = s.to()[k] * scale_;
    }
    for (int i : wk.cand) test_rational(occ_[i], A, B, hidden, wk);
  }
  s.pieces = pieces_from_hidden(std::move(hidden), depth_of(s));
}

// Hidden interval of the segment X0 -> X1 by one occluder, integer values.
template <class P>
void Engine<P>::test_integer(const Occluder<P>& o, const Vec<P>& X0, const Vec<P>& X1, Work& wk) const {
  ++wk.pairs;
  bool has_lo = false, has_hi = false;
  Frac<P> lo{V(0), V(1), 0.0}, hi{V(1), V(1), 1.0};
  int on_side = 0;  // bit k: the segment lies in side plane k (closed)
  for (int k = 0; k < 4; ++k) {
    V f0 = dot<P>(o.m[k], X0) - o.c[k];
    V f1 = dot<P>(o.m[k], X1) - o.c[k];
    int s0 = P::sign(f0), s1 = P::sign(f1);
    if (s0 > 0 && s1 > 0) continue;
    if (s0 <= 0 && s1 <= 0) {
      if (o.closed[k] && s0 == 0 && s1 == 0) {
        on_side |= 1 << k;
        continue;
      }
      return;
    }
    // Ends at the segment's own end points (t = 0 or 1: an occluder sharing a vertex with
    // the edge) are written canonically, so they compare as identical without arithmetic.
    if (s0 > 0) {  // upper bound t < f0 / (f0 - f1)
      V d = f0 - f1;
      Frac<P> r = s1 == 0 ? Frac<P>{V(1), V(1), 1.0} : Frac<P>{f0, d, P::ratio(f0, d)};
      if (!has_hi || compare(r, hi, wk.c) < 0) hi = r, has_hi = true;
    } else {  // lower bound t > -f0 / (f1 - f0)
      V d = f1 - f0;
      V nn = -f0;
      Frac<P> r = s0 == 0 ? Frac<P>{V(0), V(1), 0.0} : Frac<P>{nn, d, P::ratio(nn, d)};
      if (!has_lo || compare(r, lo, wk.c) > 0) lo = r, has_lo = true;
    }
  }
  // In two side planes: the segment runs along the sight line through their common vertex
  // (an edge seen end-on); hidden only where the ray just behind that vertex is inside.
  if (!end_on_hides(o, on_side)) return;
  if (has_lo && has_hi && compare(lo, hi, wk.c) >= 0) return;
  wk.spans.push_back({lo, hi});
}

template <class P>
void Engine<P>::merge(Work& wk, std::vector<std::pair<Rational, Rational>>& out) const {
  auto& sp = wk.spans;
  if (sp.empty()) return;
  std::sort(sp.begin(), sp.end(), [&](const auto& a, const auto& b) { return compare(a.first, b.first, wk.c) < 0; });
  std::vector<std::pair<Frac<P>, Frac<P>>> merged;
  for (auto& s : sp) {
    if (!merged.empty() && compare(s.first, merged.back().second, wk.c) <= 0) {
      if (compare(s.second, merged.back().second, wk.c) > 0) merged.back().second = s.second;
    } else {
      merged.push_back(s);
    }
  }
  auto rat = [](const Frac<P>& f) {
    Rational q{mpz_class(P::z(f.n)), mpz_class(P::z(f.d))};
    q.canonicalize();
    return q;
  };
  for (auto& m : merged) out.push_back({rat(m.first), rat(m.second)});
}

// The same on rational end points (intersection lines), values m·(L·P) - c.
template <class P>
void Engine<P>::test_rational(const Occluder<P>& o, const std::array<Rational, 3>& A, const std::array<Rational, 3>& B,
                   std::vector<std::pair<Rational, Rational>>& out, Work& wk) const {
  ++wk.pairs;
  Rational lo = 0, hi = 1;
  int on_side = 0;
  for (int k = 0; k < 4; ++k) {
    Rational f0 = -Rational(P::z(o.c[k])), f1 = f0;
    for (int j = 0; j < 3; ++j) {
      Rational m = P::zc(o.m[k][j]);
      f0 += m * A[j];
      f1 += m * B[j];
    }
    int s0 = sgn(f0), s1 = sgn(f1);
    if (s0 > 0 && s1 > 0) continue;
    if (s0 <= 0 && s1 <= 0) {
      if (o.closed[k] && s0 == 0 && s1 == 0) {
        on_side |= 1 << k;
        continue;
      }
      return;
    }
    Rational t = f0 / (f0 - f1);
    if (s0 > 0) hi = std::min(hi, t);
    else lo = std::max(lo, t);
  }
  if (!end_on_hides(o, on_side)) return;
  if (lo < hi) out.push_back({lo, hi});
}

template class Engine<Fast>;
template class Engine<Fast40>;
template class Engine<Big>;

}  // namespace hlr::face_route
