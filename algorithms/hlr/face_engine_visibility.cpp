// The per-face engine, visibility (see face_engine.hpp; course notes sections 26-28): each
// segment against the occluders the screen grid gives it, each occluder's four inequalities
// giving an interval with exact ends; the hidden part is their union. Segments run on all
// cores (parallel.hpp); each writes only its own pieces, so the result does not depend on the
// thread count.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "algorithms/hlr/face_engine.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/support/parallel_scan.hpp"
#include "kernel/error_bounds.hpp"

namespace hlr::face_route {

namespace {

// Integers a and a positive d with q = a / d (d the least common multiple of the denominators).
void common_integers(const std::array<Rational, 3>& q, std::array<mpz_class, 3>& a, mpz_class& d) {
  d = 1;
  for (const Rational& x : q) mpz_lcm(d.get_mpz_t(), d.get_mpz_t(), x.get_den_mpz_t());
  for (int k = 0; k < 3; ++k) {
    mpz_divexact(a[k].get_mpz_t(), d.get_mpz_t(), q[k].get_den_mpz_t());
    a[k] *= q[k].get_num();
  }
}

void set_z(mpz_ptr r, const Int128& v) { set_mpz(r, v); }
void set_z(mpz_ptr r, const mpz_class& v) { mpz_set(r, v.get_mpz_t()); }
template <int N>
void set_z(mpz_ptr r, const WideInt<N>& v) {
  mpz_t t;
  mpz_set(r, v.view(t));
}

// r += m·x for the policies' coefficient types (`tmp`: scratch).
void addmul(mpz_ptr r, std::int64_t m, mpz_srcptr x, mpz_ptr) {
  if (m >= 0) mpz_addmul_ui(r, x, static_cast<unsigned long>(m));
  else mpz_submul_ui(r, x, static_cast<unsigned long>(-static_cast<Int128>(m)));
}
void addmul(mpz_ptr r, const Int128& m, mpz_srcptr x, mpz_ptr tmp) {
  set_mpz(tmp, m);
  mpz_addmul(r, tmp, x);
}
void addmul(mpz_ptr r, const mpz_class& m, mpz_srcptr x, mpz_ptr) { mpz_addmul(r, m.get_mpz_t(), x); }
template <int N>
void addmul(mpz_ptr r, const WideInt<N>& m, mpz_srcptr x, mpz_ptr) {
  mpz_t t;
  mpz_addmul(r, m.view(t), x);
}

}  // namespace

template <class P>
struct alignas(128) Engine<P>::Work {  // its own cache lines: workers update theirs constantly
  ComparisonCounters c;
  std::size_t pairs = 0, skipped = 0;
  StampSet stamps;
  std::vector<int> cand;
  std::vector<std::pair<Frac<P>, Frac<P>>> spans;
  mpz_class z[4];  // test_rational's scratch
  std::array<std::pair<int, int>, 2> caps;  // the segment's: (body, part) of the caps it lies on, or part -1
};

// A section's cap lies exactly in its plane, and so does a segment on a cap face (an edge of
// one, a hatch line or an intersection line on one): at both its ends the face plane
// (constraint 0, through the triangle) of an occluder of the same cap is 0, known without
// arithmetic (which on a cut's points is long: their common denominator has thousands of bits).
template <class P>
int Engine<P>::cap_part(int body, int face) const {
  const auto b = static_cast<std::size_t>(body);
  if (body < 0 || face < 0 || b >= hooks_.cap_face.size() || hooks_.cap_face[b].empty() || !hooks_.cap_face[b][face]) return -1;
  return hooks_.face_part[b][face];
}

template <class P>
bool Engine<P>::in_cap_plane(const Occ& o, const Work& wk) const {
  if constexpr (kFiltered) {  // (on 64 and 128 bits the arithmetic is short)
    if (!o.through_vertices) return false;
    const std::pair<int, int> key{o.body, cap_part(o.body, o.face)};
    return key.second >= 0 && (wk.caps[0] == key || wk.caps[1] == key);
  } else {
    (void)o, (void)wk;
    return false;
  }
}

// A segment lying in two side planes of an occluder runs along the sight line through their
// common vertex (an edge seen end-on): hidden only where the ray just behind that vertex is
// inside (vertex_rules). `on_side`: bit k set when the segment lies in closed side plane k.
template <class P>
bool Engine<P>::end_on_hides(const Occ& o, int on_side) const {
  if (on_side == 6) return vertex_closed_[o.v[1]];
  if (on_side == 12) return vertex_closed_[o.v[2]];
  if (on_side == 10) return vertex_closed_[o.v[0]];
  return true;
}

// Without hidden lines (hooks_.back_edges off), in an orthographic view, a body that hides
// leaves out the edges its own faces hide (each would be one hidden piece), their ends marked
// for the drawing's frame. (In perspective such an edge may reach behind the eye, and clipping
// there moves its ends: it is kept.)
template <class P>
void Engine<P>::leave_out_backs(const std::vector<std::vector<DrawnEdge>>& drawn, LineDrawing& res, const ParallelLoop& loop) {
  backs_left_.assign(drawn.size(), 0);
  backs_left_count_ = 0;
  if (hooks_.back_edges || cam_.perspective) return;
  for (std::size_t b = 0; b < drawn.size(); ++b) {
    const bool hides = b >= hooks_.see_through.size() || !hooks_.see_through[b];
    if (!hides || drawn[b].empty()) continue;
    backs_left_[b] = 1;
    FrameEnds ends;
    ends.store = edge_segment(static_cast<int>(b), drawn[b][0]).store_ends();
    if (!ends.store) throw std::logic_error("face route: a body's edges do not end in its vertex store");
    ends.marks.assign(ends.store->size(), 0);
    std::atomic<std::size_t> left{0};
    loop.run(drawn[b].size(), 8192, [&](unsigned, std::size_t lo, std::size_t hi) {
      std::size_t n = 0;
      for (std::size_t i = lo; i < hi; ++i) {
        const DrawnEdge& e = drawn[b][i];
        if (!left_out(b, e)) continue;
        ++n;
        std::atomic_ref<char>(ends.marks[static_cast<std::size_t>(e.u)]).store(1, std::memory_order_relaxed);
        std::atomic_ref<char>(ends.marks[static_cast<std::size_t>(e.v)]).store(1, std::memory_order_relaxed);
      }
      left.fetch_add(n, std::memory_order_relaxed);
    });
    backs_left_count_ += left.load();
    res.frame_ends.push_back(std::move(ends));
  }
}

// The pieces of every segment: the drawn edges in order of body (each made as a segment only
// while it is solved), then the intersection lines.
template <class P>
std::vector<PieceList> Engine<P>::visibility(const std::vector<std::vector<DrawnEdge>>& drawn, std::vector<Segment>& crossing,
                                             LineDrawing& res) {
  std::vector<std::size_t> first(drawn.size() + 1, 0);  // each body's first edge
  for (std::size_t b = 0; b < drawn.size(); ++b) {
    first[b + 1] = first[b] + drawn[b].size();
    res.stats.edges += drawn[b].size();
    for (const DrawnEdge& e : drawn[b]) res.stats.self_hidden += e.self_hidden;
  }
  const std::size_t edges = first.back(), n = edges + crossing.size();
  filter_doubles();
  ParallelLoop loop(opt_.threads);
  leave_out_backs(drawn, res, loop);
  std::vector<PieceList> out(n);
  std::vector<Work> work(loop.workers());
  std::vector<char> ready(work.size(), 0);
  loop.run(n, 512, [&](unsigned w, std::size_t lo, std::size_t hi) {
    Work& wk = work[w];
    if (!ready[w]) wk.stamps.reset(occ_.size()), ready[w] = 1;
    std::size_t b = static_cast<std::size_t>(std::upper_bound(first.begin(), first.end(), lo) - first.begin()) - 1;
    for (std::size_t i = lo; i < hi; ++i) {
      if (i < edges) {
        while (i >= first[b + 1]) ++b;
        const DrawnEdge& e = drawn[b][i - first[b]];
        if (left_out(b, e)) continue;
        Segment s = edge_segment(static_cast<int>(b), e);
        solve_into(s, {voff_[b] + e.u, voff_[b] + e.v}, wk, out[i]);
      } else {
        solve_into(crossing[i - edges], {-1, -1}, wk, out[i]);  // in place: its pieces move to out[i]
      }
    }
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
  return out;
}

// The segments on all cores, in the order of the pieces, a million at a time: each run's pages
// touched on all cores, and the records and pieces it spent given back (release_pages), so that
// the segments and what they are made of do not add up at the engine's end.
template <class P>
void Engine<P>::make_segments(std::vector<std::vector<DrawnEdge>>& drawn, std::vector<PieceList> pieces, std::vector<Segment>& crossing,
                              std::size_t total, LineDrawing& res) const {
  const ParallelLoop loop(opt_.threads);
  res.segments.reserve(total - backs_left_count_);
  constexpr std::size_t kRun = std::size_t{1} << 20, kBlock = 4096;
  std::size_t at = 0, put = 0;  // the first edge of the body, its first segment
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const std::size_t n = drawn[b].size();
    const bool some_left = b < backs_left_.size() && backs_left_[b];
    for (std::size_t r0 = 0; r0 < n; r0 += kRun) {
      const std::size_t r1 = std::min(n, r0 + kRun), blocks = (r1 - r0 + kBlock - 1) / kBlock;
      // Where each block's segments go: after the segments of the blocks before it.
      const std::vector<std::size_t> to = parallel_offsets(
          blocks,
          [&](std::size_t k) {
            const std::size_t e0 = r0 + k * kBlock, e1 = std::min(r1, e0 + kBlock);
            if (!some_left) return e1 - e0;
            std::size_t c = 0;
            for (std::size_t e = e0; e < e1; ++e) c += !left_out(b, drawn[b][e]);
            return c;
          },
          loop);
      touch_pages(static_cast<void*>(res.segments.data() + put), to[blocks] * sizeof(Segment), loop);
      res.segments.resize(put + to[blocks]);
      loop.for_each(blocks, 1, [&](std::size_t k) {
        std::size_t w = put + to[k];
        for (std::size_t e = r0 + k * kBlock, e1 = std::min(r1, e + kBlock); e < e1; ++e) {
          if (left_out(b, drawn[b][e])) continue;
          Segment& s = res.segments[w++];
          s = edge_segment(static_cast<int>(b), drawn[b][e]);
          s.pieces = std::move(pieces[at + e]);
        }
      });
      release_pages(static_cast<void*>(drawn[b].data() + r0), (r1 - r0) * sizeof(DrawnEdge));
      release_pages(static_cast<void*>(pieces.data() + at + r0), (r1 - r0) * sizeof(PieceList));
      put += to[blocks];
    }
    at += n;
    std::vector<DrawnEdge>().swap(drawn[b]);
  }
  res.segments.resize(put + crossing.size());
  for (Segment& s : crossing) {
    s.pieces = std::move(pieces[at++]);
    res.segments[put++] = std::move(s);
  }
}

// Everything visibility needed, freed (the engine is done once visibility has run).
template <class P>
void Engine<P>::release_arrays() {
  std::vector<Occ>().swap(occ_);
  std::vector<Box>().swap(boxes_);
  grid_ = ScreenGrid();
  std::vector<std::array<double, 3>>().swap(vproj_);
  std::vector<char>().swap(vfront_);
  std::vector<char>().swap(vertex_closed_);
  if (keep_ && !cam_.perspective && prep_->Xd.empty()) prep_->Xd = std::move(Xd_), prep_->sigma = sigma_;
  std::vector<std::array<double, 3>>().swap(Xd_);
  if (keep_) return;  // the shared work stays for the next view
  std::vector<Tri>().swap(tris_);
  std::vector<Vec<P>>().swap(X_);
}

// One segment's pieces into `out`: a one-piece list when it is wholly visible or hidden (a
// tile's segments it does not decide: hidden placeholders).
template <class P>
void Engine<P>::solve_into(Segment& s, const std::array<int, 2>& gv, Work& wk, PieceList& out) const {
  signed char whole = -1;
  if (hooks_.decide && !hooks_.decide(s)) whole = 1;
  else solve(s, gv, wk, whole);
  if (whole < 0) {
    out = std::move(s.pieces);
    return;
  }
  out.set_whole(whole == 0);
}

template <class P>
std::optional<std::pair<Rational, Rational>> Engine<P>::depth_of(const Segment& s) const {
  if (!cam_.perspective) return std::nullopt;
  return std::make_pair(cam_.depth(s.from()), cam_.depth(s.to()));
}

// The occluders whose boxes meet the segment's box `seg` (with the margin; an occluder
// entirely deeper than the segment's farthest point skipped). The margin covers the error of
// the occluders' and the segment's projections (bounds::kBoxMargin of the larger extent).
template <class P>
void Engine<P>::candidates(const Box& seg, Work& wk) const {
  wk.cand.clear();
  wk.stamps.next();
  double m = margin_;
  for (double v : {static_cast<double>(seg.x0), static_cast<double>(seg.x1), static_cast<double>(seg.y0),
                   static_cast<double>(seg.y1), seg.dmin})
    if (std::isfinite(v)) m = std::max(m, bounds::kBoxMargin * std::fabs(v));
  const double x0 = seg.x0 - m, x1 = seg.x1 + m, y0 = seg.y0 - m, y1 = seg.y1 + m, dmax = seg.dmin + m;
  grid_.visit(ScreenRect{x0, y0, x1, y1}, [&](int i) {
    if (!wk.stamps.first(i)) return;
    const Box& bx = boxes_[i];
    if (bx.x0 > x1 || bx.x1 < x0 || bx.y0 > y1 || bx.y1 < y0 || bx.dmin > dmax) return;
    wk.cand.push_back(i);
  });
}

template <class P>
void Engine<P>::solve(Segment& s, const std::array<int, 2>& gv, Work& wk, signed char& whole) const {
  const bool hides = static_cast<std::size_t>(s.body) >= hooks_.see_through.size() || !hooks_.see_through[s.body];
  if (s.self_hidden && hides) {  // its own front faces hide it
    const bool front = gv[0] >= 0 && vfront_[gv[0]] && vfront_[gv[1]];
    if (front || !cam_.perspective) {
      whole = 1;
      return;
    }
    std::vector<std::pair<Rational, Rational>> all;  // built in place (a braced list copies)
    all.emplace_back(0, 1);
    s.pieces = pieces_from_hidden(std::move(all), front ? std::nullopt : depth_of(s));
    return;
  }
  // The segment's screen box; Box::dmin holds its farthest depth here. In perspective only its
  // part strictly in front of the eye matters (the rest is behind the eye, never drawn).
  std::array<double, 3> pr[2];
  bool front[2];
  Point3 ends[2];
  const Point3* pts[2] = {nullptr, nullptr};
  for (int k = 0; k < 2; ++k) {
    if (gv[0] >= 0) {
      pr[k] = vproj_[gv[k]];
      front[k] = vfront_[gv[k]];
      if (!vfront_[gv[0]] || !vfront_[gv[1]]) pts[k] = &world(gv[k]);
    } else {
      ends[k] = k == 0 ? s.from() : s.to();
      pr[k] = proj_.project(ends[k]);
      front[k] = !cam_.perspective || cam_.in_front(ends[k]) == Sign::Positive;
      pts[k] = &ends[k];
    }
  }
  Box sb;
  if (front[0] && front[1]) {
    sb = Box{static_cast<float>(std::min(pr[0][0], pr[1][0])), static_cast<float>(std::min(pr[0][1], pr[1][1])),
             static_cast<float>(std::max(pr[0][0], pr[1][0])), static_cast<float>(std::max(pr[0][1], pr[1][1])),
             std::max(pr[0][2], pr[1][2])};
    sb.x0 = next_float_down(sb.x0), sb.y0 = next_float_down(sb.y0);
    sb.x1 = next_float_up(sb.x1), sb.y1 = next_float_up(sb.y1);
  } else {
    if (!front[0] && !front[1]) {  // wholly behind the eye
      s.pieces = pieces_from_hidden({}, depth_of(s));
      return;
    }
    const std::array<double, 3>* pp[2] = {&pr[0], &pr[1]};
    sb = front_box(cam_, pts, pp, front, 2).box;
    sb.dmin = front[0] ? pr[0][2] : pr[1][2];
  }
  candidates(sb, wk);
  wk.skipped += occ_.size() - wk.cand.size();
  const int body1 = s.kind == Segment::Kind::Edge ? s.body : s.body2;
  wk.caps = {{{s.body, cap_part(s.body, s.face0)}, {body1, cap_part(body1, s.face1)}}};
  std::vector<std::pair<Rational, Rational>> hidden;
  if (gv[0] >= 0) {
    wk.spans.clear();
    for (int i : wk.cand) test_integer(i, gv, wk);
    merge(wk, hidden);
  } else {
    RationalEnds ends;
    std::array<Rational, 3> A, B;
    for (int k = 0; k < 3; ++k) {
      A[k] = s.from()[k] * scale_;
      B[k] = s.to()[k] * scale_;
      if constexpr (std::is_same_v<P, Big>) {  // the vertices' scale for the filter (filter_doubles)
        Rational a, b;
        mpq_div_2exp(a.get_mpq_t(), A[k].get_mpq_t(), static_cast<mp_bitcnt_t>(sigma_));
        mpq_div_2exp(b.get_mpq_t(), B[k].get_mpq_t(), static_cast<mp_bitcnt_t>(sigma_));
        ends.Ad[k] = a.get_d();
        ends.Bd[k] = b.get_d();
      } else {
        ends.Ad[k] = A[k].get_d();
        ends.Bd[k] = B[k].get_d();
      }
      for (double v : {ends.Ad[k], ends.Bd[k]})  // normal or exactly zero (see filtered_sign)
        if (!std::isfinite(v) || (v != 0 && std::fabs(v) < 0x1p-1000)) ends.filter = false;
      if ((ends.Ad[k] == 0) != (sgn(A[k]) == 0) || (ends.Bd[k] == 0) != (sgn(B[k]) == 0)) ends.filter = false;
    }
    common_integers(A, ends.a, ends.da);
    common_integers(B, ends.b, ends.db);
    for (int i : wk.cand) test_rational(occ_[i], ends, hidden, wk);
  }
  // Both ends strictly in front of the eye: no part is behind it, the depths are not needed.
  if (front[0] && front[1]) {
    if (hidden.empty()) {
      whole = 0;
      return;
    }
    if (hidden.size() == 1 && hidden[0].first == 0 && hidden[0].second == 1) {
      whole = 1;
      return;
    }
  }
  s.pieces = pieces_from_hidden(std::move(hidden), front[0] && front[1] ? std::nullopt : depth_of(s));
}

// Hidden interval of the segment X0 -> X1 by one occluder, integer values.
// With multi-limb numbers, each inequality's sign at an end is known without arithmetic where the
// end is a vertex of its plane (0; the face plane holds the triangle's three vertices, a side
// plane its edge's two), else tried on doubles (filtered_sign). When both signs are known the
// exact plane values are needed only for a crossing strictly inside the segment; any other
// case takes the same branch as the exact test below.
template <class P>
void Engine<P>::test_integer(int oi, const std::array<int, 2>& gv, Work& wk) const {
  ++wk.pairs;
  const Occ& o = occ_[oi];
  bool has_lo = false, has_hi = false;
  Frac<P> lo{V(0), V(1), 0.0}, hi{V(1), V(1), 1.0};
  int on_side = 0;  // bit k: the segment lies in side plane k (closed)
  for (int k = 0; k < 4; ++k) {
    V f0, f1;
    int s0 = 0, s1 = 0;
    bool exact = true;
    if (k == 0 && in_cap_plane(o, wk)) {
      exact = false;  // s0 = s1 = 0
    } else if constexpr (kFiltered) {
      auto known = [&](int e, int& sg) {
        const int g = gv[e];
        const bool on = k == 0 ? o.through_vertices && (g == o.v[0] || g == o.v[1] || g == o.v[2]) : g == o.v[k - 1] || g == o.v[k % 3];
        sg = on ? 0 : filtered_sign(o.m[k], o.c[k], Xd_[g]);
        return on || sg != 0;
      };
      exact = !(known(0, s0) && known(1, s1)) || (s0 != 0 && s1 != 0 && (s0 > 0) != (s1 > 0));
    }
    if (exact) {
      if constexpr (kFiltered) {
        if (!fixed_plane_values(o, k, gv, f0, f1)) {
          Vec<P> m;
          V c;
          exact_plane(o, k, m, c);
          f0 = dot<P>(m, pt(gv[0])) - c;
          f1 = dot<P>(m, pt(gv[1])) - c;
        }
      } else {
        const Vec<P>& a = plane_point(o, k);
        f0 = dot<P>(o.m[k], sub<P>(pt(gv[0]), a));
        f1 = dot<P>(o.m[k], sub<P>(pt(gv[1]), a));
      }
      s0 = P::sign(f0), s1 = P::sign(f1);
    }
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
      Frac<P> r{V(1), V(1), 1.0};
      if (s1 != 0) {
        V d = f0 - f1;
        r = Frac<P>{f0, d, P::ratio(f0, d)};
      }
      if (!has_hi || compare(r, hi, wk.c) < 0) hi = r, has_hi = true;
    } else {  // lower bound t > -f0 / (f1 - f0)
      Frac<P> r{V(0), V(1), 0.0};
      if (s0 != 0) {
        V d = f1 - f0;
        V nn = -f0;
        r = Frac<P>{nn, d, P::ratio(nn, d)};
      }
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

// Sign of m·X - c from doubles, or 0 when the filter cannot tell. Each input is within 2u
// of its exact value (mpq_get_d and mpz_get_d truncate; Int128 and int64 conversions round),
// c within 5u when made from the grid's small integers (grid_doubles); each product adds u
// and the three additions u each, so the computed value is within (2u + 2u + u + 3u)·S +
// O(u²) < 9u·S of the exact one, S = Σ|m_j X_j| + |c| (u = 2^-53; c's term: 5u + 3u).
// The bound used, 2e-15·S_d, exceeds 18u·S_d, and S_d >= S·(1 - 8u); the floor covers
// products that underflowed. The caller uses it only on ends whose doubles are zero exactly
// when the rational is, and otherwise normal above 2^-1000 (so no product of an integer and a
// coordinate underflows). S_d not finite (a value beyond the double range): no decision.
template <class P>
int Engine<P>::filtered_sign(const double* m, double c, const std::array<double, 3>& X) {
  double s = -c, mag = std::fabs(s);
  for (int j = 0; j < 3; ++j) {
    const double t = m[j] * X[j];
    s += t;
    mag += std::fabs(t);
  }
  if (!std::isfinite(mag)) return 0;
  const double bound = 2e-15 * mag + 1e-300;
  return s > bound ? 1 : (s < -bound ? -1 : 0);
}

template <class P>
int Engine<P>::filtered_sign(const Occ& o, int k, const std::array<double, 3>& X) const {
  if constexpr (kFiltered) {
    return filtered_sign(o.m[k], o.c[k], X);
  } else {
    const double m[3] = {P::cdbl(o.m[k][0]), P::cdbl(o.m[k][1]), P::cdbl(o.m[k][2])};
    return filtered_sign(m, P::dbl(dot<P>(o.m[k], plane_point(o, k))), X);
  }
}

// The doubles of every vertex (kFiltered; the occluders' are made with them), on all cores.
// Integers convert to 0 exactly when they are 0 and are otherwise at least 1; one beyond the
// double range becomes infinite, which filtered_sign leaves to the exact test.
// Big: X·2^-sigma_ instead (below 1 in magnitude), mantissa and exponent apart so that no
// integer overflows the doubles; one below 2^-1000 (not 0) becomes NaN, which filtered_sign
// leaves to the exact test.
template <class P>
void Engine<P>::filter_doubles() {
  if constexpr (kFiltered) {
    if (!Xd_.empty() || X_.empty()) return;         // made before the intersection lines (Big)
    if (!cam_.perspective && !prep_->Xd.empty()) {  // made by a view before
      Xd_ = prep_->Xd;
      return;
    }
    const ParallelLoop loop(opt_.threads);
    Xd_.resize(X_.size());
    // Big, a vertex on the grid (its X not kept: pt): X = small·K (K = scale / G) as
    // |small|·k·2^(s - sigma_), k the top 64 bits of K (K = k·2^s·(1 + d), 0 <= d < 2^-63), the
    // product exact in 128 bits and rounded once: within u + 2^-63 < 2u, as the truncation of
    // mpz_get_d_2exp.
    std::uint64_t k_top = 0;
    long k_shift = 0;
    const bool grid = std::is_same_v<P, Big> && !prep_->on_grid.empty();
    if constexpr (std::is_same_v<P, Big>) {
      if (grid) {
        k_shift = std::max<long>(0, static_cast<long>(mpz_sizeinbase(grid_factor_.get_mpz_t(), 2)) - 64);
        mpz_class k;
        mpz_tdiv_q_2exp(k.get_mpz_t(), grid_factor_.get_mpz_t(), static_cast<mp_bitcnt_t>(k_shift));
        k_top = mpz_get_ui(k.get_mpz_t());
      }
    }
    loop.for_each(X_.size(), 4096, [&](std::size_t i) {
      if (grid && prep_->on_grid[i]) {
        for (int j = 0; j < 3; ++j) {
          const std::int64_t v = prep_->small[i][j];
          double x = 0;
          if (v != 0) {
            const UInt128 a = (v < 0 ? -static_cast<UInt128>(v) : static_cast<UInt128>(v)) * k_top;  // below 2^125
            x = std::ldexp(static_cast<double>(a), static_cast<int>(std::max<long>(k_shift - sigma_, -4000)));
            if (!(x >= 0x1p-1000)) x = NAN;
            if (v < 0) x = -x;
          }
          Xd_[i][j] = x;
        }
        return;
      }
      for (int j = 0; j < 3; ++j) {
        if constexpr (std::is_same_v<P, Big>) {
          long e = 0;
          const double m = mpz_get_d_2exp(&e, X_[i][j].get_mpz_t());
          double x = 0;
          if (m != 0) {
            x = std::ldexp(m, static_cast<int>(std::max<long>(e - sigma_, -4000)));
            if (!(std::fabs(x) >= 0x1p-1000)) x = NAN;
          }
          Xd_[i][j] = x;
        } else {
          Xd_[i][j] = P::cdbl(X_[i][j]);
        }
      }
    });
  }
}

// Big: sigma_, the bit length of the largest coordinate (of the vertices and the eye).
template <class P>
void Engine<P>::filter_shift() {
  if constexpr (std::is_same_v<P, Big>) {
    if (sigma_ > 0) return;                       // made before the intersection lines
    if (!cam_.perspective && prep_->sigma > 0) {  // by a view before
      sigma_ = prep_->sigma;
      return;
    }
    // (a vertex on the grid, its X not kept: small·K has at most the bits of both together)
    const std::vector<char>& g = prep_->on_grid;
    const std::size_t k_bits = g.empty() ? 0 : mpz_sizeinbase(grid_factor_.get_mpz_t(), 2);
    std::size_t bits = 0;
    for (std::size_t i = 0; i < X_.size(); ++i)
      for (int j = 0; j < 3; ++j) {
        if (!g.empty() && g[i]) {
          const std::int64_t v = prep_->small[i][j];
          if (v != 0) bits = std::max(bits, static_cast<std::size_t>(bit_length(abs128(Int128(v)))) + k_bits);
        } else {
          bits = std::max(bits, mpz_sizeinbase(X_[i][j].get_mpz_t(), 2));
        }
      }
    if (cam_.perspective)
      for (int j = 0; j < 3; ++j) bits = std::max(bits, mpz_sizeinbase(view_[j].get_mpz_t(), 2));
    sigma_ = static_cast<long>(bits);
  }
}

// An occluder's plane m·X - c as the filter's doubles. Big: m·2^-e and c·2^-(e + sigma_), e
// the bit length of m's largest component, so that with X·2^-sigma_ the value is
// (m·X - c)·2^-(e + sigma_) (the same sign) and every term is below 4 in magnitude. An input
// converts within 2u when normal; one that falls below the normal doubles is within 2^-1022,
// and with |X·2^-sigma_| < 1 each such term errs by less than 2^-1020, far under
// filtered_sign's floor. Wide: the values themselves (below 2^450).
template <class P>
void Engine<P>::plane_doubles(const Vec<P>& m, const V& c, double* dm, double& dc) const {
  if constexpr (std::is_same_v<P, Big>) {
    std::size_t bits = 0;
    for (int j = 0; j < 3; ++j)
      if (sgn(m[j]) != 0) bits = std::max(bits, mpz_sizeinbase(m[j].get_mpz_t(), 2));
    const long e = static_cast<long>(bits);
    auto scaled = [](const mpz_class& v, long shift) {
      long x = 0;
      const double d = mpz_get_d_2exp(&x, v.get_mpz_t());
      return d == 0 ? 0.0 : std::ldexp(d, static_cast<int>(std::max<long>(x - shift, -4000)));
    };
    for (int j = 0; j < 3; ++j) dm[j] = scaled(m[j], e);
    dc = scaled(c, e + sigma_);
  } else {
    for (int j = 0; j < 3; ++j) dm[j] = P::cdbl(m[j]);
    dc = P::dbl(c);
  }
}

// The same on rational end points (intersection lines), values m·X - c. A filter on doubles
// first: an occluder whose inequality k is certainly not positive at both ends hides nothing
// of the segment (the exact loop would return at k too: the result does not depend on the
// order of k), and one certainly positive at both ends takes no exact values (the exact loop
// goes on past it). The rest is decided on the exact values.
template <class P>
void Engine<P>::test_rational(const Occ& o, const RationalEnds& e, std::vector<std::pair<Rational, Rational>>& out, Work& wk) const {
  ++wk.pairs;
  int inside = 0;  // bit k: inequality k certainly positive at both ends
  for (int k = 0; e.filter && k < 4; ++k) {
    const int a = filtered_sign(o, k, e.Ad), b = filtered_sign(o, k, e.Bd);
    if (a < 0 && b < 0) return;
    if (a > 0 && b > 0) inside |= 1 << k;
  }
  // Exact: F = m·a - c·da is f·da (da > 0), so it has f's sign; t = f0 / (f0 - f1) is
  // F0·db / (F0·db - F1·da).
  mpz_class& F0 = wk.z[0];
  mpz_class& F1 = wk.z[1];
  mpz_class& c = wk.z[2];
  std::optional<Rational> lo, hi;
  int on_side = 0;
  for (int k = 0; k < 4; ++k) {
    if (inside >> k & 1) continue;
    int s0 = 0, s1 = 0;  // (0 at both ends in the plane of its own cap)
    if (k != 0 || !in_cap_plane(o, wk)) {
      Vec<P> m;
      V ck;
      exact_plane(o, k, m, ck);
      set_z(c.get_mpz_t(), ck);
      mpz_mul(F0.get_mpz_t(), c.get_mpz_t(), e.da.get_mpz_t());
      mpz_mul(F1.get_mpz_t(), c.get_mpz_t(), e.db.get_mpz_t());
      mpz_neg(F0.get_mpz_t(), F0.get_mpz_t());
      mpz_neg(F1.get_mpz_t(), F1.get_mpz_t());
      for (int j = 0; j < 3; ++j) {
        addmul(F0.get_mpz_t(), m[j], e.a[j].get_mpz_t(), wk.z[3].get_mpz_t());
        addmul(F1.get_mpz_t(), m[j], e.b[j].get_mpz_t(), wk.z[3].get_mpz_t());
      }
      s0 = sgn(F0), s1 = sgn(F1);
    }
    if (s0 > 0 && s1 > 0) continue;
    if (s0 <= 0 && s1 <= 0) {
      if (o.closed[k] && s0 == 0 && s1 == 0) {
        on_side |= 1 << k;
        continue;
      }
      return;
    }
    mpz_class n = F0 * e.db, d = n - F1 * e.da;
    Rational t(n, d);
    t.canonicalize();
    if (s0 > 0) {
      if (!hi || t < *hi) hi = std::move(t);
    } else if (!lo || t > *lo) {
      lo = std::move(t);
    }
  }
  if (!lo) lo.emplace(0);
  if (!hi) hi.emplace(1);
  if (!end_on_hides(o, on_side)) return;
  if (*lo < *hi) out.push_back({std::move(*lo), std::move(*hi)});
}

template class Engine<Fast>;
template class Engine<Fast40>;
template class Engine<Wide>;
template class Engine<Big>;

}  // namespace hlr::face_route
