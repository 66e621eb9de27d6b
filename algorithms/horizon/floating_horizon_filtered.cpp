// The exact floating horizon on certified doubles (see floating_horizon_filtered.hpp; course
// notes section 24). The sweep mirrors floating_horizon_exact() in floating_horizon.cpp step
// for step; only the numbers differ.
#include "algorithms/horizon/floating_horizon_filtered.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <tuple>

#include "algorithms/horizon/horizon_picture.hpp"
#include "algorithms/support/parallel.hpp"

namespace hlr {
namespace {

using namespace horizon_filtered;
// Appends a piece (x0 < x1 known), joined to the last one when it continues it on the same line.
void push(const Picture& P, Env& e, const Abs& x0, const Abs& x1, const Line* line) {
  if (!e.empty() && P.cmp(e.back().x1, x0) == 0 && P.same_line(e.back().line, line)) {
    e.back().x1 = x1;
    return;
  }
  e.push_back(Seg{x0, x1, line});
}

// floating_horizon.cpp's merge(): the pointwise maximum (upper) or minimum of two horizons.
// Writes into `out` (cleared first); scratch lists are per thread.
void merge(const Picture& P, const Env& A, const Env& B, bool upper, Env& out) {
  thread_local std::vector<const Abs*> pa, pb, xs;
  auto points = [&](const Env& e, std::vector<const Abs*>& p) {
    p.clear();
    for (const Seg& s : e) {
      if (p.empty() || P.cmp(*p.back(), s.x0) != 0) p.push_back(&s.x0);
      p.push_back(&s.x1);
    }
  };
  points(A, pa);
  points(B, pb);
  // Each list strictly increases (pieces do not overlap), so the merged list has no repeats.
  xs.clear();
  std::size_t i = 0, j = 0;
  while (i < pa.size() || j < pb.size()) {
    if (j == pb.size()) {
      xs.push_back(pa[i++]);
    } else if (i == pa.size()) {
      xs.push_back(pb[j++]);
    } else {
      const int s = P.cmp(*pa[i], *pb[j]);
      if (s < 0) xs.push_back(pa[i++]);
      else if (s > 0) xs.push_back(pb[j++]);
      else xs.push_back(pa[i++]), ++j;
    }
  }
  out.clear();
  std::size_t ia = 0, ib = 0;
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const Abs &a = *xs[k], &b = *xs[k + 1];
    while (ia < A.size() && (&A[ia].x1 == &a || P.cmp(A[ia].x1, a) <= 0)) ++ia;
    while (ib < B.size() && (&B[ib].x1 == &a || P.cmp(B[ib].x1, a) <= 0)) ++ib;
    const Seg* sa = ia < A.size() && (&A[ia].x0 == &a || P.cmp(A[ia].x0, a) <= 0) ? &A[ia] : nullptr;
    const Seg* sb = ib < B.size() && (&B[ib].x0 == &a || P.cmp(B[ib].x0, a) <= 0) ? &B[ib] : nullptr;
    if (!sa && !sb) continue;
    if (!sa || !sb || P.same_line(sa->line, sb->line)) {
      push(P, out, a, b, (sa ? sa : sb)->line);
      continue;
    }
    const Line &la = *sa->line, &lb = *sb->line;
    int d0 = P.diff(la, lb, a), d1 = P.diff(la, lb, b);
    if (!upper) d0 = -d0, d1 = -d1;  // d > 0: A is the better one
    if (d0 >= 0 && d1 >= 0) {
      push(P, out, a, b, &la);
    } else if (d0 <= 0 && d1 <= 0) {
      push(P, out, a, b, &lb);
    } else {  // they cross inside (a, b)
      const Abs xc = P.crossing(&la, &lb);
      push(P, out, a, xc, d0 > 0 ? &la : &lb);
      push(P, out, xc, b, d0 > 0 ? &lb : &la);
    }
  }
}

// floating_horizon.cpp's triangle_side() for both sides at once: the upper and lower
// boundaries of the projected triangle of samples a, b, c.
void triangle_sides(const Picture& P, int a, int b, int c, LinePool& lines, Env& up, Env& lo) {
  if (P.sample_cmp(b, a) < 0) std::swap(a, b);
  if (P.sample_cmp(c, b) < 0) std::swap(b, c);
  if (P.sample_cmp(b, a) < 0) std::swap(a, b);
  if (!(P.sample_cmp(a, c) < 0)) return;  // seen edge-on: no area in the picture
  const int side = P.orient(a, b, c);
  const Line* ac = P.through(lines, a, c);
  Env& two = side > 0 ? up : lo;  // the side through b
  Env& one = side > 0 ? lo : up;  // the side a-c
  if (side != 0) {
    if (P.sample_cmp(a, b) < 0) push(P, two, P.at(a), P.at(b), P.through(lines, a, b));
    if (P.sample_cmp(b, c) < 0) push(P, two, P.at(b), P.at(c), P.through(lines, b, c));
  } else {
    two.push_back(Seg{P.at(a), P.at(c), ac});
  }
  one.push_back(Seg{P.at(a), P.at(c), ac});
}

// The upper and lower boundaries of a cell (samples q[0..3] in their order round it) at once,
// when its picture is a strictly convex quadrilateral with four different abscissas: the
// union of its two triangles is then the quadrilateral, whose boundary from the leftmost to
// the rightmost corner is one chain over it and one under it (the diagonal is inside). False
// (nothing written) otherwise: the caller merges the two triangles.
bool convex_cell_sides(const Picture& P, const std::array<int, 4>& q, LinePool& lines, Env& up, Env& lo) {
  const int turn = P.orient(q[0], q[1], q[2]);
  if (turn == 0 || P.orient(q[1], q[2], q[3]) != turn || P.orient(q[2], q[3], q[0]) != turn || P.orient(q[3], q[0], q[1]) != turn)
    return false;
  int left = 0, right = 0;
  for (int k = 1; k < 4; ++k) {
    const int l = P.sample_cmp(q[k], q[left]), r = P.sample_cmp(q[k], q[right]);
    if (l < 0) left = k;
    if (r > 0) right = k;
  }
  for (int k = 0; k < 4; ++k)
    for (int m = k + 1; m < 4; ++m)
      if (P.sample_cmp(q[k], q[m]) == 0) return false;
  // turn > 0: clockwise in (X, Y) (see orient), so the corners after the leftmost in their
  // order run over the top to the rightmost; turn < 0: under it.
  Env& forward = turn > 0 ? up : lo;
  Env& backward = turn > 0 ? lo : up;
  for (int k = left; k != right; k = (k + 1) % 4) {
    const int u = q[k], v = q[(k + 1) % 4];
    forward.push_back(Seg{P.at(u), P.at(v), P.through(lines, u, v)});
  }
  for (int k = left; k != right; k = (k + 3) % 4) {
    const int u = q[k], v = q[(k + 3) % 4];
    backward.push_back(Seg{P.at(u), P.at(v), P.through(lines, u, v)});
  }
  return true;
}

// acc = merge(acc, add): only the pieces of acc over add's range take part; the ones to the
// left and right stay as they are (joined to the merged part where the same line goes on).
// A horizon is the envelope function cut into maximal pieces on one line, so the result is
// the full merge's, piece for piece.
void merge_into(const Picture& P, Env& acc, const Env& add, bool upper) {
  if (add.empty()) return;
  if (acc.empty()) {
    acc = add;
    return;
  }
  // The first piece ending after add begins, the first beginning at or after add ends.
  // New pieces mostly land at the end (the strips are built left to right): search from the
  // end by doubling steps, then by halves.
  const std::size_t n = acc.size();
  auto ends_after = [&](std::size_t k) { return P.cmp(acc[k].x1, add.front().x0) > 0; };  // true on a suffix
  std::size_t step = 1, right = n;
  while (step <= right && ends_after(right - step)) right -= step, step *= 2;
  std::size_t left = step <= right ? right - step + 1 : 0;  // ends_after is false at left - 1 (or left = 0)
  auto lo = std::upper_bound(acc.begin() + static_cast<long>(left), acc.begin() + static_cast<long>(right), add.front().x0,
                             [&](const Abs& v, const Seg& p) { return P.cmp(v, p.x1) < 0; });
  auto hi = P.cmp(acc.back().x0, add.back().x1) < 0
                ? acc.end()
                : std::lower_bound(lo, acc.end(), add.back().x1, [&](const Seg& p, const Abs& v) { return P.cmp(p.x0, v) < 0; });
  thread_local Env middle, merged, tail;
  if (lo == acc.begin() && hi == acc.end()) {  // add spans all of acc (a strip into a horizon): no copies
    merge(P, acc, add, upper, merged);
    acc.swap(merged);
    return;
  }
  middle.assign(lo, hi);
  merge(P, middle, add, upper, merged);
  tail.assign(hi, acc.end());
  acc.erase(lo, acc.end());
  for (std::size_t k = 0; k < merged.size(); ++k) {
    if (k == 0) push(P, acc, merged[k].x0, merged[k].x1, merged[k].line);
    else acc.push_back(merged[k]);
  }
  for (std::size_t k = 0; k < tail.size(); ++k) {
    if (k == 0) push(P, acc, tail[k].x0, tail[k].x1, tail[k].line);
    else acc.push_back(tail[k]);
  }
}

// The first piece of `e` ending after x (e.size() if none), searched from `hint` outwards by
// doubling steps, then by halves (a cut's segments come in order: the answer is near the last).
std::size_t first_after(const Picture& P, const Env& e, const Abs& x, std::size_t hint) {
  const std::size_t n = e.size();
  auto after = [&](std::size_t k) { return P.cmp(x, e[k].x1) < 0; };  // false, ..., false, true, ..., true
  std::size_t lo = 0, hi = n;  // the answer is in [lo, hi]
  hint = std::min(hint, n);
  if (hint < n && after(hint)) {
    hi = hint;
    for (std::size_t step = 1; step <= hi; step *= 2) {
      if (!after(hi - step)) {
        lo = hi - step + 1;
        break;
      }
      hi -= step;
    }
  } else {
    lo = hint < n ? hint + 1 : n;
    for (std::size_t step = 1; lo + step - 1 < n; step *= 2) {
      if (after(lo + step - 1)) {
        hi = lo + step - 1;
        break;
      }
      lo += step;
    }
  }
  return static_cast<std::size_t>(
      std::partition_point(e.begin() + static_cast<long>(lo), e.begin() + static_cast<long>(hi), [&](const Seg& p) { return !(P.cmp(x, p.x1) < 0); }) -
      e.begin());
}

// floating_horizon.cpp's hidden_parts(): the hidden open intervals of the segment on `line` over
// (x0, x1), where L < segment < U.
// `hint`: where the previous segment's search in U and L ended (updated).
void hidden_parts(const Picture& P, const Line& line, const Abs& x0, const Abs& x1, const Env& U, const Env& L,
                  std::vector<std::pair<Abs, Abs>>& out, std::array<std::size_t, 2>& hint) {
  // The sub-intervals between consecutive breakpoints of U and L inside (x0, x1), walked in
  // order (the same list as sorting them all).
  std::size_t iu = hint[0] = first_after(P, U, x0, hint[0]), il = hint[1] = first_after(P, L, x0, hint[1]);
  const Abs* a = &x0;
  while (true) {
    while (iu < U.size() && P.cmp(U[iu].x1, *a) <= 0) ++iu;
    while (il < L.size() && P.cmp(L[il].x1, *a) <= 0) ++il;
    const Abs* b = &x1;
    const Seg *u = nullptr, *l = nullptr;
    for (auto [e, i, cur] : {std::make_tuple(&U, iu, &u), std::make_tuple(&L, il, &l)}) {
      if (i >= e->size()) continue;
      const Seg& piece = (*e)[i];
      const bool started = P.cmp(piece.x0, *a) <= 0;
      if (started) *cur = &piece;
      const Abs& next = started ? piece.x1 : piece.x0;
      if (P.cmp(next, *b) < 0) b = &next;
    }
    if (u && l) {
      auto where_above = [&](const Line& hi, const Line& lo, Abs& from, Abs& to) {
        const int s0 = P.diff(hi, lo, *a), s1 = P.diff(hi, lo, *b);
        if (s0 <= 0 && s1 <= 0) return false;
        from = *a, to = *b;
        if (s0 != s1 && s0 != 0 && s1 != 0) (s0 > 0 ? to : from) = P.crossing(&lo, &hi);
        return true;
      };
      Abs lo1, hi1, lo2, hi2;
      if (where_above(*u->line, line, lo1, hi1) && where_above(line, *l->line, lo2, hi2)) {
        const Abs& lo = P.cmp(lo1, lo2) >= 0 ? lo1 : lo2;
        const Abs& hi = P.cmp(hi1, hi2) <= 0 ? hi1 : hi2;
        if (P.cmp(lo, hi) < 0) {
          if (!out.empty() && P.cmp(out.back().second, lo) == 0) out.back().second = hi;
          else out.emplace_back(lo, hi);
        }
      }
    }
    if (b == &x1) break;
    a = b;
  }
}

// A visible run waiting for its exact parameters: over (x0, x1) of the segment from sample p
// to sample q (X_p < X_q); `forward`: the segment's first sample is p.
struct Run {
  int curve, segment;
  Abs x0, x1;
  int p, q;
  bool forward;
};

void emit_runs(const Picture& P, int p, int q, bool forward, const std::vector<std::pair<Abs, Abs>>& hidden, int curve,
               int segment, std::vector<Run>& out) {
  auto emit = [&](const Abs& x0, const Abs& x1) {
    if (!(P.cmp(x0, x1) < 0)) return;
    out.push_back(Run{curve, segment, x0, x1, p, q, forward});
  };
  Abs at = P.at(p);
  for (const auto& [h0, h1] : hidden) {
    emit(at, h0);
    at = h1;
  }
  emit(at, P.at(q));
}

// A run's exact parameters along its segment, written into `out` (a GMP number is built in
// place: moving one allocates).
void piece(const Picture& P, const Run& r, HorizonPiece& out) {
  out.curve = r.curve, out.segment = r.segment;
  out.t0 = P.parameter(r.x0, r.p, r.q);
  out.t1 = P.parameter(r.x1, r.p, r.q);
  if (!r.forward) {
    out.t0 = 1 - out.t0, out.t1 = 1 - out.t1;
    out.t0.swap(out.t1);
  }
}

// The exact parameters of the runs (on every core).
std::vector<HorizonPiece> pieces(const Picture& P, const std::vector<Run>& runs, const ParallelLoop& loop) {
  std::vector<HorizonPiece> out(runs.size());
  loop.for_each(runs.size(), 256, [&](std::size_t k) { piece(P, runs[k], out[k]); });
  return out;
}

// Copies the lines that the envelopes `up` and `lo` refer to (their pieces' lines and the
// lines whose crossings bound them) out of the scratch pool into one block of their own, and
// points the envelopes there.
std::unique_ptr<Line[]> compact(Env& up, Env& lo) {
  std::size_t n = 0;
  auto count = [&](const Line* l) {
    if (l && l->moved < 0) const_cast<Line*>(l)->moved = static_cast<int>(n++);
  };
  for (Env* e : {&up, &lo})
    for (const Seg& s : *e) count(s.line), count(s.x0.l1), count(s.x0.l2), count(s.x1.l1), count(s.x1.l2);
  auto out = std::make_unique<Line[]>(n);
  auto move = [&](const Line*& l) {
    if (!l) return;
    Line& dst = out[static_cast<std::size_t>(l->moved)];
    if (dst.p < 0) dst = Line{l->p, l->q, l->s, l->c};
    l = &dst;
  };
  for (Env* e : {&up, &lo})
    for (Seg& s : *e) move(s.line), move(s.x0.l1), move(s.x0.l2), move(s.x1.l1), move(s.x1.l2);
  return out;
}

}  // namespace

HorizonResult floating_horizon_filtered(const HeightGrid& g, const Camera& cam, unsigned threads, HorizonCounters* counters, bool flat) {
  const std::size_t nx = g.xs.size(), nz = g.zs.size();
  const Vector3& v = cam.direction;
  const std::array<Vector3, 2> axes = horizon_axes(g, cam);
  const Vector3 &r = axes[0], &u = axes[1];
  // The picture (X, Y) = (sx·(c·x − a·z), sy·(c·y − b·z)) for v = (a, b, c): r = λ·(c, 0, −a),
  // so X is the exact picture's abscissa times |1/λ|; (0, c, −b) is orthogonal to v, so Y is
  // a positive multiple of the exact picture's ordinate plus a multiple of its abscissa (a
  // shear). The map keeps the order along x and, at one x, the order in y: the same horizons.
  const int sx = sgn(r.x()) * sgn(v.z());
  const int sy = sgn(v.z() * u.y() - v.y() * u.z());
  ParallelLoop loop(threads);
  const Picture P(g, v, sx, sy, threads);
  auto idx = [nx](std::size_t i, std::size_t j) { return static_cast<int>(j * nx + i); };
  HorizonResult res;
  for (std::size_t k = 0; k < nz; ++k) res.order.push_back(static_cast<int>(v.z() > 0 ? nz - 1 - k : k));
  // The strips' envelopes, on every core, a batch at a time (the memory of a batch only), each
  // strip built on its thread's scratch lines and keeping the lines its envelopes use.
  std::vector<std::unique_ptr<Line[]>> strip_lines(nz);
  std::vector<Env> strip_up(nz), strip_lo(nz);
  auto build_strip = [&](std::size_t k) {
    const std::size_t j = static_cast<std::size_t>(res.order[k]), jp = static_cast<std::size_t>(res.order[k - 1]);
    const std::size_t j0 = std::min(j, jp), j1 = std::max(j, jp);
    // The cells in the order of their abscissas (X is monotone in i along a cut), each
    // triangle merged into the strip's envelopes where it lies: linear in the strip's size.
    const bool fw = P.sample_cmp(idx(0, j0), idx(1, j0)) < 0;
    thread_local LinePool scratch;
    scratch.reset();
    Env up, lo, tu, tl;
    for (std::size_t n = 0; n + 1 < nx; ++n) {
      const std::size_t i = fw ? n : nx - 2 - n;
      const int a = idx(i, j0), b = idx(i + 1, j0), cc = idx(i + 1, j1), d = idx(i, j1);
      tu.clear();
      tl.clear();
      if (convex_cell_sides(P, {a, b, cc, d}, scratch, tu, tl)) {  // both triangles at once
        merge_into(P, up, tu, true);
        merge_into(P, lo, tl, false);
        continue;
      }
      for (auto [p, q, s] : {std::array<int, 3>{a, b, cc}, std::array<int, 3>{a, cc, d}}) {
        tu.clear();
        tl.clear();
        triangle_sides(P, p, q, s, scratch, tu, tl);
        merge_into(P, up, tu, true);
        merge_into(P, lo, tl, false);
      }
    }
    strip_lines[k] = compact(up, lo);
    strip_up[k] = std::move(up);
    strip_lo[k] = std::move(lo);
  };
  const std::size_t batch = std::max<std::size_t>(16, 8 * static_cast<std::size_t>(loop.workers()));
  Env U, L;
  LinePool lines;  // the first cut's lines and the side edges' (the horizons keep them)
  LinePool cut_lines;  // a later cut's lines: needed until its runs have their parameters
  std::vector<std::vector<HorizonPiece>> parts;  // res.visible, a chunk of a cut each
  for (std::size_t k = 0; k < nz; ++k) {
    const std::size_t j = static_cast<std::size_t>(res.order[k]);
    if (k > 0 && !strip_lines[k]) {
      const std::size_t end = std::min(nz, k + batch);
      loop.for_each(end - k, 1, [&](std::size_t n) { build_strip(k + n); });
    }
    if (k > 0) {  // the upper and the lower horizon at once (they share nothing but lines)
      loop.for_each(2, 1, [&](std::size_t upper) {
        if (upper) merge_into(P, U, strip_up[k], true);
        else merge_into(P, L, strip_lo[k], false);
      });
      Env().swap(strip_up[k]);
      Env().swap(strip_lo[k]);
    }
    // The cut's segments against the horizons of what is in front, on every core.
    LinePool& pool = k == 0 ? lines : cut_lines;
    cut_lines.reset();
    std::vector<const Line*> cut(nx - 1);
    std::vector<int> left(nx - 1), right(nx - 1);
    std::vector<char> forward(nx - 1);
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      const int c0 = idx(i, j), c1 = idx(i + 1, j);
      forward[i] = P.sample_cmp(c0, c1) < 0;
      left[i] = forward[i] ? c0 : c1, right[i] = forward[i] ? c1 : c0;
      cut[i] = P.through(pool, left[i], right[i]);
    }
    // Each chunk's runs with their exact parameters; a backward segment's runs came in
    // increasing X: turned round, the list is in sort_visible()'s order (cuts, segments, t).
    constexpr std::size_t kGrain = 128;
    std::vector<std::vector<HorizonPiece>> part((nx - 1 + kGrain - 1) / kGrain);
    loop.for_each(part.size(), 1, [&](std::size_t chunk) {
      thread_local std::vector<Run> runs;
      thread_local std::vector<std::pair<Abs, Abs>> hidden;
      std::array<std::size_t, 2> hint{0, 0};
      runs.clear();
      for (std::size_t i = chunk * kGrain, end = std::min(nx - 1, i + kGrain); i < end; ++i) {
        hidden.clear();
        if (k > 0) hidden_parts(P, *cut[i], P.at(left[i]), P.at(right[i]), U, L, hidden, hint);
        const std::size_t from = runs.size();
        emit_runs(P, left[i], right[i], forward[i] != 0, hidden, static_cast<int>(j), static_cast<int>(i), runs);
        if (!forward[i]) std::reverse(runs.begin() + static_cast<long>(from), runs.end());
      }
      part[chunk].resize(runs.size());
      for (std::size_t n = 0; n < runs.size(); ++n) piece(P, runs[n], part[chunk][n]);
    });
    for (std::vector<HorizonPiece>& p : part) parts.push_back(std::move(p));
    if (k == 0) {  // the nearest cut is the first geometry: a strip of zero width
      Env first;
      const bool fw = forward[0] != 0;
      for (std::size_t n = 0; n + 1 < nx; ++n) {
        const std::size_t i = fw ? n : nx - 2 - n;
        push(P, first, P.at(left[i]), P.at(right[i]), cut[i]);
      }
      U = first, L = first;
    }
    res.horizon_breakpoints = std::max({res.horizon_breakpoints, U.size(), L.size()});
  }
  if (!flat) {
    res.visible_chunks = std::move(parts);
  } else {  // swapped into place on every core (a GMP number's move allocates)
    std::vector<std::size_t> at(parts.size() + 1, 0);
    for (std::size_t n = 0; n < parts.size(); ++n) at[n + 1] = at[n] + parts[n].size();
    res.visible.resize(at.back());
    loop.for_each(parts.size(), 16, [&](std::size_t n) {
      for (std::size_t m = 0; m < parts[n].size(); ++m) {
        HorizonPiece &to = res.visible[at[n] + m], &from = parts[n][m];
        to.curve = from.curve, to.segment = from.segment;
        to.t0.swap(from.t0), to.t1.swap(from.t1);
      }
      std::vector<HorizonPiece>().swap(parts[n]);
    });
  }
  std::vector<Run> side_runs;
  if (nz >= 2) {
    const Rational& vx = v.x();
    const std::size_t far = vx > 0 ? 0 : nx - 1, near = vx > 0 ? nx - 1 : 0;
    for (std::size_t j = 0; j + 1 < nz; ++j) {
      if (vx == 0) {
        res.side.push_back({0, static_cast<int>(j), Rational(0), Rational(1)});
        res.side.push_back({static_cast<int>(nx - 1), static_cast<int>(j), Rational(0), Rational(1)});
        continue;
      }
      res.side.push_back({static_cast<int>(near), static_cast<int>(j), Rational(0), Rational(1)});
      const int a = idx(far, j), b = idx(far, j + 1);
      const bool fw = P.sample_cmp(a, b) < 0;
      const int p = fw ? a : b, q = fw ? b : a;
      const Line* edge = P.through(lines, p, q);
      std::vector<std::pair<Abs, Abs>> hidden;
      std::array<std::size_t, 2> hint{0, 0};
      hidden_parts(P, *edge, P.at(p), P.at(q), U, L, hidden, hint);
      emit_runs(P, p, q, fw, hidden, static_cast<int>(far), static_cast<int>(j), side_runs);
    }
    for (HorizonPiece& hp : pieces(P, side_runs, loop)) res.side.push_back(std::move(hp));
    std::stable_sort(res.side.begin(), res.side.end(), [](const HorizonPiece& a, const HorizonPiece& b) {
      if (a.curve != b.curve) return a.curve < b.curve;
      if (a.segment != b.segment) return a.segment < b.segment;
      return a.t0 < b.t0;
    });
  }
  if (counters) counters->exact = P.exact_count();
  return res;
}

}  // namespace hlr
