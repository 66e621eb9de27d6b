// The per-face engine, drawn edges (see face_engine.hpp): which edges of each body are lines
// of the drawing (boundary, silhouette, crease over the threshold, or every edge) and which
// are self-hidden (both faces non-facing, the notes' Stage 1).
#include "algorithms/hlr/face_engine.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/support/parallel_scan.hpp"

namespace hlr::face_route {

// ---- drawn edges
template <class P>
std::vector<DrawnEdge> Engine<P>::collect_edges(int b) const {
  const auto& facing = facing_[b];
  const RawVector<BodyEdge>& edges = topo_[b].edges;
  // Each edge classified on every core (-1: not drawn), then the drawn ones appended in order.
  std::vector<signed char> kinds(edges.size()), hidden(edges.size());
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
        int third_a = topo_[b].slot_third[a.slot], third_c = topo_[b].slot_third[c.slot];
        if (third_a >= 0 && third_c >= 0 && !opposite_in_projection(voff_[b] + e.u, voff_[b] + e.v, third_a, third_c))
          kind = LineKind::Silhouette;
      }
      if (kind == LineKind::Edge && (opt_.edges == EdgeSelection::Feature || opt_.classify_all)) kind = feature_kind(b, a, c);
    } else if (n_live == 1) {
      kind = LineKind::Boundary;
    } else {
      kind = LineKind::Crease;  // non-manifold: a feature
    }
    if (opt_.edges == EdgeSelection::All && !opt_.classify_all && kind != LineKind::Edge) kind = LineKind::Edge;
    else if (opt_.edges == EdgeSelection::Feature && kind == LineKind::Edge) {
      kinds[i] = -1;
      return;
    }
    kinds[i] = static_cast<signed char>(kind);
    hidden[i] = self_hidden;
  });
  // The drawn ones in order, on all cores.
  const ParallelLoop loop(opt_.threads);
  const std::vector<std::uint32_t> drawn = parallel_select(edges.size(), [&](std::size_t i) { return kinds[i] >= 0; }, loop);
  std::vector<DrawnEdge> out;
  reserve_touched(out, drawn.size(), loop);
  out.resize(drawn.size());
  loop.for_each(drawn.size(), 8192, [&](std::size_t k) {
    const std::uint32_t i = drawn[k];
    const BodyEdge& e = edges[i];
    out[k] = {e.u, e.v, e.uses.empty() ? -1 : e.uses[0].face, e.uses.size() > 1 ? e.uses[1].face : -1, kinds[i], hidden[i] != 0};
  });
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
  s.borrow_ends(p.vertices());
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
  return P::sign(dot<P>(m, X_[x]) - c) * P::sign(dot<P>(m, X_[y]) - c) < 0;
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
  return crease(b, a, c) ? LineKind::Crease : LineKind::Edge;
}

template <class P>
bool Engine<P>::crease(int b, const EdgeUse& a, const EdgeUse& c) const {
  // Consistently oriented neighbours traverse the edge in opposite directions; otherwise turn one.
  const Vec<P>& na = face_normal_[b][a.face];
  Vec<P> nc = a.forward != c.forward ? face_normal_[b][c.face] : neg<P>(face_normal_[b][c.face]);
  if constexpr (std::is_same_v<P, Fast>) {
    long x[3] = {na[0], na[1], na[2]}, y[3] = {nc[0], nc[1], nc[2]};
    return crease_.exceeds(x, y);
  } else {
    mpz_class x[3] = {P::zc(na[0]), P::zc(na[1]), P::zc(na[2])}, y[3] = {P::zc(nc[0]), P::zc(nc[1]), P::zc(nc[2])};
    return crease_.exceeds(x, y);
  }
}

template class Engine<Fast>;
template class Engine<Fast40>;
template class Engine<Big>;

}  // namespace hlr::face_route
