// The per-face engine, intersection lines (see face_engine.hpp; course notes section 28):
// triangle pairs from the broad phase (intersection_broad_phase.hpp), exact integer plane-side
// tests and a certified double filter, then the exact segment (intersection_lines.hpp).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <tuple>

#include "algorithms/hlr/face_engine.hpp"
#include "algorithms/hlr/intersection_broad_phase.hpp"
#include "algorithms/hlr/intersection_lines.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/support/uninitialised.hpp"
#include "kernel/error_bounds.hpp"

namespace hlr::face_route {
namespace {

using Line = CrossLine;  // bodies, faces, ends
const std::vector<int> kNoParts;

// Pieces of one face pair's line cut by face diagonals: joined where they meet end to end.
void join_collinear(std::vector<Line>& v) {
  std::sort(v.begin(), v.end(), [](const auto& p, const auto& q) {
    auto kp = std::make_tuple(std::get<0>(p), std::get<1>(p), std::get<2>(p), std::get<3>(p));
    auto kq = std::make_tuple(std::get<0>(q), std::get<1>(q), std::get<2>(q), std::get<3>(q));
    if (kp != kq) return kp < kq;
    return std::get<4>(p) < std::get<4>(q);
  });
  std::vector<Line> out;
  out.reserve(v.size());
  for (auto& s : v) {
    if (!out.empty()) {
      auto& o = out.back();
      bool same = std::get<0>(o) == std::get<0>(s) && std::get<1>(o) == std::get<1>(s) && std::get<2>(o) == std::get<2>(s) &&
                  std::get<3>(o) == std::get<3>(s);
      if (same && std::get<5>(o) == std::get<4>(s) &&
          cross(std::get<5>(o) - std::get<4>(o), std::get<5>(s) - std::get<4>(s)).is_zero()) {
        std::get<5>(o) = std::get<5>(s);
        continue;
      }
    }
    out.push_back(std::move(s));
  }
  v = std::move(out);
}

}  // namespace

// Broad phase: triangles' bounding boxes hashed into cubic cells; exact integer plane-side
// tests reject almost every pair; the segment itself is built in rationals.
template <class P>
void Engine<P>::find_intersections(LineDrawing& res) {
  const std::size_t n = tris_.size();
  if (n < 2) return;
  const ParallelLoop loop(opt_.threads);
  auto box = [&](std::size_t i) {
    Box3 b{INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
    if constexpr (std::is_same_v<P, Fast> || std::is_same_v<P, Fast40>) {
      // The engine's integer coordinates (below 2^40: exact doubles), one frame for every
      // body: the exact boxes, without a division (the broad phase takes any one frame).
      for (int v : tris_[i].v)
        for (int k = 0; k < 3; ++k) {
          const double x = P::cdbl(pt(v)[k]);
          b[k] = std::min(b[k], x);
          b[k + 3] = std::max(b[k + 3], x);
        }
      return b;
    }
    const PointStore& store = bodies_[tris_[i].body]->vertex_store();
    for (int v : tris_[i].v)
      for (int k = 0; k < 3; ++k) {
        const Bounds q = store.approx(static_cast<std::size_t>(v - voff_[tris_[i].body]), k);
        b[k] = std::min(b[k], q.lo);
        b[k + 3] = std::max(b[k + 3], q.hi);
      }
    return b;
  };
  // Each pair takes its two normals once. Big: those of the triangles off the grid (a cut's
  // points: multi-limb products) are made once for all pairs when they are few (a sixteenth of
  // the triangles, or up to 65,536).
  std::vector<int> slot;
  std::vector<Vec<P>> kept_normal;
  if constexpr (std::is_same_v<P, Big>) {
    if (!prep_->on_grid.empty()) {
      std::size_t off = 0;
      for (std::size_t i = 0; i < n; ++i) off += !on_grid(tris_[i]);
      if (off * 16 <= n || off <= 65536) {
        slot.assign(n, -1);
        for (std::size_t i = 0; i < n; ++i)
          if (!on_grid(tris_[i])) slot[i] = static_cast<int>(kept_normal.size()), kept_normal.push_back(normal(tris_[i]));
      }
    }
  }
  mark_cap_vertices();
  const auto normal_of = [&](std::uint32_t i, Vec<P>& made) -> const Vec<P>& {
    if (!slot.empty() && slot[i] >= 0) return kept_normal[slot[i]];
    made = normal(tris_[i]);
    return made;
  };
  const auto judge = [&](std::uint32_t ta, std::uint32_t tc) {
    const Tri &x = tris_[ta], &y = tris_[tc];
    if (x.body == y.body) {
      bool shared = false;
      for (int u : x.v)
        for (int w : y.v) shared = shared || u == w;
      if (shared || x.face == y.face) return PairVerdict::Skip;
      // Two faces of one part of the user's face (a section split it) or of one cap lie in one
      // plane: no line.
      const auto& part = static_cast<std::size_t>(x.body) < hooks_.face_part.size() ? hooks_.face_part[x.body] : kNoParts;
      if (!part.empty() && part[x.face] == part[y.face]) return PairVerdict::Skip;
      // Two caps of one body lie on the boundary of one convex region (what the planes keep,
      // or what a cut-away removes): they meet only along its edges, where the cut's faces
      // share their edges (the seams). No line crosses there.
      if (cap_part(x.body, x.face) >= 0 && cap_part(y.body, y.face) >= 0) return PairVerdict::Skip;
    }
    Vec<P> mx, my;
    if constexpr (kFiltered) {  // sides from doubles or the grid first: the normals only when a pair stays
      auto kept = [&](std::uint32_t i) { return !slot.empty() && slot[i] >= 0 ? &kept_normal[static_cast<std::size_t>(slot[i])] : nullptr; };
      if (!straddles(x, kept(ta), y) || !straddles(y, kept(tc), x)) return PairVerdict::Reject;
      const Vec<P>&nx = normal_of(ta, mx), &ny = normal_of(tc, my);
      return may_meet(x, nx, y, ny) ? PairVerdict::Keep : PairVerdict::Reject;
    }
    const Vec<P>& nx = normal_of(ta, mx);
    if (!straddles(x, &nx, y)) return PairVerdict::Reject;
    const Vec<P>& ny = normal_of(tc, my);
    return straddles(y, &ny, x) && may_meet(x, nx, y, ny) ? PairVerdict::Keep : PairVerdict::Reject;
  };
  // Triangles with a vertex in common (global vertex numbers: of one body) are the judge's
  // Skip; the broad phase passes them over, reading the vertices in place.
  const BoxCorners corners{reinterpret_cast<const std::byte*>(tris_.data()) + offsetof(Tri, v), sizeof(Tri)};
  // The boxes in floats rounded outward (half the memory; boxes only grow, so no pair is lost),
  // in doubles when some coordinate lies beyond the floats' range.
  BoxPairs pairs;
  bool done = false;
  {
    RawVector<Box3f> bf(n);  // each written below, on all cores (its pages first touched there)
    PerWorker<char> beyond(loop, 0);
    loop.run(n, 8192, [&](unsigned w, std::size_t b, std::size_t e) {
      bool out = false;
      for (std::size_t i = b; i < e; ++i) out = !outward_floats(box(i), bf[i]) || out;
      if (out) beyond[w] = 1;
    });
    bool fits = true;
    for (unsigned w = 0; w < beyond.size(); ++w) fits = fits && !beyond[w];
    if (fits) {
      pairs = overlapping_box_pairs(bf, loop, judge, kSlabEntries, corners);
      done = true;
    }
  }
  if (!done) {  // beyond the floats' range: doubles
    RawVector<Box3> bb(n);
    loop.for_each(n, 8192, [&](std::size_t i) { bb[i] = box(i); });
    pairs = overlapping_box_pairs(bb, loop, judge, kSlabEntries, corners);
  }
  res.stats.faces->intersection_pairs = pairs.tested;
  const auto& hits = pairs.kept;
  // The exact segments on all cores, each pair into its own slot (then in pair order).
  std::vector<std::optional<Line>> found(hits.size());
  ParallelLoop(opt_.threads).for_each(hits.size(), 64, [&](std::size_t i) {
    const Tri &x = tris_[hits[i].first], &y = tris_[hits[i].second];
    auto seg = segment(x, y);
    if (!seg) return;
    bool swap = y.body < x.body;
    const Tri& f = swap ? y : x;
    const Tri& g = swap ? x : y;
    if (seg->second < seg->first) std::swap(seg->first, seg->second);
    found[i].emplace(f.body, g.body, f.face, g.face, std::move(seg->first), std::move(seg->second));
  });
  std::vector<Line> segs;
  segs.reserve(found.size());
  for (auto& l : found)
    if (l) segs.push_back(std::move(*l));
  // The same segment from two triangles of one face (along a diagonal): once.
  std::sort(segs.begin(), segs.end(), [](const auto& p, const auto& q) {
    if (std::get<0>(p) != std::get<0>(q)) return std::get<0>(p) < std::get<0>(q);
    if (std::get<1>(p) != std::get<1>(q)) return std::get<1>(p) < std::get<1>(q);
    if (!(std::get<4>(p) == std::get<4>(q))) return std::get<4>(p) < std::get<4>(q);
    if (!(std::get<5>(p) == std::get<5>(q))) return std::get<5>(p) < std::get<5>(q);
    if (std::get<2>(p) != std::get<2>(q)) return std::get<2>(p) < std::get<2>(q);
    return std::get<3>(p) < std::get<3>(q);
  });
  std::vector<Line> uniq;
  uniq.reserve(segs.size());
  for (std::size_t i = 0; i < segs.size(); ++i) {
    if (!uniq.empty() && std::get<0>(uniq.back()) == std::get<0>(segs[i]) && std::get<1>(uniq.back()) == std::get<1>(segs[i]) &&
        std::get<4>(uniq.back()) == std::get<4>(segs[i]) && std::get<5>(uniq.back()) == std::get<5>(segs[i]))
      continue;
    uniq.push_back(std::move(segs[i]));
  }
  join_collinear(uniq);
  cross_ = std::move(uniq);
}

// The intersection lines as segments, after the edges.
template <class P>
std::vector<Segment> Engine<P>::crossing_segments(LineDrawing& res) {
  std::vector<Segment> out;
  out.reserve(cross_.size());
  for (auto& [b0, b1, f0, f1, a, b] : cross_) {
    Segment s;
    s.kind = Segment::Kind::Intersection;
    s.line = LineKind::Intersection;
    s.body = b0;
    s.body2 = b1;
    s.face0 = f0;
    s.face1 = f1;
    s.set_ends(a, b);
    ++res.stats.intersection_segments;
    out.push_back(std::move(s));
  }
  std::vector<CrossLine>().swap(cross_);
  return out;
}

// The exact segment of two triangles (triangle_intersection's rules: no line when the planes
// are parallel, either triangle meets the other's plane in fewer than two points or along a
// mesh edge). Under Fast on the integer coordinates: a crossing point of edge p_k p_j with
// plane values s_k, s_j is (p_k·(-s_j) + p_j·s_k) / (s_k - s_j); with |p| < 2^29 and
// |s| < 2^93 the numerators stay below 2^123 and the denominators below 2^94 (Int128). All
// points lie on the planes' common line, so their order along it is their order along one
// axis where the line's direction u is not zero (times u's sign there), compared as products
// in 256 bits. Only the two ends become rationals (divided by the scale). Other policies: in
// rationals.
template <class P>
std::optional<std::pair<Point3, Point3>> Engine<P>::segment(const Tri& x, const Tri& y) const {
  if constexpr (!std::is_same_v<P, Fast>) {
    TriangleRef rx{{&world(x.v[0]), &world(x.v[1]), &world(x.v[2])}, x.edge};
    TriangleRef ry{{&world(y.v[0]), &world(y.v[1]), &world(y.v[2])}, y.edge};
    return triangle_intersection(rx, ry);
  } else {
    struct Pt {
      Int128 num[3], den;
    };
    struct Cut {
      Pt p[2];
      int n = 0;
      bool along = false;
    };
    auto cut = [&](const Tri& t, const Vec<P>& nrm, const Vec<P>& q, Cut& c) {
      Int128 sv[3];
      int sg[3], zeros = 0;
      for (int k = 0; k < 3; ++k) {
        sv[k] = dot<P>(nrm, sub<P>(pt(t.v[k]), q));
        sg[k] = P::sign(sv[k]);
        zeros += sg[k] == 0;
      }
      if (zeros == 3) return;
      for (int k = 0; k < 3; ++k) {
        const int j = (k + 1) % 3;
        const Vec<P>&a = pt(t.v[k]), &b = pt(t.v[j]);
        if (sg[k] == 0 && c.n < 2) c.p[c.n++] = Pt{{a[0], a[1], a[2]}, 1};
        if (sg[k] * sg[j] < 0 && c.n < 2) {
          Int128 d = sv[k] - sv[j];
          const int flip = d < 0 ? -1 : 1;
          Pt r;
          for (int i = 0; i < 3; ++i) r.num[i] = flip * (static_cast<Int128>(a[i]) * -sv[j] + static_cast<Int128>(b[i]) * sv[k]);
          r.den = flip * d;
          c.p[c.n++] = r;
        }
        if (sg[k] == 0 && sg[j] == 0 && t.edge[k]) c.along = true;
      }
    };
    const Vec<P> na = normal(x), nb = normal(y);
    Int128 u[3];
    for (int i = 0; i < 3; ++i) {
      const int a = (i + 1) % 3, b = (i + 2) % 3;
      u[i] = static_cast<Int128>(na[a]) * nb[b] - static_cast<Int128>(na[b]) * nb[a];
    }
    int ax = 0;
    for (int i = 1; i < 3; ++i)
      if (abs128(u[i]) > abs128(u[ax])) ax = i;
    if (u[ax] == 0) return std::nullopt;  // parallel planes
    Cut ca, cb;
    cut(x, nb, pt(y.v[0]), ca);
    cut(y, na, pt(x.v[0]), cb);
    if (ca.n < 2 || cb.n < 2 || ca.along || cb.along) return std::nullopt;
    const int dir = u[ax] > 0 ? 1 : -1;
    auto cmp = [&](const Pt& p, const Pt& q) { return dir * compare_products(p.num[ax], q.den, q.num[ax], p.den); };
    for (Cut* c : {&ca, &cb})
      if (cmp(c->p[1], c->p[0]) < 0) std::swap(c->p[0], c->p[1]);
    const Pt& lo = cmp(ca.p[0], cb.p[0]) >= 0 ? ca.p[0] : cb.p[0];
    const Pt& hi = cmp(ca.p[1], cb.p[1]) <= 0 ? ca.p[1] : cb.p[1];
    if (!(cmp(lo, hi) < 0)) return std::nullopt;
    auto point = [&](const Pt& p) {
      std::array<Rational, 3> c;
      const mpz_class den = to_mpz(p.den);
      for (int i = 0; i < 3; ++i) {
        c[i] = Rational(to_mpz(p.num[i]), den);
        c[i].canonicalize();
        c[i] /= scale_;
      }
      return Point3(std::move(c[0]), std::move(c[1]), std::move(c[2]));
    };
    return std::make_pair(point(lo), point(hi));
  }
}

// A filter before the rational construction: the parts of x on y's plane and of y on x's
// plane lie on one line; if their extents along a coordinate axis are certainly disjoint they
// do not meet. Plane values are exact integers, so each crossing parameter s/(s - t) (s, t
// of opposite signs) is within 4 ulps in doubles, each point within 8 ulps of the largest
// coordinate; intervals farther apart than that are disjoint. Otherwise: exact.
template <class P>
bool Engine<P>::may_meet(const Tri& x, const Vec<P>& nx, const Tri& y, const Vec<P>& ny) const {
  double ax[2], ay[2];
  int axis = 0;
  {
    double u[3] = {P::dbl(nx[1]) * P::dbl(ny[2]) - P::dbl(nx[2]) * P::dbl(ny[1]),
                   P::dbl(nx[2]) * P::dbl(ny[0]) - P::dbl(nx[0]) * P::dbl(ny[2]),
                   P::dbl(nx[0]) * P::dbl(ny[1]) - P::dbl(nx[1]) * P::dbl(ny[0])};
    for (int k = 1; k < 3; ++k)
      if (std::fabs(u[k]) > std::fabs(u[axis])) axis = k;
  }
  double scale = 0;
  if (!extent_on_plane(x, y, ny, axis, ax, scale) || !extent_on_plane(y, x, nx, axis, ay, scale)) return true;
  double err = bounds::kExtentUlps * std::numeric_limits<double>::epsilon() * scale;
  return !(ax[1] + err < ay[0] - err || ay[1] + err < ax[0] - err);
}

// Extent along `axis` of the part of t on the plane of o (normal n), in doubles; false if
// undecidable.
template <class P>
bool Engine<P>::extent_on_plane(const Tri& t, const Tri& o, const Vec<P>& n, int axis, double out[2], double& scale) const {
  V s[3];
  for (int k = 0; k < 3; ++k) s[k] = dot<P>(n, sub<P>(pt(t.v[k]), pt(o.v[0])));
  out[0] = INFINITY;
  out[1] = -INFINITY;
  // Big: the coordinates as the filter's doubles (X·2^-sigma_, filter_doubles: any scale
  // keeps the test) and the parameter from mantissas and exponents (Big::ratio, within 4 ulps).
  auto coordinate = [&](int g) {
    if constexpr (std::is_same_v<P, Big>) {
      return Xd_[g][axis];
    } else {
      return P::dbl(pt(g)[axis]);
    }
  };
  for (int k = 0; k < 3; ++k) {
    double a = coordinate(t.v[k]);
    if (std::isnan(a)) return false;
    scale = std::max(scale, std::fabs(a));
    int j = (k + 1) % 3;
    int sk = P::sign(s[k]), sj = P::sign(s[j]);
    if (sk == 0) out[0] = std::min(out[0], a), out[1] = std::max(out[1], a);
    if (sk * sj < 0) {
      double u = 0;
      if constexpr (std::is_same_v<P, Big>) {
        u = P::ratio(s[k], V(s[k] - s[j]));
      } else {
        u = P::dbl(s[k]) / (P::dbl(s[k]) - P::dbl(s[j]));
      }
      double b = coordinate(t.v[j]);
      if (std::isnan(b) || !std::isfinite(u)) return false;
      double c = a + u * (b - a);
      out[0] = std::min(out[0], c);
      out[1] = std::max(out[1], c);
    }
  }
  return std::isfinite(out[0]) && std::isfinite(out[1]) && std::isfinite(scale);
}

// Triangle y has vertices strictly on both sides of x's plane (normal *n; Big: from the grid's
// small integers, or for a cut's points from doubles with a bound, then the scaled points), or
// on it (not all on it). Wide: from doubles with a bound, then exact (normal(x) made when n is
// null).
template <class P>
bool Engine<P>::straddles(const Tri& x, const Vec<P>* n, const Tri& y) const {
  int pos = 0, neg_ = 0;
  std::optional<Vec<P>> made;
  const int cap = vertex_cap_.empty() ? -1 : cap_part(x.body, x.face);
  const int lo = voff_[x.body], hi = lo + static_cast<int>(bodies_[x.body]->num_vertices());  // x's body's vertices
  for (int v : y.v) {
    int s = 0;
    if (cap >= 0 && vertex_cap_[v] == cap && v >= lo && v < hi) {
      s = 0;  // a corner of a face of x's cap: in its plane
    } else if constexpr (kFiltered) {
      // Doubles first (orient_filter), then the grid's small integers when x and v are on it
      // (a positive multiple of the scaled points' value), else the scaled points.
      s = orient_filter(Xd_[x.v[0]], Xd_[x.v[1]], Xd_[x.v[2]], Xd_[v]);
      if (s == 2 && !grid_side_sign(x, v, s)) {
        if (!n) n = &made.emplace(normal(x));
        s = P::sign(dot<P>(*n, sub<P>(pt(v), pt(x.v[0]))));
      }
    } else {
      s = P::sign(dot<P>(*n, sub<P>(pt(v), pt(x.v[0]))));
    }
    pos += s > 0;
    neg_ += s < 0;
  }
  if (pos == 3 || neg_ == 3) return false;
  return pos + neg_ > 0;  // all three on the plane: coplanar, no line
}

// Which vertices lie on a section's cap (a corner of one of its faces, hooks_.cap_face): in
// the plane of every face of that cap, which straddles() then knows without arithmetic.
template <class P>
void Engine<P>::mark_cap_vertices() {
  vertex_cap_.clear();
  bool any = false;
  for (const auto& c : hooks_.cap_face) any = any || std::find(c.begin(), c.end(), 1) != c.end();
  if (!any) return;
  vertex_cap_.assign(X_.size(), -1);
  for (std::size_t b = 0; b < bodies_.size() && b < hooks_.cap_face.size(); ++b) {
    const std::vector<char>& cap = hooks_.cap_face[b];
    for (std::size_t f = 0; f < cap.size(); ++f) {
      if (!cap[f]) continue;
      const int part = hooks_.face_part[b][f];
      for (int v : bodies_[b]->faces()[f]) {
        int& at = vertex_cap_[static_cast<std::size_t>(voff_[b] + v)];
        at = at == -1 || at == part ? part : -2;
      }
    }
  }
}

template <class P>
const Point3& Engine<P>::world(int g) const {
  int b = static_cast<int>(std::upper_bound(voff_.begin(), voff_.end(), g) - voff_.begin()) - 1;
  return bodies_[b]->vertices()[g - voff_[b]];
}

template class Engine<Fast>;
template class Engine<Fast40>;
template class Engine<Wide>;
template class Engine<Big>;

}  // namespace hlr::face_route
