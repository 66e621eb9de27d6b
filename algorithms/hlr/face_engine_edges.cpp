// The per-face engine, drawn edges (see face_engine.hpp): which edges of each body are lines
// of the drawing (boundary, silhouette, crease over the threshold, or every edge) and which
// are self-hidden (both faces non-facing, the notes' Stage 1); a crease line that ends goes on
// along its straightest continuation over half the crease angle (docs/design.md, "Crease lines");
// normals and occluder planes in fixed widths when the coordinates allow.
#include <numeric>

#include "algorithms/hlr/face_engine.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/support/parallel_scan.hpp"
#include "kernel/fixed_int.hpp"

namespace hlr::face_route {

// ---- drawn edges
template <class P>
EdgeClasses Engine<P>::classify_edges(int b) {
  const auto& facing = facing_[b];
  const RawVector<BodyEdge>& edges = topo_[b].edges;
  const bool classing = opt_.edges == EdgeSelection::Feature || opt_.classify_all;
  // Shared with other views: every edge's feature class once, for all of them.
  const std::vector<signed char>* feature = keep_ && classing ? &feature_classes(b) : nullptr;
  const auto feature_of = [&](std::size_t i, const EdgeUse& a, const EdgeUse& c) {
    return feature ? static_cast<LineKind>((*feature)[i]) : feature_kind(b, a, c);
  };
  // Each edge classified on every core (-1: not drawn), then the drawn ones appended in order.
  std::vector<signed char> kinds(edges.size()), hidden(edges.size());
  // Per edge: a line whatever the view (a boundary, a crease, a cut, a non-manifold edge), the
  // ends of crease lines are found by.
  const bool continuing = opt_.continue_creases && classing;
  std::vector<char> line(continuing ? edges.size() : 0);
  ParallelLoop(opt_.threads).for_each(edges.size(), 4096, [&](std::size_t i) {
    const BodyEdge& e = edges[i];
    LineKind kind = LineKind::Edge;
    bool self_hidden = false;
    int live[2], n_live = 0;  // uses on non-degenerate faces (the first two)
    for (std::size_t k = 0; k < e.uses.size(); ++k)
      if (!degenerate_[b][e.uses[k].face]) {
        if (n_live < 2) live[n_live] = static_cast<int>(k);
        ++n_live;
      }
    if (n_live == 2) {
      const EdgeUse& a = e.uses[live[0]];
      const EdgeUse& c = e.uses[live[1]];
      int fa = facing[a.face], fc = facing[c.face];
      if (static_cast<std::size_t>(b) < hooks_.face_part.size() && !hooks_.face_part[b].empty()) {
        const std::vector<int>& part = hooks_.face_part[b];
        if (part[a.face] == part[c.face]) {  // inside one face of the model
          kinds[i] = -1;
          return;
        }
        const std::vector<char>& cap = hooks_.cap_face[b];
        if (cap[a.face] || cap[c.face]) {
          if (continuing) line[i] = 1;
          kinds[i] = static_cast<signed char>(LineKind::Cut);
          hidden[i] = solid_[b] && fa < 0 && fc < 0;
          return;
        }
      }
      if (solid_[b]) {
        self_hidden = fa < 0 && fc < 0;
        bool silhouette = (fa > 0) != (fc > 0);
        if (silhouette) kind = LineKind::Silhouette;
      } else {
        // Open surface: a fold in the projection (both faces on one side of the edge).
        int third_a = side_third(b, a), third_c = side_third(b, c);
        if (third_a >= 0 && third_c >= 0 && !opposite_in_projection(voff_[b] + e.u, voff_[b] + e.v, third_a, third_c))
          kind = LineKind::Silhouette;
      }
      if (continuing) {
        const LineKind f = feature_of(i, a, c);
        line[i] = f == LineKind::Crease;
        if (kind == LineKind::Edge) kind = f;
      } else if (kind == LineKind::Edge && classing) {
        kind = feature_of(i, a, c);
      }
    } else if (n_live == 1) {
      kind = LineKind::Boundary;
      if (continuing) line[i] = 1;
    } else {
      kind = LineKind::Crease;  // non-manifold: a feature
      if (continuing) line[i] = 1;
    }
    if (opt_.edges == EdgeSelection::All && !opt_.classify_all && kind != LineKind::Edge) kind = LineKind::Edge;
    else if (opt_.edges == EdgeSelection::Feature && kind == LineKind::Edge) {
      kinds[i] = -1;
      return;
    }
    kinds[i] = static_cast<signed char>(kind);
    hidden[i] = self_hidden;
  });
  if (continuing) continue_creases(b, kinds, hidden, line);
  return EdgeClasses{std::move(kinds), std::move(hidden)};
}

// The drawn edges of body b in order, made a million edges at a time on all cores: each run's
// records in fresh pages touched there. With `spend_topology` (nothing reads the topology's
// edges afterwards) each run's edges are given back as they are read (release_pages), so that
// the records and the edges they are read from do not add up at the engine's peak (an edge
// needs no destructor: freeing the array later reads none of it again).
template <class P>
std::vector<DrawnEdge> Engine<P>::drawn_edges(int b, const EdgeClasses& classes, bool spend_topology) {
  const RawVector<BodyEdge>& edges = topo_[b].edges;
  const std::vector<signed char>& kinds = classes.kinds;
  const ParallelLoop loop(opt_.threads);
  constexpr std::size_t kRun = std::size_t{1} << 20, kBlock = 8192;
  const std::size_t n = edges.size(), n_blocks = (n + kBlock - 1) / kBlock;
  std::vector<std::size_t> at(n_blocks + 1, 0);  // each block's first drawn record
  loop.for_each(n_blocks, 1, [&](std::size_t c) {
    std::size_t k = 0;
    for (std::size_t i = c * kBlock, end = std::min(n, i + kBlock); i < end; ++i) k += kinds[i] >= 0;
    at[c + 1] = k;
  });
  std::partial_sum(at.begin(), at.end(), at.begin());
  std::vector<DrawnEdge> out;
  out.reserve(at.back());  // (address space: each run's pages are touched below)
  for (std::size_t c0 = 0; c0 < n_blocks; c0 += kRun / kBlock) {
    const std::size_t c1 = std::min(n_blocks, c0 + kRun / kBlock), r0 = c0 * kBlock, r1 = std::min(n, c1 * kBlock);
    touch_pages(static_cast<void*>(out.data() + at[c0]), (at[c1] - at[c0]) * sizeof(DrawnEdge), loop);
    out.resize(at[c1]);
    loop.for_each(c1 - c0, 1, [&](std::size_t c) {
      std::size_t k = at[c0 + c];
      for (std::size_t i = (c0 + c) * kBlock, end = std::min(n, i + kBlock); i < end; ++i) {
        if (kinds[i] < 0) continue;
        const BodyEdge& e = edges[i];
        out[k++] = {e.u, e.v, e.uses.empty() ? -1 : e.uses[0].face, e.uses.size() > 1 ? e.uses[1].face : -1, kinds[i], classes.hidden[i] != 0};
      }
    });
    if (spend_topology) release_pages(const_cast<BodyEdge*>(edges.data() + r0), (r1 - r0) * sizeof(BodyEdge));
  }
  return out;
}

// A drawn edge of body b as a segment (its ends borrowed from the body's vertices).
template <class P>
Segment Engine<P>::edge_segment(int b, const DrawnEdge& e) const {
  const Polyhedron& p = *bodies_[b];
  Segment s;
  s.body = b;
  s.line = static_cast<LineKind>(e.kind);
  s.v0 = e.u;
  s.v1 = e.v;
  s.face0 = e.face0;
  s.face1 = e.face1;
  s.borrow_ends(p.vertex_store());
  s.self_hidden = e.self_hidden;
  return s;
}

// The far vertices x and y of two triangles on edge (u, v) lie strictly on opposite sides of
// the edge in the projection.
template <class P>
bool Engine<P>::opposite_in_projection(int u, int v, int x, int y) const {
  Vec<P> m;
  V c;
  side_plane(u, v, m, c);
  return P::sign(dot<P>(m, pt(x)) - c) * P::sign(dot<P>(m, pt(y)) - c) < 0;
}

// Body b's feature class of every edge between two live faces (else -1), as collect_edges
// reads them (an edge inside one face of the model, or on a cap, is not read).
template <class P>
std::vector<signed char> Engine<P>::features(int b) const {
  const RawVector<BodyEdge>& edges = topo_[b].edges;
  std::vector<signed char> out(edges.size(), -1);
  ParallelLoop(opt_.threads).for_each(edges.size(), 4096, [&](std::size_t i) {
    const BodyEdge& e = edges[i];
    int live[2], n_live = 0;
    for (std::size_t k = 0; k < e.uses.size(); ++k)
      if (!degenerate_[b][e.uses[k].face] && n_live++ < 2) live[n_live - 1] = static_cast<int>(k);
    if (n_live == 2) out[i] = static_cast<signed char>(feature_kind(b, e.uses[live[0]], e.uses[live[1]]));
  });
  return out;
}

// The feature classes of body b, made once for every view that shares the engine's work.
template <class P>
const std::vector<signed char>& Engine<P>::feature_classes(int b) {
  Prepared<P>& p = *prep_;
  if (!p.crease || *p.crease != opt_.crease_degrees) {
    p.crease = opt_.crease_degrees;
    p.feature.assign(bodies_.size(), {});
    p.continued.assign(bodies_.size(), {});
  }
  if (p.feature[b].empty() && !topo_[b].edges.empty()) p.feature[b] = features(b);
  return p.feature[b];
}

// A non-silhouette edge between two faces: a crease, a tangent edge or nothing (Edge), by the
// faces' surfaces where the model has them, else by the crease angle.
template <class P>
LineKind Engine<P>::feature_kind(int b, const EdgeUse& a, const EdgeUse& c) const {
  const FaceSurfaces* s = static_cast<std::size_t>(b) < hooks_.surfaces.size() ? hooks_.surfaces[b] : nullptr;
  switch (s ? surface_edge(*s, a.face, c.face) : SurfaceEdge::ByAngle) {
    case SurfaceEdge::Inside:
      return LineKind::Edge;
    case SurfaceEdge::Sharp:
      return LineKind::Crease;
    case SurfaceEdge::Tangent:
      return LineKind::Tangent;
    case SurfaceEdge::ByAngle:
      break;
  }
  return crease(b, a, c, crease_) ? LineKind::Crease : LineKind::Edge;
}

// Face f's normal as triangulate_body put it (turned where the face was turned): the kept one,
// or, from a lazy store, made again from the face's triangle.
template <class P>
Vec<P> Engine<P>::face_normal(int b, int f) const {
  const FaceNormals<P>& store = face_normal_[b];
  if (!store.lazy()) return store.get(static_cast<std::size_t>(f));
  const Face& face = bodies_[b]->faces()[static_cast<std::size_t>(f)];
  const int vo = voff_[b];
  const Vec<P> n = normal(Tri{b, f, {vo + face[0], vo + face[1], vo + face[2]}, {true, true, true}});
  return store.turned(static_cast<std::size_t>(f)) ? neg<P>(n) : n;
}

template <class P>
bool Engine<P>::crease(int b, const EdgeUse& a, const EdgeUse& c, const CreaseAngle& angle) const {
  // Consistently oriented neighbours traverse the edge in opposite directions; otherwise turn one.
  const bool turn = a.forward == c.forward;
  if constexpr (!std::is_same_v<P, Fast> && !std::is_same_v<P, Big>) {  // the filter on doubles before any GMP number
    const std::array<double, 3> x = face_normal_[b].approx(a.face), y0 = face_normal_[b].approx(c.face);
    const double y[3] = {turn ? -y0[0] : y0[0], turn ? -y0[1] : y0[1], turn ? -y0[2] : y0[2]};
    if (const int f = angle.filter(x.data(), y); f >= 0) return f == 1;
  }
  const Vec<P> na = face_normal(b, a.face);
  Vec<P> nc = face_normal(b, c.face);
  if (turn) nc = neg<P>(nc);
  if constexpr (std::is_same_v<P, Fast>) {
    long x[3] = {na[0], na[1], na[2]}, y[3] = {nc[0], nc[1], nc[2]};
    return angle.exceeds(x, y);
  } else {
    if constexpr (std::is_same_v<P, Big>) {  // normals from the grid's small integers: in machine words
      bool words = true;
      for (int k = 0; k < 3; ++k) words = words && mpz_fits_slong_p(na[k].get_mpz_t()) && mpz_fits_slong_p(nc[k].get_mpz_t());
      if (words) {
        long x[3], y[3];
        for (int k = 0; k < 3; ++k) x[k] = mpz_get_si(na[k].get_mpz_t()), y[k] = mpz_get_si(nc[k].get_mpz_t());
        return angle.exceeds(x, y);
      }
    }
    mpz_class x[3] = {P::zc(na[0]), P::zc(na[1]), P::zc(na[2])}, y[3] = {P::zc(nc[0]), P::zc(nc[1]), P::zc(nc[2])};
    return angle.exceeds(x, y);
  }
}

// Whether an edge may continue a crease line: two live faces, not inside one surface of the
// model nor tangent, at more than half the crease angle.
template <class P>
bool Engine<P>::continues(int b, const BodyEdge& e) const {
  int live[2], n = 0;
  for (std::size_t k = 0; k < e.uses.size(); ++k)
    if (!degenerate_[b][e.uses[k].face] && n++ < 2) live[n - 1] = static_cast<int>(k);
  if (n != 2) return false;
  const EdgeUse &a = e.uses[live[0]], &c = e.uses[live[1]];
  if (static_cast<std::size_t>(b) < hooks_.face_part.size() && !hooks_.face_part[b].empty() &&
      hooks_.face_part[b][a.face] == hooks_.face_part[b][c.face])
    return false;
  const FaceSurfaces* s = static_cast<std::size_t>(b) < hooks_.surfaces.size() ? hooks_.surfaces[b] : nullptr;
  if (s && surface_edge(*s, a.face, c.face) != SurfaceEdge::ByAngle) return false;
  return crease(b, a, c, continued_);
}

// A crease line that ends at a vertex (the vertex has one line edge) goes on along the
// straightest edge there that turns less than 45 degrees and meets its faces at more than half
// the crease angle, and so on until it meets another line or finds no such edge (or two
// equally straight ones): the intersection of a cone and a plane is drawn whole where its
// angle falls under the crease angle near the tangent point. Exact (rational dot products);
// independent of the view.
template <class P>
void Engine<P>::continue_creases(int b, std::vector<signed char>& kinds, std::vector<signed char>& hidden, std::vector<char>& line) {
  const RawVector<BodyEdge>& edges = topo_[b].edges;
  std::vector<int> mine;
  const std::vector<int>* added = keep_ ? continued_lines(b, line) : nullptr;
  if (!added) mine = continued_edges(b, line), added = &mine;
  for (int best : *added)
    if (kinds[best] < 0 || kinds[best] == static_cast<signed char>(LineKind::Edge)) {
      kinds[best] = static_cast<signed char>(LineKind::Crease);
      const EdgeUse &a = edges[best].uses[0], &c = edges[best].uses[1];
      hidden[best] = solid_[b] && facing_[b][a.face] < 0 && facing_[b][c.face] < 0;
    }
}

// The edges of body b a crease line goes on along (see continue_creases), in the order they
// are found (`line`, the lines whatever the view, gets them). Independent of the view.
template <class P>
std::vector<int> Engine<P>::continued_edges(int b, std::vector<char>& line) const {
  const RawVector<BodyEdge>& edges = topo_[b].edges;
  const std::size_t nv = bodies_[b]->num_vertices();
  std::vector<int> added;
  std::vector<int> degree(nv);
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (line[i]) ++degree[edges[i].u], ++degree[edges[i].v];
  std::vector<int> ends;
  for (std::size_t v = 0; v < degree.size(); ++v)
    if (degree[v] == 1) ends.push_back(static_cast<int>(v));
  if (ends.empty()) return added;
  const std::vector<Point3>& pts = bodies_[b]->vertices();
  // Each vertex's edges (compressed rows).
  std::vector<int> first(nv + 1), at(2 * edges.size());
  for (const BodyEdge& e : edges) ++first[e.u + 1], ++first[e.v + 1];
  for (std::size_t v = 0; v < nv; ++v) first[v + 1] += first[v];
  std::vector<int> fill(first.begin(), first.end() - 1);
  for (std::size_t i = 0; i < edges.size(); ++i) at[fill[edges[i].u]++] = at[fill[edges[i].v]++] = static_cast<int>(i);
  auto other = [&](int i, int v) { return edges[i].u == v ? edges[i].v : edges[i].u; };
  for (int v : ends) {
    if (degree[v] != 1) continue;  // a line continued from elsewhere reached it
    int came = -1;
    for (int k = first[v]; k < first[v + 1]; ++k)
      if (line[at[k]]) came = at[k];
    for (std::size_t steps = 0; steps < edges.size(); ++steps) {
      const Vector3 d = pts[v] - pts[other(came, v)];
      const Rational dd = dot(d, d);
      int best = -1;
      bool tie = false;
      Rational best_key;
      for (int k = first[v]; k < first[v + 1]; ++k) {
        const int i = at[k];
        if (line[i] || !continues(b, edges[i])) continue;
        const Vector3 e = pts[other(i, v)] - pts[v];
        const Rational de = dot(d, e), ee = dot(e, e);
        if (de <= 0 || 2 * de * de <= dd * ee) continue;  // turns by 45 degrees or more
        const Rational key = de * de / ee;                // |d|² cos²: larger is straighter
        if (best < 0 || key > best_key) best = i, best_key = key, tie = false;
        else if (key == best_key) tie = true;
      }
      if (best < 0 || tie) break;
      line[best] = 1;
      added.push_back(best);
      const int w = other(best, v);
      ++degree[v], ++degree[w];
      if (degree[w] != 1) break;  // it met another line
      came = best;
      v = w;
    }
  }
  return added;
}

// The continued edges of body b, found once for every view that shares the engine's work
// (null: not shared under these options).
template <class P>
const std::vector<int>* Engine<P>::continued_lines(int b, std::vector<char>& line) {
  Prepared<P>& p = *prep_;
  if (!p.crease || *p.crease != opt_.crease_degrees) return nullptr;  // feature_classes sets it
  if (p.feature[b].size() != topo_[b].edges.size()) return nullptr;
  if (!p.continued[b]) p.continued[b] = continued_edges(b, line);
  return &*p.continued[b];
}

// ---- fixed widths (docs/design.md, "Number paths"): on the multi-limb path, when every scaled
// coordinate lies below 2^125, the normals and an orthographic view's occluder planes are made
// in two's complement of fixed widths (kernel/fixed_int.hpp) instead of WideInt's sign and
// size. The numbers are the generic construction's, so are their doubles: nothing downstream
// can tell the two apart.
namespace {

constexpr int kFixedCoordinateBits = 125;  // differences below 2^126: Int128 with a bit free
constexpr int kFixedViewBits = 61;         // an orthographic direction's components

std::array<Int128, 3> diff(const std::array<Int128, 3>& a, const std::array<Int128, 3>& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

}  // namespace

// Whether every coordinate lies below 2^125 (each worker's answer, then all of them), and an
// orthographic direction's components below 2^61.
template <class P>
void Engine<P>::fixed_width() {
  fixed_ = false;
  view_fixed_.reset();
  if constexpr (std::is_same_v<P, Wide>) {
    const ParallelLoop loop(opt_.threads);
    PerWorker<char> wide(loop, 0);
    loop.run(X_.size(), 16384, [&](unsigned w, std::size_t begin, std::size_t end) {
      bool any = false;
      for (std::size_t i = begin; i < end && !any; ++i)
        for (int k = 0; k < 3; ++k) any = any || X_[i][k].bits() > kFixedCoordinateBits;
      if (any) wide[w] = 1;
    });
    for (unsigned w = 0; w < wide.size(); ++w)
      if (wide[w]) return;
    fixed_ = true;
    if (cam_.perspective) return;
    std::array<std::int64_t, 3> d;
    for (int k = 0; k < 3; ++k) {
      if (view_[k].bits() > kFixedViewBits) return;
      d[k] = static_cast<std::int64_t>(view_[k].to_int128());
    }
    view_fixed_ = d;
  }
}

// A vertex's coordinates as 128-bit integers (fixed_: each below 2^125).
template <class P>
std::array<Int128, 3> Engine<P>::fixed_point(int g) const {
  if constexpr (std::is_same_v<P, Wide>) {
    const Vec<P>& x = pt(g);
    return {x[0].to_int128(), x[1].to_int128(), x[2].to_int128()};
  } else {
    (void)g;
    return {};
  }
}

// The normal (B - A) x (C - A) of normal(), in fixed widths (fixed_).
template <class P>
bool Engine<P>::fixed_normal(const Tri& t, Vec<P>& n) const {
  if constexpr (std::is_same_v<P, Wide>) {
    if (!fixed_) return false;
    const std::array<Int128, 3> a = fixed_point(t.v[0]);
    const std::array<FixedInt<4>, 3> f = fixed_cross(diff(fixed_point(t.v[1]), a), diff(fixed_point(t.v[2]), a));
    n = {f[0].to_wide<5>(), f[1].to_wide<5>(), f[2].to_wide<5>()};
    return true;
  } else {
    (void)t, (void)n;
    return false;
  }
}

// The same normal's doubles alone (a lazy store keeps no more), each WideInt::to_double of its
// component: 0 exactly for 0.
template <class P>
bool Engine<P>::fixed_normal_doubles(const Tri& t, std::array<double, 3>& d) const {
  if constexpr (std::is_same_v<P, Wide>) {
    if (!fixed_) return false;
    const std::array<Int128, 3> a = fixed_point(t.v[0]);
    const std::array<FixedInt<4>, 3> f = fixed_cross(diff(fixed_point(t.v[1]), a), diff(fixed_point(t.v[2]), a));
    d = {f[0].to_double(), f[1].to_double(), f[2].to_double()};
    return true;
  } else {
    (void)t, (void)d;
    return false;
  }
}

// shared_edge_planes() in fixed widths (fixed_ and view_fixed_): the normal below 2^253 and
// its value at a vertex below 2^381; a side plane's normal D x e below 2·2^61·2^126 = 2^188 in
// 4 limbs (D's components as 64-bit factors) and its value at a vertex below 3·2^188·2^125 <
// 2^315 in 6; D·n below 2^317 in 6.
template <class P>
bool Engine<P>::fixed_edge_planes(const Tri& t, std::uint8_t closed, Occ& o) const {
  if constexpr (std::is_same_v<P, Wide>) {
    if (!view_fixed_) return false;
    const std::array<Int128, 3> a = fixed_point(t.v[0]), b = fixed_point(t.v[1]), c = fixed_point(t.v[2]);
    const std::array<std::int64_t, 3>& view = *view_fixed_;
    const std::array<Int128, 3> u = diff(b, a), w = diff(c, a);
    const std::array<FixedInt<4>, 3> n = fixed_cross(u, w);
    const std::array<double, 3> nd = {n[0].to_double(), n[1].to_double(), n[2].to_double()};
    const std::array<double, 3> dd = {P::cdbl(view_[0]), P::cdbl(view_[1]), P::cdbl(view_[2])};
    int facing = filtered_sign(nd.data(), 0.0, dd);
    if (facing == 0) facing = fixed_dot(n, {view[0], view[1], view[2]}).sign();
    const bool turn = facing < 0;
    o.through_vertices = true;
    o.turned = 0;
    for (int k = 0; k < 3; ++k) o.m[0][k] = -nd[k];
    o.c[0] = fixed_dot(n, a).negated().to_double();
    const std::array<Int128, 3> edge[3] = {u, diff(c, b), diff(a, c)};
    const std::array<Int128, 3>* from[3] = {&a, &b, &c};
    for (int k = 0; k < 3; ++k) {
      std::array<FixedInt<4>, 3> m = fixed_cross(view, edge[k]);
      FixedInt<6> cm = fixed_dot(m, *from[k]);
      if (turn) {
        for (FixedInt<4>& x : m) x = x.negated();
        cm = cm.negated();
        o.turned |= static_cast<std::uint8_t>(1u << (k + 1));
      }
      for (int j = 0; j < 3; ++j) o.m[k + 1][j] = m[j].to_double();
      o.c[k + 1] = cm.to_double();
      o.closed[k + 1] = !t.edge[k] || (closed >> (k + 1) & 1) != 0;
    }
    return true;
  } else {
    (void)t, (void)closed, (void)o;
    return false;
  }
}

// Constraint k's values m·X - c at the segment's two end vertices, as exact_plane's plane gives
// them, in fixed widths: m·(X - a) for a vertex a on the plane (the face plane through the
// triangle's first vertex, -n: exact_plane's m; side plane k, orthographic, D x (q - p) through
// p, turned as make_occluder turned it). Not where normal() or side_plane() take the grid's
// multiples (every corner on the grid; both of the side's ends), nor for a face plane moved to
// the eye: false, and the caller makes the plane. X - a below 2^126, m below 2^253: the values
// below 2^381 (fixed_dot).
template <class P>
bool Engine<P>::fixed_plane_values(const Occ& o, int k, const std::array<int, 2>& gv, V& f0, V& f1) const {
  if constexpr (std::is_same_v<P, Wide>) {
    if (!fixed_) return false;
    const std::vector<char>& g = prep_->on_grid;
    auto on = [&](int v) { return !g.empty() && g[static_cast<std::size_t>(v)] != 0; };
    std::array<FixedInt<4>, 3> m;
    std::array<Int128, 3> a;
    if (k == 0) {
      if (!o.through_vertices || (on(o.v[0]) && on(o.v[1]) && on(o.v[2]))) return false;
      a = fixed_point(o.v[0]);
      m = fixed_cross(diff(fixed_point(o.v[2]), a), diff(fixed_point(o.v[1]), a));  // -(b - a) x (c - a)
    } else {
      const int p = o.v[k - 1], q = o.v[k % 3];
      if (!view_fixed_ || (on(p) && on(q))) return false;
      a = fixed_point(p);
      m = fixed_cross(*view_fixed_, diff(fixed_point(q), a));
      if (o.turned >> k & 1)
        for (FixedInt<4>& x : m) x = x.negated();
    }
    f0 = fixed_dot(m, diff(fixed_point(gv[0]), a)).template to_wide<10>();
    f1 = fixed_dot(m, diff(fixed_point(gv[1]), a)).template to_wide<10>();
    return true;
  } else {
    (void)o, (void)k, (void)gv, (void)f0, (void)f1;
    return false;
  }
}

template class Engine<Fast>;
template class Engine<Fast40>;
template class Engine<Wide>;
template class Engine<Big>;

}  // namespace hlr::face_route
