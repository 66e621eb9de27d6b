// The per-face engine behind face_occluders() (course notes "Visibility semantics", sections
// 26-28 for the inequalities): one class template over the number policy P (exact_int.hpp),
// its members defined by concern in files of their own and instantiated there for Fast,
// Fast40, Wide and Big:
//   face_engine_bodies.cpp         triangles, facing, closed solids, eye inside, orientation
//   face_engine_occluders.cpp      sight prisms of the front triangles, closed sides, grid
//   face_engine_edges.cpp          which edges are drawn (boundary, silhouette, crease)
//   face_engine_intersections.cpp  intersection lines (broad phase, filter, exact segment)
//   face_engine_visibility.cpp     the hidden intervals of every segment, on all cores
// Internal to the library: callers use face_occluders.hpp.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/model/camera.hpp"
#include "algorithms/solids/body_topology.hpp"
#include "algorithms/solids/crease_angle.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/support/screen_grid.hpp"
#include "kernel/exact_int.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr::face_route {

/// One triangle of a face, global vertex ids in the face's orientation.
struct Tri {
  int body, face;
  std::array<int, 3> v;
  std::array<bool, 3> edge;  // side k is a polygon edge (else a diagonal)
};

/// A front triangle's sight prism: constraint k is m[k]·(X - a_k) > 0 (>= 0 when closed[k]);
/// 0 is "behind the plane", 1..3 the side planes through the view direction or the eye. a_k
/// is a point of plane k (Engine::plane_point): the vertex v[0] for the face plane, or the eye
/// where that plane was moved to it (through_vertices false), and v[k-1] for side plane k
/// (which holds v[k-1], v[k] and the eye). The constants m[k]·a_k are not kept: they were a
/// third of the record, which is the largest array of a large drawing.
template <class P>
struct Occluder {
  Vec<P> m[4];
  bool closed[4] = {false, false, false, false};
  bool through_vertices = true;
  int body, face;
  std::array<int, 3> v;  // global vertex ids, oriented toward the viewer (side k+1: v[k] -> v[k+1])
};
static_assert(sizeof(Occluder<Fast>) <= 128, "an occluder of the 64-bit path costs 128 bytes");

/// A drawn edge of a body (what its segment needs once the body's topology is freed).
struct DrawnEdge {
  int u, v, face0, face1;  // body-local vertices, the faces of its first two uses (-1: none)
  signed char kind;        // LineKind
  bool self_hidden;
};

/// Each edge of a body's topology as a drawn line: its kind (LineKind, -1: not drawn) and
/// whether its own faces hide it.
struct EdgeClasses {
  std::vector<signed char> kinds, hidden;
};

/// An intersection line: the two bodies, the two faces, the exact ends.
using CrossLine = std::tuple<int, int, int, int, Point3, Point3>;

/// The same for the multi-limb policies (Wide, Big), kept small: the planes' doubles only
/// (each within 2^-52 of the exact value, for filtered_sign), and what makes each exact plane
/// again when a test needs it (Engine::exact_plane): the oriented vertices, whether the face
/// plane holds them (else it was moved to the eye) and which side planes were turned.
struct LazyOccluder {
  double m[4][3];
  double c[4];
  bool closed[4] = {false, false, false, false};
  bool through_vertices = true;  // constraint 0's plane holds the triangle (not moved to the eye)
  std::uint8_t turned = 0;       // bit k: side plane k was negated to face the third vertex
  int body, face;
  std::array<int, 3> v;
};

/// An occluder's screen box (float for memory, rounded outward) and its nearest depth.
struct Box {
  float x0, y0, x1, y1;
  double dmin;
};

/// Perspective: the screen box of the part strictly in front of the eye of the convex hull of
/// `n` points (`pts`, their projections `proj`, `front`: strictly in front, exact): the front
/// points' projections, unbounded on each side where a crossing point of the eye plane has a
/// positive (or negative) screen sign (Camera::eye_plane_signs). dmin is -inf. `empty` when no
/// point is in front.
struct FrontBox {
  Box box;
  bool empty;
};
FrontBox front_box(const Camera& cam, const Point3* const* pts, const std::array<double, 3>* const* proj,
                   const bool* front, int n);

/// Sign of det(q - p, r - p, s - p), the side of s against the plane of p, q, r (n·(s - p),
/// n = (q - p) x (r - p)), from doubles of the points each within 2u of the exact value
/// (relative; NaN: unknown), or 2 when they cannot tell (face_engine_occluders.cpp).
int orient_filter(const std::array<double, 3>& p, const std::array<double, 3>& q, const std::array<double, 3>& r, const std::array<double, 3>& s);

/// A 128-bit integer as a coordinate of policy P (Fast only below 2^63).
template <class P>
typename P::C from128(Int128 v) {
  if constexpr (std::is_same_v<P, Big>) {
    return to_mpz(v);
  } else {
    return static_cast<typename P::C>(v);
  }
}

/// One body's face normals. Compact (the multi-limb path with a grid): a normal below 2^126
/// in magnitude (a face on the grid) as three 128-bit integers, any other in a second array
/// that its first integer's mark points into; a third of the memory of five-limb numbers.
/// Lazy (the multi-limb path without a grid, a body of triangles only): the normal's doubles
/// and whether it was turned; the exact normal is made again from the face's triangle when a
/// test needs it (Engine::face_normal), a sixth of the memory of five-limb numbers.
/// Otherwise every normal in the policy's own numbers.
template <class P>
class FaceNormals {
 public:
  enum class Store { Full, Compact, Lazy };
  void reset(std::size_t faces, Store store) {
    store_ = store;
    full_.clear();
    small_.clear();
    wide_.clear();
    approx_.clear();
    turned_.clear();
    if (store == Store::Compact) small_.resize(faces);
    else if (store == Store::Lazy) approx_.resize(faces), turned_.resize(faces, 0);
    else full_.resize(faces);
  }
  std::size_t size() const { return store_ == Store::Compact ? small_.size() : store_ == Store::Lazy ? approx_.size() : full_.size(); }
  bool lazy() const { return store_ == Store::Lazy; }
  /// Lazy: whether face f's normal was turned (negate) since it was put.
  bool turned(std::size_t f) const { return turned_[f] != 0; }
  /// Not for a lazy store (Engine::face_normal makes its normals).
  Vec<P> get(std::size_t f) const {
    if (store_ == Store::Lazy) throw std::logic_error("FaceNormals: a lazy store keeps no exact normal");
    if (store_ == Store::Full) return full_[f];
    const std::array<Int128, 3>& s = small_[f];
    if (s[0] == kMark) return wide_[static_cast<std::size_t>(s[1])];
    return {from128<P>(s[0]), from128<P>(s[1]), from128<P>(s[2])};
  }
  /// Doubles of the normal, each within 2^-52 of the exact value (relative). Not for Big.
  std::array<double, 3> approx(std::size_t f) const {
    if (store_ == Store::Lazy) return approx_[f];
    if (store_ == Store::Compact) {
      const std::array<Int128, 3>& s = small_[f];
      if (s[0] != kMark) return {static_cast<double>(s[0]), static_cast<double>(s[1]), static_cast<double>(s[2])};
      return doubles(wide_[static_cast<std::size_t>(s[1])]);
    }
    return doubles(full_[f]);
  }
  /// On all cores for distinct faces. False when compact and n does not fit (then put_wide).
  bool put(std::size_t f, Vec<P> n) {
    if (store_ == Store::Full) {
      full_[f] = std::move(n);
    } else if (store_ == Store::Lazy) {
      approx_[f] = doubles(n);
    } else if constexpr (std::is_same_v<P, Wide>) {
      for (int k = 0; k < 3; ++k)
        if (n[k].bits() > 126) return false;
      for (int k = 0; k < 3; ++k) small_[f][k] = n[k].to_int128();
    }
    return true;
  }
  /// Lazy: the doubles of a non-zero normal (as put() makes them from the exact one).
  void put_doubles(std::size_t f, const std::array<double, 3>& d) { approx_[f] = d; }
  /// One caller at a time.
  void put_wide(std::size_t f, Vec<P> n) {
    small_[f] = {kMark, static_cast<Int128>(wide_.size()), 0};
    wide_.push_back(std::move(n));
  }
  void negate(std::size_t f) {
    if (store_ == Store::Full) {
      full_[f] = neg<P>(full_[f]);
    } else if (store_ == Store::Lazy) {
      for (double& v : approx_[f]) v = -v;
      turned_[f] ^= 1;
    } else if (small_[f][0] == kMark) {
      Vec<P>& w = wide_[static_cast<std::size_t>(small_[f][1])];
      w = neg<P>(w);
    } else {
      for (Int128& v : small_[f]) v = -v;
    }
  }

 private:
  static std::array<double, 3> doubles(const Vec<P>& n) { return {P::cdbl(n[0]), P::cdbl(n[1]), P::cdbl(n[2])}; }
  static constexpr Int128 kMark = -(Int128(1) << 126) - 1;  // below every kept value
  Store store_ = Store::Full;
  std::vector<Vec<P>> full_;
  std::vector<std::array<Int128, 3>> small_;
  std::vector<Vec<P>> wide_;
  std::vector<std::array<double, 3>> approx_;
  std::vector<std::uint8_t> turned_;
};

/// The engine's work that no view changes (FaceRouteShare): filled by the first view, read by
/// the next ones of the same bodies. Triangles, normals and facing vertices are after every
/// inside-out solid or component was turned.
template <class P>
struct Prepared {
  std::vector<Vec<P>> X;  // every vertex scaled to integers (Big: those on the grid left 0, Engine::pt)
  Rational scale;
  /// Wide and Big only (else empty): per vertex, whether it lies on the scene's grid (a
  /// common denominator G of most vertices, below 2^62), and then its coordinates times G,
  /// each below 2^61; X = small·(scale / G). A face with only such corners takes its normal
  /// from these (a positive multiple of the one from X), which a few far finer points (a
  /// cut's split points, an exporter's near-zero noise) would otherwise make as long as their
  /// common denominator.
  std::vector<char> on_grid;
  std::vector<std::array<std::int64_t, 3>> small;
  std::uint64_t grid = 1;  // G
  bool done = false;       // every body below is prepared
  std::vector<BodyTopology> topo;
  std::vector<std::vector<char>> degenerate;
  std::vector<FaceNormals<P>> face_normal;
  std::vector<std::vector<int>> facing_at;  // per face: the vertex its facing is measured at
  std::vector<Tri> tris;
  std::vector<int> first_tri;  // per body
  std::vector<bool> solid;
  std::vector<int> flipped;
  std::vector<BodyNote> notes;  // per body in order: turned components, not a solid
  // Per body, per edge: the feature class of an edge between two live faces (feature_kind;
  // -1: none), and the edges a crease line goes on along, under the angles of `crease`.
  std::optional<Rational> crease;
  std::vector<std::vector<signed char>> feature;
  std::vector<std::optional<std::vector<int>>> continued;
  std::optional<std::vector<CrossLine>> cross;  // the intersection lines
  std::size_t intersection_pairs = 0;
  // Orthographic views: the facing of every face for the direction of the view that made it
  // (a later drawing in that direction, a section's hatch pass, reads it), and the filter's
  // doubles of the multi-limb paths (Engine::filter_doubles; no direction changes them).
  std::optional<Vec<P>> facing_view;
  std::vector<std::vector<signed char>> facing;
  std::vector<std::array<double, 3>> Xd;
  long sigma = 0;
};

template <class P>
class Engine {
 public:
  using C = typename P::C;
  using V = typename P::V;
  /// Multi-limb numbers (Wide, Big): the doubles of every vertex and occluder plane, in front
  /// of the exact plane values (filtered_sign's bound; exact_int.hpp); exact planes made when
  /// a test needs them.
  static constexpr bool kFiltered = std::is_same_v<P, Big> || std::is_same_v<P, Wide>;
  using Occ = std::conditional_t<kFiltered, LazyOccluder, Occluder<P>>;

  /// `prep`: the scaled points and scale, and the rest when a view before prepared the bodies;
  /// `keep`: other views will read it (nothing of it is freed).
  Engine(const std::vector<const Polyhedron*>& bodies, const Camera& cam, const LineOptions& opt, const FaceRouteHooks& hooks,
         std::shared_ptr<Prepared<P>> prep, Vec<P> view, bool keep);
  LineDrawing run();

 private:
  struct Work;

  /// A vertex's scaled coordinates. Big with a grid: a vertex on the grid keeps only its small
  /// integers (Prepared::small), and its coordinates, small·(scale / G), are made here when a
  /// test needs them (a copy); any other is read from X_ (by reference under the other policies).
  decltype(auto) pt(int g) const {
    if constexpr (std::is_same_v<P, Big>) {
      const auto i = static_cast<std::size_t>(g);
      if (!prep_->on_grid.empty() && prep_->on_grid[i]) {
        Vec<P> x;
        for (int k = 0; k < 3; ++k) mpz_mul_si(x[k].get_mpz_t(), grid_factor_.get_mpz_t(), static_cast<long>(prep_->small[i][k]));
        return x;
      }
      return Vec<P>(X_[i]);
    } else {
      return static_cast<const Vec<P>&>(X_[static_cast<std::size_t>(g)]);
    }
  }

  // face_engine_bodies.cpp
  void offsets();
  Vec<P> normal(const Tri& t) const;
  Vec<P> face_normal(int b, int f) const;
  int facing_of(int b, int f, const std::vector<int>& at) const;
  bool on_grid(const Tri& t) const;
  int volume_filter(const std::vector<int>& ids) const;
  void prepare_body(int b);
  void view_body(int b, LineDrawing& res);
  std::vector<signed char> features(int b) const;
  std::vector<int> continued_edges(int b, std::vector<char>& line) const;
  const std::vector<signed char>& feature_classes(int b);
  const std::vector<int>* continued_lines(int b, std::vector<char>& line);
  int triangulate_body(int b);
  int volume_sign(const std::vector<int>& ids) const;
  int parity(const Vec<P>& x, const std::vector<int>& ids) const;
  bool orient_components(int b, int first);
  bool eye_inside(int first) const;
  bool eye_on_surface(int first) const;
  static void flip(Tri& t);
  // face_engine_occluders.cpp
  bool neighbour(const Tri& t, int k, int& face, int& third) const;
  int side_third(int b, const EdgeUse& use) const;
  int third_off_edge(int b, int face, int u, int v) const;
  void vertex_rules();
  void give_back() const;
  void project_vertices();
  void select_occluders(const std::vector<std::vector<DrawnEdge>>& drawn);
  void build_occluders();
  std::function<bool(const Tri&)> near_segments(const std::vector<std::vector<DrawnEdge>>& drawn, ScreenGrid& grid,
                                                std::vector<ScreenRect>& rects) const;
  void make_occluder(const Tri& t0, std::uint8_t closed, Occ& o, Box& bx) const;
  bool closed_side(const Tri& t, int k, const Vec<P>& m, const V& c, int fs, std::optional<Vec<P>>& n) const;
  int wedge_side(const Tri& t, int g, int third, std::optional<Vec<P>>& n) const;
  void side_plane(int p, int q, Vec<P>& m, V& c) const;
  bool grid_side_sign(const Tri& t, int v, int& sign) const;
  bool grid_normal(const Tri& t, std::array<Int128, 3>& n) const;
  bool grid_side(int p, int q, std::array<Int128, 3>& m) const;
  bool grid_planes(const Tri& t, std::uint8_t closed, Occ& o) const;
  bool local_planes(const Tri& t, std::uint8_t closed, Occ& o) const;
  bool shared_edge_planes(const Tri& t, std::uint8_t closed, Occ& o) const;
  void grid_doubles(const std::array<Int128, 3>& m, const std::array<std::int64_t, 3>& o, bool turn, double* dm, double& dc) const;
  void occluder_box(const Tri& t, int fs, Box& bx) const;
  // face_engine_edges.cpp
  EdgeClasses classify_edges(int b);
  std::vector<DrawnEdge> drawn_edges(int b, const EdgeClasses& classes, bool spend_topology);
  Segment edge_segment(int b, const DrawnEdge& e) const;
  bool opposite_in_projection(int u, int v, int x, int y) const;
  LineKind feature_kind(int b, const EdgeUse& a, const EdgeUse& c) const;
  bool crease(int b, const EdgeUse& a, const EdgeUse& c, const CreaseAngle& angle) const;
  void continue_creases(int b, std::vector<signed char>& kinds, std::vector<signed char>& hidden, std::vector<char>& line);
  bool continues(int b, const BodyEdge& e) const;
  void fixed_width();
  std::array<Int128, 3> fixed_point(int g) const;
  bool fixed_normal(const Tri& t, Vec<P>& n) const;
  bool fixed_normal_doubles(const Tri& t, std::array<double, 3>& d) const;
  bool fixed_edge_planes(const Tri& t, std::uint8_t closed, Occ& o) const;
  bool fixed_plane_values(const Occ& o, int k, const std::array<int, 2>& gv, V& f0, V& f1) const;
  // face_engine_intersections.cpp
  void find_intersections(LineDrawing& res);
  std::vector<Segment> crossing_segments(LineDrawing& res);
  bool pair_may_cross(std::uint32_t ta, std::uint32_t tc) const;
  bool may_meet(const Tri& x, const Vec<P>& nx, const Tri& y, const Vec<P>& ny) const;
  bool extent_on_plane(const Tri& t, const Tri& o, const Vec<P>& no, int axis, double out[2], double& scale) const;
  bool straddles(const Tri& x, const Vec<P>* nx, const Tri& y) const;
  std::optional<std::pair<Point3, Point3>> segment(const Tri& x, const Tri& y) const;
  const Point3& world(int g) const;
  // face_engine_visibility.cpp
  void leave_out_backs(const std::vector<std::vector<DrawnEdge>>& drawn, LineDrawing& res, const ParallelLoop& loop);
  std::vector<PieceList> visibility(const std::vector<std::vector<DrawnEdge>>& drawn, std::vector<Segment>& crossing,
                                    LineDrawing& res);
  /// Whether drawn edge e of body b is left out (backs_left_: hidden by its own faces).
  bool left_out(std::size_t b, const DrawnEdge& e) const { return e.self_hidden && b < backs_left_.size() && backs_left_[b]; }
  /// The segments of the drawn edges (but those left out) and the crossing lines, with their
  /// pieces (drawn is freed).
  void make_segments(std::vector<std::vector<DrawnEdge>>& drawn, std::vector<PieceList> pieces, std::vector<Segment>& crossing, std::size_t total,
                     LineDrawing& res) const;
  void release_arrays();
  std::optional<std::pair<Rational, Rational>> depth_of(const Segment& s) const;
  void candidates(const Box& seg, Work& wk) const;
  void solve(Segment& s, const std::array<int, 2>& gv, Work& wk, signed char& whole) const;
  void solve_into(Segment& s, const std::array<int, 2>& gv, Work& wk, PieceList& out) const;
  void test_integer(int oi, const std::array<int, 2>& gv, Work& wk) const;
  void exact_plane(const Occ& o, int k, Vec<P>& m, V& c) const;
  void mark_cap_vertices();
  int cap_part(int body, int face) const;
  bool in_cap_plane(const Occ& o, const Work& wk) const;
  void filter_shift();
  void grid_view();
  void plane_doubles(const Vec<P>& m, const V& c, double* dm, double& dc) const;
  void filter_doubles();
  static int filtered_sign(const double* m, double c, const std::array<double, 3>& X);
  bool end_on_hides(const Occ& o, int on_side) const;
  void merge(Work& wk, std::vector<std::pair<Rational, Rational>>& out) const;
  /// A segment with rational ends (scaled like the points) and their doubles for the filter.
  struct RationalEnds {
    std::array<mpz_class, 3> a, b;  // A = a / da, B = b / db (common denominators, positive)
    mpz_class da, db;
    std::array<double, 3> Ad, Bd;
    bool filter = true;  // the doubles are fit for filtered_sign
  };
  int filtered_sign(const Occ& o, int k, const std::array<double, 3>& X) const;
  /// The point a_k of constraint k's plane that an Occluder's values are taken from.
  decltype(auto) plane_point(const Occ& o, int k) const { return k == 0 ? (o.through_vertices ? pt(o.v[0]) : view_) : pt(o.v[k - 1]); }
  void test_rational(const Occ& o, const RationalEnds& e, std::vector<std::pair<Rational, Rational>>& out, Work& wk) const;

  const std::vector<const Polyhedron*>& bodies_;
  const Camera& cam_;
  const LineOptions& opt_;
  const FaceRouteHooks& hooks_;
  std::vector<char> backs_left_;      // per body: its edges hidden by its own faces are left out (hooks_.back_edges off)
  std::size_t backs_left_count_ = 0;  // how many edges that leaves out
  std::shared_ptr<Prepared<P>> prep_;
  bool keep_;           // prep_ is shared with other views: nothing of it is freed
  bool large_ = false;  // a large drawing without shared work: give_back() before visibility
  std::vector<Vec<P>>& X_;
  Vec<P> view_;  // orthographic direction, or the eye (scaled like the points)
  Rational& scale_;
  Projector proj_;
  CreaseAngle crease_;
  CreaseAngle continued_;  // half the crease angle: how far a crease line continues

  std::vector<int> voff_;
  std::vector<bool>& solid_;
  std::vector<char> eye_on_;  // perspective: the eye lies on this solid's surface
  std::vector<int>& flipped_;
  std::vector<std::vector<signed char>> facing_;  // per body and face: 1 facing, 0 edge-on, -1 not
  std::vector<BodyTopology>& topo_;
  std::vector<std::vector<char>>& degenerate_;
  std::vector<FaceNormals<P>>& face_normal_;
  std::vector<Tri>& tris_;
  std::vector<int> sel_;               // the triangles that become occluders
  std::vector<std::uint8_t> closed_;   // their closed sides (bit k + 1: side k)
  std::vector<Occ> occ_;
  std::size_t hiding_ = 0;  // triangles that hide (occ_ without a tile's restriction)
  std::vector<Box> boxes_;
  ScreenGrid grid_;
  double margin_ = 0;
  std::vector<std::array<double, 3>> vproj_;
  std::vector<std::array<double, 3>> Xd_;  // kFiltered: every vertex's doubles (X_ · 2^-sigma_)
  long sigma_ = 0;                         // Big: every |X| and the eye below 2^sigma_ (filter_shift)
  // Wide and Big with a grid (Prepared::on_grid): scale / G, and the eye's coordinates times G
  // when it lies on the grid (perspective), for side planes through grid vertices (grid_view).
  C grid_factor_{};
  double grid_factor_mant_ = 0;  // grid_factor_ as mantissa (within 2u, truncated) and exponent
  long grid_factor_exp_ = 0;
  std::optional<std::array<std::int64_t, 3>> eye_small_;
  std::optional<std::array<Int128, 3>> view_small_;        // orthographic: the direction, each component below 2^62
  bool fixed_ = false;                                     // Wide: every coordinate below 2^125 (face_engine_edges.cpp)
  std::optional<std::array<std::int64_t, 3>> view_fixed_;  // and an orthographic direction below 2^61
  std::vector<char> vfront_;
  std::vector<char> vertex_closed_;
  std::vector<int> vertex_cap_;   // find_intersections: per vertex, the cap part of its cap faces (-1 none, -2 several)
  std::vector<CrossLine> cross_;  // intersection lines, found before the occluders are built
};

}  // namespace hlr::face_route
