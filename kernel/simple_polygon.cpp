// Simple polygons: the exact simplicity test and the triangulation (see simple_polygon.hpp).
#include "kernel/simple_polygon.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <deque>

#include "kernel/epeck_bridge.hpp"

namespace hlr {
namespace {

constexpr int kFanLimit = kConvexFanLimit;

using K = Epeck;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fb = CGAL::Triangulation_face_base_with_info_2<int, K, CGAL::Constrained_triangulation_face_base_2<K>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

std::vector<K::Point_2> projected(const std::vector<Point3>& pts, const std::vector<int>& poly, const PolygonView& view) {
  std::vector<K::Point_2> out;
  out.reserve(poly.size());
  for (int v : poly) out.emplace_back(to_epeck_ft(pts[v][view.i]), to_epeck_ft(pts[v][view.j]));
  return out;
}

// Sign of the turn a -> b -> c in the view, exact.
int turn(const Point3& a, const Point3& b, const Point3& c, const PolygonView& v) {
  Rational d = (b[v.i] - a[v.i]) * (c[v.j] - a[v.j]) - (b[v.j] - a[v.j]) * (c[v.i] - a[v.i]);
  return v.ccw ? sgn(d) : -sgn(d);
}

// Nesting level of every face: 0 outside, crossing a constrained edge adds one (odd: inside).
void mark_nesting(CDT& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::deque<std::pair<CDT::Face_handle, int>> todo{{cdt.infinite_face(), 0}};
  while (!todo.empty()) {
    auto [f, level] = todo.front();
    todo.pop_front();
    if (f->info() != -1) continue;
    f->info() = level;
    for (int k = 0; k < 3; ++k) {
      CDT::Face_handle g = f->neighbor(k);
      if (g->info() != -1) continue;
      if (cdt.is_constrained(CDT::Edge(f, k)))
        todo.emplace_back(g, level + 1);
      else
        todo.emplace_front(g, level);
    }
  }
}

}  // namespace

PolygonView polygon_view(const Vector3& n) {
  int k = 0;
  for (int a = 1; a < 3; ++a)
    if (abs(n[a]) > abs(n[k])) k = a;
  // Dropping axis k keeps (k+1, k+2) in cyclic order: counter-clockwise when n_k > 0.
  return {(k + 1) % 3, (k + 2) % 3, sgn(n[k]) > 0};
}

bool polygon_is_convex(const std::vector<Point3>& pts, const std::vector<int>& poly, const PolygonView& view) {
  const std::size_t n = poly.size();
  if (n < 3) return false;
  int changes = 0, last = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const Point3 &a = pts[poly[k]], &b = pts[poly[(k + 1) % n]], &c = pts[poly[(k + 2) % n]];
    if (turn(a, b, c, view) <= 0) return false;
    // Strict turns all one way go round once exactly when the x direction changes sign twice.
    int s = sgn(b[view.i] - a[view.i]);
    if (s != 0) {
      if (last != 0 && s != last) ++changes;
      last = s;
    }
  }
  // Close the cycle: compare the last non-zero x direction with the first.
  for (std::size_t k = 0; k < n; ++k)
    if (int s = sgn(pts[poly[(k + 1) % n]][view.i] - pts[poly[k]][view.i]); s != 0) {
      if (s != last) ++changes;
      break;
    }
  return changes <= 2;
}

bool polygon_is_simple(const std::vector<Point3>& pts, const std::vector<int>& poly, const PolygonView& view) {
  if (poly.size() < 3) return false;
  if (polygon_is_convex(pts, poly, view)) return true;
  std::vector<K::Point_2> p = projected(pts, poly, view);
  return CGAL::is_simple_2(p.begin(), p.end(), K());
}

std::vector<PolygonTriangle> triangulate_simple_polygon(const std::vector<Point3>& pts, const std::vector<int>& poly,
                                                        const PolygonView& view) {
  const int n = static_cast<int>(poly.size());
  std::vector<PolygonTriangle> out;
  if (polygon_is_convex(pts, poly, view)) {
    if (n <= kFanLimit) {
      for (int k = 1; k + 1 < n; ++k) out.push_back({{0, k, k + 1}, {k == 1, true, k + 1 == n - 1}});
      return out;
    }
    // Many vertices: halve recursively, so that triangles far from the centre are small and
    // their boxes overlap few others (a fan's long triangles all overlap each other and every
    // side face of a prism: quadratic intersection candidates).
    auto is_edge = [n](int a, int b) { return (a + 1) % n == b; };
    auto add = [&](int a, int b, int c) { out.push_back({{a, b, c}, {is_edge(a, b), is_edge(b, c), is_edge(c, a)}}); };
    const int a = 0, b = n / 3, c = 2 * n / 3;
    add(a, b, c);
    std::vector<std::pair<int, int>> chains = {{a, b}, {b, c}, {c, n}};  // positions, end exclusive of wrap
    while (!chains.empty()) {
      auto [u, w] = chains.back();
      chains.pop_back();
      if (w - u < 2) continue;
      const int m = u + (w - u) / 2;
      add(u, m, w % n);
      chains.push_back({u, m});
      chains.push_back({m, w});
    }
    return out;
  }
  std::vector<K::Point_2> p = projected(pts, poly, view);
  CDT cdt;
  std::vector<CDT::Vertex_handle> vh(n);
  for (int k = 0; k < n; ++k) {
    vh[k] = cdt.insert(p[k]);
    vh[k]->info() = k;
  }
  for (int k = 0; k < n; ++k) cdt.insert_constraint(vh[k], vh[(k + 1) % n]);
  mark_nesting(cdt);
  auto is_edge = [n](int a, int b) { return (a + 1) % n == b || (b + 1) % n == a; };
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info() % 2 == 0) continue;
    std::array<int, 3> t = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};  // ccw in the view
    if (!view.ccw) std::swap(t[1], t[2]);
    out.push_back({t, {is_edge(t[0], t[1]), is_edge(t[1], t[2]), is_edge(t[2], t[0])}});
  }
  return out;
}

std::vector<std::array<int, 3>> triangulate_loops(const std::vector<Point3>& pts, const std::vector<std::array<int, 2>>& edges,
                                                  const PolygonView& view) {
  CDT cdt;
  std::vector<CDT::Vertex_handle> vh(pts.size());
  auto vertex = [&](int k) {
    if (vh[k] == CDT::Vertex_handle()) {
      vh[k] = cdt.insert(K::Point_2(to_epeck_ft(pts[k][view.i]), to_epeck_ft(pts[k][view.j])));
      vh[k]->info() = k;
    }
    return vh[k];
  };
  for (const auto& e : edges)
    if (e[0] != e[1]) cdt.insert_constraint(vertex(e[0]), vertex(e[1]));
  mark_nesting(cdt);
  std::vector<std::array<int, 3>> out;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info() % 2 == 0) continue;
    std::array<int, 3> t = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};  // ccw in the view
    if (!view.ccw) std::swap(t[1], t[2]);
    out.push_back(t);
  }
  return out;
}

}  // namespace hlr
