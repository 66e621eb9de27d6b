// Exact convexity test, course notes section 23 (see convexity.hpp).
#include "algorithms/solids/convexity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <unordered_set>

#include "algorithms/solids/hull_triangles.hpp"

#include "kernel/predicates.hpp"

namespace hlr {

namespace {

// The first vertex (by index) strictly on each side of plane f: the verdict's witnesses.
void first_witnesses(const Plane& h, const std::vector<Point3>& vs, int& pos, int& neg) {
  pos = neg = -1;
  for (std::size_t v = 0; v < vs.size() && (pos < 0 || neg < 0); ++v) {
    Sign s = side_of_plane(h, vs[v]);
    if (s == Sign::Positive && pos < 0) pos = static_cast<int>(v);
    if (s == Sign::Negative && neg < 0) neg = static_cast<int>(v);
  }
}

// A bounding-volume tree over the vertices' certified boxes: "is some vertex strictly on this
// side of the plane?" prunes every node whose box lies strictly on the other side (a bound in
// doubles with a rounding margin, so a pruned node holds no such vertex), and decides the rest
// with the exact predicate. On a convex body only the vertices near each face plane are tested.
class VertexTree {
 public:
  explicit VertexTree(const std::vector<Point3>& vs) : vs_(vs), order_(vs.size()) {
    for (std::size_t i = 0; i < vs.size(); ++i) order_[i] = static_cast<int>(i);
    if (!vs.empty()) build(0, vs.size());
  }
  /// Some vertex with side_of_plane(h, v) == want (Positive or Negative)?
  bool any(const Plane& h, Sign want) const { return !nodes_.empty() && search(0, h, want); }

 private:
  struct Node {
    std::array<double, 3> lo, hi;
    std::size_t begin, end;
    int left = -1, right = -1;
  };
  int build(std::size_t begin, std::size_t end) {
    Node n{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}, begin, end};
    for (std::size_t i = begin; i < end; ++i)
      for (int k = 0; k < 3; ++k) {
        n.lo[k] = std::min(n.lo[k], vs_[order_[i]].approx(k).lo);
        n.hi[k] = std::max(n.hi[k], vs_[order_[i]].approx(k).hi);
      }
    int id = static_cast<int>(nodes_.size());
    nodes_.push_back(n);
    if (end - begin > 8) {
      int axis = 0;
      for (int k = 1; k < 3; ++k)
        if (n.hi[k] - n.lo[k] > n.hi[axis] - n.lo[axis]) axis = k;
      std::size_t mid = (begin + end) / 2;
      std::nth_element(order_.begin() + static_cast<long>(begin), order_.begin() + static_cast<long>(mid),
                       order_.begin() + static_cast<long>(end),
                       [&](int a, int b) { return vs_[a].approx(axis).lo < vs_[b].approx(axis).lo; });
      int l = build(begin, mid), r = build(mid, end);
      nodes_[id].left = l, nodes_[id].right = r;
    }
    return id;
  }
  // Bounds of want·h over the node's box: false when certainly no point of it is strictly on
  // the wanted side. Interval products of the certified bounds, plus a margin of 1e-14 of the
  // terms' magnitudes for the roundings of these few operations (NaN or inf never prunes).
  bool may_hold(const Node& n, const Plane& h, Sign want) const {
    double sum = want == Sign::Positive ? h.approx(3).hi : -h.approx(3).lo, mag = std::fabs(h.approx(3).lo) + std::fabs(h.approx(3).hi);
    for (int k = 0; k < 3; ++k) {
      double a0 = h.approx(k).lo, a1 = h.approx(k).hi;
      double p[4] = {a0 * n.lo[k], a0 * n.hi[k], a1 * n.lo[k], a1 * n.hi[k]};
      double best = want == Sign::Positive ? std::max({p[0], p[1], p[2], p[3]}) : -std::min({p[0], p[1], p[2], p[3]});
      sum += best;
      mag += std::fabs(p[0]) + std::fabs(p[1]) + std::fabs(p[2]) + std::fabs(p[3]);
    }
    return !(sum + 1e-14 * mag < 0);  // the largest value of want·h over the box may be positive
  }
  bool search(int id, const Plane& h, Sign want) const {
    const Node& n = nodes_[id];
    if (!may_hold(n, h, want)) return false;
    if (n.left < 0) {
      for (std::size_t i = n.begin; i < n.end; ++i)
        if (side_of_plane(h, vs_[order_[i]]) == want) return true;
      return false;
    }
    return search(n.left, h, want) || search(n.right, h, want);
  }
  const std::vector<Point3>& vs_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

// A plane as a key: its coefficients divided by the first non-zero one of its normal, which
// makes them unique for the plane whichever way it faces (exact rationals), hashed by their
// doubles (equal rationals, equal doubles).
struct PlaneKey {
  int lead = 0;
  std::array<Rational, 4> k;
  explicit PlaneKey(const Plane& h) {
    while (h[lead] == 0) ++lead;  // callers skip degenerate planes
    for (int i = 0; i < 4; ++i) k[i] = h[i] / h[lead];
  }
  bool operator==(const PlaneKey& o) const { return lead == o.lead && k == o.k; }
};
struct PlaneKeyHash {
  std::size_t operator()(const PlaneKey& p) const {
    std::size_t x = static_cast<std::size_t>(p.lead);
    for (const Rational& q : p.k) x = x * 1000003u ^ std::hash<double>()(q.get_d());
    return x;
  }
};

// The Hull method: a verdict from the first face (by index) whose plane is not a plane of the
// vertices' convex hull, with the plain scan's witnesses; Flat when every vertex lies in the
// first face plane (then in all of them).
ConvexityResult convexity_by_hull(const Polyhedron& body) {
  const std::vector<Plane>& planes = body.planes();
  const std::vector<Point3>& vs = body.vertices();
  ConvexityResult r;
  std::size_t f0 = 0;
  while (f0 < planes.size() && planes[f0].is_degenerate()) ++f0;
  if (f0 == planes.size()) {
    r.verdict = planes.empty() ? ConvexityResult::Verdict::NoFaces : ConvexityResult::Verdict::Flat;
    return r;
  }
  int pos = -1, neg = -1;
  first_witnesses(planes[f0], vs, pos, neg);
  if (pos < 0 && neg < 0) {  // every vertex in one plane: every face plane is that plane
    r.verdict = ConvexityResult::Verdict::Flat;
    return r;
  }
  // A face that is a hull triangle (the same three vertices) lies in a hull plane; any other
  // face plane is looked up among the hull triangles' planes.
  const std::vector<std::array<std::size_t, 3>> triangles = hull_triangles(vs);
  auto sorted = [](std::array<std::size_t, 3> t) {
    std::sort(t.begin(), t.end());
    return t;
  };
  struct TripleHash {
    std::size_t operator()(const std::array<std::size_t, 3>& t) const { return (t[0] * 1000003u ^ t[1]) * 1000003u ^ t[2]; }
  };
  std::unordered_set<std::array<std::size_t, 3>, TripleHash> hull_triples;
  hull_triples.reserve(triangles.size());
  for (const auto& t : triangles) hull_triples.insert(sorted(t));
  std::unordered_set<PlaneKey, PlaneKeyHash> hull_planes;  // made when a face first needs them
  const std::vector<Face>& faces = body.faces();
  for (std::size_t f = f0; f < planes.size(); ++f) {
    if (planes[f].is_degenerate()) continue;
    const Face& face = faces[f];
    if (face.size() == 3 &&
        hull_triples.count(sorted({static_cast<std::size_t>(face[0]), static_cast<std::size_t>(face[1]), static_cast<std::size_t>(face[2])})))
      continue;
    if (hull_planes.empty())
      for (const auto& t : triangles) {
        const Point3* corners[3] = {&vs[t[0]], &vs[t[1]], &vs[t[2]]};
        hull_planes.insert(PlaneKey(plane_of_polygon(corners, 3)));
      }
    if (hull_planes.count(PlaneKey(planes[f]))) continue;
    first_witnesses(planes[f], vs, pos, neg);
    if (pos >= 0 && neg >= 0) {  // always, for a plane through vertices that is not a hull plane
      r.verdict = ConvexityResult::Verdict::NonConvex;
      r.face = static_cast<int>(f);
      r.vertex_positive = pos;
      r.vertex_negative = neg;
      return r;
    }
  }
  r.verdict = ConvexityResult::Verdict::Convex;
  return r;
}

}  // namespace

ConvexityResult convexity(const Polyhedron& body, ConvexityMethod method) {
  ConvexityResult r;
  const auto& planes = body.planes();
  const auto& vs = body.vertices();
  if (method == ConvexityMethod::Automatic)
    method = vs.size() * planes.size() > 200'000 ? ConvexityMethod::Hull : ConvexityMethod::AllPairs;
  if (method == ConvexityMethod::Hull) return convexity_by_hull(body);
  std::optional<VertexTree> tree;
  if (method == ConvexityMethod::Tree) tree.emplace(vs);
  bool any_plane = false, any_off = false;
  for (std::size_t f = 0; f < planes.size(); ++f) {
    if (planes[f].is_degenerate()) continue;
    any_plane = true;
    int pos = -1, neg = -1;
    if (tree) {
      bool p = tree->any(planes[f], Sign::Positive), n = tree->any(planes[f], Sign::Negative);
      if (p || n) any_off = true;
      if (!(p && n)) continue;
      first_witnesses(planes[f], vs, pos, neg);  // the same witnesses as the plain test
    } else {
      first_witnesses(planes[f], vs, pos, neg);
      if (pos >= 0 || neg >= 0) any_off = true;
    }
    if (pos >= 0 && neg >= 0) {
      r.verdict = ConvexityResult::Verdict::NonConvex;
      r.face = static_cast<int>(f);
      r.vertex_positive = pos;
      r.vertex_negative = neg;
      return r;
    }
  }
  if (planes.empty())
    r.verdict = ConvexityResult::Verdict::NoFaces;
  else if (!any_plane || !any_off)
    r.verdict = ConvexityResult::Verdict::Flat;
  else
    r.verdict = ConvexityResult::Verdict::Convex;
  return r;
}

std::string describe(const ConvexityResult& r) {
  switch (r.verdict) {
    case ConvexityResult::Verdict::Convex: return "convex";
    case ConvexityResult::Verdict::Flat: return "flat (degenerate): every vertex lies in every face plane";
    case ConvexityResult::Verdict::NoFaces: return "no faces";
    case ConvexityResult::Verdict::NonConvex:
      return "not convex: face " + std::to_string(r.face) + " has vertex " +
             std::to_string(r.vertex_positive) + " on one side of its plane and vertex " +
             std::to_string(r.vertex_negative) + " on the other";
  }
  return {};
}

}  // namespace hlr
