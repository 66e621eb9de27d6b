// Cutting a body by half-spaces, with exact caps (see section_cut.hpp; docs/design.md,
// "Sections"). One plane at a time: every vertex gets the exact sign of the plane's test
// function; a face wholly on the kept side stays, one wholly on the removed side goes, one that
// crosses is cut (a convex face as it is, any other through its exact triangles) at split
// points made once per edge, so that the two faces of an edge share them. The kept faces'
// edges left without their twin all lie in the plane (for a closed, oriented input): they bound
// the cap, which the constrained triangulation of those loops fills.
#include "algorithms/sections/section_cut.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdint>
#include <unordered_map>

#include "algorithms/solids/face_triangles.hpp"
#include "algorithms/support/parallel.hpp"
#include "kernel/predicates.hpp"
#include "kernel/simple_polygon.hpp"

namespace hlr {
namespace {

std::uint64_t edge_key(int u, int v) { return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(u)) << 32) | static_cast<std::uint32_t>(v); }

// The directed edges of `faces` (vertices below nv) grouped by their lower vertex, in linear
// time on all cores: whether one occurs twice, and those whose reverse does not occur (each
// occurrence), sorted. (Each group is sorted before it is read: the order in which the cores
// filled it does not show.)
struct EdgeCensus {
  bool duplicate = false;
  std::vector<std::array<int, 2>> unpaired;
  bool any = false;  // some face has an edge
};

EdgeCensus edge_census(const std::vector<Face>& faces, std::size_t nv) {
  constexpr std::size_t kGrain = 4096;
  const ParallelLoop loop;
  EdgeCensus c;
  std::vector<int> start(nv + 1, 0);
  loop.for_each(faces.size(), kGrain, [&](std::size_t fi) {
    const Face& f = faces[fi];
    for (std::size_t k = 0; k < f.size(); ++k)
      std::atomic_ref<int>(start[std::min(f[k], f[(k + 1) % f.size()]) + 1]).fetch_add(1, std::memory_order_relaxed);
  });
  for (std::size_t i = 0; i < nv; ++i) start[i + 1] += start[i];
  c.any = start[nv] > 0;
  std::vector<std::uint32_t> other(start[nv]);  // the higher vertex, times 2, plus 1 when the edge runs downward
  std::vector<int> at(start.begin(), start.end() - 1);
  loop.for_each(faces.size(), kGrain, [&](std::size_t fi) {
    const Face& f = faces[fi];
    for (std::size_t k = 0; k < f.size(); ++k) {
      const int u = f[k], v = f[(k + 1) % f.size()];
      other[std::atomic_ref<int>(at[std::min(u, v)]).fetch_add(1, std::memory_order_relaxed)] =
          static_cast<std::uint32_t>(std::max(u, v)) * 2 + (u > v);
    }
  });
  PerWorker<char> duplicate(loop, 0);
  PerWorker<std::vector<std::array<int, 2>>> unpaired(loop);
  loop.run(nv, kGrain, [&](unsigned w, std::size_t b, std::size_t e) {
    for (std::size_t lo = b; lo < e; ++lo) {
      auto first = other.begin() + start[lo], last = other.begin() + start[lo + 1];
      std::sort(first, last);
      for (auto i = first; i != last;) {
        const std::uint32_t hi = *i / 2;
        int up = 0, down = 0;
        for (; i != last && *i / 2 == hi; ++i) (*i & 1 ? down : up) += 1;
        if (up > 1 || down > 1) duplicate[w] = 1;
        if (hi == lo) continue;  // an edge from a vertex to itself is its own reverse
        const int l = static_cast<int>(lo), h = static_cast<int>(hi);
        for (int k = 0; k < up && down == 0; ++k) unpaired[w].push_back({l, h});
        for (int k = 0; k < down && up == 0; ++k) unpaired[w].push_back({h, l});
      }
    }
  });
  for (unsigned w = 0; w < duplicate.size(); ++w) {
    c.duplicate = c.duplicate || duplicate[w];
    c.unpaired.insert(c.unpaired.end(), unpaired[w].begin(), unpaired[w].end());
  }
  std::sort(c.unpaired.begin(), c.unpaired.end());
  return c;
}

// Closed and oriented: every directed edge once, and its reverse there too.
bool closed_oriented(const std::vector<Face>& faces, std::size_t nv) {
  const EdgeCensus c = edge_census(faces, nv);
  return c.any && !c.duplicate && c.unpaired.empty();
}

// The faces being cut: the input's vertices (read, not copied) and the split points added
// after them, plane after plane.
struct Work {
  const std::vector<Point3>* base;
  std::vector<Point3> added;
  std::vector<Face> f;
  std::vector<int> part, cap;
  std::size_t vertices() const { return base->size() + added.size(); }
  const Point3& at(int i) const {
    const std::size_t k = static_cast<std::size_t>(i);
    return k < base->size() ? (*base)[k] : added[k - base->size()];
  }
};

class PlaneCut {
 public:
  PlaneCut(Work& w, const Plane& h) : w_(w), h_(h), sign_(w.vertices()) {
    loop_.for_each(sign_.size(), 4096, [&](std::size_t i) { sign_[i] = static_cast<signed char>(side_of_plane(h, w.at(static_cast<int>(i)))); });
  }

  // Which side the body is on: -1 all kept (nothing above), 1 all removed (nothing below), 0 cut.
  int side() const {
    bool below = false, above = false;
    for (const Face& f : w_.f)
      for (int x : f) (sign_[x] < 0 ? below : above) |= sign_[x] != 0;
    return !above ? -1 : !below ? 1 : 0;
  }

  // The kept faces in the input's order (a cut face's pieces in its place); the cap's edges
  // (in the kept solid's orientation) into `rim`. Which faces stay whole is decided on all
  // cores; the cut faces are split in order, so that the split points are numbered as met.
  // `closed`: the faces are known closed and oriented (every directed edge once, its reverse
  // too), so that only edges with an end in the plane can lose their twin (rim_census).
  void run(Work& out, std::vector<std::array<int, 2>>& rim, bool& off_plane_rim, bool closed) {
    const std::size_t nf = w_.f.size();
    std::vector<signed char> kind(nf);  // kDrop, kKeep, kSplit
    loop_.for_each(nf, 4096, [&](std::size_t fi) { kind[fi] = classify(w_.f[fi]); });
    std::vector<std::size_t> pos(nf + 1, 0);  // first output face of each input face
    std::vector<Face> pieces;
    std::vector<std::size_t> first_piece(nf, 0);
    for (std::size_t fi = 0; fi < nf; ++fi) {
      std::size_t n = kind[fi] == kKeep ? 1 : 0;
      if (kind[fi] == kSplit) {
        first_piece[fi] = pieces.size();
        split_face(static_cast<int>(fi), pieces);
        n = pieces.size() - first_piece[fi];
      }
      pos[fi + 1] = pos[fi] + n;
    }
    out.f.resize(pos[nf]);
    out.part.resize(pos[nf]);
    out.cap.resize(pos[nf]);
    loop_.for_each(nf, 4096, [&](std::size_t fi) {
      for (std::size_t k = pos[fi]; k < pos[fi + 1]; ++k) {
        out.f[k] = kind[fi] == kKeep ? w_.f[fi] : std::move(pieces[first_piece[fi] + (k - pos[fi])]);
        out.part[k] = w_.part[fi];
        out.cap[k] = w_.cap[fi];
      }
    });
    // Directed edges whose twin is not kept: the cap's rim, reversed.
    off_plane_rim = false;
    for (const auto& [u, v] : closed ? rim_census(out.f) : edge_census(out.f, w_.vertices()).unpaired) {
      if (on_plane(u) && on_plane(v)) rim.push_back({v, u});
      else off_plane_rim = true;
    }
  }

 private:
  static constexpr signed char kDrop = 0, kKeep = 1, kSplit = 2;

  bool on_plane(int x) const { return x >= static_cast<int>(sign_.size()) || sign_[x] == 0; }

  // The directed edges of the kept faces whose reverse is not kept, sorted (edge_census's
  // unpaired), when the input was closed and oriented. An edge with an end strictly on the kept
  // side keeps its twin: it is an input edge or a diagonal of a face's exact triangles, whose
  // twin's face (or triangle) is kept whole or split with those two corners still consecutive,
  // or an edge's part from that end to its split point, which is made once per edge and which
  // the twin's split makes too. So only the edges with both ends in the plane are counted.
  std::vector<std::array<int, 2>> rim_census(const std::vector<Face>& faces) const {
    PerWorker<std::vector<std::array<int, 2>>> found(loop_);
    loop_.run(faces.size(), 4096, [&](unsigned wk, std::size_t b, std::size_t e) {
      for (std::size_t fi = b; fi < e; ++fi) {
        const Face& f = faces[fi];
        for (std::size_t k = 0; k < f.size(); ++k) {
          const int u = f[k], v = f[(k + 1) % f.size()];
          if (on_plane(u) && on_plane(v)) found[wk].push_back({u, v});
        }
      }
    });
    std::vector<std::array<int, 2>> all;
    for (unsigned wk = 0; wk < found.size(); ++wk) all.insert(all.end(), found[wk].begin(), found[wk].end());
    std::sort(all.begin(), all.end());
    std::vector<std::array<int, 2>> out;
    for (std::size_t i = 0; i < all.size();) {  // (u, v) repeated: each occurrence, as the census lists them
      std::size_t j = i;
      while (j < all.size() && all[j] == all[i]) ++j;
      const auto& [u, v] = all[i];
      if (u != v && !std::binary_search(all.begin(), all.end(), std::array<int, 2>{v, u}))
        for (std::size_t k = i; k < j; ++k) out.push_back(all[i]);
      i = j;
    }
    return out;
  }

  Vector3 normal(const Face& f) const {
    std::vector<const Point3*> p;
    for (int x : f) p.push_back(&w_.at(x));
    return newell_normal(p.data(), p.size());
  }

  signed char classify(const Face& f) const {
    int lo = 1, hi = -1;
    for (int x : f) lo = std::min<int>(lo, sign_[x]), hi = std::max<int>(hi, sign_[x]);
    if (lo == 0 && hi == 0) return dot(normal(f), h_.normal()) > 0 ? kKeep : kDrop;  // in the plane: kept when it faces the removed side
    if (lo >= 0) return kDrop;                                                       // nothing strictly on the kept side
    return hi <= 0 ? kKeep : kSplit;
  }

  // A face that crosses the plane: its part on the kept side, as it is when convex, else
  // through its exact triangles.
  void split_face(int fi, std::vector<Face>& out) {
    const Face& f = w_.f[fi];
    std::vector<Point3> corners;
    std::vector<int> local;
    for (int x : f) local.push_back(static_cast<int>(corners.size())), corners.push_back(w_.at(x));
    if (f.size() == 3 || polygon_is_convex(corners, local, polygon_view(normal(f)))) {
      clip(out, std::vector<int>(f.begin(), f.end()));
      return;
    }
    const Polyhedron one(std::move(corners), {Face(local.begin(), local.end())});  // the face's exact triangles (positions in the face)
    const FaceTriangles tris = face_triangles(one, 0);
    if (tris.status != FaceTriangles::Status::Ok) throw std::invalid_argument("a section cuts a face it cannot split: " + tris.problem(fi));
    for (const FaceTriangle& t : tris.triangles) {
      std::vector<int> tri = {f[t.v[0]], f[t.v[1]], f[t.v[2]]};
      int tlo = 1;
      for (int x : tri) tlo = std::min<int>(tlo, sign_[x]);
      if (tlo < 0) clip(out, tri);
    }
  }

  // The convex polygon's part on the kept side (it has a vertex strictly there).
  void clip(std::vector<Face>& out, const std::vector<int>& poly) {
    Face piece;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const int a = poly[k], b = poly[(k + 1) % poly.size()];
      if (sign_[a] <= 0) piece.push_back(a);
      if (sign_[a] * sign_[b] < 0) piece.push_back(split(a, b));
    }
    out.push_back(std::move(piece));
  }

  // The exact point where edge ab meets the plane, made once per edge.
  int split(int a, int b) {
    const std::uint64_t key = edge_key(std::min(a, b), std::max(a, b));
    auto it = splits_.find(key);
    if (it != splits_.end()) return it->second;
    const Point3 &lo = w_.at(std::min(a, b)), &hi = w_.at(std::max(a, b));
    const Rational va = h_.value(lo), vb = h_.value(hi);
    const Rational t = va / (va - vb);
    const int id = static_cast<int>(w_.vertices());
    w_.added.push_back(lo + t * (hi - lo));
    splits_.emplace(key, id);
    return id;
  }

  const ParallelLoop loop_;
  Work& w_;
  const Plane& h_;
  std::vector<signed char> sign_;
  std::unordered_map<std::uint64_t, int> splits_;
};

// The cap: the rim's loops triangulated in the plane, on their own points (in the order of
// their numbers in `w`).
std::vector<std::array<int, 3>> triangulate_rim(const Work& w, const std::vector<std::array<int, 2>>& rim, const Plane& h) {
  std::vector<int> global;
  for (const auto& e : rim) global.insert(global.end(), e.begin(), e.end());
  std::sort(global.begin(), global.end());
  global.erase(std::unique(global.begin(), global.end()), global.end());
  std::vector<Point3> pts;
  for (int g : global) pts.push_back(w.at(g));
  auto local = [&](int g) { return static_cast<int>(std::lower_bound(global.begin(), global.end(), g) - global.begin()); };
  std::vector<std::array<int, 2>> edges;
  for (const auto& [u, v] : rim) edges.push_back({local(u), local(v)});
  std::vector<std::array<int, 3>> tris = triangulate_loops(pts, edges, polygon_view(h.normal()));
  for (auto& t : tris)
    for (int& x : t) x = global[static_cast<std::size_t>(x)];
  return tris;
}

// The output: the vertices that faces use, numbered in the order the faces first use them,
// copied (the input's) or moved (the split points) on all cores.
void compact(Work& w, CutSolid& c) {
  const std::size_t nv = w.vertices();
  std::vector<int> id(nv, -1), from;
  for (Face& f : w.f)
    for (int& x : f) {
      if (id[x] < 0) id[x] = static_cast<int>(from.size()), from.push_back(x);
      x = id[x];
    }
  c.vertices.resize(from.size());
  ParallelLoop().for_each(from.size(), 4096, [&](std::size_t i) {
    const std::size_t k = static_cast<std::size_t>(from[i]);
    if (k < w.base->size()) c.vertices[i] = (*w.base)[k];
    else c.vertices[i] = std::move(w.added[k - w.base->size()]);
  });
  c.faces = std::move(w.f);
  c.part = std::move(w.part);
  c.cap = std::move(w.cap);
}

}  // namespace

CutSolid cut_solid(const Polyhedron& body, const std::vector<Plane>& planes) {
  CutSolid out;
  const int nf = static_cast<int>(body.num_faces());
  Work w{&body.vertices(), {}, body.faces(), {}, std::vector<int>(nf, -1)};
  for (int f = 0; f < nf; ++f) w.part.push_back(f);
  out.open = !closed_oriented(w.f, w.vertices());
  bool cut = false, input = !out.open;  // w is the input, checked closed and oriented
  for (std::size_t k = 0; k < planes.size(); ++k) {
    PlaneCut pc(w, planes[k]);
    const int side = pc.side();
    if (side < 0) continue;
    if (side > 0) {
      out.state = CutSolid::State::Removed;
      return out;
    }
    cut = true;
    Work kept{w.base, {}, {}, {}, {}};
    std::vector<std::array<int, 2>> rim;
    bool off_plane = false;
    pc.run(kept, rim, off_plane, input);
    input = false;
    kept.added = std::move(w.added);
    if (!out.open && !off_plane && !rim.empty()) {
      for (const auto& t : triangulate_rim(kept, rim, planes[k])) {
        kept.f.push_back(Face{t[0], t[1], t[2]});
        kept.part.push_back(nf + static_cast<int>(k));
        kept.cap.push_back(static_cast<int>(k));
      }
    } else if (off_plane) {
      out.open = true;
    }
    w = std::move(kept);
  }
  if (!cut) return out;
  out.state = CutSolid::State::Cut;
  compact(w, out);
  return out;
}

namespace {

// The convex polygon's closed part where h < 0 (empty when no corner is strictly there).
std::vector<Point3> keep_below(const std::vector<Point3>& poly, const Plane& h) {
  std::vector<Rational> v;
  bool any = false;
  for (const Point3& p : poly) v.push_back(h.value(p)), any = any || v.back() < 0;
  std::vector<Point3> out;
  if (!any) return out;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const std::size_t n = (k + 1) % poly.size();
    if (v[k] <= 0) out.push_back(poly[k]);
    if (sgn(v[k]) * sgn(v[n]) < 0) out.push_back(poly[k] + Rational(v[k] / (v[k] - v[n])) * (poly[n] - poly[k]));
  }
  return out;
}

// Faces joined into one mesh: equal points are one vertex, and a vertex lying inside an edge
// that runs in one of the planes is put into that edge (the pieces' seams). Points are found by
// a hash of their certified double bounds (equal points have equal bounds) in an open-addressed
// table of vertex numbers, then compared exactly; a piece's vertex is looked up once, when a
// face first uses it, so the vertices are numbered in the order the faces first use them.
struct Joiner {
  CutSolid out;
  std::vector<int> slots;  // vertex numbers, -1 empty; a power of two of them

  static std::uint64_t hash(const Point3& p) {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (int k = 0; k < 3; ++k)
      for (double d : {p.approx(k).lo, p.approx(k).hi}) h = (h ^ std::bit_cast<std::uint64_t>(d)) * 0xff51afd7ed558ccdull, h ^= h >> 32;
    return h;
  }
  int intern(const Point3& p) {
    if (2 * (out.vertices.size() + 1) > slots.size()) grow();
    const std::size_t mask = slots.size() - 1;
    for (std::size_t at = hash(p) & mask;; at = (at + 1) & mask) {
      int& s = slots[at];
      if (s < 0) {
        s = static_cast<int>(out.vertices.size());
        out.vertices.push_back(p);
        return s;
      }
      if (out.vertices[static_cast<std::size_t>(s)] == p) return s;
    }
  }
  void grow() {
    std::vector<int> old = std::move(slots);
    slots.assign(std::max<std::size_t>(1024, 2 * old.size()), -1);
    const std::size_t mask = slots.size() - 1;
    for (int v : old) {
      if (v < 0) continue;
      std::size_t at = hash(out.vertices[static_cast<std::size_t>(v)]) & mask;
      while (slots[at] >= 0) at = (at + 1) & mask;
      slots[at] = v;
    }
  }
  void add(const std::vector<Point3>& corners, int part, int cap) {
    Face f;
    for (const Point3& p : corners) f.push_back(intern(p));
    push(std::move(f), part, cap);
  }
  // Face f of piece c, its vertices' numbers in `ids` (-1: not looked up yet).
  void add(const CutSolid& c, std::size_t f, std::vector<int>& ids, int part, int cap) {
    Face g;
    for (int v : c.faces[f]) {
      int& id = ids[static_cast<std::size_t>(v)];
      if (id < 0) id = intern(c.vertices[static_cast<std::size_t>(v)]);
      g.push_back(id);
    }
    push(std::move(g), part, cap);
  }
  void push(Face f, int part, int cap) {
    out.faces.push_back(std::move(f));
    out.part.push_back(part);
    out.cap.push_back(cap);
  }
  void join_seams(const Plane& h) {
    std::vector<int> on;  // the vertices in the plane, in lexicographic order
    for (std::size_t i = 0; i < out.vertices.size(); ++i)
      if (side_of_plane(h, out.vertices[i]) == Sign::Zero) on.push_back(static_cast<int>(i));
    if (on.empty()) return;
    std::vector<char> in_plane(out.vertices.size(), 0);
    for (int i : on) in_plane[i] = 1;
    auto lex = [&](int a, int b) { return out.vertices[a] < out.vertices[b]; };
    std::sort(on.begin(), on.end(), lex);
    for (Face& f : out.faces) {
      Face g;
      for (std::size_t k = 0; k < f.size(); ++k) {
        const int u = f[k], v = f[(k + 1) % f.size()];
        g.push_back(u);
        if (!in_plane[u] || !in_plane[v]) continue;
        const bool up = lex(u, v);
        auto lo = std::upper_bound(on.begin(), on.end(), up ? u : v, lex), hi = std::lower_bound(on.begin(), on.end(), up ? v : u, lex);
        std::vector<int> inner;
        for (auto it = lo; it < hi; ++it)  // (filtered: most candidates are off the line)
          if (collinear(out.vertices[u], out.vertices[v], out.vertices[*it])) inner.push_back(*it);
        if (!up) std::reverse(inner.begin(), inner.end());
        for (int w : inner) g.push_back(w);
      }
      f = std::move(g);
    }
  }
};

std::vector<Point3> corners_of(const CutSolid& c, std::size_t f) {
  std::vector<Point3> out;
  for (int v : c.faces[f]) out.push_back(c.vertices[v]);
  return out;
}

}  // namespace

CutSolid cut_away(const Polyhedron& body, const std::vector<Plane>& given) {
  // A plane given twice is one plane; a plane and its opposite bound a region without inside:
  // nothing is removed. The cap numbers stay those of the planes as given.
  std::vector<Plane> planes;
  std::vector<int> index;
  for (std::size_t k = 0; k < given.size(); ++k) {
    const Plane h = primitive_plane(given[k]);
    bool twice = false;
    for (const Plane& o : planes) {
      if (o == h.opposite()) return CutSolid{};
      twice = twice || o == h;
    }
    if (!twice) planes.push_back(h), index.push_back(static_cast<int>(k));
  }
  const int nf = static_cast<int>(body.num_faces());
  Joiner j;
  bool cut = false;
  for (std::size_t i = 0; i < planes.size(); ++i) {
    std::vector<Plane> piece(planes.begin(), planes.begin() + static_cast<long>(i));
    piece.push_back(planes[i].opposite());
    const CutSolid c = cut_solid(body, piece);
    j.out.open = j.out.open || c.open;
    if (c.state == CutSolid::State::Removed) continue;
    if (c.state == CutSolid::State::Whole) return CutSolid{};  // wholly in one piece: the region does not reach it
    cut = true;
    std::vector<int> ids(c.vertices.size(), -1);
    for (std::size_t f = 0; f < c.faces.size(); ++f) {
      if (c.cap[f] >= 0 && c.cap[f] < static_cast<int>(i)) continue;  // shared with an earlier piece: inside
      if (c.cap[f] < 0) {
        j.add(c, f, ids, c.part[f], -1);
        continue;
      }
      std::vector<Point3> pts = corners_of(c, f);  // the cap on plane i: only where the later planes remove too
      for (std::size_t k = i + 1; k < planes.size() && !pts.empty(); ++k) pts = keep_below(pts, planes[k]);
      if (!pts.empty()) j.add(pts, nf + index[i], index[i]);
    }
  }
  if (!cut) {  // in no piece: wholly inside the removed region
    CutSolid out;
    out.state = CutSolid::State::Removed;
    return out;
  }
  for (const Plane& h : planes) j.join_seams(h);
  j.out.state = CutSolid::State::Cut;
  return std::move(j.out);
}

}  // namespace hlr
