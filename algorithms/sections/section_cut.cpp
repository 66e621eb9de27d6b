// Cutting a body by half-spaces, with exact caps (see section_cut.hpp; docs/design.md,
// "Sections"). One plane at a time: every vertex gets the exact sign of the plane's test
// function; a face wholly on the kept side stays, one wholly on the removed side goes, one that
// crosses is cut (a convex face as it is, any other through its exact triangles) at split
// points made once per edge, so that the two faces of an edge share them. The kept faces'
// edges left without their twin all lie in the plane (for a closed, oriented input): they bound
// the cap, which the constrained triangulation of those loops fills.
#include "algorithms/sections/section_cut.hpp"

#include <algorithm>
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
// time: whether one occurs twice, and those whose reverse does not occur (each occurrence),
// sorted.
struct EdgeCensus {
  bool duplicate = false;
  std::vector<std::array<int, 2>> unpaired;
  bool any = false;  // some face has an edge
};

EdgeCensus edge_census(const std::vector<Face>& faces, std::size_t nv) {
  EdgeCensus c;
  std::vector<int> start(nv + 1, 0);
  for (const Face& f : faces)
    for (std::size_t k = 0; k < f.size(); ++k) ++start[std::min(f[k], f[(k + 1) % f.size()]) + 1];
  for (std::size_t i = 0; i < nv; ++i) start[i + 1] += start[i];
  c.any = start[nv] > 0;
  std::vector<std::uint32_t> other(start[nv]);  // the higher vertex, times 2, plus 1 when the edge runs downward
  std::vector<int> at(start.begin(), start.end() - 1);
  for (const Face& f : faces)
    for (std::size_t k = 0; k < f.size(); ++k) {
      const int u = f[k], v = f[(k + 1) % f.size()];
      other[at[std::min(u, v)]++] = static_cast<std::uint32_t>(std::max(u, v)) * 2 + (u > v);
    }
  for (std::size_t lo = 0; lo < nv; ++lo) {
    auto b = other.begin() + start[lo], e = other.begin() + start[lo + 1];
    std::sort(b, e);
    for (auto i = b; i != e;) {
      const std::uint32_t hi = *i / 2;
      int up = 0, down = 0;
      for (; i != e && *i / 2 == hi; ++i) (*i & 1 ? down : up) += 1;
      if (up > 1 || down > 1) c.duplicate = true;
      if (hi == lo) continue;  // an edge from a vertex to itself is its own reverse
      const int l = static_cast<int>(lo), h = static_cast<int>(hi);
      for (int k = 0; k < up && down == 0; ++k) c.unpaired.push_back({l, h});
      for (int k = 0; k < down && up == 0; ++k) c.unpaired.push_back({h, l});
    }
  }
  std::sort(c.unpaired.begin(), c.unpaired.end());
  return c;
}

// Closed and oriented: every directed edge once, and its reverse there too.
bool closed_oriented(const std::vector<Face>& faces, std::size_t nv) {
  const EdgeCensus c = edge_census(faces, nv);
  return c.any && !c.duplicate && c.unpaired.empty();
}

struct Work {
  std::vector<Point3> v;
  std::vector<Face> f;
  std::vector<int> part, cap;
};

class PlaneCut {
 public:
  PlaneCut(Work& w, const Plane& h) : w_(w), h_(h), sign_(w.v.size()) {
    ParallelLoop().for_each(w.v.size(), 4096, [&](std::size_t i) { sign_[i] = static_cast<signed char>(side_of_plane(h, w.v[i])); });
  }

  // Which side the body is on: -1 all kept (nothing above), 1 all removed (nothing below), 0 cut.
  int side() const {
    bool below = false, above = false;
    for (const Face& f : w_.f)
      for (int x : f) (sign_[x] < 0 ? below : above) |= sign_[x] != 0;
    return !above ? -1 : !below ? 1 : 0;
  }

  // The kept faces; the cap's edges (in the kept solid's orientation) into `rim`.
  void run(Work& out, std::vector<std::array<int, 2>>& rim, bool& off_plane_rim) {
    for (std::size_t fi = 0; fi < w_.f.size(); ++fi) keep_face(static_cast<int>(fi), out);
    // Directed edges whose twin is not kept: the cap's rim, reversed.
    off_plane_rim = false;
    for (const auto& [u, v] : edge_census(out.f, w_.v.size()).unpaired) {
      if (on_plane(u) && on_plane(v)) rim.push_back({v, u});
      else off_plane_rim = true;
    }
  }

 private:
  bool on_plane(int x) const { return x >= static_cast<int>(sign_.size()) || sign_[x] == 0; }

  void keep_face(int fi, Work& out) {
    const Face& f = w_.f[fi];
    int lo = 1, hi = -1;
    for (int x : f) lo = std::min<int>(lo, sign_[x]), hi = std::max<int>(hi, sign_[x]);
    if (lo == 0 && hi == 0) {  // in the plane: kept when it faces the removed side
      std::vector<const Point3*> p;
      for (int x : f) p.push_back(&w_.v[x]);
      if (dot(newell_normal(p.data(), p.size()), h_.normal()) > 0) add(out, f, fi);
      return;
    }
    if (lo >= 0) return;  // nothing strictly on the kept side
    if (hi <= 0) {
      add(out, f, fi);
      return;
    }
    std::vector<const Point3*> p;
    for (int x : f) p.push_back(&w_.v[x]);
    const Vector3 n = newell_normal(p.data(), p.size());
    std::vector<int> poly(f.begin(), f.end());
    if (f.size() == 3 || polygon_is_convex(w_.v, poly, polygon_view(n))) {
      clip(out, poly, fi);
      return;
    }
    std::vector<Point3> corners;
    Face local;
    for (int x : f) local.push_back(static_cast<int>(corners.size())), corners.push_back(w_.v[x]);
    const Polyhedron one(std::move(corners), {local});  // the face's exact triangles (positions in the face)
    const FaceTriangles tris = face_triangles(one, 0);
    if (tris.status != FaceTriangles::Status::Ok) throw std::invalid_argument("a section cuts a face it cannot split: " + tris.problem(fi));
    for (const FaceTriangle& t : tris.triangles) {
      std::vector<int> tri = {f[t.v[0]], f[t.v[1]], f[t.v[2]]};
      int tlo = 1;
      for (int x : tri) tlo = std::min<int>(tlo, sign_[x]);
      if (tlo < 0) clip(out, tri, fi);
    }
  }

  // The convex polygon's part on the kept side (it has a vertex strictly there).
  void clip(Work& out, const std::vector<int>& poly, int fi) {
    Face piece;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const int a = poly[k], b = poly[(k + 1) % poly.size()];
      if (sign_[a] <= 0) piece.push_back(a);
      if (sign_[a] * sign_[b] < 0) piece.push_back(split(a, b));
    }
    add(out, piece, fi);
  }

  // The exact point where edge ab meets the plane, made once per edge.
  int split(int a, int b) {
    const std::uint64_t key = edge_key(std::min(a, b), std::max(a, b));
    auto it = splits_.find(key);
    if (it != splits_.end()) return it->second;
    const int lo = std::min(a, b), hi = std::max(a, b);
    const Rational va = h_.value(w_.v[lo]), vb = h_.value(w_.v[hi]);
    const Rational t = va / (va - vb);
    const Vector3 d = w_.v[hi] - w_.v[lo];
    const int id = static_cast<int>(w_.v.size());
    w_.v.push_back(w_.v[lo] + t * d);
    splits_.emplace(key, id);
    return id;
  }

  void add(Work& out, const Face& f, int fi) {
    out.f.push_back(f);
    out.part.push_back(w_.part[fi]);
    out.cap.push_back(w_.cap[fi]);
  }

  Work& w_;
  const Plane& h_;
  std::vector<signed char> sign_;
  std::unordered_map<std::uint64_t, int> splits_;
};

// Drops the vertices no face uses, renumbering the faces.
void compact(CutSolid& c) {
  std::vector<int> id(c.vertices.size(), -1);
  std::vector<Point3> kept;
  for (Face& f : c.faces)
    for (int& x : f) {
      if (id[x] < 0) id[x] = static_cast<int>(kept.size()), kept.push_back(std::move(c.vertices[x]));  // each moved once
      x = id[x];
    }
  c.vertices = std::move(kept);
}

}  // namespace

CutSolid cut_solid(const Polyhedron& body, const std::vector<Plane>& planes) {
  CutSolid out;
  const int nf = static_cast<int>(body.num_faces());
  Work w{body.vertices(), body.faces(), {}, std::vector<int>(nf, -1)};
  for (int f = 0; f < nf; ++f) w.part.push_back(f);
  out.open = !closed_oriented(w.f, w.v.size());
  bool cut = false;
  for (std::size_t k = 0; k < planes.size(); ++k) {
    PlaneCut pc(w, planes[k]);
    const int side = pc.side();
    if (side < 0) continue;
    if (side > 0) {
      out.state = CutSolid::State::Removed;
      return out;
    }
    cut = true;
    Work kept;
    std::vector<std::array<int, 2>> rim;
    bool off_plane = false;
    pc.run(kept, rim, off_plane);
    kept.v = std::move(w.v);
    if (!out.open && !off_plane && !rim.empty()) {
      const PolygonView view = polygon_view(planes[k].normal());
      for (const auto& t : triangulate_loops(kept.v, rim, view)) {
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
  out.vertices = std::move(w.v);
  out.faces = std::move(w.f);
  out.part = std::move(w.part);
  out.cap = std::move(w.cap);
  compact(out);
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

// Faces as corner lists joined into one mesh: equal points are one vertex, and a vertex lying
// inside an edge that runs in one of the planes is put into that edge (the pieces' seams).
// A point's hash from its coordinates' canonical numerators and denominators (equal points
// have equal limbs).
struct PointHash {
  std::size_t operator()(const Point3& p) const {
    std::size_t h = 0;
    auto mix = [&](const mpz_class& z) {
      const std::size_t low = mpz_size(z.get_mpz_t()) ? static_cast<std::size_t>(mpz_getlimbn(z.get_mpz_t(), 0)) : 0;
      h ^= (low + static_cast<std::size_t>(mpz_sgn(z.get_mpz_t()) + 1) * 0x9e3779b97f4a7c15ull) + (h << 6) + (h >> 2);
    };
    for (int k = 0; k < 3; ++k) mix(p[k].get_num()), mix(p[k].get_den());
    return h;
  }
};

struct Joiner {
  std::unordered_map<Point3, int, PointHash> id;
  CutSolid out;
  void add(const std::vector<Point3>& corners, int part, int cap) {
    Face f;
    for (const Point3& p : corners) {
      auto [it, fresh] = id.emplace(p, static_cast<int>(out.vertices.size()));
      if (fresh) out.vertices.push_back(p);
      f.push_back(it->second);
    }
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
    for (std::size_t f = 0; f < c.faces.size(); ++f) {
      if (c.cap[f] >= 0 && c.cap[f] < static_cast<int>(i)) continue;  // shared with an earlier piece: inside
      if (c.cap[f] < 0) {
        j.add(corners_of(c, f), c.part[f], -1);
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
