// The per-face engine, occluders (see face_engine.hpp): every front triangle with the sight
// rays behind it bounds a convex sight prism (its plane and three side planes through the view
// direction or the eye); a prism side is closed where the ray just behind that polygon edge is
// inside the solid (or crosses the open surface). Boxes of the projected prisms go into the
// screen grid (screen_grid.hpp), a filter only.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

#include "algorithms/hlr/face_engine.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/support/parallel_scan.hpp"
#include "kernel/error_bounds.hpp"

namespace hlr::face_route {

// Sign of det(q - p, r - p, s - p) from the doubles of the points (each within 2u of the
// exact value, relative; NaN: unknown), or 2 when they cannot tell. Each difference errs by
// at most 3u·(|q| + |p|) (inputs and one rounding), each monomial of three such by 10u times
// the product M of those magnitudes, the six monomials and their sum by under 16u·ΣM: 64u·ΣM
// covers it, and 1e-300 the products that underflow (every nonzero input is at least 2^-1000
// and at most 1, filter_doubles). The determinant is (q - p)·((r - p) x (s - p)), the sign
// of n·(s - p) for the normal n of p, q, r. (Wide: the doubles are the integers themselves,
// nonzero ones at least 1 and below 2^150, so no product overflows or underflows.)
int orient_filter(const std::array<double, 3>& p, const std::array<double, 3>& q, const std::array<double, 3>& r, const std::array<double, 3>& s) {
  double a[3], b[3], c[3], ma[3], mb[3], mc[3];
  for (int k = 0; k < 3; ++k) {
    a[k] = q[k] - p[k], b[k] = r[k] - p[k], c[k] = s[k] - p[k];
    ma[k] = std::fabs(q[k]) + std::fabs(p[k]), mb[k] = std::fabs(r[k]) + std::fabs(p[k]), mc[k] = std::fabs(s[k]) + std::fabs(p[k]);
  }
  const double det = a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  const double mag = ma[0] * (mb[1] * mc[2] + mb[2] * mc[1]) + ma[1] * (mb[2] * mc[0] + mb[0] * mc[2]) + ma[2] * (mb[0] * mc[1] + mb[1] * mc[0]);
  if (!std::isfinite(det) || !std::isfinite(mag)) return 2;
  const double bound = 64 * kUnitRoundoff * mag + 1e-300;
  return det > bound ? 1 : det < -bound ? -1 : 2;
}

FrontBox front_box(const Camera& cam, const Point3* const* pts, const std::array<double, 3>* const* proj,
                   const bool* front, int n) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  FrontBox out{Box{inf, inf, -inf, -inf, -std::numeric_limits<double>::infinity()}, true};
  for (int i = 0; i < n; ++i) {
    if (!front[i]) continue;
    out.empty = false;
    const auto& pr = *proj[i];
    out.box.x0 = std::min(out.box.x0, next_float_down(static_cast<float>(pr[0])));
    out.box.y0 = std::min(out.box.y0, next_float_down(static_cast<float>(pr[1])));
    out.box.x1 = std::max(out.box.x1, next_float_up(static_cast<float>(pr[0])));
    out.box.y1 = std::max(out.box.y1, next_float_up(static_cast<float>(pr[1])));
  }
  if (out.empty) return out;
  // Every edge from a front point to one that is not: where it meets the eye plane.
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (!front[i] || front[j]) continue;
      open_toward(out.box, cam.eye_plane_signs(*pts[i], *pts[j]));
    }
  return out;
}

// ---- occluders
// The neighbour of triangle side (p -> q) across a polygon edge: its face and the opposite
// vertex of its triangle on that edge; false for boundary, non-manifold or degenerate.
template <class P>
bool Engine<P>::neighbour(const Tri& t, int k, int& face, int& third) const {
  const int b = t.body;
  const Face& poly = bodies_[b]->faces()[t.face];
  // Find the polygon position of side k: the position of t.v[k] in the face.
  const int vo = voff_[b];
  int pos = -1;
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (vo + poly[i] == t.v[k] && vo + poly[(i + 1) % poly.size()] == t.v[(k + 1) % 3]) pos = static_cast<int>(i);
  if (pos < 0)  // a flipped (inside-out) solid traverses its sides backwards
    for (std::size_t i = 0; i < poly.size(); ++i)
      if (vo + poly[i] == t.v[(k + 1) % 3] && vo + poly[(i + 1) % poly.size()] == t.v[k]) pos = static_cast<int>(i);
  if (pos < 0) return false;
  const BodyTopology& topo = topo_[b];
  const int slot = topo.face_offset[t.face] + pos;
  int across = -1;    // the face across, then the third vertex of its triangle on the edge
  if (topo.paired) {  // pair_sides: the mates in place of the edges
    across = topo.slot_edge[slot];
    if (!topo.slot_third.empty()) third = topo.slot_third[slot];
    else if (across >= 0 && !degenerate_[b][across]) third = third_off_edge(b, across, t.v[k], t.v[(k + 1) % 3]);
  } else if (const int e = topo.slot_edge[slot]; e >= 0 && topo.edges[e].uses.size() == 2) {
    const BodyEdge& be = topo.edges[e];
    const EdgeUse& other = be.uses[0].slot == slot ? be.uses[1] : be.uses[0];
    across = other.face;
    third = side_third(b, other);
  }
  if (across < 0 || degenerate_[b][across]) return false;
  face = across;
  return third >= 0;
}

// The third vertex (global id) of the triangle on the side of a use: the caller's slot_third,
// or, for a body of triangles that keeps none, the vertex of the use's own face after the
// side's two (-1 for a degenerate face, which has no triangle).
template <class P>
int Engine<P>::side_third(int b, const EdgeUse& use) const {
  const BodyTopology& topo = topo_[b];
  if (!topo.slot_third.empty()) return topo.slot_third[use.slot];
  if (degenerate_[b][use.face]) return -1;
  const Face& f = bodies_[b]->faces()[use.face];
  return voff_[b] + f[(use.slot - topo.face_offset[use.face] + 2) % 3];
}

// The vertex of triangle face `face` of body b (a body of triangles) that is neither end of
// the edge (u, v) (global ids); -1 if none (the face has a repeated vertex).
template <class P>
int Engine<P>::third_off_edge(int b, int face, int u, int v) const {
  for (int x : bodies_[b]->faces()[face])
    if (voff_[b] + x != u && voff_[b] + x != v) return voff_[b] + x;
  return -1;
}

// A large drawing's stages of new arrays begin with the heap's free pages given back
// (release_free_pages): its peak is then about what is in use, not the holes of the stages
// before (docs/design.md, "Memory on huge pages").
template <class P>
void Engine<P>::give_back() const {
  if (large_) release_free_pages();
}

// A vertex hides the sight line just behind it when every face around it faces the viewer
// (solid: all front, so the surface is locally a graph over the image with material behind;
// open surface: all one way and not on the boundary, so the ray crosses it). Faces that are
// edge-on or turn away around a vertex: not closed (a ray along the boundary).
template <class P>
void Engine<P>::vertex_rules() {
  // 0 unset, 1 all facing, 2 all non-facing, 3 mixed or edge-on or boundary: a join (0 with s
  // is s, s with s is s, any other pair 3), so the faces mark on all cores in any order.
  std::vector<char> state(X_.size(), 0);
  auto mark = [&](int g, char st) {
    std::atomic_ref<char> x(state[g]);
    char cur = x.load(std::memory_order_relaxed);
    for (;;) {
      const char next = (cur == 0 || cur == st) ? st : 3;
      if (next == cur || x.compare_exchange_weak(cur, next, std::memory_order_relaxed)) return;
    }
  };
  const ParallelLoop loop(opt_.threads);
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const auto& faces = bodies_[b]->faces();
    loop.for_each(faces.size(), 8192, [&](std::size_t f) {
      int fs = facing_[b][f];
      char st = degenerate_[b][f] || fs == 0 ? 3 : (fs > 0 ? 1 : (solid_[b] && !eye_on_[b] ? 3 : 2));
      for (int v : faces[f]) mark(voff_[b] + v, st);
    });
    const RawVector<BodyEdge>& edges = topo_[b].edges;
    loop.for_each(edges.size(), 8192, [&](std::size_t i) {
      if (edges[i].uses.size() != 2) mark(voff_[b] + edges[i].u, 3), mark(voff_[b] + edges[i].v, 3);
    });
  }
  vertex_closed_.resize(X_.size());
  loop.for_each(X_.size(), 16384, [&](std::size_t g) { vertex_closed_[g] = state[g] == 1 || state[g] == 2; });
}

// Feature lines of a large mesh are few: then only the triangles whose screen box comes near
// some segment's box can hide anything drawn, and only those become occluders. Orthographic
// views only. A filter (it skips work, never decides): every box is widened by
// 4·kBoxMargin·E + 1e-6·E, E the largest projected coordinate (depth included) of any vertex
// or segment end, so two
// widened boxes meet whenever the occluder's box and the segment's box of visibility() can
// (each widened there by at most kBoxMargin·E, rounded outward to floats within 2^-23·E):
// docs/design.md, "Filters". Returns an empty function when it does not apply.
template <class P>
std::function<bool(const Tri&)> Engine<P>::near_segments(const std::vector<std::vector<DrawnEdge>>& drawn, ScreenGrid& grid,
                                                         std::vector<ScreenRect>& rects) const {
  std::size_t n = cross_.size();
  for (const auto& d : drawn) n += d.size();
  if (cam_.perspective || n * 8 >= tris_.size()) return {};
  std::vector<std::array<double, 3>> ends;  // the intersection lines' projected ends
  for (const CrossLine& l : cross_) ends.push_back(proj_.project(std::get<4>(l))), ends.push_back(proj_.project(std::get<5>(l)));
  double ext = 0;
  // E covers the depths too: the margins of visibility() grow with them.
  for (const auto& p : vproj_) ext = std::max({ext, std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])});
  for (const auto& p : ends) ext = std::max({ext, std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])});
  if (!std::isfinite(ext) || ext > 1e30) return {};
  const double w = 4 * bounds::kBoxMargin * ext + 1e-6 * ext + 1e-300;
  auto rect = [w](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return ScreenRect{std::min(a[0], b[0]) - w, std::min(a[1], b[1]) - w, std::max(a[0], b[0]) + w, std::max(a[1], b[1]) + w};
  };
  rects.clear();
  rects.reserve(n);
  for (std::size_t b = 0; b < drawn.size(); ++b)
    for (const DrawnEdge& e : drawn[b]) rects.push_back(rect(vproj_[voff_[b] + e.u], vproj_[voff_[b] + e.v]));
  for (std::size_t k = 0; k < ends.size(); k += 2) rects.push_back(rect(ends[k], ends[k + 1]));
  grid.build(rects, std::vector<char>(rects.size(), 0), 2.0, 2048, opt_.threads);
  return [this, w, &grid, &rects](const Tri& t) {
    ScreenRect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (int v : t.v) {
      const auto& p = vproj_[v];
      r.x0 = std::min(r.x0, p[0]), r.y0 = std::min(r.y0, p[1]), r.x1 = std::max(r.x1, p[0]), r.y1 = std::max(r.y1, p[1]);
    }
    r.x0 -= w, r.y0 -= w, r.x1 += w, r.y1 += w;
    bool meets = false;
    grid.visit(r, [&](int i) { meets = meets || rects[i].meets(r); });
    return meets;
  };
}

// Drawing projections of every vertex, once, on all cores.
template <class P>
void Engine<P>::project_vertices() {
  const ParallelLoop loop(opt_.threads);
  reserve_touched(vproj_, X_.size(), loop);  // fresh pages zeroed on all cores, not by resize alone
  reserve_touched(vfront_, X_.size(), loop);
  vproj_.resize(X_.size());
  vfront_.assign(X_.size(), 1);
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    loop.for_each(bodies_[b]->num_vertices(), 4096, [&](std::size_t i) {
      vproj_[voff_[b] + i] = proj_.project(bodies_[b]->vertex_store(), i);
      if (cam_.perspective) vfront_[voff_[b] + i] = cam_.in_front(bodies_[b]->vertices()[i]) == Sign::Positive;
    });
}

// The triangles that become occluders (counting the ones that hide into hiding_), and which of
// their sides are closed (bit k+1: side k), while the topology is still there.
template <class P>
void Engine<P>::select_occluders(const std::vector<std::vector<DrawnEdge>>& drawn) {
  ScreenGrid seg_grid;
  std::vector<ScreenRect> seg_rects;
  const std::function<bool(const Tri&)> near = near_segments(drawn, seg_grid, seg_rects);
  // Each triangle's state on all cores (0: hides nothing, 1: hides, 2: hides and is taken),
  // then the taken ones in order.
  const ParallelLoop loop(opt_.threads);
  std::vector<char> state(tris_.size(), 0);
  PerWorker<std::size_t> hiding(loop, 0);
  loop.run(tris_.size(), 4096, [&](unsigned w, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const Tri& t0 = tris_[i];
      int fs = facing_[t0.body][t0.face];
      if (fs == 0) continue;  // edge-on: sight rays graze it
      if (static_cast<std::size_t>(t0.body) < hooks_.see_through.size() && hooks_.see_through[t0.body]) continue;  // hides nothing
      if (solid_[t0.body] && fs < 0 && !eye_on_[t0.body]) continue;  // a closed solid is hidden by its front faces
      // No point strictly in front of the eye: its sight cone lies behind the eye, where nothing
      // is drawn (docs/design.md, "Occluders that reach behind the eye").
      if (cam_.perspective && !vfront_[t0.v[0]] && !vfront_[t0.v[1]] && !vfront_[t0.v[2]]) continue;
      ++hiding[w];
      state[i] = 1;
      if (hooks_.may_occlude) {  // a tile: only the triangles that can reach it
        const int o = voff_[t0.body];
        if (!hooks_.may_occlude(t0.body, {t0.v[0] - o, t0.v[1] - o, t0.v[2] - o})) continue;
      }
      if (near && !near(t0)) continue;  // no drawn segment comes near it
      state[i] = 2;
    }
  });
  hiding_ = 0;
  for (unsigned w = 0; w < hiding.size(); ++w) hiding_ += hiding[w];
  const std::vector<std::uint32_t> taken = parallel_select(tris_.size(), [&](std::size_t i) { return state[i] == 2; }, loop);
  sel_.assign(taken.begin(), taken.end());
  closed_.assign(sel_.size(), 0);
  loop.for_each(sel_.size(), 1024, [&](std::size_t i) {
    Tri t = tris_[sel_[i]];
    const int fs = facing_[t.body][t.face];
    if (fs < 0) flip(t);  // as make_occluder turns it
    std::optional<Vec<P>> n;  // the triangle's normal, made once for its sides
    for (int k = 0; k < 3; ++k) {
      if (!t.edge[k]) continue;  // a diagonal: make_occluder closes it
      Vec<P> m;
      V c;
      if (!solid_[t.body]) {  // the open-surface rule reads the side plane, oriented inward
        side_plane(t.v[k], t.v[(k + 1) % 3], m, c);
        if (P::sign(dot<P>(m, pt(t.v[(k + 2) % 3])) - c) < 0) {
          m = neg<P>(m);
          c = -c;
        }
      }
      if (closed_side(t, k, m, c, fs, n)) closed_[i] |= static_cast<std::uint8_t>(1u << (k + 1));
    }
  });
}

// The selected triangles' occluders and boxes, and the grid over the boxes.
template <class P>
void Engine<P>::build_occluders() {
  filter_shift();
  const ParallelLoop loop(opt_.threads);
  std::vector<Box> boxes;
  // A million occluders at a time: each run's pages touched on all cores, then built on all
  // cores; a large drawing (large_: no shared work) gives back the triangles a run spent as it ends
  // (sel_ is in order), so that the triangles and the occluders do not add up at their peak.
  const std::size_t n = sel_.size();
  constexpr std::size_t kRun = std::size_t{1} << 20;
  occ_.reserve(n);  // (address space: each run's pages are touched below)
  boxes.reserve(n);
  std::size_t spent = 0;  // the triangles before this one are given back
  for (std::size_t r0 = 0; r0 < n; r0 += kRun) {
    const std::size_t r1 = std::min(n, r0 + kRun);
    touch_pages(static_cast<void*>(occ_.data() + r0), (r1 - r0) * sizeof(Occ), loop);
    touch_pages(static_cast<void*>(boxes.data() + r0), (r1 - r0) * sizeof(Box), loop);
    occ_.resize(r1);
    boxes.resize(r1);
    loop.for_each(r1 - r0, 1024, [&](std::size_t i) { make_occluder(tris_[sel_[r0 + i]], closed_[r0 + i], occ_[r0 + i], boxes[r0 + i]); });
    if (!large_) continue;
    const auto upto = static_cast<std::size_t>(sel_[r1 - 1]) + 1;
    release_pages(static_cast<void*>(tris_.data() + spent), (upto - spent) * sizeof(Tri));
    spent = upto;
  }
  std::vector<int>().swap(sel_);
  std::vector<std::uint8_t>().swap(closed_);
  if (!keep_) std::vector<Tri>().swap(tris_);  // the triangles' last use: visibility reads the occluders
  // Widen every box by a margin far above the error of the double projections (a filter
  // only: it skips work, never decides; bounds::kBoxMargin).
  // (The largest magnitude per worker, then over the workers: a maximum in any order.)
  std::vector<double> exts(loop.workers(), 1e-300);
  loop.run(boxes.size(), 16384, [&](unsigned w, std::size_t begin, std::size_t end) {
    double ext = exts[w];
    for (std::size_t i = begin; i < end; ++i) {
      const Box& bx = boxes[i];
      for (double v : {static_cast<double>(bx.x0), static_cast<double>(bx.x1), static_cast<double>(bx.y0),
                       static_cast<double>(bx.y1), bx.dmin})
        if (std::isfinite(v)) ext = std::max(ext, std::fabs(v));
    }
    exts[w] = ext;
  });
  const double ext = *std::max_element(exts.begin(), exts.end());
  margin_ = bounds::kBoxMargin * ext;
  loop.for_each(boxes.size(), 16384, [&](std::size_t i) {
    Box& bx = boxes[i];
    bx.x0 -= static_cast<float>(margin_);
    bx.y0 -= static_cast<float>(margin_);
    bx.x1 += static_cast<float>(margin_);
    bx.y1 += static_cast<float>(margin_);
    bx.dmin -= margin_;
  });
  boxes_ = std::move(boxes);
  // Unbounded sides (occluders reaching the eye plane) clamp to the grid's edge cells.
  grid_.build(
      boxes_.size(),
      [&](std::size_t i) {
        return ScreenRect{boxes_[i].x0, boxes_[i].y0, boxes_[i].x1, boxes_[i].y1};
      },
      2.0, 2048, opt_.threads);
}

template <class P>
void Engine<P>::make_occluder(const Tri& t0, std::uint8_t closed, Occ& o, Box& bx) const {
  const int b = t0.body;
  const int fs = facing_[b][t0.face];
  Tri t = t0;
  if (fs < 0) flip(t);  // open surface seen from its back: orient toward the viewer
  o.body = b;
  o.face = t.face;
  o.v = t.v;
  // Constraint 0: strictly behind the plane: -n·(X - a) > 0. A back face of a convex solid
  // whose surface holds the eye hides its whole forward cone from the eye instead (in front
  // of the face too: those points are inside the solid), so the plane moves to the eye:
  // -n·(X - E) > 0. Exact for convex solids (docs/design.md); others are refused.
  const bool to_eye = fs < 0 && solid_[b];
  if constexpr (kFiltered) {
    if (!to_eye && (grid_planes(t, closed, o) || local_planes(t, closed, o) || shared_edge_planes(t, closed, o))) {
      occluder_box(t, fs, bx);
      return;
    }
  }
  const Vec<P> n = normal(t);
  // Each side plane is turned to hold the third vertex on its positive side. For side k the
  // value at the third vertex r is det(D, q - p, r - p) = D·n (orthographic, D the view
  // direction), or det(p - E, q - E, r - E) = (p - E)·n = (a - E)·n for any vertex a
  // (perspective): the same sign for the three sides, computed once.
  const bool turn = P::sign(cam_.perspective ? dot<P>(n, sub<P>(pt(t.v[0]), view_)) : dot<P>(n, view_)) < 0;
  Vec<P> m0 = neg<P>(n);
  V c0 = to_eye ? dot<P>(m0, view_) : dot<P>(m0, pt(t.v[0]));
  if constexpr (kFiltered) {
    o.through_vertices = !to_eye;
    o.turned = 0;
    plane_doubles(m0, c0, o.m[0], o.c[0]);
  } else {
    o.through_vertices = !to_eye;
    o.m[0] = std::move(m0);
  }
  for (int k = 0; k < 3; ++k) {
    Vec<P> m;
    V c;
    side_plane(t.v[k], t.v[(k + 1) % 3], m, c);
    if (turn) {
      m = neg<P>(m);
      c = -c;
    }
    if constexpr (kFiltered) {
      if (turn) o.turned |= static_cast<std::uint8_t>(1u << (k + 1));
      plane_doubles(m, c, o.m[k + 1], o.c[k + 1]);
    } else {
      o.m[k + 1] = m;  // c = m·v[k] (side_plane: through p, and the eye's plane holds p)
    }
    o.closed[k + 1] = !t.edge[k] || (closed >> (k + 1) & 1) != 0;
  }
  occluder_box(t, fs, bx);
}

// A triangle on the grid (and the eye on it, or a small direction): the face plane and side
// planes' doubles from the grid's small integers (grid_doubles) without their exact values,
// which exact_plane makes when a test needs them; false when the grid cannot give them.
template <class P>
bool Engine<P>::grid_planes(const Tri& t, std::uint8_t closed, Occ& o) const {
  if constexpr (kFiltered) {
    std::array<Int128, 3> n, side[3];
    if (!grid_normal(t, n)) return false;
    for (int k = 0; k < 3; ++k)
      if (!grid_side(t.v[k], t.v[(k + 1) % 3], side[k])) return false;
    // The side planes' value at the third vertex, D·n or (a - E)·n (make_occluder), on the grid.
    std::array<Int128, 3> toward;
    const auto& a = prep_->small[t.v[0]];
    for (int k = 0; k < 3; ++k) toward[k] = cam_.perspective ? Int128(a[k]) - (*eye_small_)[k] : (*view_small_)[k];
    WideInt<4> d;
    for (int k = 0; k < 3; ++k) d += WideInt<4>::product(WideInt<4>(n[k]), WideInt<4>(toward[k]));
    const bool turn = d.sign() < 0;
    o.through_vertices = true;
    o.turned = 0;
    grid_doubles({-n[0], -n[1], -n[2]}, a, false, o.m[0], o.c[0]);
    for (int k = 0; k < 3; ++k) {
      grid_doubles(side[k], cam_.perspective ? *eye_small_ : prep_->small[t.v[k]], turn, o.m[k + 1], o.c[k + 1]);
      if (turn) o.turned |= static_cast<std::uint8_t>(1u << (k + 1));
      o.closed[k + 1] = !t.edge[k] || (closed >> (k + 1) & 1) != 0;
    }
    return true;
  }
  return false;
}

// GMP path, orthographic, a triangle off the grid (a cut's split points): the face plane and
// side planes' doubles from each corner's own integers instead of the scaled points, whose
// common denominator L can have thousands of bits. A corner p = p_n / d (d > 0 the lowest
// common denominator of its coordinates) is X = p_n·(L / d). With u = q_n·d_p - p_n·d_q
// (for q - p, times d_p·d_q) the planes through p are positive multiples of make_occluder's:
// the normal u × w (w the same for r), side k's D × u, each constant m·X = (m·p_n)·(L / d_p),
// one product with the long factor; plane_doubles reads them as it reads make_occluder's, and
// exact_plane makes the exact ones when a test needs them. False where it does not apply.
template <class P>
bool Engine<P>::local_planes(const Tri& t, std::uint8_t closed, Occ& o) const {
  if constexpr (std::is_same_v<P, Big>) {
    if (cam_.perspective || mpz_cmp_ui(scale_.get_den_mpz_t(), 1) != 0) return false;
    const mpz_class& L = scale_.get_num();
    mpz_class pn[3][3], d[3], Ld[3];
    for (int i = 0; i < 3; ++i) {
      const Point3& w = world(t.v[i]);
      d[i] = 1;
      for (int k = 0; k < 3; ++k) mpz_lcm(d[i].get_mpz_t(), d[i].get_mpz_t(), w[k].get_den_mpz_t());
      if (!mpz_divisible_p(L.get_mpz_t(), d[i].get_mpz_t())) return false;
      mpz_divexact(Ld[i].get_mpz_t(), L.get_mpz_t(), d[i].get_mpz_t());
      for (int k = 0; k < 3; ++k) {
        mpz_divexact(pn[i][k].get_mpz_t(), d[i].get_mpz_t(), w[k].get_den_mpz_t());
        pn[i][k] *= w[k].get_num();
      }
    }
    auto diff = [&](int a, int b) {  // (corner b - corner a)·d_a·d_b
      Vec<P> u;
      for (int k = 0; k < 3; ++k) u[k] = pn[b][k] * d[a] - pn[a][k] * d[b];
      return u;
    };
    auto constant = [&](const Vec<P>& m, int a) { return V(dot<P>(m, Vec<P>{pn[a][0], pn[a][1], pn[a][2]}) * Ld[a]); };
    const Vec<P> n = cross<P>(diff(0, 1), diff(0, 2));
    const bool turn = P::sign(dot<P>(n, view_)) < 0;
    const Vec<P> m0 = neg<P>(n);
    o.through_vertices = true;
    o.turned = 0;
    plane_doubles(m0, constant(m0, 0), o.m[0], o.c[0]);
    for (int k = 0; k < 3; ++k) {
      Vec<P> m = cross<P>(view_, diff(k, (k + 1) % 3));
      if (turn) m = neg<P>(m);
      plane_doubles(m, constant(m, k), o.m[k + 1], o.c[k + 1]);
      if (turn) o.turned |= static_cast<std::uint8_t>(1u << (k + 1));
      o.closed[k + 1] = !t.edge[k] || (closed >> (k + 1) & 1) != 0;
    }
    return true;
  } else {
    (void)t, (void)closed, (void)o;
    return false;
  }
}

// Wide, orthographic, no corner on the grid: make_occluder's planes' doubles with the edge
// vectors made once for the normal and the side planes (side k: D x (q - p), through p, the
// same numbers as normal's and side_plane's), and the turn of the side planes (the sign of n·D) from the
// doubles when filtered_sign decides it (the normal's doubles and the direction's, integers
// within 2^-52 each, c = 0). False where it does not apply.
template <class P>
bool Engine<P>::shared_edge_planes(const Tri& t, std::uint8_t closed, Occ& o) const {
  if constexpr (std::is_same_v<P, Wide>) {
    const std::vector<char>& g = prep_->on_grid;
    if (cam_.perspective || (!g.empty() && (g[t.v[0]] || g[t.v[1]] || g[t.v[2]]))) return false;  // (side_plane's grid pairs)
    if (fixed_edge_planes(t, closed, o)) return true;
    const Vec<P>&a = pt(t.v[0]), &b = pt(t.v[1]), &c = pt(t.v[2]);
    const Vec<P> u = sub<P>(b, a), w = sub<P>(c, a);
    const Vec<P> n = cross<P>(u, w);
    const std::array<double, 3> nd = {P::cdbl(n[0]), P::cdbl(n[1]), P::cdbl(n[2])};
    const std::array<double, 3> dd = {P::cdbl(view_[0]), P::cdbl(view_[1]), P::cdbl(view_[2])};
    int facing = filtered_sign(nd.data(), 0.0, dd);
    if (facing == 0) facing = P::sign(dot<P>(n, view_));
    const bool turn = facing < 0;
    o.through_vertices = true;
    o.turned = 0;
    for (int k = 0; k < 3; ++k) o.m[0][k] = -nd[k];
    o.c[0] = P::dbl(dot<P>(neg<P>(n), a));
    const Vec<P> edge[3] = {u, sub<P>(c, b), neg<P>(w)};
    const Vec<P>* from[3] = {&a, &b, &c};
    for (int k = 0; k < 3; ++k) {
      Vec<P> m = cross<P>(view_, edge[k]);
      V cm = dot<P>(m, *from[k]);
      if (turn) {
        m = neg<P>(m);
        cm = -cm;
        o.turned |= static_cast<std::uint8_t>(1u << (k + 1));
      }
      plane_doubles(m, cm, o.m[k + 1], o.c[k + 1]);
      o.closed[k + 1] = !t.edge[k] || (closed >> (k + 1) & 1) != 0;
    }
    return true;
  } else {
    (void)t, (void)closed, (void)o;
    return false;
  }
}

// The occluder's screen box and nearest depth.
template <class P>
void Engine<P>::occluder_box(const Tri& t, int fs, Box& bx) const {
  const Point3* pts[3];
  const std::array<double, 3>* proj[3];
  bool front[3];
  for (int k = 0; k < 3; ++k) {
    proj[k] = &vproj_[t.v[k]];
    front[k] = vfront_[t.v[k]];
  }
  for (int k = 0; k < 3; ++k)  // the exact corners only where one is not in front (front_box)
    pts[k] = front[0] && front[1] && front[2] ? nullptr : &world(t.v[k]);
  bx = front_box(cam_, pts, proj, front, 3).box;
  if (front[0] && front[1] && front[2])
    bx.dmin = std::min({(*proj[0])[2], (*proj[1])[2], (*proj[2])[2]});
  // A forward cone from the eye (back face of a solid holding the eye) reaches in front of its
  // face: no depth pruning (its projection is still the face's).
  if (fs < 0 && solid_[t.body]) bx.dmin = -INFINITY;
}

// Is the sight ray just behind the polygon edge under side k inside the body (closed side)?
template <class P>
bool Engine<P>::closed_side(const Tri& t, int k, const Vec<P>& m, const V& c, int fs, std::optional<Vec<P>>& n) const {
  int g = -1, third = -1;
  if (!neighbour(t, k, g, third)) return false;
  const int b = t.body;
  if (solid_[b]) {
    // Wedge: where the neighbour's far vertex lies against this face's plane. A front face hides
    // the ray just behind the edge when the wedge holds it; a back face (an occluder only when
    // the eye is on the surface; `t` is turned, its normal points inward) when the wedge holds
    // the ray just beyond the edge, toward the eye: the mirror rule.
    const int w = wedge_side(t, g, third, n);
    if (fs > 0) {
      if (w > 0) return true;            // reflex edge: the wedge holds the ray
      return facing_[b][g] > 0;          // convex or flat: both faces toward the viewer
    }
    if (w < 0) return true;              // reflex edge
    return facing_[b][g] < 0;            // convex or flat: both faces away from the viewer
  }
  // Open surface: the neighbour continues on the other side of the edge in the projection.
  return P::sign(dot<P>(m, pt(third)) - c) < 0;
}

// Sign of det(B - A, C - A, X - A) for triangle t = ABC and the far vertex X of its
// neighbour g (face of the same body), exact: the same cap (both faces of one section's cap,
// in its plane: 0 without arithmetic), the doubles' filter (orient_filter), the grid's small
// integers (a positive multiple of the scaled points' value), or the scaled points.
template <class P>
int Engine<P>::wedge_side(const Tri& t, int g, int third, std::optional<Vec<P>>& n) const {
  if constexpr (kFiltered) {
    const int part = cap_part(t.body, t.face);
    if (part >= 0 && cap_part(t.body, g) == part) return 0;
    const int w = orient_filter(Xd_[t.v[0]], Xd_[t.v[1]], Xd_[t.v[2]], Xd_[third]);
    if (w != 2) return w;
    int s = 0;
    if (grid_side_sign(t, third, s)) return s;
  }
  if (!n) n = normal(t);
  return P::sign(dot<P>(*n, sub<P>(pt(third), pt(t.v[0]))));
}

// Constraint k of a lazy occluder, exact, as make_occluder made it: the face plane (turned
// toward the viewer, through the triangle or moved to the eye), or side plane k, turned where
// make_occluder turned it.
template <class P>
void Engine<P>::exact_plane(const Occ& o, int k, Vec<P>& m, V& c) const {
  if constexpr (kFiltered) {
    if (k == 0) {
      m = neg<P>(normal(Tri{o.body, o.face, o.v, {true, true, true}}));
      c = o.through_vertices ? dot<P>(m, pt(o.v[0])) : dot<P>(m, view_);
      return;
    }
    side_plane(o.v[k - 1], o.v[k % 3], m, c);
    if (o.turned >> k & 1) {
      m = neg<P>(m);
      c = -c;
    }
  } else {
    m = o.m[k];
    c = dot<P>(m, plane_point(o, k));
  }
}

// The plane through vertices p and q containing the view direction (orthographic) or the eye
// (perspective), as m·X - c = 0; its orientation is the caller's to fix.
//
// Wide and Big, p and q on the grid (and the eye, in perspective): the same plane divided by
// scale / G (orthographic) or its square (perspective), from the grid's small integers:
// m = D x (q - p) or (p - E) x (q - E) on them, c = (scale / G)·(m·p) or (m·E). (Wide: m
// below 2^(kBits + 64), m·p below 2^(kBits + 127), times scale / G below 2^(2 kBits + 127).)
template <class P>
void Engine<P>::side_plane(int p, int q, Vec<P>& m, V& c) const {
  if constexpr (kFiltered) {
    const std::vector<char>& g = prep_->on_grid;
    if (!g.empty() && g[p] && g[q] && (!cam_.perspective || eye_small_)) {
      const auto &a = prep_->small[p], &b = prep_->small[q];
      std::array<Int128, 3> sm;
      if (grid_side(p, q, sm)) {
        m = {from128<P>(sm[0]), from128<P>(sm[1]), from128<P>(sm[2])};
      } else {
        const Vec<P> d = {C(static_cast<long>(b[0] - a[0])), C(static_cast<long>(b[1] - a[1])), C(static_cast<long>(b[2] - a[2]))};  // below 2^62
        m = cross<P>(view_, d);
      }
      const auto& base = cam_.perspective ? *eye_small_ : a;
      const Vec<P> o = {C(static_cast<long>(base[0])), C(static_cast<long>(base[1])), C(static_cast<long>(base[2]))};
      if constexpr (std::is_same_v<P, Big>) {
        c = dot<P>(m, o) * grid_factor_;
      } else {
        c = V::product(dot<P>(m, o), grid_factor_);
      }
      return;
    }
  }
  if (cam_.perspective) {
    m = cross<P>(sub<P>(pt(p), view_), sub<P>(pt(q), view_));
    c = dot<P>(m, view_);
  } else {
    m = cross<P>(view_, sub<P>(pt(q), pt(p)));
    c = dot<P>(m, pt(p));
  }
}

// Side plane (p, q)'s m from the grid's small integers in 128 bits, when p and q are on the grid
// and so is the eye (perspective: (p - E) x (q - E)) or the direction is small (D x (q - p));
// every factor below 2^62, each product below 2^124.
template <class P>
bool Engine<P>::grid_side(int p, int q, std::array<Int128, 3>& m) const {
  const std::vector<char>& g = prep_->on_grid;
  if (g.empty() || !g[p] || !g[q]) return false;
  const auto &a = prep_->small[p], &b = prep_->small[q];
  Int128 u[3], w[3];
  if (cam_.perspective) {
    if (!eye_small_) return false;
    const auto& e = *eye_small_;
    for (int k = 0; k < 3; ++k) u[k] = Int128(a[k]) - e[k], w[k] = Int128(b[k]) - e[k];
  } else {
    if (!view_small_) return false;
    for (int k = 0; k < 3; ++k) u[k] = (*view_small_)[k], w[k] = Int128(b[k]) - a[k];
  }
  m = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  return true;
}

// The filter's doubles (plane_doubles' form) of the plane m·X - c with c = (scale / G)·(m·o),
// m and o from the grid's small integers (|m| below 2^126, |o| below 2^62), negated when
// `turn`: m·o exact in limbs, then its double times that of scale / G. c is within 5u of its
// exact value (the two doubles within 2u and u + 2^-64, their product rounded: below 4.01u);
// filtered_sign allows it.
template <class P>
void Engine<P>::grid_doubles(const std::array<Int128, 3>& m, const std::array<std::int64_t, 3>& o, bool turn, double* dm, double& dc) const {
  WideInt<4> d;
  for (int k = 0; k < 3; ++k) d += WideInt<4>::product(WideInt<4>(m[k]), WideInt<4>(static_cast<long>(o[k])));
  const double sgn = turn ? -1.0 : 1.0;
  if constexpr (std::is_same_v<P, Big>) {  // m·2^-e, c·2^-(e + sigma_)
    Int128 top = 0;
    for (int k = 0; k < 3; ++k) top = std::max(top, abs128(m[k]));
    const int e = bit_length(top);
    for (int k = 0; k < 3; ++k) dm[k] = sgn * std::ldexp(static_cast<double>(m[k]), -e);
    dc = sgn * std::ldexp(grid_factor_mant_ * d.to_double(), static_cast<int>(std::max<long>(grid_factor_exp_ - e - sigma_, -4000)));
  } else {
    for (int k = 0; k < 3; ++k) dm[k] = sgn * static_cast<double>(m[k]);
    dc = sgn * std::ldexp(grid_factor_mant_ * d.to_double(), static_cast<int>(grid_factor_exp_));
  }
}

template class Engine<Fast>;
template class Engine<Fast40>;
template class Engine<Wide>;
template class Engine<Big>;

}  // namespace hlr::face_route
