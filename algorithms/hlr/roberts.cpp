// Roberts' algorithm, exact (see roberts.hpp; course notes sections 26-28).
#include "algorithms/hlr/roberts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "algorithms/hlr/int128_interval.hpp"
#include "algorithms/model/facing.hpp"
#include "algorithms/solids/convexity.hpp"
#include "algorithms/solids/crease_angle.hpp"
#include "algorithms/support/progress.hpp"
#include "algorithms/support/screen_grid.hpp"
#include "kernel/exact_int.hpp"

namespace hlr {
namespace {

// [x y z w]·V_j for every column j.
std::vector<Rational> values(const Rational& x, const Rational& y, const Rational& z, const Rational& w,
                             const BodyMatrixData& V) {
  RowVector4 row;
  row << x, y, z, w;
  return row_times_matrix(row, V);
}

// ---------------------------------------------------------------- Stage 0: checks
void check_body(const Polyhedron& p, int i) {
  const MeshReport& r = p.report();
  auto fail = [&](const std::string& why) {
    throw BodyError(i, why);
  };
  if (!r.closed()) fail("is not closed (boundary edge " + (r.boundary_edges.empty() ? std::string("?") : to_string(r.boundary_edges[0])) + ")");
  if (!r.manifold()) fail("is not manifold");
  if (!r.oriented()) fail("is not consistently oriented (edge " + to_string(r.misoriented_edges[0]) + ")");
  if (!r.degenerate_faces.empty()) fail("has a degenerate face (face " + std::to_string(r.degenerate_faces[0].face) + ": " + r.degenerate_faces[0].why + ")");
  if (!r.planar()) fail("has a non-planar face (face " + std::to_string(r.non_planar_faces[0].face) + ")");
  if (!r.duplicate_vertices.empty())
    fail("has duplicate vertices (" + std::to_string(r.duplicate_vertices[0].first) + " and " +
         std::to_string(r.duplicate_vertices[0].second) + ")");
  if (!r.t_junctions.empty())
    fail("has a T-junction (vertex " + std::to_string(r.t_junctions[0].vertex) + " inside edge " +
         to_string(r.t_junctions[0].edge) + ")");
  if (!r.self_intersecting_faces.empty())
    fail("has a self-intersecting face (face " + std::to_string(r.self_intersecting_faces[0]) + ")");
  ConvexityResult cv = convexity(p);
  if (!cv.convex())
    fail("is " + describe(cv) + "; Roberts' algorithm takes convex bodies (split non-convex ones into convex pieces first)");
}

// ---------------------------------------------------------------- pre-filter (doubles, conservative)
struct Box2 {
  double x0, y0, x1, y1, d0, d1;  // screen bounds and depth range
  bool behind = false;            // perspective: no point strictly in front of the eye
};

struct PreFilter {
  std::vector<Box2> boxes;
  double margin = 0;
  ScreenGrid grid;
  mutable StampSet stamps;

  // The box of the points `pts` (projections `pr`) strictly in front of the eye (`front`,
  // decided exactly), opened toward where the edges `edges` (index pairs; for a segment its two
  // ends, for a body its polygon edges) from a front point to one that is not cross the eye
  // plane: it holds the projection of their convex hull's part in front of the eye.
  static Box2 bound(const Camera& cam, const std::vector<const Point3*>& pts, const std::vector<std::array<double, 3>>& pr,
                    const std::vector<char>& front, const std::vector<std::pair<int, int>>& edges) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    Box2 b{inf, inf, -inf, -inf, inf, -inf};
    bool all = true, any = false;
    for (std::size_t i = 0; i < pr.size(); ++i) {
      all = all && front[i];
      if (!front[i]) continue;
      any = true;
      b.x0 = std::min(b.x0, pr[i][0]);
      b.y0 = std::min(b.y0, pr[i][1]);
      b.x1 = std::max(b.x1, pr[i][0]);
      b.y1 = std::max(b.y1, pr[i][1]);
      b.d0 = std::min(b.d0, pr[i][2]);
      b.d1 = std::max(b.d1, pr[i][2]);
    }
    if (all) return b;
    b.behind = !any;
    b.d0 = -inf;
    for (auto [u, v] : edges) {
      if (front[u] == front[v]) continue;
      if (!front[u]) std::swap(u, v);
      open_toward(b, cam.eye_plane_signs(*pts[u], *pts[v]));
    }
    return b;
  }

  ScreenRect rect(const Box2& b) const { return {b.x0 - margin, b.y0 - margin, b.x1 + margin, b.y1 + margin}; }

  void build(const std::vector<const Polyhedron*>& bodies, const Projector& proj, const Camera& cam) {
    double ext = 0;
    for (const Polyhedron* p : bodies) {
      std::vector<const Point3*> pts;
      std::vector<std::array<double, 3>> pr;
      std::vector<char> front;
      for (const Point3& v : p->vertices()) {
        pts.push_back(&v);
        pr.push_back(proj.project(v));
        front.push_back(!cam.perspective || cam.in_front(v) == Sign::Positive);
      }
      std::vector<std::pair<int, int>> edges;
      for (const Face& f : p->faces())
        for (std::size_t k = 0; k < f.size(); ++k) edges.push_back({f[k], f[(k + 1) % f.size()]});
      boxes.push_back(bound(cam, pts, pr, front, edges));
      const Box2& b = boxes.back();
      for (double v : {b.x0, b.x1, b.y0, b.y1, b.d0, b.d1})
        if (std::isfinite(v)) ext = std::max(ext, std::fabs(v));
    }
    // A conservative filter only (it skips work, never decides visibility): see
    // bounds::kBodyBoxMargin in exact_int.hpp.
    margin = bounds::kBodyBoxMargin * (ext + 1e-300);
    std::vector<ScreenRect> rects;
    for (const Box2& b : boxes) rects.push_back(b.behind ? ScreenRect{0, 0, 0, 0} : rect(b));
    grid.build(rects, std::vector<char>(rects.size(), 0), 1.0, 512);
    stamps.reset(boxes.size());
  }

  // Bodies that may hide some point of a segment with the given projected bounds: a body
  // behind the eye hides nothing in front of it, a segment behind the eye is never drawn.
  void candidates(const Box2& e, std::vector<int>& out) const {
    out.clear();
    stamps.next();
    if (e.behind) return;
    ScreenRect q = rect(e);
    double m = margin;
    for (double v : {e.x0, e.x1, e.y0, e.y1})
      if (std::isfinite(v)) m = std::max(m, bounds::kBodyBoxMargin * std::fabs(v));
    q = {e.x0 - m, e.y0 - m, e.x1 + m, e.y1 + m};
    grid.visit(q, [&](int i) {
      if (!stamps.first(i)) return;
      const Box2& b = boxes[i];
      if (b.behind) return;
      if (!ScreenRect{b.x0, b.y0, b.x1, b.y1}.meets(q)) return;
      if (b.d0 > e.d1 + m) return;  // entirely farther than every point of the segment
      out.push_back(i);
    });
    std::sort(out.begin(), out.end());
  }
};

// ---------------------------------------------------------------- pieces
using Span = std::pair<Rational, Rational>;  // open, lo < hi, within [0, 1]

// Adds the part of `iv` inside [0, 1] to `out`.
void clip_to_unit(const OpenInterval& iv, std::vector<Span>& out) {
  if (iv.empty) return;
  Rational lo = iv.lo && *iv.lo > 0 ? *iv.lo : Rational(0);
  Rational hi = iv.hi && *iv.hi < 1 ? *iv.hi : Rational(1);
  if (lo < hi) out.push_back({std::move(lo), std::move(hi)});
}

// ---------------------------------------------------------------- Stage 3: intersection lines
struct Bounds3 {
  Point3 lo, hi;
};

Bounds3 exact_bounds(const Polyhedron& p) {
  Rational lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = p.vertices()[0][k];
  for (const Point3& v : p.vertices())
    for (int k = 0; k < 3; ++k) {
      if (v[k] < lo[k]) lo[k] = v[k];
      if (v[k] > hi[k]) hi[k] = v[k];
    }
  return {Point3(lo[0], lo[1], lo[2]), Point3(hi[0], hi[1], hi[2])};
}

// Distinct planes (columns) of a body matrix with the first face of each.
std::vector<int> distinct_columns(const BodyMatrixData& V) {
  std::vector<int> cols;
  for (int j = 0; j < V.cols(); ++j) {
    bool seen = false;
    for (int c : cols)
      if (V.col(c) == V.col(j)) {
        seen = true;
        break;
      }
    if (!seen) cols.push_back(j);
  }
  return cols;
}

Rational value_at(const BodyMatrixData& V, int j, const Point3& p) {
  Rational s = p.x() * V(0, j) + p.y() * V(1, j);
  s += p.z() * V(2, j);
  s += V(3, j);
  return s;
}

void intersection_lines(int a, int b, const BodyMatrixData& A, const BodyMatrixData& B, std::vector<Segment>& out) {
  const std::vector<int> ca = distinct_columns(A), cb = distinct_columns(B);
  for (int f : ca)
    for (int g : cb) {
      Vector3 nf(A(0, f), A(1, f), A(2, f)), ng(B(0, g), B(1, g), B(2, g));
      Vector3 u = cross(nf, ng);
      if (u.is_zero()) continue;  // parallel facets meet in no line
      // Point on both planes: n·x = -d for each.
      Rational uu = dot(u, u);
      Vector3 x0v = Rational(-A(3, f)) * cross(ng, u) + Rational(-B(3, g)) * cross(u, nf);
      Point3 x0(x0v.x() / uu, x0v.y() / uu, x0v.z() / uu);
      std::optional<Rational> slo, shi;
      bool empty = false;
      auto clip = [&](const BodyMatrixData& V, int j) {
        Rational c = V(0, j) * u.x() + V(1, j) * u.y() + V(2, j) * u.z();
        Rational h = value_at(V, j, x0);
        if (c == 0) {
          if (h < 0) empty = true;
          return;
        }
        Rational s = -h / c;
        if (c > 0) {
          if (!slo || s > *slo) slo = s;
        } else {
          if (!shi || s < *shi) shi = s;
        }
      };
      for (int j = 0; j < A.cols() && !empty; ++j) clip(A, j);
      for (int j = 0; j < B.cols() && !empty; ++j) clip(B, j);
      if (empty || !slo || !shi || !(*slo < *shi)) continue;
      Point3 p0 = x0 + (*slo) * u, p1 = x0 + (*shi) * u;
      // On an edge of A or of B: that edge is drawn as itself.
      auto on_other_plane = [&](const BodyMatrixData& V, const std::vector<int>& cols, int own) {
        for (int j : cols)
          if (j != own && value_at(V, j, p0) == 0 && value_at(V, j, p1) == 0) return true;
        return false;
      };
      if (on_other_plane(A, ca, f) || on_other_plane(B, cb, g)) continue;
      Segment s;
      s.kind = Segment::Kind::Intersection;
      s.line = LineKind::Intersection;
      s.body = a;
      s.body2 = b;
      s.face0 = f;
      s.face1 = g;
      s.set_ends(p0, p1);
      out.push_back(std::move(s));
    }
}

bool boxes_meet(const Bounds3& x, const Bounds3& y) {
  for (int k = 0; k < 3; ++k)
    if (x.hi[k] < y.lo[k] || y.hi[k] < x.lo[k]) return false;
  return true;
}

}  // namespace

std::vector<Segment> body_edge_segments(const Polyhedron& p, int body, const std::vector<signed char>& facing,
                                        const LineOptions& opt, DrawingStats& stats) {
  std::map<std::pair<int, int>, std::pair<int, int>> faces_of;  // edge -> its two faces
  for (std::size_t f = 0; f < p.faces().size(); ++f) {
    const Face& face = p.faces()[f];
    for (std::size_t k = 0; k < face.size(); ++k) {
      int u = face[k], v = face[(k + 1) % face.size()];
      auto& slot = faces_of[{std::min(u, v), std::max(u, v)}];
      if (u < v) slot.first = static_cast<int>(f);
      else slot.second = static_cast<int>(f);
    }
  }
  CreaseAngle crease(opt.crease_degrees);
  std::vector<Segment> out;
  for (const auto& [e, ff] : faces_of) {
    LineKind kind = LineKind::Edge;
    if (opt.edges == EdgeSelection::Feature) {
      if (p.planes()[ff.first] == p.planes()[ff.second]) continue;
      if ((facing[ff.first] > 0) != (facing[ff.second] > 0)) {
        kind = LineKind::Silhouette;
      } else {
        mpz_class na[3], nb[3];
        for (int k = 0; k < 3; ++k) na[k] = p.planes()[ff.first][k].get_num(), nb[k] = p.planes()[ff.second][k].get_num();
        if (!crease.exceeds(na, nb)) continue;
        kind = LineKind::Crease;
      }
    }
    Segment s;
    s.line = kind;
    s.body = body;
    s.v0 = e.first;
    s.v1 = e.second;
    s.face0 = ff.first;
    s.face1 = ff.second;
    s.borrow_ends(p.vertices());
    s.self_hidden = facing[ff.first] < 0 && facing[ff.second] < 0;
    ++stats.edges;
    if (s.self_hidden) ++stats.self_hidden;
    out.push_back(std::move(s));
  }
  return out;
}

OpenInterval hidden_interval(const Point3& p1, const Point3& p2, const BodyMatrixData& V, const RowVector4& g) {
  const int n = static_cast<int>(V.cols());
  Vector3 d = p2 - p1;
  std::vector<Rational> p = values(p1.x(), p1.y(), p1.z(), 1, V);
  std::vector<Rational> q = values(d.x(), d.y(), d.z(), 0, V);
  std::vector<Rational> w = values(g(0), g(1), g(2), g(3), V);
  OpenInterval r;
  std::optional<Rational>& lo = r.lo;
  std::optional<Rational>& hi = r.hi;
  // alpha + beta·t > 0
  auto add = [&](const Rational& alpha, const Rational& beta) -> bool {
    if (beta == 0) return alpha > 0;
    Rational t = -alpha / beta;
    if (beta > 0) {
      if (!lo || t > *lo) lo = t;
    } else {
      if (!hi || t < *hi) hi = t;
    }
    return true;
  };
  std::vector<int> lower, upper;
  for (int j = 0; j < n; ++j) {
    int s = sgn(w[j]);
    if (s > 0) lower.push_back(j);
    else if (s < 0) upper.push_back(j);
    else if (!add(p[j], q[j])) return r;  // a face that excludes the whole line
  }
  // Eliminate a: every lower bound below every upper bound. The lower bound a > 0 gives
  // p_k + q_k·t > 0 for each upper k.
  for (int k : upper) {
    if (!add(p[k], q[k])) return r;
    for (int j : lower)
      if (!add(p[k] * w[j] - p[j] * w[k], q[k] * w[j] - q[j] * w[k])) return r;
  }
  r.empty = lo && hi && !(*lo < *hi);
  return r;
}

RobertsResult roberts(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineOptions& opt) {
  RobertsResult res;
  res.stats.method = Method::Roberts;
  const RowVector4 g = camera.viewpoint();
  // Stage 0: checks and body matrices; Stage 1: facing classes.
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    check_body(*bodies[i], static_cast<int>(i));
    res.matrices.push_back(body_matrix(*bodies[i]));
    std::vector<Rational> gv = values(g(0), g(1), g(2), g(3), res.matrices.back().V);
    std::vector<Rational> ev;
    bool eye_inside = camera.perspective;
    for (auto& x : gv) {
      ev.push_back(-x);
      if (!(x > 0)) eye_inside = false;
    }
    if (eye_inside)
      throw BodyError(static_cast<int>(i), "contains the eye " + to_string(camera.eye) + ": an eye inside a solid sees nothing");
    std::vector<signed char> fc;
    const BodyMatrixData& V = res.matrices.back().V;
    for (int j = 0; j < V.cols(); ++j)  // the outward plane is minus the inward column
      fc.push_back(static_cast<signed char>(facing_sign(Plane(-V(0, j), -V(1, j), -V(2, j), -V(3, j)), g)));
    res.facing.push_back(std::move(fc));
    res.ev.push_back(std::move(ev));
  }
  std::vector<FastBody> fast;
  for (const BodyMatrix& bm : res.matrices) fast.push_back(prepare_fast_body(bm.V, g));
  std::vector<const Point3*> all;
  for (const Polyhedron* p : bodies)
    for (const Point3& v : p->vertices()) all.push_back(&v);
  Projector proj(camera, drawing_frame(all.size(), [&](std::size_t i) -> const Point3& { return *all[i]; }));
  PreFilter pre;
  pre.build(bodies, proj, camera);

  auto depth_of = [&](const Segment& s) -> std::optional<std::pair<Rational, Rational>> {
    if (!camera.perspective) return std::nullopt;
    return std::make_pair(camera.depth(s.from()), camera.depth(s.to()));
  };
  std::vector<int> cand;
  auto solve = [&](Segment& s, int skip_a, int skip_b) {
    std::vector<Span> hidden;
    std::vector<char> front = {1, 1};
    if (camera.perspective)
      front = {camera.in_front(s.from()) == Sign::Positive, camera.in_front(s.to()) == Sign::Positive};
    Box2 eb = PreFilter::bound(camera, {&s.from(), &s.to()}, {proj.project(s.from()), proj.project(s.to())}, front,
                               {{0, 1}});
    if (opt.prefilter) {
      pre.candidates(eb, cand);
    } else {
      cand.clear();
      for (std::size_t i = 0; i < bodies.size(); ++i) cand.push_back(static_cast<int>(i));
    }
    res.stats.pairs_skipped += bodies.size() - cand.size();
    for (int j : cand) {
      if (j == skip_a || j == skip_b) continue;
      ++res.stats.pairs_tested;
      if (auto iv = fast_hidden_interval(s.from(), s.to(), fast[j])) {
        clip_to_unit(*iv, hidden);
      } else {
        ++res.stats.pairs_rational;
        clip_to_unit(hidden_interval(s.from(), s.to(), res.matrices[j].V, g), hidden);
      }
    }
    s.pieces = pieces_from_hidden(std::move(hidden), front[0] && front[1] ? std::nullopt : depth_of(s));
  };

  // Stage 1 and 2: the bodies' edges.
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (progress_enabled() && (bodies.size() < 50 || i % 16 == 0))  // a long run says where it is
      progress("Roberts: the edges of body " + std::to_string(i + 1) + " of " + std::to_string(bodies.size()) + " against every body");
    for (Segment& s : body_edge_segments(*bodies[i], static_cast<int>(i), res.facing[i], opt, res.stats)) {
      if (s.self_hidden)
        s.pieces = pieces_from_hidden({{Rational(0), Rational(1)}}, depth_of(s));
      else
        solve(s, static_cast<int>(i), -1);
      res.segments.push_back(std::move(s));
    }
  }

  // Stage 3: intersection lines of every pair of bodies whose bounding boxes meet.
  std::vector<Bounds3> bb;
  for (const Polyhedron* p : bodies) bb.push_back(exact_bounds(*p));
  std::vector<int> order(bodies.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int x, int y) { return bb[x].lo.x() < bb[y].lo.x() || (bb[x].lo.x() == bb[y].lo.x() && x < y); });
  std::vector<Segment> lines;
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t ii = 0; ii < order.size(); ++ii)
    for (std::size_t jj = ii + 1; jj < order.size() && !(bb[order[ii]].hi.x() < bb[order[jj]].lo.x()); ++jj)
      if (boxes_meet(bb[order[ii]], bb[order[jj]]))
        pairs.push_back({std::min(order[ii], order[jj]), std::max(order[ii], order[jj])});
  std::sort(pairs.begin(), pairs.end());
  for (auto [a, b] : pairs) intersection_lines(a, b, res.matrices[a].V, res.matrices[b].V, lines);
  for (Segment& s : lines) {
    solve(s, -1, -1);  // the two bodies themselves may hide their intersection line too
    ++res.stats.intersection_segments;
    res.segments.push_back(std::move(s));
  }
  return res;
}

}  // namespace hlr
