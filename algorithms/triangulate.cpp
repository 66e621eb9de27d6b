// Exact ear-clipping triangulation (see triangulate.hpp).
#include "algorithms/triangulate.hpp"

namespace hlr {
namespace {

struct Plane2 {
  int i, j;   // kept coordinates
  int flip;   // +1 when (i, j) is counter-clockwise seen along the normal
};

Plane2 drop_axis(const Vector3& n) {
  int k = 0;
  for (int a = 1; a < 3; ++a)
    if (abs(n[a]) > abs(n[k])) k = a;
  // Dropping axis k keeps (k+1, k+2) in cyclic order: counter-clockwise when n_k > 0.
  return {(k + 1) % 3, (k + 2) % 3, sgn(n[k]) > 0 ? 1 : -1};
}

int orient2(const Point3& a, const Point3& b, const Point3& c, const Plane2& p) {
  Rational d = (b[p.i] - a[p.i]) * (c[p.j] - a[p.j]) - (b[p.j] - a[p.j]) * (c[p.i] - a[p.i]);
  return sgn(d) * p.flip;
}

}  // namespace

std::vector<FaceTriangle> triangulate_face(const std::vector<Point3>& pts, const std::vector<int>& poly,
                                           const Vector3& normal) {
  const int n = static_cast<int>(poly.size());
  std::vector<FaceTriangle> out;
  if (n == 3) {
    out.push_back({{0, 1, 2}, {true, true, true}});
    return out;
  }
  Plane2 pl = drop_axis(normal);
  auto P = [&](int k) -> const Point3& { return pts[poly[k]]; };
  bool convex = true;
  for (int k = 0; k < n && convex; ++k)
    if (orient2(P(k), P((k + 1) % n), P((k + 2) % n), pl) <= 0) convex = false;
  if (convex) {
    for (int k = 1; k + 1 < n; ++k) out.push_back({{0, k, k + 1}, {k == 1, true, k + 1 == n - 1}});
    return out;
  }
  // Ear clipping over a ring; `on_edge[k]`: the side from ring[k] to its successor is a polygon edge.
  std::vector<int> ring(n);
  std::vector<bool> on_edge(n, true);
  for (int k = 0; k < n; ++k) ring[k] = k;
  auto inside_or_on = [&](int a, int b, int c, int x) {
    return orient2(P(a), P(b), P(x), pl) >= 0 && orient2(P(b), P(c), P(x), pl) >= 0 && orient2(P(c), P(a), P(x), pl) >= 0;
  };
  while (ring.size() > 3) {
    const int m = static_cast<int>(ring.size());
    bool clipped = false;
    for (int k = 0; k < m && !clipped; ++k) {
      int a = ring[(k + m - 1) % m], b = ring[k], c = ring[(k + 1) % m];
      if (orient2(P(a), P(b), P(c), pl) <= 0) continue;
      bool ear = true;
      for (int x : ring)
        if (x != a && x != b && x != c && !(pts[poly[x]] == P(a) || pts[poly[x]] == P(b) || pts[poly[x]] == P(c)) &&
            inside_or_on(a, b, c, x)) {
          ear = false;
          break;
        }
      if (!ear) continue;
      int km = (k + m - 1) % m;
      out.push_back({{a, b, c}, {on_edge[km], on_edge[k], false}});
      ring.erase(ring.begin() + k);
      on_edge.erase(on_edge.begin() + k);
      on_edge[k == 0 ? m - 2 : k - 1] = false;  // the new side a -> c is a diagonal
      clipped = true;
    }
    if (!clipped) {
      // Only collinear (zero-angle) vertices left as candidates: drop one; the side that
      // replaces two polygon edges is marked a diagonal (no neighbour information across it).
      for (int k = 0; k < m && !clipped; ++k) {
        int a = ring[(k + m - 1) % m], b = ring[k], c = ring[(k + 1) % m];
        if (orient2(P(a), P(b), P(c), pl) != 0) continue;
        ring.erase(ring.begin() + k);
        on_edge.erase(on_edge.begin() + k);
        on_edge[k == 0 ? m - 2 : k - 1] = false;
        clipped = true;
      }
      if (!clipped) return {};
    }
  }
  if (orient2(P(ring[0]), P(ring[1]), P(ring[2]), pl) > 0)
    out.push_back({{ring[0], ring[1], ring[2]}, {on_edge[0], on_edge[1], on_edge[2]}});
  return out;
}

}  // namespace hlr
