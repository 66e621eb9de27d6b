// The per-face engine, drawn edges (see face_engine.hpp): which edges of each body are lines
// of the drawing (boundary, silhouette, crease over the threshold, or every edge) and which
// are self-hidden (both faces non-facing, the notes' Stage 1).
#include "algorithms/face_engine.hpp"

namespace hlr::face_route {

// ---- drawn edges
template <class P>
void Engine<P>::collect_edges(int b, LineDrawing& res) {
  const Polyhedron& p = *bodies_[b];
  const auto& facing = facing_[b];
  for (const BodyEdge& e : topo_[b].edges) {
    LineKind kind = LineKind::Edge;
    bool self_hidden = false;
    std::vector<int> live;  // uses on non-degenerate faces
    for (const EdgeUse& u : e.uses)
      if (!degenerate_[b][u.face]) live.push_back(static_cast<int>(&u - e.uses.data()));
    if (live.size() == 2) {
      const EdgeUse& a = e.uses[live[0]];
      const EdgeUse& c = e.uses[live[1]];
      int fa = facing[a.face], fc = facing[c.face];
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
      if (kind == LineKind::Edge && (opt_.edges == EdgeSelection::Feature || opt_.classify_all) && crease(b, a, c)) kind = LineKind::Crease;
    } else if (live.size() == 1) {
      kind = LineKind::Boundary;
    } else {
      kind = LineKind::Crease;  // non-manifold: a feature
    }
    if (opt_.edges == EdgeSelection::Feature && kind == LineKind::Edge) continue;
    if (opt_.edges == EdgeSelection::All && !opt_.classify_all) kind = LineKind::Edge;
    Segment s;
    s.body = b;
    s.line = kind;
    s.v0 = e.u;
    s.v1 = e.v;
    s.face0 = e.uses.empty() ? -1 : e.uses[0].face;
    s.face1 = e.uses.size() > 1 ? e.uses[1].face : -1;
    s.borrow_ends(p.vertices()[e.u], p.vertices()[e.v]);
    s.self_hidden = self_hidden;
    ++res.stats.edges;
    if (self_hidden) ++res.stats.self_hidden;
    res.segments.push_back(std::move(s));
    gv_.push_back({voff_[b] + e.u, voff_[b] + e.v});
  }
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
