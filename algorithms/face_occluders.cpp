// Per-face occluders (see face_occluders.hpp).
#include "algorithms/face_occluders.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>
#include <tuple>

#include "algorithms/crease_angle.hpp"
#include "algorithms/intersection_lines.hpp"
#include "algorithms/triangulate.hpp"
#include "kernel/int128.hpp"

namespace hlr {
namespace {

// ---------------------------------------------------------------- number policies
// Fast: coordinates below 2^29 in 64-bit integers; cross products below 2^61 (64-bit); plane
// values below 2^93 (128-bit); products of two values compared in 256 bits.
struct Fast {
  using C = std::int64_t;
  using V = Int128;
  static V mul(C a, C b) { return static_cast<V>(a) * b; }
  static int sign(const V& v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }
  static double dbl(const V& v) { return static_cast<double>(v); }
  static int compare(const V& a, const V& b, const V& c, const V& d) { return compare_products(a, b, c, d); }
  static mpz_class z(const V& v) { return to_mpz(v); }
  static mpz_class zc(C v) { return mpz_class(static_cast<long>(v)); }
};

// Fast40: coordinates below 2^40 (decimals with up to 10 places, as in scanned meshes) held in
// 128-bit integers: cross products below 2^84, plane values below 2^126, still exact.
struct Fast40 {
  using C = Int128;
  using V = Int128;
  static V mul(C a, C b) { return a * b; }
  static int sign(const V& v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }
  static double dbl(const V& v) { return static_cast<double>(v); }
  static int compare(const V& a, const V& b, const V& c, const V& d) { return compare_products(a, b, c, d); }
  static mpz_class z(const V& v) { return to_mpz(v); }
  static mpz_class zc(C v) { return to_mpz(v); }
};

// Big: the same on GMP integers, for coordinates that do not fit.
struct Big {
  using C = mpz_class;
  using V = mpz_class;
  static V mul(const C& a, const C& b) { return a * b; }
  static int sign(const V& v) { return sgn(v); }
  static double dbl(const V& v) { return v.get_d(); }
  static int compare(const V& a, const V& b, const V& c, const V& d) {
    mpz_class l = a * b, r = c * d;
    return cmp(l, r) < 0 ? -1 : (cmp(l, r) > 0 ? 1 : 0);
  }
  static const mpz_class& z(const V& v) { return v; }
  static const mpz_class& zc(const C& v) { return v; }
};

template <class P>
using Vec = std::array<typename P::C, 3>;

template <class P>
Vec<P> sub(const Vec<P>& a, const Vec<P>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class P>
Vec<P> cross(const Vec<P>& a, const Vec<P>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class P>
typename P::V dot(const Vec<P>& a, const Vec<P>& b) {
  return P::mul(a[0], b[0]) + P::mul(a[1], b[1]) + P::mul(a[2], b[2]);
}
template <class P>
Vec<P> neg(const Vec<P>& a) {
  return {-a[0], -a[1], -a[2]};
}

// A split parameter num/den (den > 0) with a double approximation for the filter.
template <class P>
struct Frac {
  typename P::V n, d;
  double x;
};

struct Counters {
  std::size_t pairs = 0, skipped = 0, comparisons = 0, exact = 0, identical = 0;
};

// Exact order of two split parameters: identical fractions (neighbouring occluders share a
// side plane, so this is common) are recognised first, then a double filter, then 256-bit
// (or GMP) cross products.
template <class P>
int compare(const Frac<P>& a, const Frac<P>& b, Counters& c) {
  ++c.comparisons;
  if (a.n == b.n && a.d == b.d) {
    ++c.identical;
    return 0;
  }
  double diff = a.x - b.x, scale = std::fabs(a.x) + std::fabs(b.x);
  if (std::fabs(diff) > 1e-12 * scale + 1e-300) return diff < 0 ? -1 : 1;
  ++c.exact;
  return P::compare(a.n, b.d, b.n, a.d);
}

// ---------------------------------------------------------------- scene in integers
struct Tri {
  int body, face;
  std::array<int, 3> v;      // global vertex ids, the face's orientation
  std::array<bool, 3> edge;  // side k is a polygon edge (else a diagonal)
};

// One undirected edge of a body: its faces (with the polygon slot of each use).
struct EdgeUse {
  int face, slot;  // slot: face_offset[face] + position of the edge's first vertex
  bool forward;    // traversed from the lower vertex id to the higher
};

template <class P>
struct Occluder {
  Vec<P> m[4];
  typename P::V c[4];  // constraint k: m[k]·X - c[k] > 0 (or >= 0 when closed[k])
  bool closed[4] = {false, false, false, false};
  int body, face;
  std::array<int, 3> v;  // global vertex ids, oriented toward the viewer (side k+1: v[k] -> v[k+1])
};

struct Box {
  float x0, y0, x1, y1;
  double dmin;
};

class Grid {
 public:
  void build(const std::vector<Box>& boxes, const std::vector<char>& always) {
    double X0 = std::numeric_limits<double>::infinity(), Y0 = X0, X1 = -X0, Y1 = -X0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      if (always[i]) {
        always_.push_back(static_cast<int>(i));
        continue;
      }
      ++count;
      X0 = std::min<double>(X0, boxes[i].x0);
      Y0 = std::min<double>(Y0, boxes[i].y0);
      X1 = std::max<double>(X1, boxes[i].x1);
      Y1 = std::max<double>(Y1, boxes[i].y1);
    }
    if (!(X1 >= X0)) X0 = Y0 = 0, X1 = Y1 = 1;
    n_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(count) / 2)), 1, 2048);
    x0_ = X0;
    y0_ = Y0;
    cell_ = std::max({(X1 - X0) / n_, (Y1 - Y0) / n_, 1e-300});
    start_.assign(static_cast<std::size_t>(n_) * n_ + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<std::uint32_t> fill;
      if (pass == 1) {
        for (std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
        items_.resize(start_.back());
        fill.assign(start_.begin(), start_.end() - 1);
      }
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        if (always[i]) continue;
        auto [cx0, cy0, cx1, cy1] = range(boxes[i].x0, boxes[i].y0, boxes[i].x1, boxes[i].y1);
        for (int cy = cy0; cy <= cy1; ++cy)
          for (int cx = cx0; cx <= cx1; ++cx) {
            std::size_t cellid = static_cast<std::size_t>(cy) * n_ + cx;
            if (pass == 0) ++start_[cellid + 1];
            else items_[fill[cellid]++] = static_cast<std::uint32_t>(i);
          }
      }
    }
  }
  std::array<int, 4> range(double x0, double y0, double x1, double y1) const {
    auto c = [&](double v, double o) {
      double k = std::floor((v - o) / cell_);
      return static_cast<int>(std::clamp(k, 0.0, static_cast<double>(n_ - 1)));
    };
    return {c(x0, x0_), c(y0, y0_), c(x1, x0_), c(y1, y0_)};
  }
  template <class F>
  void visit(double x0, double y0, double x1, double y1, F&& f) const {
    for (int i : always_) f(i);
    auto [cx0, cy0, cx1, cy1] = range(x0, y0, x1, y1);
    for (int cy = cy0; cy <= cy1; ++cy)
      for (int cx = cx0; cx <= cx1; ++cx) {
        std::size_t id = static_cast<std::size_t>(cy) * n_ + cx;
        for (std::uint32_t k = start_[id]; k < start_[id + 1]; ++k) f(static_cast<int>(items_[k]));
      }
  }

 private:
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int n_ = 1;
  std::vector<std::uint32_t> start_, items_;
  std::vector<int> always_;
};

// ---------------------------------------------------------------- the engine
template <class P>
class Engine {
 public:
  using C = typename P::C;
  using V = typename P::V;

  Engine(const std::vector<const Polyhedron*>& bodies, const Camera& cam, const LineOptions& opt,
         std::vector<Vec<P>> pts, Vec<P> view, Rational scale)
      : bodies_(bodies), cam_(cam), opt_(opt), X_(std::move(pts)), view_(std::move(view)), scale_(std::move(scale)),
        proj_(cam), crease_(opt.crease_degrees) {}

  RobertsResult run() {
    RobertsResult res;
    res.stats.method = "faces";
    res.stats.integer_path = !std::is_same_v<P, Big>;
    using Clock = std::chrono::steady_clock;
    auto t0 = Clock::now();
    offsets();
    for (std::size_t b = 0; b < bodies_.size(); ++b) prepare_body(static_cast<int>(b), res);
    build_occluders();
    res.stats.occluders = occ_.size();
    std::size_t total = 0;
    for (const auto& E : edges_) total += E.size();
    res.segments.reserve(total + 64);
    gv_.reserve(total + 64);
    for (std::size_t b = 0; b < bodies_.size(); ++b) collect_edges(static_cast<int>(b), res);
    // Edge structure is no longer needed: free it before the memory-heavy stages.
    release(edges_);
    release(slot_edges_);
    release(slot_third_);
    release(face_offset_);
    release(face_normal_);
    auto t1 = Clock::now();
    if (opt_.intersections) add_intersections(res);
    auto t2 = Clock::now();
    visibility(res);
    auto t3 = Clock::now();
    res.stats.setup_seconds = std::chrono::duration<double>(t1 - t0).count();
    res.stats.intersections_seconds = std::chrono::duration<double>(t2 - t1).count();
    res.stats.visibility_seconds = std::chrono::duration<double>(t3 - t2).count();
    return res;
  }

 private:
  // ---- per body: triangles, facing, edge uses
  void offsets() {
    int o = 0;
    for (const Polyhedron* p : bodies_) {
      voff_.push_back(o);
      o += static_cast<int>(p->num_vertices());
    }
    solid_.assign(bodies_.size(), false);
    degenerate_.resize(bodies_.size());
    face_normal_.resize(bodies_.size());
    facing_.resize(bodies_.size());
    face_offset_.resize(bodies_.size());
    slot_third_.resize(bodies_.size());
    edges_.resize(bodies_.size());
  }

  Vec<P> normal(const Tri& t) const {
    return cross<P>(sub<P>(X_[t.v[1]], X_[t.v[0]]), sub<P>(X_[t.v[2]], X_[t.v[0]]));
  }
  // Sign of the viewer's side of a plane through `a` with normal n: positive = facing.
  int facing_sign(const Vec<P>& n, int a) const {
    return cam_.perspective ? P::sign(dot<P>(n, sub<P>(view_, X_[a]))) : P::sign(dot<P>(n, view_));
  }

  void prepare_body(int b, RobertsResult& res) {
    const Polyhedron& p = *bodies_[b];
    const int vo = voff_[b];
    const auto& faces = p.faces();
    std::vector<int>& fo = face_offset_[b];
    fo.resize(faces.size() + 1, 0);
    for (std::size_t f = 0; f < faces.size(); ++f) fo[f + 1] = fo[f] + static_cast<int>(faces[f].size());
    slot_third_[b].assign(fo.back(), -1);
    std::vector<int>& facing = facing_[b];
    facing.assign(faces.size(), 0);
    degenerate_[b].assign(faces.size(), 0);
    face_normal_[b].resize(faces.size());
    const std::size_t first_tri = tris_.size();
    std::vector<const Point3*> pts;
    std::vector<FaceTriangle> ft;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const Face& face = faces[f];
      ft.clear();
      if (face.size() == 3) {
        ft.push_back({{0, 1, 2}, {true, true, true}});
        Tri probe{b, static_cast<int>(f), {vo + face[0], vo + face[1], vo + face[2]}, {true, true, true}};
        Vec<P> n = normal(probe);
        if (P::sign(n[0]) == 0 && P::sign(n[1]) == 0 && P::sign(n[2]) == 0) {
          degenerate_[b][f] = 1;  // zero area: neither occludes nor faces
          continue;
        }
      } else {
        pts.clear();
        for (int v : face) pts.push_back(&p.vertices()[v]);
        Plane h = plane_of_polygon(pts.data(), pts.size());
        if (h.is_degenerate()) {
          degenerate_[b][f] = 1;
          continue;
        }
        for (std::size_t k = 0; k < face.size(); ++k)
          if (h.value(*pts[k]) != 0)
            throw RobertsError(b, "body " + std::to_string(b) + " has a non-planar face (face " + std::to_string(f) + ", vertex " +
                                      std::to_string(face[k]) + " is off its plane)");
        ft = triangulate_face(p.vertices(), face, h.normal());
        if (ft.empty())
          throw RobertsError(b, "body " + std::to_string(b) + " has a self-intersecting face (face " + std::to_string(f) + ")");
      }
      for (const FaceTriangle& t : ft) {
        Tri tri{b, static_cast<int>(f), {vo + face[t.v[0]], vo + face[t.v[1]], vo + face[t.v[2]]}, t.edge};
        for (int k = 0; k < 3; ++k)
          if (t.edge[k]) slot_third_[b][fo[f] + t.v[k]] = tri.v[(k + 2) % 3];  // side k's opposite vertex
        tris_.push_back(tri);
      }
      face_normal_[b][f] = normal(tris_.back());
      facing[f] = facing_sign(face_normal_[b][f], tris_.back().v[0]);
    }
    group_edges(b);
    // A closed solid: every edge in exactly two faces, traversed in opposite directions.
    bool closed = true;
    for (const BodyEdge& e : edges_[b])
      closed = closed && e.uses.size() == 2 && e.uses[0].forward != e.uses[1].forward;
    // Six times the volume; Fast40's terms reach 2^123, so its sum is kept in GMP.
    int volume_sign = 0;
    if (closed) {
      if constexpr (std::is_same_v<P, Fast40>) {
        mpz_class v6 = 0;
        for (std::size_t i = first_tri; i < tris_.size(); ++i)
          v6 += P::z(dot<P>(sub<P>(X_[tris_[i].v[0]], X_[tris_[first_tri].v[0]]),
                            cross<P>(sub<P>(X_[tris_[i].v[1]], X_[tris_[first_tri].v[0]]), sub<P>(X_[tris_[i].v[2]], X_[tris_[first_tri].v[0]]))));
        volume_sign = sgn(v6);
      } else {
        V volume6 = 0;
        for (std::size_t i = first_tri; i < tris_.size(); ++i)
          volume6 += dot<P>(X_[tris_[i].v[0]], cross<P>(X_[tris_[i].v[1]], X_[tris_[i].v[2]]));
        volume_sign = P::sign(volume6);
      }
    }
    solid_[b] = closed && volume_sign != 0;
    if (!solid_[b]) {
      std::string why = "has zero volume";
      for (const BodyEdge& e : edges_[b])
        if (e.uses.size() != 2 || e.uses[0].forward == e.uses[1].forward) {
          why = e.uses.size() == 1   ? "is open (edge " + std::to_string(e.u) + "-" + std::to_string(e.v) + " is in one face)"
                : e.uses.size() != 2 ? "is not manifold (edge " + std::to_string(e.u) + "-" + std::to_string(e.v) + " is in " +
                                           std::to_string(e.uses.size()) + " faces)"
                                     : "is not consistently oriented (edge " + std::to_string(e.u) + "-" + std::to_string(e.v) + ")";
          break;
        }
      res.notes.push_back({b, "body " + std::to_string(b) + " " + why + ": drawn as a surface (hidden where a sight ray crosses it)"});
    }
    if (solid_[b] && cam_.perspective && eye_inside(static_cast<int>(first_tri)))
      throw RobertsError(b, "body " + std::to_string(b) + " contains the eye " + to_string(cam_.eye) +
                                ": an eye inside a solid sees nothing");
    if (solid_[b] && volume_sign < 0) {  // inside out: turn it
      for (std::size_t i = first_tri; i < tris_.size(); ++i) flip(tris_[i]);
      for (int& s : facing) s = -s;
      for (auto& n : face_normal_[b]) n = neg<P>(n);
      flipped_.push_back(b);
    }
    res.facing.emplace_back(facing.begin(), facing.end());
  }

  void group_edges(int b) {
    const auto& faces = bodies_[b]->faces();
    const std::vector<int>& fo = face_offset_[b];
    // Edge uses, grouped by undirected edge.
    struct U {
      std::uint64_t key;
      int face, slot;
      bool forward;
    };
    // Bucketed by the lower vertex (counting sort, linear), then sorted within each bucket.
    const std::size_t nv = bodies_[b]->num_vertices();
    std::vector<std::uint32_t> start(nv + 1, 0);
    for (std::size_t f = 0; f < faces.size(); ++f)
      for (std::size_t k = 0; k < faces[f].size(); ++k) {
        int u = faces[f][k], v = faces[f][(k + 1) % faces[f].size()];
        if (u != v) ++start[std::min(u, v) + 1];
      }
    for (std::size_t i = 1; i <= nv; ++i) start[i] += start[i - 1];
    std::vector<U> uses(start[nv]);
    {
      std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
      for (std::size_t f = 0; f < faces.size(); ++f)
        for (std::size_t k = 0; k < faces[f].size(); ++k) {
          int u = faces[f][k], v = faces[f][(k + 1) % faces[f].size()];
          if (u == v) continue;
          std::uint64_t key = (static_cast<std::uint64_t>(std::min(u, v)) << 32) | static_cast<std::uint32_t>(std::max(u, v));
          uses[fill[std::min(u, v)]++] = {key, static_cast<int>(f), fo[f] + static_cast<int>(k), u < v};
        }
    }
    auto less = [](const U& a, const U& c) { return a.key < c.key || (a.key == c.key && a.slot < c.slot); };
    for (std::size_t i = 0; i < nv; ++i)
      if (start[i + 1] - start[i] > 1) std::sort(uses.begin() + start[i], uses.begin() + start[i + 1], less);
    auto& E = edges_[b];
    std::vector<int>& se = slot_edge_body_(b, fo.back());
    for (std::size_t i = 0; i < uses.size();) {
      std::size_t j = i;
      BodyEdge e;
      e.u = static_cast<int>(uses[i].key >> 32);
      e.v = static_cast<int>(uses[i].key & 0xffffffffu);
      for (; j < uses.size() && uses[j].key == uses[i].key; ++j) {
        e.uses.push_back({uses[j].face, uses[j].slot, uses[j].forward});
        se[uses[j].slot] = static_cast<int>(E.size());
      }
      E.push_back(std::move(e));
      i = j;
    }
  }

  // Parity of the crossings of a ray from the eye with the body's triangles (from `first`
  // on), exactly; a ray through an edge or a vertex is replaced by the next direction.
  bool eye_inside(int first) const {
    static const int dirs[][3] = {{7, 3, 5}, {2, 11, 3}, {-13, 1, 7}, {5, -9, 2}, {1, 4, -11}, {-3, -5, 8}, {17, 6, -1}, {-2, 3, -19}};
    for (const auto& dd : dirs) {
      Vec<P> d{C(dd[0]), C(dd[1]), C(dd[2])};
      bool degenerate = false;
      int crossings = 0;
      for (std::size_t i = first; i < tris_.size() && tris_[i].body == tris_[first].body && !degenerate; ++i) {
        const Tri& t = tris_[i];
        Vec<P> a = sub<P>(X_[t.v[0]], view_), b = sub<P>(X_[t.v[1]], view_), c = sub<P>(X_[t.v[2]], view_);
        int o1 = P::sign(dot<P>(a, cross<P>(b, d))), o2 = P::sign(dot<P>(b, cross<P>(c, d))), o3 = P::sign(dot<P>(c, cross<P>(a, d)));
        if (!((o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0))) continue;  // the line misses it
        if (o1 == 0 || o2 == 0 || o3 == 0) {
          degenerate = true;  // through an edge or a vertex (or in its plane)
          break;
        }
        Vec<P> n = normal(t);
        int sa = P::sign(dot<P>(n, a)), sd = P::sign(dot<P>(n, d));
        if (sa == 0) return false;  // the eye lies on the surface: not inside
        if (sa == sd) ++crossings;  // the crossing is ahead of the eye
      }
      if (!degenerate) return crossings % 2 == 1;
    }
    return false;
  }

  template <class T>
  static void release(T& v) {
    T().swap(v);
  }

  static void flip(Tri& t) {
    std::swap(t.v[1], t.v[2]);
    // Sides were (0,1), (1,2), (2,0); now (0,2)=old 2, (2,1)=old 1, (1,0)=old 0.
    t.edge = {t.edge[2], t.edge[1], t.edge[0]};
  }

  struct BodyEdge {
    int u, v;  // body-local vertex ids, u < v
    std::vector<EdgeUse> uses;
  };

  std::vector<int>& slot_edge_body_(int b, int n) {
    if (static_cast<int>(slot_edges_.size()) <= b) slot_edges_.resize(b + 1);
    slot_edges_[b].assign(n, -1);
    return slot_edges_[b];
  }

  // ---- occluders
  // The neighbour of triangle side (p -> q) across a polygon edge: its face and the opposite
  // vertex of its triangle on that edge; false for boundary, non-manifold or degenerate.
  bool neighbour(const Tri& t, int k, int& face, int& third) const {
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
    const int slot = face_offset_[b][t.face] + pos;
    const int e = slot_edges_[b][slot];
    if (e < 0) return false;
    const BodyEdge& be = edges_[b][e];
    if (be.uses.size() != 2) return false;
    const EdgeUse& other = be.uses[0].slot == slot ? be.uses[1] : be.uses[0];
    if (degenerate_[b][other.face]) return false;
    face = other.face;
    third = slot_third_[b][other.slot];
    return third >= 0;
  }

  // A vertex hides the sight line just behind it when every face around it faces the viewer
  // (solid: all front, so the surface is locally a graph over the image with material behind;
  // open surface: all one way and not on the boundary, so the ray crosses it). Faces that are
  // edge-on or turn away around a vertex: not closed (a ray along the boundary).
  void vertex_rules() {
    // 0 unset, 1 all facing, 2 all non-facing, 3 mixed or edge-on or boundary.
    std::vector<char> state(X_.size(), 0);
    auto mark = [&](int g, char st) {
      char& x = state[g];
      x = (x == 0 || x == st) ? st : 3;
    };
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      const auto& faces = bodies_[b]->faces();
      for (std::size_t f = 0; f < faces.size(); ++f) {
        int fs = facing_[b][f];
        char st = degenerate_[b][f] || fs == 0 ? 3 : (fs > 0 ? 1 : (solid_[b] ? 3 : 2));
        for (int v : faces[f]) mark(voff_[b] + v, st);
      }
      for (const BodyEdge& e : edges_[b])
        if (e.uses.size() != 2) mark(voff_[b] + e.u, 3), mark(voff_[b] + e.v, 3);
    }
    vertex_closed_.resize(X_.size());
    for (std::size_t g = 0; g < X_.size(); ++g) vertex_closed_[g] = state[g] == 1 || state[g] == 2;
  }

  void build_occluders() {
    vertex_rules();
    occ_.reserve(tris_.size() / 2 + 1);
    std::vector<Box> boxes;
    std::vector<char> always;
    // Drawing projections of every vertex, once.
    vproj_.resize(X_.size());
    vfront_.assign(X_.size(), 1);
    for (std::size_t b = 0; b < bodies_.size(); ++b)
      for (std::size_t i = 0; i < bodies_[b]->num_vertices(); ++i) {
        const Point3& q = bodies_[b]->vertices()[i];
        vproj_[voff_[b] + i] = proj_.project(q);
        if (cam_.perspective) vfront_[voff_[b] + i] = cam_.in_front(q) == Sign::Positive;
      }
    std::vector<int> sel;
    for (std::size_t i = 0; i < tris_.size(); ++i) {
      const Tri& t0 = tris_[i];
      int fs = facing_[t0.body][t0.face];
      if (fs == 0) continue;                       // edge-on: sight rays graze it
      if (solid_[t0.body] && fs < 0) continue;     // a closed solid is hidden by its front faces
      sel.push_back(static_cast<int>(i));
    }
    occ_.resize(sel.size());
    boxes.resize(sel.size());
    always.resize(sel.size());
    parallel_for(sel.size(), [&](std::size_t i) { make_occluder(tris_[sel[i]], occ_[i], boxes[i], always[i]); });
    // Widen every box by a margin far above the error of the double projections (a filter
    // only: it skips work, never decides).
    double ext = 1e-300;
    for (std::size_t i = 0; i < boxes.size(); ++i)
      if (!always[i])
        ext = std::max({ext, std::fabs(static_cast<double>(boxes[i].x0)), std::fabs(static_cast<double>(boxes[i].x1)),
                        std::fabs(static_cast<double>(boxes[i].y0)), std::fabs(static_cast<double>(boxes[i].y1)),
                        std::fabs(boxes[i].dmin)});
    margin_ = 1e-6 * ext;
    for (Box& bx : boxes) {
      bx.x0 -= static_cast<float>(margin_);
      bx.y0 -= static_cast<float>(margin_);
      bx.x1 += static_cast<float>(margin_);
      bx.y1 += static_cast<float>(margin_);
      bx.dmin -= margin_;
    }
    boxes_ = std::move(boxes);
    grid_.build(boxes_, always);
  }

  template <class F>
  void parallel_for(std::size_t n, F&& f) const {
    unsigned threads = opt_.threads ? opt_.threads : std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, n / 4096)));
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
      for (;;) {
        std::size_t i0 = next.fetch_add(1024);
        if (i0 >= n) break;
        for (std::size_t i = i0; i < std::min(n, i0 + 1024); ++i) f(i);
      }
    };
    if (threads <= 1) {
      worker();
      return;
    }
    std::vector<std::thread> pool;
    for (unsigned w = 0; w < threads; ++w) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
  }

  void make_occluder(const Tri& t0, Occluder<P>& o, Box& bx, char& always) const {
    const int b = t0.body;
    const int fs = facing_[b][t0.face];
    Tri t = t0;
    if (fs < 0) flip(t);  // open surface seen from its back: orient toward the viewer
    o.body = b;
    o.face = t.face;
    o.v = t.v;
    Vec<P> n = normal(t);
    // Constraint 0: strictly behind the plane: -n·(X - a) > 0.
    o.m[0] = neg<P>(n);
    o.c[0] = dot<P>(o.m[0], X_[t.v[0]]);
    for (int k = 0; k < 3; ++k) {
      int r = t.v[(k + 2) % 3];
      Vec<P> m;
      V c;
      side_plane(t.v[k], t.v[(k + 1) % 3], m, c);
      if (P::sign(dot<P>(m, X_[r]) - c) < 0) {
        m = neg<P>(m);
        c = -c;
      }
      o.m[k + 1] = m;
      o.c[k + 1] = c;
      o.closed[k + 1] = !t.edge[k] || closed_side(t, k, m, c, fs);
    }
    bx = Box{std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
             -std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
             std::numeric_limits<double>::infinity()};
    bool all_front = true;
    for (int v : t.v) {
      const auto& pr = vproj_[v];
      bx.x0 = std::min(bx.x0, std::nextafter(static_cast<float>(pr[0]), -INFINITY));
      bx.y0 = std::min(bx.y0, std::nextafter(static_cast<float>(pr[1]), -INFINITY));
      bx.x1 = std::max(bx.x1, std::nextafter(static_cast<float>(pr[0]), INFINITY));
      bx.y1 = std::max(bx.y1, std::nextafter(static_cast<float>(pr[1]), INFINITY));
      bx.dmin = std::min(bx.dmin, pr[2]);
      all_front = all_front && vfront_[v];
    }
    always = !all_front;
  }

  // Is the sight ray just behind the polygon edge under side k inside the body (closed side)?
  bool closed_side(const Tri& t, int k, const Vec<P>& m, const V& c, int fs) const {
    int g = -1, third = -1;
    if (!neighbour(t, k, g, third)) return false;
    const int b = t.body;
    if (solid_[b]) {
      // Wedge: where the neighbour's far vertex lies against this (front) face's plane.
      Vec<P> n = normal(t);
      int w = P::sign(dot<P>(n, sub<P>(X_[third], X_[t.v[0]])));
      if (w > 0) return true;              // reflex edge: the wedge holds the ray
      return facing_[b][g] > 0;            // convex or flat: both faces toward the viewer
    }
    // Open surface: the neighbour continues on the other side of the edge in the projection.
    return P::sign(dot<P>(m, X_[third]) - c) < 0;
  }

  // ---- drawn edges
  void collect_edges(int b, RobertsResult& res) {
    const Polyhedron& p = *bodies_[b];
    const auto& facing = facing_[b];
    for (const BodyEdge& e : edges_[b]) {
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
          int third_a = slot_third_[b][a.slot], third_c = slot_third_[b][c.slot];
          if (third_a >= 0 && third_c >= 0 && !opposite_in_projection(voff_[b] + e.u, voff_[b] + e.v, third_a, third_c))
            kind = LineKind::Silhouette;
        }
        if (kind == LineKind::Edge && opt_.edges == EdgeSelection::Feature && crease(b, a, c)) kind = LineKind::Crease;
      } else if (live.size() == 1) {
        kind = LineKind::Boundary;
      } else {
        kind = LineKind::Crease;  // non-manifold: a feature
      }
      if (opt_.edges == EdgeSelection::Feature && kind == LineKind::Edge) continue;
      if (opt_.edges == EdgeSelection::All) kind = LineKind::Edge;
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

  // The plane through vertices p and q containing the view direction (orthographic) or the eye
  // (perspective), as m·X - c = 0; its orientation is the caller's to fix.
  void side_plane(int p, int q, Vec<P>& m, V& c) const {
    if (cam_.perspective) {
      m = cross<P>(sub<P>(X_[p], view_), sub<P>(X_[q], view_));
      c = dot<P>(m, view_);
    } else {
      m = cross<P>(view_, sub<P>(X_[q], X_[p]));
      c = dot<P>(m, X_[p]);
    }
  }

  // The far vertices x and y of two triangles on edge (u, v) lie strictly on opposite sides of
  // the edge in the projection.
  bool opposite_in_projection(int u, int v, int x, int y) const {
    Vec<P> m;
    V c;
    side_plane(u, v, m, c);
    return P::sign(dot<P>(m, X_[x]) - c) * P::sign(dot<P>(m, X_[y]) - c) < 0;
  }

  bool crease(int b, const EdgeUse& a, const EdgeUse& c) const {
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

  // ---- intersection lines
  // Broad phase: triangles' bounding boxes hashed into cubic cells (a pair is tested in the
  // cell holding the low corner of the boxes' overlap, so once); exact integer plane-side
  // tests reject almost every pair; the segment itself is built in rationals.
  void add_intersections(RobertsResult& res) {
    const std::size_t n = tris_.size();
    if (n < 2) return;
    std::vector<std::array<double, 6>> bb(n);
    double mean = 0;
    for (std::size_t i = 0; i < n; ++i) {
      std::array<double, 6> b{INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
      for (int v : tris_[i].v) {
        const Point3& q = bodies_[tris_[i].body]->vertices()[v - voff_[tris_[i].body]];
        for (int k = 0; k < 3; ++k) {
          b[k] = std::min(b[k], q.approx(k).lo);
          b[k + 3] = std::max(b[k + 3], q.approx(k).hi);
        }
      }
      bb[i] = b;
      mean += std::max({b[3] - b[0], b[4] - b[1], b[5] - b[2]});
    }
    double lo[3] = {INFINITY, INFINITY, INFINITY};
    for (const auto& b : bb)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], b[k]);
    double hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (const auto& b : bb)
      for (int k = 0; k < 3; ++k) hi[k] = std::max(hi[k], b[k + 3]);
    double cell = std::max(2 * mean / static_cast<double>(n), 1e-300);
    auto key = [&](int k, double x) { return static_cast<std::int64_t>(std::floor((x - lo[k]) / cell)); };
    // Dense cell numbers (x, y, z) -> (x·ny + y)·nz + z keep the radix sort short.
    std::int64_t dims[3];
    for (int k = 0; k < 3; ++k) dims[k] = key(k, hi[k]) + 1;
    auto cell_id = [&](std::int64_t x, std::int64_t y, std::int64_t z) {
      return static_cast<std::uint64_t>((x * dims[1] + y) * dims[2] + z);
    };
    struct Entry {
      std::uint64_t cell;
      std::uint32_t tri;
    };
    std::vector<Entry> entries;
    entries.reserve(n * 2);
    bool coarse = false;
    for (std::size_t i = 0; i < n && !coarse; ++i) {
      std::int64_t c0[3], c1[3];
      for (int k = 0; k < 3; ++k) c0[k] = key(k, bb[i][k]), c1[k] = key(k, bb[i][k + 3]);
      if ((c1[0] - c0[0] + 1) * (c1[1] - c0[1] + 1) * (c1[2] - c0[2] + 1) > 64 || dims[0] >= (1 << 20) || dims[1] >= (1 << 20) || dims[2] >= (1 << 20)) {
        coarse = true;  // a huge triangle among small ones: fall back to one coarse cell list
        break;
      }
      for (std::int64_t x = c0[0]; x <= c1[0]; ++x)
        for (std::int64_t y = c0[1]; y <= c1[1]; ++y)
          for (std::int64_t z = c0[2]; z <= c1[2]; ++z)
            entries.push_back({cell_id(x, y, z),
                               static_cast<std::uint32_t>(i)});
    }
    if (coarse) {
      entries.clear();
      for (std::size_t i = 0; i < n; ++i) entries.push_back({0, static_cast<std::uint32_t>(i)});
    }
    radix_sort(entries);
    // Cells in ranges for the threads; each keeps its own hits.
    std::vector<std::size_t> cell_start;
    for (std::size_t i = 0; i < entries.size(); ++i)
      if (i == 0 || entries[i].cell != entries[i - 1].cell) cell_start.push_back(i);
    cell_start.push_back(entries.size());
    const std::size_t ncells = cell_start.size() - 1;
    unsigned threads = opt_.threads ? opt_.threads : std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, ncells / 64)));
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> found(threads);
    std::vector<std::size_t> counted(threads, 0);
    std::atomic<std::size_t> next_cell{0};
    auto worker = [&](unsigned w) {
      for (;;) {
        std::size_t c0 = next_cell.fetch_add(256);
        if (c0 >= ncells) break;
        for (std::size_t c = c0; c < std::min(ncells, c0 + 256); ++c)
          pairs_in_cell(entries, cell_start[c], cell_start[c + 1], bb, coarse, key, cell_id, found[w], counted[w]);
      }
    };
    if (threads <= 1) {
      worker(0);
    } else {
      std::vector<std::thread> pool;
      for (unsigned w = 0; w < threads; ++w) pool.emplace_back(worker, w);
      for (auto& t : pool) t.join();
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> hits;
    std::size_t tested = 0;
    for (unsigned w = 0; w < threads; ++w) {
      hits.insert(hits.end(), found[w].begin(), found[w].end());
      tested += counted[w];
    }
    res.stats.intersection_pairs = tested;
    std::sort(hits.begin(), hits.end());
    std::vector<std::tuple<int, int, int, int, Point3, Point3>> segs;
    for (auto [ta, tc] : hits) {
      const Tri &x = tris_[ta], &y = tris_[tc];
      TriangleRef rx{{&world(x.v[0]), &world(x.v[1]), &world(x.v[2])}, x.edge};
      TriangleRef ry{{&world(y.v[0]), &world(y.v[1]), &world(y.v[2])}, y.edge};
      auto seg = triangle_intersection(rx, ry);
      if (!seg) continue;
      bool swap = y.body < x.body;
      const Tri& f = swap ? y : x;
      const Tri& g = swap ? x : y;
      Point3 a = seg->first, b = seg->second;
      if (b < a) std::swap(a, b);
      segs.emplace_back(f.body, g.body, f.face, g.face, a, b);
    }
    // The same segment from two triangles of one face (along a diagonal): once.
    std::sort(segs.begin(), segs.end(), [](const auto& p, const auto& q) {
      if (std::get<0>(p) != std::get<0>(q)) return std::get<0>(p) < std::get<0>(q);
      if (std::get<1>(p) != std::get<1>(q)) return std::get<1>(p) < std::get<1>(q);
      if (!(std::get<4>(p) == std::get<4>(q))) return std::get<4>(p) < std::get<4>(q);
      if (!(std::get<5>(p) == std::get<5>(q))) return std::get<5>(p) < std::get<5>(q);
      if (std::get<2>(p) != std::get<2>(q)) return std::get<2>(p) < std::get<2>(q);
      return std::get<3>(p) < std::get<3>(q);
    });
    std::vector<std::tuple<int, int, int, int, Point3, Point3>> uniq;
    for (std::size_t i = 0; i < segs.size(); ++i) {
      if (i > 0 && std::get<0>(segs[i - 1]) == std::get<0>(segs[i]) && std::get<1>(segs[i - 1]) == std::get<1>(segs[i]) &&
          std::get<4>(segs[i - 1]) == std::get<4>(segs[i]) && std::get<5>(segs[i - 1]) == std::get<5>(segs[i]))
        continue;
      uniq.push_back(segs[i]);
    }
    join_collinear(uniq);
    for (auto& [b0, b1, f0, f1, a, b] : uniq) {
      Segment s;
      s.kind = Segment::Kind::Intersection;
      s.line = LineKind::Intersection;
      s.body = b0;
      s.body2 = b1;
      s.face0 = f0;
      s.face1 = f1;
      s.set_ends(a, b);
      ++res.stats.junction_segments;
      res.segments.push_back(std::move(s));
      gv_.push_back({-1, -1});
    }
  }

  // Pieces of one face pair's line cut by face diagonals: joined where they meet end to end.
  static void join_collinear(std::vector<std::tuple<int, int, int, int, Point3, Point3>>& v) {
    std::sort(v.begin(), v.end(), [](const auto& p, const auto& q) {
      auto kp = std::make_tuple(std::get<0>(p), std::get<1>(p), std::get<2>(p), std::get<3>(p));
      auto kq = std::make_tuple(std::get<0>(q), std::get<1>(q), std::get<2>(q), std::get<3>(q));
      if (kp != kq) return kp < kq;
      return std::get<4>(p) < std::get<4>(q);
    });
    std::vector<std::tuple<int, int, int, int, Point3, Point3>> out;
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

  // Stable LSD radix sort by cell (entries arrive in triangle order, so ties stay sorted by
  // triangle): 11-bit digits over the bits the keys use.
  template <class E>
  static void radix_sort(std::vector<E>& v) {
    std::uint64_t all = 0;
    for (const E& e : v) all |= e.cell;
    std::vector<E> tmp(v.size());
    for (int shift = 0; shift < 64 && (all >> shift) != 0; shift += 11) {
      std::array<std::size_t, 2049> count{};
      for (const E& e : v) ++count[((e.cell >> shift) & 2047) + 1];
      for (int i = 1; i < 2049; ++i) count[i] += count[i - 1];
      for (const E& e : v) tmp[count[(e.cell >> shift) & 2047]++] = e;
      v.swap(tmp);
    }
  }

  template <class E, class Key, class Id>
  void pairs_in_cell(const std::vector<E>& entries, std::size_t i, std::size_t j, const std::vector<std::array<double, 6>>& bb,
                     bool coarse, const Key& key, const Id& cell_id, std::vector<std::pair<std::uint32_t, std::uint32_t>>& hits,
                     std::size_t& tested) const {
    for (std::size_t a = i; a < j; ++a)
      for (std::size_t c = a + 1; c < j; ++c) {
        std::uint32_t ta = entries[a].tri, tc = entries[c].tri;
        const auto &A = bb[ta], &B = bb[tc];
        if (A[0] > B[3] || B[0] > A[3] || A[1] > B[4] || B[1] > A[4] || A[2] > B[5] || B[2] > A[5]) continue;
        if (!coarse) {  // test the pair only in the cell of the overlap's low corner
          std::uint64_t own = cell_id(key(0, std::max(A[0], B[0])), key(1, std::max(A[1], B[1])), key(2, std::max(A[2], B[2])));
          if (own != entries[i].cell) continue;
        }
        const Tri &x = tris_[ta], &y = tris_[tc];
        if (x.body == y.body) {
          bool shared = false;
          for (int u : x.v)
            for (int w : y.v) shared = shared || u == w;
          if (shared || x.face == y.face) continue;
        }
        ++tested;
        if (straddles(x, y) && straddles(y, x) && may_meet(x, y)) hits.push_back({std::min(ta, tc), std::max(ta, tc)});
      }
  }

  const Point3& world(int g) const {
    int b = static_cast<int>(std::upper_bound(voff_.begin(), voff_.end(), g) - voff_.begin()) - 1;
    return bodies_[b]->vertices()[g - voff_[b]];
  }

  // A filter before the rational construction: the parts of x on y's plane and of y on x's
  // plane lie on one line; if their extents along a coordinate axis are certainly disjoint they
  // do not meet. Plane values are exact integers, so each crossing parameter s/(s - t) (s, t
  // of opposite signs) is within 4 ulps in doubles, each point within 8 ulps of the largest
  // coordinate; intervals farther apart than that are disjoint. Otherwise: exact.
  bool may_meet(const Tri& x, const Tri& y) const {
    double ax[2], ay[2];
    int axis = 0;
    {
      Vec<P> nx = normal(x), ny = normal(y);
      double u[3] = {P::dbl(nx[1]) * P::dbl(ny[2]) - P::dbl(nx[2]) * P::dbl(ny[1]),
                     P::dbl(nx[2]) * P::dbl(ny[0]) - P::dbl(nx[0]) * P::dbl(ny[2]),
                     P::dbl(nx[0]) * P::dbl(ny[1]) - P::dbl(nx[1]) * P::dbl(ny[0])};
      for (int k = 1; k < 3; ++k)
        if (std::fabs(u[k]) > std::fabs(u[axis])) axis = k;
    }
    double scale = 0;
    if (!extent_on_plane(x, y, axis, ax, scale) || !extent_on_plane(y, x, axis, ay, scale)) return true;
    double err = 64 * std::numeric_limits<double>::epsilon() * scale;
    return !(ax[1] + err < ay[0] - err || ay[1] + err < ax[0] - err);
  }

  // Extent along `axis` of the part of t on the plane of o, in doubles; false if undecidable.
  bool extent_on_plane(const Tri& t, const Tri& o, int axis, double out[2], double& scale) const {
    Vec<P> n = normal(o);
    V s[3];
    for (int k = 0; k < 3; ++k) s[k] = dot<P>(n, sub<P>(X_[t.v[k]], X_[o.v[0]]));
    out[0] = INFINITY;
    out[1] = -INFINITY;
    for (int k = 0; k < 3; ++k) {
      double a = P::dbl(X_[t.v[k]][axis]);
      scale = std::max(scale, std::fabs(a));
      int j = (k + 1) % 3;
      int sk = P::sign(s[k]), sj = P::sign(s[j]);
      if (sk == 0) out[0] = std::min(out[0], a), out[1] = std::max(out[1], a);
      if (sk * sj < 0) {
        double u = P::dbl(s[k]) / (P::dbl(s[k]) - P::dbl(s[j]));
        double b = P::dbl(X_[t.v[j]][axis]);
        double c = a + u * (b - a);
        out[0] = std::min(out[0], c);
        out[1] = std::max(out[1], c);
      }
    }
    return std::isfinite(out[0]) && std::isfinite(out[1]) && std::isfinite(scale);
  }

  // Triangle y has vertices strictly on both sides of x's plane, or on it (not all on it).
  bool straddles(const Tri& x, const Tri& y) const {
    Vec<P> n = normal(x);
    int pos = 0, neg_ = 0;
    for (int v : y.v) {
      int s = P::sign(dot<P>(n, sub<P>(X_[v], X_[x.v[0]])));
      pos += s > 0;
      neg_ += s < 0;
    }
    if (pos == 3 || neg_ == 3) return false;
    return pos + neg_ > 0;  // all three on the plane: coplanar, no line
  }

  // ---- visibility
  struct Work {
    Counters c;
    std::vector<std::uint32_t> stamp;
    std::uint32_t current = 0;
    std::vector<int> cand;
    std::vector<std::pair<Frac<P>, Frac<P>>> spans;
  };

  void visibility(RobertsResult& res) {
    const std::size_t n = res.segments.size();
    unsigned threads = opt_.threads ? opt_.threads : std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, n / 256)));
    std::vector<Work> work(threads);
    std::atomic<std::size_t> next{0};
    auto worker = [&](unsigned w) {
      Work& wk = work[w];
      wk.stamp.assign(occ_.size(), 0);
      for (;;) {
        std::size_t i0 = next.fetch_add(512);
        if (i0 >= n) break;
        for (std::size_t i = i0; i < std::min(n, i0 + 512); ++i) solve(res.segments[i], gv_[i], wk);
      }
    };
    if (threads <= 1) {
      worker(0);
    } else {
      std::vector<std::thread> pool;
      for (unsigned w = 0; w < threads; ++w) pool.emplace_back(worker, w);
      for (auto& t : pool) t.join();
    }
    for (const Work& w : work) {
      res.stats.pairs_tested += w.c.pairs;
      res.stats.pairs_skipped += w.c.skipped;
      res.stats.comparisons += w.c.comparisons;
      res.stats.comparisons_exact += w.c.exact;
      res.stats.comparisons_identical += w.c.identical;
    }
    if (std::is_same_v<P, Big>) res.stats.pairs_rational = res.stats.pairs_tested;
  }

  std::optional<std::pair<Rational, Rational>> depth_of(const Segment& s) const {
    if (!cam_.perspective) return std::nullopt;
    return std::make_pair(cam_.depth(s.from()), cam_.depth(s.to()));
  }

  void candidates(const std::array<double, 3>& a, const std::array<double, 3>& b, bool front, Work& wk) const {
    wk.cand.clear();
    if (++wk.current == 0) {
      std::fill(wk.stamp.begin(), wk.stamp.end(), 0);
      wk.current = 1;
    }
    if (!front) {
      for (std::size_t i = 0; i < occ_.size(); ++i) wk.cand.push_back(static_cast<int>(i));
      return;
    }
    double x0 = std::min(a[0], b[0]), x1 = std::max(a[0], b[0]), y0 = std::min(a[1], b[1]), y1 = std::max(a[1], b[1]);
    double dmax = std::max(a[2], b[2]) + margin_;
    grid_.visit(x0 - margin_, y0 - margin_, x1 + margin_, y1 + margin_, [&](int i) {
      if (wk.stamp[i] == wk.current) return;
      wk.stamp[i] = wk.current;
      const Box& bx = boxes_[i];
      if (bx.x0 > x1 + margin_ || bx.x1 < x0 - margin_ || bx.y0 > y1 + margin_ || bx.y1 < y0 - margin_ || bx.dmin > dmax) return;
      wk.cand.push_back(i);
    });
  }

  void solve(Segment& s, const std::array<int, 2>& gv, Work& wk) const {
    if (s.self_hidden) {
      s.pieces = pieces_from_hidden({{Rational(0), Rational(1)}}, depth_of(s));
      return;
    }
    std::array<double, 3> pa, pb;
    bool front = true;
    if (gv[0] >= 0) {
      pa = vproj_[gv[0]];
      pb = vproj_[gv[1]];
      front = vfront_[gv[0]] && vfront_[gv[1]];
    } else {
      pa = proj_.project(s.from());
      pb = proj_.project(s.to());
      front = !cam_.perspective || (cam_.in_front(s.from()) == Sign::Positive && cam_.in_front(s.to()) == Sign::Positive);
    }
    candidates(pa, pb, front, wk);
    wk.c.skipped += occ_.size() - wk.cand.size();
    std::vector<std::pair<Rational, Rational>> hidden;
    if (gv[0] >= 0) {
      wk.spans.clear();
      for (int i : wk.cand) test_integer(occ_[i], X_[gv[0]], X_[gv[1]], wk);
      merge(wk, hidden);
    } else {
      std::array<Rational, 3> A, B;
      for (int k = 0; k < 3; ++k) {
        A[k] = s.from()[k] * scale_;
        B[k] = s.to()[k] * scale_;
      }
      for (int i : wk.cand) test_rational(occ_[i], A, B, hidden, wk);
    }
    s.pieces = pieces_from_hidden(std::move(hidden), depth_of(s));
  }

  // Hidden interval of the segment X0 -> X1 by one occluder, integer values.
  void test_integer(const Occluder<P>& o, const Vec<P>& X0, const Vec<P>& X1, Work& wk) const {
    ++wk.c.pairs;
    bool has_lo = false, has_hi = false;
    Frac<P> lo{V(0), V(1), 0.0}, hi{V(1), V(1), 1.0};
    int on_side = 0;  // bit k: the segment lies in side plane k (closed)
    for (int k = 0; k < 4; ++k) {
      V f0 = dot<P>(o.m[k], X0) - o.c[k];
      V f1 = dot<P>(o.m[k], X1) - o.c[k];
      int s0 = P::sign(f0), s1 = P::sign(f1);
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
        V d = f0 - f1;
        Frac<P> r = s1 == 0 ? Frac<P>{V(1), V(1), 1.0} : Frac<P>{f0, d, P::dbl(f0) / P::dbl(d)};
        if (!has_hi || compare(r, hi, wk.c) < 0) hi = r, has_hi = true;
      } else {  // lower bound t > -f0 / (f1 - f0)
        V d = f1 - f0;
        V nn = -f0;
        Frac<P> r = s0 == 0 ? Frac<P>{V(0), V(1), 0.0} : Frac<P>{nn, d, P::dbl(nn) / P::dbl(d)};
        if (!has_lo || compare(r, lo, wk.c) > 0) lo = r, has_lo = true;
      }
    }
    // In two side planes: the segment runs along the sight line through their common vertex
    // (an edge seen end-on); hidden only where the ray just behind that vertex is inside.
    if (on_side == 6 && !vertex_closed_[o.v[1]]) return;
    if (on_side == 12 && !vertex_closed_[o.v[2]]) return;
    if (on_side == 10 && !vertex_closed_[o.v[0]]) return;
    if (has_lo && has_hi && compare(lo, hi, wk.c) >= 0) return;
    wk.spans.push_back({lo, hi});
  }

  void merge(Work& wk, std::vector<std::pair<Rational, Rational>>& out) const {
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

  // The same on rational end points (intersection lines), values m·(L·P) - c.
  void test_rational(const Occluder<P>& o, const std::array<Rational, 3>& A, const std::array<Rational, 3>& B,
                     std::vector<std::pair<Rational, Rational>>& out, Work& wk) const {
    ++wk.c.pairs;
    Rational lo = 0, hi = 1;
    int on_side = 0;
    for (int k = 0; k < 4; ++k) {
      Rational f0 = -Rational(P::z(o.c[k])), f1 = f0;
      for (int j = 0; j < 3; ++j) {
        Rational m = P::zc(o.m[k][j]);
        f0 += m * A[j];
        f1 += m * B[j];
      }
      int s0 = sgn(f0), s1 = sgn(f1);
      if (s0 > 0 && s1 > 0) continue;
      if (s0 <= 0 && s1 <= 0) {
        if (o.closed[k] && s0 == 0 && s1 == 0) {
          on_side |= 1 << k;
          continue;
        }
        return;
      }
      Rational t = f0 / (f0 - f1);
      if (s0 > 0) hi = std::min(hi, t);
      else lo = std::max(lo, t);
    }
    if (on_side == 6 && !vertex_closed_[o.v[1]]) return;
    if (on_side == 12 && !vertex_closed_[o.v[2]]) return;
    if (on_side == 10 && !vertex_closed_[o.v[0]]) return;
    if (lo < hi) out.push_back({lo, hi});
  }

  const std::vector<const Polyhedron*>& bodies_;
  const Camera& cam_;
  const LineOptions& opt_;
  std::vector<Vec<P>> X_;
  Vec<P> view_;  // orthographic direction, or the eye (scaled like the points)
  Rational scale_;
  Projector proj_;
  CreaseAngle crease_;

  std::vector<int> voff_;
  std::vector<bool> solid_;
  std::vector<int> flipped_;
  std::vector<std::vector<int>> facing_, face_offset_, slot_third_, slot_edges_;
  std::vector<std::vector<char>> degenerate_;
  std::vector<std::vector<Vec<P>>> face_normal_;
  std::vector<std::vector<BodyEdge>> edges_;
  std::vector<Tri> tris_;
  std::vector<Occluder<P>> occ_;
  std::vector<Box> boxes_;
  Grid grid_;
  double margin_ = 0;
  std::vector<std::array<double, 3>> vproj_;
  std::vector<char> vfront_;
  std::vector<char> vertex_closed_;
  std::vector<std::array<int, 2>> gv_;  // global vertex ids of each segment's ends (-1: rational ends)
};

// Scale every coordinate (and the eye) by a common denominator; the view direction by its own.
// False when a scaled value reaches `bits` bits (then a wider policy takes the scene).
template <class P>
bool scale_fast(const std::vector<const Polyhedron*>& bodies, const Camera& cam, int bits, std::vector<Vec<P>>& pts,
                Vec<P>& view, Rational& scale) {
  const Int128 kLimit = Int128(1) << bits;
  std::vector<const Rational*> qs;
  for (const Polyhedron* p : bodies)
    for (const Point3& v : p->vertices())
      for (int k = 0; k < 3; ++k) qs.push_back(&v[k]);
  if (cam.perspective)
    for (int k = 0; k < 3; ++k) qs.push_back(&cam.eye[k]);
  std::uint64_t L = 1;
  if (qs.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) return false;
  if (!common_denominator(qs.data(), static_cast<int>(qs.size()), std::uint64_t(1) << 62, L)) return false;
  pts.clear();
  pts.reserve(qs.size() / 3);
  for (const Polyhedron* p : bodies)
    for (const Point3& v : p->vertices()) {
      Vec<P> x;
      for (int k = 0; k < 3; ++k) {
        Int128 s;
        if (!scaled_integer(v[k], L, kLimit, s)) return false;
        x[k] = static_cast<typename P::C>(s);
      }
      pts.push_back(x);
    }
  if (cam.perspective) {
    for (int k = 0; k < 3; ++k) {
      Int128 s;
      if (!scaled_integer(cam.eye[k], L, kLimit, s)) return false;
      view[k] = static_cast<typename P::C>(s);
    }
  } else {
    const Rational* d[3] = {&cam.direction[0], &cam.direction[1], &cam.direction[2]};
    std::uint64_t Ld = 1;
    if (!common_denominator(d, 3, std::uint64_t(1) << 62, Ld)) return false;
    Int128 s[3];
    for (int k = 0; k < 3; ++k)
      if (!scaled_integer(*d[k], Ld, Int128(1) << 62, s[k])) return false;
    Int128 g = gcd128(gcd128(s[0], s[1]), s[2]);
    for (int k = 0; k < 3; ++k) {
      s[k] /= g;
      if (abs128(s[k]) >= kLimit) return false;
      view[k] = static_cast<typename P::C>(s[k]);
    }
  }
  scale = Rational(static_cast<unsigned long>(L));
  return true;
}

void scale_big(const std::vector<const Polyhedron*>& bodies, const Camera& cam, std::vector<Vec<Big>>& pts,
               Vec<Big>& view, Rational& scale) {
  mpz_class L = 1;
  auto acc = [&](const Rational& q) { mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), q.get_den_mpz_t()); };
  for (const Polyhedron* p : bodies)
    for (const Point3& v : p->vertices())
      for (int k = 0; k < 3; ++k) acc(v[k]);
  if (cam.perspective)
    for (int k = 0; k < 3; ++k) acc(cam.eye[k]);
  auto sc = [&](const Rational& q) { return mpz_class(q.get_num() * (L / q.get_den())); };
  for (const Polyhedron* p : bodies)
    for (const Point3& v : p->vertices()) pts.push_back({sc(v[0]), sc(v[1]), sc(v[2])});
  if (cam.perspective) {
    view = {sc(cam.eye[0]), sc(cam.eye[1]), sc(cam.eye[2])};
  } else {
    mpz_class Ld = 1;
    for (int k = 0; k < 3; ++k) mpz_lcm(Ld.get_mpz_t(), Ld.get_mpz_t(), cam.direction[k].get_den_mpz_t());
    for (int k = 0; k < 3; ++k) view[k] = cam.direction[k].get_num() * (Ld / cam.direction[k].get_den());
  }
  scale = Rational(L);
}

}  // namespace

RobertsResult face_occluders(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineOptions& opt) {
  {
    std::vector<Vec<Fast>> pts;
    Vec<Fast> view{};
    Rational scale;
    if (scale_fast<Fast>(bodies, camera, 29, pts, view, scale))
      return Engine<Fast>(bodies, camera, opt, std::move(pts), view, scale).run();
  }
  {
    std::vector<Vec<Fast40>> pts;
    Vec<Fast40> view{};
    Rational scale;
    if (scale_fast<Fast40>(bodies, camera, 40, pts, view, scale))
      return Engine<Fast40>(bodies, camera, opt, std::move(pts), view, scale).run();
  }
  std::vector<Vec<Big>> pts;
  Vec<Big> view;
  Rational scale;
  scale_big(bodies, camera, pts, view, scale);
  return Engine<Big>(bodies, camera, opt, std::move(pts), view, scale).run();
}

}  // namespace hlr
