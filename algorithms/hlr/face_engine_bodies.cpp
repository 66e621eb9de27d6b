// The per-face engine, bodies (see face_engine.hpp): triangles of every face, facing of
// every face (facing.hpp), which bodies are closed solids (body_topology.hpp), inside-out
// solids turned, an eye inside a solid refused.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numeric>

#include "algorithms/hlr/face_engine.hpp"
#include "algorithms/model/facing.hpp"
#include "algorithms/solids/convexity.hpp"
#include "algorithms/solids/face_triangles.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/support/parallel_scan.hpp"
#include "algorithms/support/union_find.hpp"
#include "kernel/error_bounds.hpp"

namespace hlr::face_route {
namespace {

// All vertices of all bodies, for the drawing frame of the filters' projections.
DrawingFrame frame_of(const std::vector<const Polyhedron*>& bodies) {
  std::vector<StorePoints> pts;
  for (const Polyhedron* p : bodies) pts.push_back({&p->vertex_store(), nullptr});
  return drawing_frame(pts);
}

}  // namespace

template <class P>
Engine<P>::Engine(const std::vector<const Polyhedron*>& bodies, const Camera& cam, const LineOptions& opt, const FaceRouteHooks& hooks,
                  std::shared_ptr<Prepared<P>> prep, Vec<P> view, bool keep)
    : bodies_(bodies),
      cam_(cam),
      opt_(opt),
      hooks_(hooks),
      prep_(std::move(prep)),
      keep_(keep),
      X_(prep_->X),
      view_(std::move(view)),
      scale_(prep_->scale),
      proj_(cam, frame_of(bodies)),
      crease_(opt.crease_degrees),
      continued_(opt.crease_degrees / 2),
      solid_(prep_->solid),
      flipped_(prep_->flipped),
      topo_(prep_->topo),
      degenerate_(prep_->degenerate),
      face_normal_(prep_->face_normal),
      tris_(prep_->tris) {}

template <class P>
LineDrawing Engine<P>::run() {
  LineDrawing res;
  res.stats.method = Method::Faces;
  res.stats.faces.emplace();
  res.stats.faces->integer_path = !std::is_same_v<P, Big>;
  using Clock = std::chrono::steady_clock;
  auto t0 = Clock::now();
  offsets();
  grid_view();
  fixed_width();
  std::size_t faces = 0;
  for (const Polyhedron* p : bodies_) faces += p->num_faces();
  large_ = !keep_ && faces >= kLargeArrays;
  // The view-independent work once (or from a view before), then this view's facing and checks.
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    if (!prep_->done) prepare_body(static_cast<int>(b));
    view_body(static_cast<int>(b), res);
  }
  prep_->done = true;
  if (hooks_.facing_only) {
    res.stats.setup_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return res;
  }
  // Every edge classified; then the topology keeps only each side's mate (the face normals
  // freed), the drawn edges are read off its edges as compact records (a large drawing gives
  // each run of edges back as it is read), the occluders' closed sides are read off the mates, and it is freed:
  // before the intersection lines' broad phase when the occluders do not depend on those lines
  // (no feature-line filter), else after it. (give_back before visibility: the peak is what
  // is in use. Before the topology, the drawn edges and the occluders the peak was the same
  // without it, and the pages given back cost their zeroing again.)
  std::vector<EdgeClasses> classes(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (!hooks_.extra_only) classes[b] = classify_edges(static_cast<int>(b));
  vertex_rules();
  if (!keep_) {  // from here only the drawn records and neighbour() read the topology, and no face normal is read
    for (BodyTopology& t : topo_) pair_sides(t, opt_.threads, false);
    std::vector<FaceNormals<P>>().swap(face_normal_);
  }
  std::vector<std::vector<DrawnEdge>> drawn(bodies_.size());
  std::size_t total = 0;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    if (!hooks_.extra_only) drawn[b] = drawn_edges(static_cast<int>(b), classes[b], large_);
    classes[b] = EdgeClasses{};
    if (!keep_) RawVector<BodyEdge>().swap(topo_[b].edges);
    total += drawn[b].size();
  }
  project_vertices();
  if constexpr (kFiltered) filter_shift(), filter_doubles();         // the intersections' filters read them
  const bool early = cam_.perspective || total * 8 >= tris_.size();  // near_segments() would not apply
  auto free_topology = [&] {
    if (keep_) return;
    std::vector<BodyTopology>().swap(topo_);
  };
  if (early) select_occluders(drawn), free_topology();
  const auto ti0 = Clock::now();
  if (opt_.intersections && prep_->cross) {  // found by a view before
    cross_ = *prep_->cross;
    res.stats.faces->intersection_pairs = prep_->intersection_pairs;
  } else if (opt_.intersections) {
    find_intersections(res);
    if (keep_) prep_->cross = cross_, prep_->intersection_pairs = res.stats.faces->intersection_pairs;
  }
  const std::size_t n_crossing = cross_.size();
  for (const auto& x : hooks_.extra_lines) cross_.emplace_back(x.body, x.body, x.face, x.face, x.a, x.b);
  const auto ti1 = Clock::now();
  if (!early) select_occluders(drawn), free_topology();
  total += cross_.size();
  build_occluders();
  give_back();                           // the occluders' making left holes beside the arrays visibility reads
  res.stats.faces->occluders = hiding_;  // a tile's too: every hiding triangle of the scene
  std::vector<Segment> crossing = crossing_segments(res);
  for (std::size_t k = n_crossing; k < crossing.size(); ++k) {
    crossing[k].line = hooks_.extra_lines[k - n_crossing].kind;
    --res.stats.intersection_segments;
  }
  auto t1 = Clock::now();
  // Visibility runs on the compact records; the segments are made once the occluders, the grid
  // and the triangles are freed, so that they do not add to the engine's peak.
  std::vector<PieceList> pieces = visibility(drawn, crossing, res);
  release_arrays();
  make_segments(drawn, std::move(pieces), crossing, total, res);
  auto t3 = Clock::now();
  res.stats.setup_seconds = std::chrono::duration<double>((t1 - t0) - (ti1 - ti0)).count();
  res.stats.intersections_seconds = std::chrono::duration<double>(ti1 - ti0).count();
  res.stats.visibility_seconds = std::chrono::duration<double>(t3 - t1).count();
  return res;
}

template <class P>
void Engine<P>::offsets() {
  int o = 0;
  for (const Polyhedron* p : bodies_) {
    voff_.push_back(o);
    o += static_cast<int>(p->num_vertices());
  }
  eye_on_.assign(bodies_.size(), 0);
  facing_.resize(bodies_.size());
  if (prep_->done) return;
  // Anything a view left half made (it failed) is made again.
  Prepared<P>& p = *prep_;
  p.solid.assign(bodies_.size(), false);
  p.degenerate.assign(bodies_.size(), {});
  p.face_normal.assign(bodies_.size(), {});
  p.facing_at.assign(bodies_.size(), {});
  p.topo = std::vector<BodyTopology>(bodies_.size());
  p.tris.clear();
  p.first_tri.assign(bodies_.size(), 0);
  p.flipped.clear();
  p.notes.clear();
  p.crease.reset();
  p.feature.clear();
  p.continued.clear();
  p.cross.reset();
}

template <class P>
void Engine<P>::grid_view() {
  if constexpr (kFiltered) {
    if (prep_->on_grid.empty()) return;
    const mpz_class G(static_cast<unsigned long>(prep_->grid));
    mpz_class K;
    mpz_divexact(K.get_mpz_t(), scale_.get_num_mpz_t(), G.get_mpz_t());  // scale is an integer, G divides it
    grid_factor_mant_ = mpz_get_d_2exp(&grid_factor_exp_, K.get_mpz_t());
    if constexpr (std::is_same_v<P, Big>) {
      grid_factor_ = std::move(K);
    } else {
      grid_factor_ = C(K.get_mpz_t());  // below the coordinates' bound: scale is, G >= 1
    }
    eye_small_.reset();
    view_small_.reset();
    if (!cam_.perspective) {
      std::array<Int128, 3> d;
      for (int k = 0; k < 3; ++k) {
        const mpz_class z = P::zc(view_[k]);
        if (mpz_sizeinbase(z.get_mpz_t(), 2) > 61) return;
        d[k] = mpz_get_si(z.get_mpz_t());
      }
      view_small_ = d;
      return;
    }
    std::array<std::int64_t, 3> e;
    for (int k = 0; k < 3; ++k) {
      const Rational& q = cam_.eye[k];
      if (!mpz_fits_ulong_p(q.get_den_mpz_t()) || prep_->grid % mpz_get_ui(q.get_den_mpz_t()) != 0) return;  // off the grid
      Int128 v;
      if (!scaled_integer(q, prep_->grid, Int128(1) << 61, v)) return;
      e[k] = static_cast<std::int64_t>(v);
    }
    eye_small_ = e;
  }
}

template <class P>
bool Engine<P>::on_grid(const Tri& t) const {
  const std::vector<char>& g = prep_->on_grid;
  return !g.empty() && g[t.v[0]] && g[t.v[1]] && g[t.v[2]];
}

// The normal (B - A) x (C - A), or a positive multiple of it: on the grid's small integers
// when every corner is on it (Prepared::small: differences below 2^62, each product below
// 2^124, each component below 2^125, exact in 128 bits).
template <class P>
Vec<P> Engine<P>::normal(const Tri& t) const {
  if constexpr (kFiltered) {
    std::array<Int128, 3> n;
    if (grid_normal(t, n)) return {from128<P>(n[0]), from128<P>(n[1]), from128<P>(n[2])};
    if (Vec<P> f; fixed_normal(t, f)) return f;
  }
  return cross<P>(sub<P>(pt(t.v[1]), pt(t.v[0])), sub<P>(pt(t.v[2]), pt(t.v[0])));
}

// The same from the grid's small integers alone; false when a corner is off the grid.
template <class P>
bool Engine<P>::grid_normal(const Tri& t, std::array<Int128, 3>& n) const {
  if (!on_grid(t)) return false;
  const auto& a = prep_->small[t.v[0]];
  const auto& b = prep_->small[t.v[1]];
  const auto& c = prep_->small[t.v[2]];
  Int128 u[3], w[3];
  for (int k = 0; k < 3; ++k) u[k] = Int128(b[k]) - a[k], w[k] = Int128(c[k]) - a[k];
  n = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  return true;
}

// Sign of det(B - A, C - A, X - A) for triangle t = ABC and vertex v = X from the grid's small
// integers (a positive multiple of the scaled points' value: normal below 2^125, X - A below
// 2^62, exact in 256 bits); false when a corner or v is off the grid.
template <class P>
bool Engine<P>::grid_side_sign(const Tri& t, int v, int& sign) const {
  const std::vector<char>& on = prep_->on_grid;
  std::array<Int128, 3> m;
  if (on.empty() || !on[static_cast<std::size_t>(v)] || !grid_normal(t, m)) return false;
  const auto &a = prep_->small[t.v[0]], &x = prep_->small[v];
  WideInt<4> d;
  for (int k = 0; k < 3; ++k) d += WideInt<4>::product(WideInt<4>(m[k]), WideInt<4>(Int128(x[k]) - a[k]));
  sign = d.sign();
  return true;
}

// Triangles of every face of body b into tris_, face normals, facing and the opposite vertex
// of every polygon side (topo_[b].slot_third); returns the index of the body's first triangle.
template <class P>
int Engine<P>::triangulate_body(int b) {
  const Polyhedron& p = *bodies_[b];
  const int vo = voff_[b];
  const auto& faces = p.faces();
  BodyTopology& topo = topo_[b];
  const std::vector<int>& fo = topo.face_offset;
  std::vector<int>& facing_at = prep_->facing_at[b];
  facing_at.assign(faces.size(), -1);
  degenerate_[b].assign(faces.size(), 0);
  const ParallelLoop loop(opt_.threads);
  PerWorker<char> polygon(loop, 0);  // some face is not a triangle
  loop.run(faces.size(), 16384, [&](unsigned w, std::size_t b0, std::size_t e) {
    bool any = false;
    for (std::size_t f = b0; f < e; ++f) any = any || faces[f].size() != 3;
    if (any) polygon[w] = 1;
  });
  bool triangles = true;
  for (unsigned w = 0; w < polygon.size(); ++w) triangles = triangles && !polygon[w];
  // Wide with a grid over most vertices (a face off it in about three in eight at most): the
  // normals kept compact; else, for a body of triangles, only their doubles (FaceNormals).
  std::size_t on = 0;
  const std::size_t nv = p.num_vertices();
  if (std::is_same_v<P, Wide> && !prep_->on_grid.empty())
    for (std::size_t i = 0; i < nv; ++i) on += prep_->on_grid[static_cast<std::size_t>(vo) + i] != 0;
  using Store = typename FaceNormals<P>::Store;
  const Store store = !std::is_same_v<P, Wide> ? Store::Full : on > 0 && on * 8 >= nv * 7 ? Store::Compact : triangles ? Store::Lazy : Store::Full;
  face_normal_[b].reset(faces.size(), store);
  const int first_tri = static_cast<int>(tris_.size());
  // Triangles' normals on all cores (integer arithmetic on the shared coordinates; each face
  // writes its own slots; a compact store's few long normals after), then the triangles
  // listed in face order.
  std::vector<char> long_normal(faces.size(), 0);
  loop.for_each(faces.size(), 4096, [&](std::size_t f) {
    const Face& face = faces[f];
    if (face.size() != 3) return;  // after the triangulation below
    Tri probe{b, static_cast<int>(f), {vo + face[0], vo + face[1], vo + face[2]}, {true, true, true}};
    // A lazy store's doubles in fixed widths, as normal() makes them off the grid (0 exactly when 0).
    if (std::array<double, 3> d; face_normal_[b].lazy() && !on_grid(probe) && fixed_normal_doubles(probe, d)) {
      if (d[0] == 0 && d[1] == 0 && d[2] == 0) degenerate_[b][f] = 1;
      else facing_at[f] = probe.v[0], face_normal_[b].put_doubles(f, d);
      return;
    }
    Vec<P> n = normal(probe);
    if (P::sign(n[0]) == 0 && P::sign(n[1]) == 0 && P::sign(n[2]) == 0) {
      degenerate_[b][f] = 1;  // zero area: neither occludes nor faces
      return;
    }
    facing_at[f] = probe.v[0];
    if (!face_normal_[b].put(f, std::move(n))) long_normal[f] = 1;
  });
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (long_normal[f]) {
      const Face& face = faces[f];
      face_normal_[b].put_wide(f, normal(Tri{b, static_cast<int>(f), {vo + face[0], vo + face[1], vo + face[2]}, {true, true, true}}));
    }
  if (triangles) {
    // Only triangles (most large meshes): listed on all cores, each chunk of faces after the
    // ones before it (the order of the loop below).
    constexpr std::size_t kChunk = 16384;
    const std::size_t chunks = (faces.size() + kChunk - 1) / kChunk;
    std::vector<std::size_t> at(chunks + 1, 0);
    loop.for_each(chunks, 1, [&](std::size_t c) {
      std::size_t k = 0;  // (a local: neighbouring chunks' counts share a cache line)
      for (std::size_t f = c * kChunk, e = std::min(faces.size(), f + kChunk); f < e; ++f) k += !degenerate_[b][f];
      at[c + 1] = k;
    });
    at[0] = tris_.size();
    for (std::size_t c = 0; c < chunks; ++c) at[c + 1] += at[c];
    reserve_touched(tris_, at[chunks], loop);
    tris_.resize(at[chunks]);
    loop.for_each(chunks, 1, [&](std::size_t c) {
      std::size_t w = at[c];
      for (std::size_t f = c * kChunk, e = std::min(faces.size(), f + kChunk); f < e; ++f) {
        if (degenerate_[b][f]) continue;
        const Face& face = faces[f];
        Tri tri{b, static_cast<int>(f), {vo + face[0], vo + face[1], vo + face[2]}, {true, true, true}};
        if (!topo.slot_third.empty())
          for (int k = 0; k < 3; ++k) topo.slot_third[fo[f] + k] = tri.v[(k + 2) % 3];
        tris_[w++] = tri;
      }
    });
    return first_tri;
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Face& face = faces[f];
    static const std::vector<FaceTriangle> kTriangle = {{{0, 1, 2}, {true, true, true}}};
    FaceTriangles ft;  // triangles need no triangulation (nor an allocation each)
    if (face.size() == 3) {
      if (degenerate_[b][f]) continue;
    } else {
      ft = face_triangles(p, static_cast<int>(f));
      if (ft.status == FaceTriangles::Status::Degenerate) {
        degenerate_[b][f] = 1;
        continue;
      }
      if (ft.status != FaceTriangles::Status::Ok) throw BodyError(b, "has " + ft.problem(static_cast<int>(f)));
    }
    for (const FaceTriangle& t : face.size() == 3 ? kTriangle : ft.triangles) {
      Tri tri{b, static_cast<int>(f), {vo + face[t.v[0]], vo + face[t.v[1]], vo + face[t.v[2]]}, t.edge};
      for (int k = 0; k < 3; ++k)
        if (t.edge[k] && !topo.slot_third.empty()) topo.slot_third[fo[f] + t.v[k]] = tri.v[(k + 2) % 3];  // side k's opposite vertex
      tris_.push_back(tri);
    }
    if (face.size() == 3) continue;  // normal and facing above
    if (!face_normal_[b].put(f, normal(tris_.back()))) face_normal_[b].put_wide(f, normal(tris_.back()));
    facing_at[f] = tris_.back().v[0];
  }
  return first_tri;
}

// Sign of six times the volume of the triangles `ids`, summed on all cores (exact integers:
// the sum is the same in any order); Fast40's terms reach 2^123, so its sum carries into a
// third word.
template <class P>
int Engine<P>::volume_sign(const std::vector<int>& ids) const {
  if constexpr (kFiltered)
    if (const int s = volume_filter(ids)) return s;
  const ParallelLoop loop(opt_.threads);
  if constexpr (std::is_same_v<P, Fast40>) {
    // Each term fits in Int128, their sum may not: high·2^128 + low, a carry counted on each
    // wrap of low (its direction is the term's sign), exact for fewer than 2^63 terms.
    struct WideSum {
      Int128 low = 0;
      std::int64_t high = 0;
      void add(Int128 t) {
        Int128 r;
        if (__builtin_add_overflow(low, t, &r)) high += t > 0 ? 1 : -1;
        low = r;
      }
    };
    std::vector<WideSum> part(loop.workers());
    const Vec<P>& o = pt(tris_[ids[0]].v[0]);
    loop.run(ids.size(), 16384, [&](unsigned w, std::size_t begin, std::size_t end) {
      WideSum sum = part[w];
      for (std::size_t k = begin; k < end; ++k) {
        const int i = ids[k];
        sum.add(dot<P>(sub<P>(pt(tris_[i].v[0]), o), cross<P>(sub<P>(pt(tris_[i].v[1]), o), sub<P>(pt(tris_[i].v[2]), o))));
      }
      part[w] = sum;
    });
    WideSum v6;
    for (const WideSum& x : part) {
      v6.add(x.low);
      v6.high += x.high;
    }
    return v6.high != 0 ? (v6.high > 0 ? 1 : -1) : P::sign(v6.low);
  } else {
    std::vector<V> part(loop.workers(), V(0));
    loop.run(ids.size(), 16384, [&](unsigned w, std::size_t begin, std::size_t end) {
      V sum = 0;
      for (std::size_t k = begin; k < end; ++k) {
        const int i = ids[k];
        sum += dot<P>(pt(tris_[i].v[0]), cross<P>(pt(tris_[i].v[1]), pt(tris_[i].v[2])));
      }
      part[w] += sum;
    });
    V volume6 = 0;
    for (const V& x : part) volume6 += x;
    return P::sign(volume6);
  }
}

// The same sign from doubles of the input's rational vertices (the scaled ones are a positive
// multiple), 0 when the bound does not decide it. Each coordinate's double is the end of its
// tight bounds toward 0 (Point3::approx: the neighbouring doubles at worst), within one ulp,
// so within 2u of it (u = 2^-53); each term x0 (y1 z2 - z1 y2) + ... takes 9 more roundings
// and the sum of N terms on W workers N + W more: with k = N + W + 64 every monomial carries a
// factor (1 + t), |t| <= gamma_k = k u / (1 - k u), so the computed sum is within gamma_k M
// of the exact one, M the sum of the monomials' absolute values, itself computed within the
// same factor; 4 k u M-hat covers both for k u <= 1/4. Coordinates beyond [2^-250, 2^250]
// (a product could leave the normal doubles), and non-zero ones whose bounds reach 0, are
// left to the exact sum.
template <class P>
int Engine<P>::volume_filter(const std::vector<int>& ids) const {
  if (ids.empty()) return 0;
  const int b = tris_[ids[0]].body;
  const PointStore& vs = bodies_[b]->vertex_store();
  const int vo = voff_[b];
  const ParallelLoop loop(opt_.threads);
  std::vector<std::array<double, 3>> d(vs.size());
  PerWorker<char> wild(loop, 0);
  loop.run(vs.size(), 16384, [&](unsigned w, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      for (int k = 0; k < 3; ++k) {
        const Bounds q = vs.approx(i, k);
        const double x = q.lo > 0 ? q.lo : q.hi, a = std::fabs(x);  // the end toward 0
        d[i][k] = x;
        if (!(q.lo == 0 && q.hi == 0) && !(a >= 0x1p-250 && a <= 0x1p250)) wild[w] = 1;
      }
  });
  for (unsigned w = 0; w < wild.size(); ++w)
    if (wild[w]) return 0;
  std::vector<std::array<double, 2>> part(loop.workers(), {0.0, 0.0});  // sum, sum of |monomials|
  loop.run(ids.size(), 16384, [&](unsigned w, std::size_t begin, std::size_t end) {
    double sum = part[w][0], mag = part[w][1];
    for (std::size_t i = begin; i < end; ++i) {
      const Tri& t = tris_[ids[i]];
      const auto &x = d[t.v[0] - vo], &y = d[t.v[1] - vo], &z = d[t.v[2] - vo];
      sum += x[0] * (y[1] * z[2] - y[2] * z[1]) + x[1] * (y[2] * z[0] - y[0] * z[2]) + x[2] * (y[0] * z[1] - y[1] * z[0]);
      mag += std::fabs(x[0]) * (std::fabs(y[1] * z[2]) + std::fabs(y[2] * z[1])) +
             std::fabs(x[1]) * (std::fabs(y[2] * z[0]) + std::fabs(y[0] * z[2])) +
             std::fabs(x[2]) * (std::fabs(y[0] * z[1]) + std::fabs(y[1] * z[0]));
    }
    part[w] = {sum, mag};
  });
  double sum = 0, mag = 0;
  for (const auto& p : part) sum += p[0], mag += p[1];
  const double k = static_cast<double>(ids.size()) + 64 + loop.workers();
  if (!(k * kUnitRoundoff <= 0.25) || !std::isfinite(sum) || !std::isfinite(mag)) return 0;
  const double bound = 4 * k * kUnitRoundoff * mag;
  return sum > bound ? 1 : sum < -bound ? -1 : 0;
}

// The view-independent part of body b: topology, triangles and normals, whether it is a
// closed solid (a note when not), inside-out components and solids turned (with notes).
template <class P>
void Engine<P>::prepare_body(int b) {
  const std::vector<Face>& faces = bodies_[b]->faces();  // (triangles: no third vertex per side, side_third reads the faces)
  const bool triangles = std::all_of(faces.begin(), faces.end(), [](const Face& f) { return f.size() == 3; });
  topo_[b] = body_topology(faces, bodies_[b]->num_vertices(), opt_.threads, !triangles);
  const int first_tri = triangulate_body(b);
  prep_->first_tri[b] = first_tri;
  // A closed solid: every edge in exactly two faces, traversed in opposite directions.
  const ParallelLoop loop(opt_.threads);
  PerWorker<char> open(loop, 0);
  loop.run(topo_[b].edges.size(), 16384, [&](unsigned w, std::size_t begin, std::size_t end) {
    if (open[w]) return;
    for (std::size_t i = begin; i < end; ++i)
      if (!topo_[b].edges[i].closed_pair()) {
        open[w] = 1;
        return;
      }
  });
  bool closed = true;
  for (unsigned w = 0; w < open.size(); ++w) closed = closed && !open[w];
  std::vector<int> ids(tris_.size() - static_cast<std::size_t>(first_tri));
  std::iota(ids.begin(), ids.end(), first_tri);
  // Orientation per component first (an inside-out one is turned, with a note); then the sign
  // of the whole.
  const bool components_ok = closed && !ids.empty() && orient_components(b, first_tri);
  int vsign = components_ok ? volume_sign(ids) : 0;
  solid_[b] = closed && vsign != 0;
  if (!solid_[b]) {
    std::string why = "has zero volume";
    for (const BodyEdge& e : topo_[b].edges)
      if (!e.closed_pair()) {
        why = e.uses.size() == 1   ? "is open (edge " + std::to_string(e.u) + "-" + std::to_string(e.v) + " is in one face)"
              : e.uses.size() != 2 ? "is not manifold (edge " + std::to_string(e.u) + "-" + std::to_string(e.v) + " is in " +
                                         std::to_string(e.uses.size()) + " faces)"
                                   : "is not consistently oriented (edge " + std::to_string(e.u) + "-" + std::to_string(e.v) + ")";
        break;
      }
    prep_->notes.push_back({b, why + ": drawn as a surface (hidden where a sight ray crosses it)"});
  }
  if (solid_[b] && vsign < 0) {  // inside out: turn it
    for (std::size_t i = first_tri; i < tris_.size(); ++i) flip(tris_[i]);
    for (std::size_t f = 0; f < face_normal_[b].size(); ++f) face_normal_[b].negate(f);
    flipped_.push_back(b);
  }
}

// This view's part of body b: each face's facing (from the turned normals), the eye inside or
// on a solid, the notes.
template <class P>
void Engine<P>::view_body(int b, LineDrawing& res) {
  std::vector<signed char>& facing = facing_[b];
  const std::vector<int>& at = prep_->facing_at[b];
  const bool again = !cam_.perspective && prep_->facing_view == view_ && static_cast<std::size_t>(b) < prep_->facing.size();
  if (again) {
    facing = prep_->facing[b];
  } else {
    facing.assign(at.size(), 0);
    ParallelLoop(opt_.threads).for_each(at.size(), 4096, [&](std::size_t f) {
      if (at[f] < 0) return;
      facing[f] = static_cast<signed char>(facing_of(b, static_cast<int>(f), at));
    });
    if (keep_ && !cam_.perspective) {  // for the next view in this direction
      if (b == 0) prep_->facing_view = view_, prep_->facing.clear();
      prep_->facing.push_back(facing);
    }
  }
  for (const BodyNote& n : prep_->notes)
    if (n.body == b) res.notes.push_back(n);
  const int first_tri = prep_->first_tri[b];
  if (solid_[b] && cam_.perspective && eye_inside(first_tri))
    throw BodyError(b, "contains the eye " + to_string(cam_.eye) + ": an eye inside a solid sees nothing");
  // The eye on the surface: a sight segment may end inside the solid without leaving it through
  // a front face, so the back faces hide too (their forward cones from the eye, see occluders).
  // (Turning a triangle turns its normal too: the test reads the same.)
  if (solid_[b] && cam_.perspective) eye_on_[b] = eye_on_surface(first_tri);
  if (eye_on_[b] && !convexity(*bodies_[b]).convex())
    throw BodyError(b, "holds the eye " + to_string(cam_.eye) +
                           " on its surface and is not convex: move the eye off the surface (by any amount)");
  res.facing.emplace_back(facing.begin(), facing.end());
  res.back_faces_unseen.resize(b + 1, 0);
  res.back_faces_unseen[b] = solid_[b] && !eye_on_[b];
}

// Facing of face f of body b (facing_sign; perspective: measured at vertex at[f]). A lazy
// store's doubles decide an orthographic view when filtered_sign can (the normal's doubles and
// the direction's, integers' each within 2^-52, c = 0); otherwise the exact normal does.
template <class P>
int Engine<P>::facing_of(int b, int f, const std::vector<int>& at) const {
  if constexpr (std::is_same_v<P, Wide>) {
    if (!cam_.perspective && face_normal_[b].lazy()) {
      const std::array<double, 3> n = face_normal_[b].approx(static_cast<std::size_t>(f));
      const std::array<double, 3> d = {P::cdbl(view_[0]), P::cdbl(view_[1]), P::cdbl(view_[2])};
      if (const int s = filtered_sign(n.data(), 0.0, d)) return s;
    }
  }
  // (orthographic: the point is not read; none is made)
  return cam_.perspective ? facing_sign<P>(face_normal(b, f), pt(at[static_cast<std::size_t>(f)]), view_, true)
                          : facing_sign<P>(face_normal(b, f), view_, view_, false);
}

// Parity of the crossings of a ray from `x` with the triangles `ids`, exactly: 1 inside, 0
// outside, -1 when x lies on one of them; a ray through an edge or a vertex is replaced by the
// next direction (-1 when every direction is degenerate).
template <class P>
int Engine<P>::parity(const Vec<P>& x, const std::vector<int>& ids) const {
  static const int dirs[][3] = {{7, 3, 5}, {2, 11, 3}, {-13, 1, 7}, {5, -9, 2}, {1, 4, -11}, {-3, -5, 8}, {17, 6, -1}, {-2, 3, -19}};
  for (const auto& dd : dirs) {
    Vec<P> d{C(dd[0]), C(dd[1]), C(dd[2])};
    bool degenerate = false;
    int crossings = 0;
    for (int i : ids) {
      const Tri& t = tris_[i];
      Vec<P> a = sub<P>(pt(t.v[0]), x), b = sub<P>(pt(t.v[1]), x), c = sub<P>(pt(t.v[2]), x);
      int o1 = P::sign(dot<P>(a, cross<P>(b, d))), o2 = P::sign(dot<P>(b, cross<P>(c, d))), o3 = P::sign(dot<P>(c, cross<P>(a, d)));
      if (!((o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0))) continue;  // the line misses it
      if (o1 == 0 || o2 == 0 || o3 == 0) {
        degenerate = true;  // through an edge or a vertex (or in its plane)
        break;
      }
      Vec<P> n = normal(t);
      int sa = P::sign(dot<P>(n, a)), sd = P::sign(dot<P>(n, d));
      if (sa == 0) return -1;     // x lies on the surface
      if (sa == sd) ++crossings;  // the crossing is ahead of x
    }
    if (!degenerate) return crossings % 2;
  }
  return -1;
}

template <class P>
bool Engine<P>::eye_inside(int first) const {
  std::vector<int> ids;
  for (std::size_t i = first; i < tris_.size() && tris_[i].body == tris_[first].body; ++i) ids.push_back(static_cast<int>(i));
  return parity(view_, ids) == 1;
}

// Closed components of body b (faces joined across edges) whose volume is negative and that do
// not lie inside another component (a cavity's shell is negative and inside): inside out.
// They are turned (triangles, facing, normals) with a note. Returns false when some component
// has zero volume.
template <class P>
bool Engine<P>::orient_components(int b, int first) {
  const std::size_t nf = bodies_[b]->faces().size();
  // Faces joined across edges, on all cores: each set's root is its smallest face.
  const ParallelLoop loop(opt_.threads);
  ConcurrentUnionFind faces(nf);
  loop.for_each(topo_[b].edges.size(), 8192, [&](std::size_t i) {
    const BodyEdge& e = topo_[b].edges[i];
    for (std::size_t k = 1; k < e.uses.size(); ++k) faces.unite(static_cast<std::uint32_t>(e.uses[k].face), static_cast<std::uint32_t>(e.uses[0].face));
  });
  std::vector<int> root(nf);
  loop.for_each(nf, 8192, [&](std::size_t f) { root[f] = static_cast<int>(faces.root(static_cast<std::uint32_t>(f))); });
  auto find = [&](int f) { return root[f]; };
  // The components with triangles (most meshes have one: then nothing more to do).
  std::vector<char> has(nf, 0);
  loop.for_each(tris_.size() - static_cast<std::size_t>(first), 8192, [&](std::size_t i) {
    std::atomic_ref<char>(has[root[tris_[first + i].face]]).store(1, std::memory_order_relaxed);
  });
  std::vector<int> slot(nf, -1), roots;  // slot: a root's index in roots
  for (std::uint32_t f : parallel_select(nf, [&](std::size_t f) { return has[f] != 0; }, loop)) {
    roots.push_back(static_cast<int>(f));
    slot[f] = 0;
  }
  if (roots.size() < 2) return true;
  std::sort(roots.begin(), roots.end());
  for (std::size_t k = 0; k < roots.size(); ++k) slot[roots[k]] = static_cast<int>(k);
  std::vector<std::vector<int>> comp(roots.size());  // the triangles of each component
  for (std::size_t i = first; i < tris_.size(); ++i) comp[slot[find(tris_[i].face)]].push_back(static_cast<int>(i));
  std::vector<int> sign(roots.size(), 0);
  for (std::size_t k = 0; k < roots.size(); ++k) {
    sign[k] = volume_sign(comp[k]);
    if (sign[k] == 0) return false;
  }
  for (std::size_t k = 0; k < roots.size(); ++k) {
    const int r = roots[k];
    if (sign[k] > 0) continue;
    const std::vector<int>& mine = comp[k];
    std::vector<int> others;
    for (std::size_t q = 0; q < roots.size(); ++q)
      if (q != k) others.insert(others.end(), comp[q].begin(), comp[q].end());
    // A cavity lies wholly inside the others: some vertex outside them all means inside out.
    bool outside = false;
    for (std::size_t i = 0; i < mine.size() && !outside; ++i)
      for (int j = 0; j < 3 && !outside; ++j) outside = parity(pt(tris_[mine[i]].v[j]), others) == 0;
    if (!outside) continue;  // a cavity's shell (or undecided: left as it is)
    for (int i : mine) flip(tris_[i]);
    int lowest = static_cast<int>(nf);
    for (std::size_t f = 0; f < nf; ++f)
      if (find(static_cast<int>(f)) == r) {
        face_normal_[b].negate(f);
        lowest = std::min(lowest, static_cast<int>(f));
      }
    prep_->notes.push_back({b, "has an inside-out component (the one with face " + std::to_string(lowest) +
                                   ": negative volume, not inside another component): drawn turned outward"});
  }
  return true;
}

// Does the eye lie in a (closed) triangle of the body from `first` on? Only faces seen edge-on
// can hold it.
template <class P>
bool Engine<P>::eye_on_surface(int first) const {
  for (std::size_t i = first; i < tris_.size() && tris_[i].body == tris_[first].body; ++i) {
    const Tri& t = tris_[i];
    if (facing_[t.body][t.face] != 0) continue;
    Vec<P> n = normal(t);
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      const Vec<P>& a = pt(t.v[k]);
      inside = P::sign(dot<P>(n, cross<P>(sub<P>(pt(t.v[(k + 1) % 3]), a), sub<P>(view_, a)))) >= 0;
    }
    if (inside) return true;
  }
  return false;
}

template <class P>
void Engine<P>::flip(Tri& t) {
  std::swap(t.v[1], t.v[2]);
  // Sides were (0,1), (1,2), (2,0); now (0,2)=old 2, (2,1)=old 1, (1,0)=old 0.
  t.edge = {t.edge[2], t.edge[1], t.edge[0]};
}

template class Engine<Fast>;
template class Engine<Fast40>;
template class Engine<Wide>;
template class Engine<Big>;

}  // namespace hlr::face_route
