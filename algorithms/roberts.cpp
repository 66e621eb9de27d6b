// Roberts' algorithm, exact (see roberts.hpp; course notes sections 26-28).
#include "algorithms/roberts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "algorithms/convexity.hpp"
#include "algorithms/crease_angle.hpp"
#include "algorithms/int128_interval.hpp"

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
    throw RobertsError(i, "body " + std::to_string(i) + " " + why);
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
  bool always = false;            // cannot be bounded (perspective, at or behind the eye)
};

struct PreFilter {
  std::vector<Box2> boxes;
  std::vector<int> always;
  double gx0 = 0, gy0 = 0, cell = 1, margin = 0;
  int n = 1;
  std::vector<std::vector<int>> cells;
  mutable std::vector<unsigned> stamp;
  mutable unsigned current = 0;

  // `in_front_exactly`: every point is strictly in front of the eye, decided exactly; otherwise
  // (perspective) the box is marked `always` and nothing is skipped against it.
  Box2 bound(const std::vector<std::array<double, 3>>& pts, bool perspective, bool in_front_exactly = true) const {
    Box2 b{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (const auto& p : pts) {
      if (perspective && !in_front_exactly) b.always = true;
      b.x0 = std::min(b.x0, p[0]);
      b.y0 = std::min(b.y0, p[1]);
      b.x1 = std::max(b.x1, p[0]);
      b.y1 = std::max(b.y1, p[1]);
      b.d0 = std::min(b.d0, p[2]);
      b.d1 = std::max(b.d1, p[2]);
    }
    return b;
  }

  void build(const std::vector<const Polyhedron*>& bodies, const Projector& proj, const Camera& cam) {
    const bool perspective = cam.perspective;
    double ext = 0;
    for (const Polyhedron* p : bodies) {
      std::vector<std::array<double, 3>> pts;
      bool front = true;
      for (const Point3& v : p->vertices()) {
        pts.push_back(proj.project(v));
        front = front && (!perspective || cam.in_front(v) == Sign::Positive);
      }
      boxes.push_back(bound(pts, perspective, front));
      const Box2& b = boxes.back();
      if (!b.always)
        ext = std::max({ext, std::fabs(b.x0), std::fabs(b.x1), std::fabs(b.y0), std::fabs(b.y1), std::fabs(b.d0), std::fabs(b.d1)});
    }
    // A conservative filter only (it skips work, never decides visibility): double projections
    // are within ~1e-15 relative of the exact ones, and the margin is far wider.
    margin = 1e-7 * (ext + 1e-300);
    double X0 = std::numeric_limits<double>::infinity(), Y0 = X0, X1 = -X0, Y1 = -X0;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      if (boxes[i].always) {
        always.push_back(static_cast<int>(i));
        continue;
      }
      X0 = std::min(X0, boxes[i].x0);
      Y0 = std::min(Y0, boxes[i].y0);
      X1 = std::max(X1, boxes[i].x1);
      Y1 = std::max(Y1, boxes[i].y1);
    }
    n = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(boxes.size()))), 1, 512);
    if (!(X1 >= X0)) {
      X0 = Y0 = 0;
      X1 = Y1 = 1;
    }
    gx0 = X0;
    gy0 = Y0;
    cell = std::max({(X1 - X0) / n, (Y1 - Y0) / n, 1e-300});
    cells.assign(static_cast<std::size_t>(n) * n, {});
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      if (boxes[i].always) continue;
      auto [cx0, cy0, cx1, cy1] = range(boxes[i].x0 - margin, boxes[i].y0 - margin, boxes[i].x1 + margin, boxes[i].y1 + margin);
      for (int cy = cy0; cy <= cy1; ++cy)
        for (int cx = cx0; cx <= cx1; ++cx) cells[static_cast<std::size_t>(cy) * n + cx].push_back(static_cast<int>(i));
    }
    stamp.assign(boxes.size(), 0);
  }

  std::array<int, 4> range(double x0, double y0, double x1, double y1) const {
    auto c = [&](double v, double o) { return std::clamp(static_cast<int>(std::floor((v - o) / cell)), 0, n - 1); };
    return {c(x0, gx0), c(y0, gy0), c(x1, gx0), c(y1, gy0)};
  }

  // Bodies that may hide some point of a segment with the given projected bounds.
  void candidates(const Box2& e, std::vector<int>& out) const {
    out.clear();
    if (++current == 0) {
      std::fill(stamp.begin(), stamp.end(), 0);
      current = 1;
    }
    if (e.always) {
      for (std::size_t i = 0; i < boxes.size(); ++i) out.push_back(static_cast<int>(i));
      return;
    }
    for (int i : always) {
      stamp[i] = current;
      out.push_back(i);
    }
    auto [cx0, cy0, cx1, cy1] = range(e.x0 - margin, e.y0 - margin, e.x1 + margin, e.y1 + margin);
    for (int cy = cy0; cy <= cy1; ++cy)
      for (int cx = cx0; cx <= cx1; ++cx)
        for (int i : cells[static_cast<std::size_t>(cy) * n + cx]) {
          if (stamp[i] == current) continue;
          stamp[i] = current;
          const Box2& b = boxes[i];
          if (b.x0 > e.x1 + margin || b.x1 < e.x0 - margin || b.y0 > e.y1 + margin || b.y1 < e.y0 - margin) continue;
          if (b.d0 > e.d1 + margin) continue;  // entirely farther than every point of the segment
          out.push_back(i);
        }
    std::sort(out.begin(), out.end());
  }
};

// ---------------------------------------------------------------- pieces
struct Span {
  Rational lo, hi;  // open, lo < hi, within [0, 1]
};

std::vector<Piece> assemble(std::vector<Span> hidden, const std::optional<std::pair<Rational, Rational>>& depth) {
  std::sort(hidden.begin(), hidden.end(), [](const Span& a, const Span& b) { return a.lo < b.lo; });
  std::vector<Span> merged;
  for (auto& s : hidden) {
    // Touching open intervals leave a single visible point between them: not a line, merged.
    if (!merged.empty() && s.lo <= merged.back().hi) {
      if (s.hi > merged.back().hi) merged.back().hi = s.hi;
    } else {
      merged.push_back(s);
    }
  }
  std::vector<Rational> cuts = {Rational(0), Rational(1)};
  for (auto& s : merged) {
    cuts.push_back(s.lo);
    cuts.push_back(s.hi);
  }
  // Perspective: depth(t) = d0 + t (d1 - d0); the part with depth <= 0 is behind the eye.
  if (depth && depth->first != depth->second) {
    Rational t = depth->first / (depth->first - depth->second);
    if (t > 0 && t < 1) cuts.push_back(t);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<Piece> pieces;
  std::size_t k = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    Rational mid = (cuts[i] + cuts[i + 1]) / 2;
    while (k < merged.size() && merged[k].hi <= mid) ++k;
    bool hidden_here = k < merged.size() && merged[k].lo < mid && mid < merged[k].hi;
    bool behind = depth && depth->first + mid * (depth->second - depth->first) <= 0;
    Piece p{cuts[i], cuts[i + 1], !hidden_here && !behind, behind};
    if (!pieces.empty() && pieces.back().visible == p.visible && pieces.back().behind_eye == p.behind_eye)
      pieces.back().t1 = p.t1;
    else
      pieces.push_back(p);
  }
  return pieces;
}

// Adds the part of `iv` inside [0, 1] to `out`.
void clip_to_unit(const OpenInterval& iv, std::vector<Span>& out) {
  if (iv.empty) return;
  Rational lo = iv.lo && *iv.lo > 0 ? *iv.lo : Rational(0);
  Rational hi = iv.hi && *iv.hi < 1 ? *iv.hi : Rational(1);
  if (lo < hi) out.push_back({lo, hi});
}

// ---------------------------------------------------------------- Stage 3: junction lines
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

void junctions(int a, int b, const BodyMatrixData& A, const BodyMatrixData& B, std::vector<Segment>& out) {
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

std::vector<Piece> pieces_from_hidden(std::vector<std::pair<Rational, Rational>> hidden,
                                      const std::optional<std::pair<Rational, Rational>>& depth) {
  // Common cases without any arithmetic: nothing hidden, or one span over the whole edge.
  if (!depth && hidden.empty()) return {Piece{Rational(0), Rational(1), true}};
  if (!depth && hidden.size() == 1 && hidden[0].first == 0 && hidden[0].second == 1)
    return {Piece{Rational(0), Rational(1), false}};
  std::vector<Span> spans;
  spans.reserve(hidden.size());
  for (auto& h : hidden) spans.push_back({std::move(h.first), std::move(h.second)});
  return assemble(std::move(spans), depth);
}

std::vector<Segment> body_edge_segments(const Polyhedron& p, int body, const std::vector<signed char>& facing,
                                        const RobertsOptions& opt, RobertsStats& stats) {
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
    s.borrow_ends(p.vertices()[e.first], p.vertices()[e.second]);
    s.self_hidden = facing[ff.first] < 0 && facing[ff.second] < 0;
    ++stats.edges;
    if (s.self_hidden) ++stats.self_hidden;
    out.push_back(std::move(s));
  }
  return out;
}

const char* to_string(LineKind k) {
  switch (k) {
    case LineKind::Boundary: return "boundary";
    case LineKind::Crease: return "crease";
    case LineKind::Silhouette: return "silhouette";
    case LineKind::Intersection: return "intersection";
    case LineKind::Edge: break;
  }
  return "edge";
}

Point3 Segment::at(const Rational& t) const {
  if (t == 0) return from();
  if (t == 1) return to();
  return from() + t * (to() - from());
}

void Segment::set_ends(Point3 a, Point3 b) {
  own_ = std::make_shared<const std::array<Point3, 2>>(std::array<Point3, 2>{std::move(a), std::move(b)});
  a_ = &(*own_)[0];
  b_ = &(*own_)[1];
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

RobertsResult roberts(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const RobertsOptions& opt) {
  RobertsResult res;
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
    if (eye_inside) throw RobertsError(static_cast<int>(i), "body " + std::to_string(i) + " contains the eye " + to_string(camera.eye) +
                                                  ": an eye inside a solid sees nothing");
    std::vector<signed char> fc;
    for (const Rational& e : ev) fc.push_back(static_cast<signed char>(sgn(e)));
    res.facing.push_back(std::move(fc));
    res.ev.push_back(std::move(ev));
  }
  std::vector<FastBody> fast;
  for (const BodyMatrix& bm : res.matrices) fast.push_back(prepare_fast_body(bm.V, g));
  Projector proj(camera);
  PreFilter pre;
  pre.build(bodies, proj, camera);

  auto depth_of = [&](const Segment& s) -> std::optional<std::pair<Rational, Rational>> {
    if (!camera.perspective) return std::nullopt;
    return std::make_pair(camera.depth(s.from()), camera.depth(s.to()));
  };
  std::vector<int> cand;
  auto solve = [&](Segment& s, int skip_a, int skip_b) {
    std::vector<Span> hidden;
    auto a = proj.project(s.from()), b = proj.project(s.to());
    bool front = !camera.perspective ||
                 (camera.in_front(s.from()) == Sign::Positive && camera.in_front(s.to()) == Sign::Positive);
    Box2 eb = pre.bound({a, b}, camera.perspective, front);
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
    s.pieces = assemble(std::move(hidden), depth_of(s));
  };

  // Stage 1 and 2: the bodies' edges.
  for (std::size_t i = 0; i < bodies.size(); ++i)
    for (Segment& s : body_edge_segments(*bodies[i], static_cast<int>(i), res.facing[i], opt, res.stats)) {
      if (s.self_hidden)
        s.pieces = pieces_from_hidden({{Rational(0), Rational(1)}}, depth_of(s));
      else
        solve(s, static_cast<int>(i), -1);
      res.segments.push_back(std::move(s));
    }

  // Stage 3: junction lines of every pair of bodies whose bounding boxes meet.
  std::vector<Bounds3> bb;
  for (const Polyhedron* p : bodies) bb.push_back(exact_bounds(*p));
  std::vector<int> order(bodies.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int x, int y) { return bb[x].lo.x() < bb[y].lo.x() || (bb[x].lo.x() == bb[y].lo.x() && x < y); });
  std::vector<Segment> junction;
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t ii = 0; ii < order.size(); ++ii)
    for (std::size_t jj = ii + 1; jj < order.size() && !(bb[order[ii]].hi.x() < bb[order[jj]].lo.x()); ++jj)
      if (boxes_meet(bb[order[ii]], bb[order[jj]]))
        pairs.push_back({std::min(order[ii], order[jj]), std::max(order[ii], order[jj])});
  std::sort(pairs.begin(), pairs.end());
  for (auto [a, b] : pairs) junctions(a, b, res.matrices[a].V, res.matrices[b].V, junction);
  for (Segment& s : junction) {
    solve(s, -1, -1);  // the two bodies themselves may hide their junction line too
    ++res.stats.junction_segments;
    res.segments.push_back(std::move(s));
  }
  return res;
}

}  // namespace hlr
