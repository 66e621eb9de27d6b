// Combinatorial and exact geometric checks of a face list (see mesh_checks.hpp).
#include "kernel/mesh_checks.hpp"
#include "kernel/simple_polygon.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include "kernel/polyhedron.hpp"
#include "kernel/predicates.hpp"

namespace hlr {
namespace {

std::uint64_t key(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

struct EdgeUse {
  int forward = 0;   // traversals a -> b with a < b
  int backward = 0;  // traversals b -> a
};

void check_edges(const std::vector<Face>& faces, MeshReport& r) {
  std::unordered_map<std::uint64_t, EdgeUse> uses;
  uses.reserve(faces.size() * 2);
  for (const auto& f : faces)
    for (std::size_t i = 0; i < f.size(); ++i) {
      int a = f[i], b = f[(i + 1) % f.size()];
      if (a == b) continue;
      if (a < b)
        ++uses[key(a, b)].forward;
      else
        ++uses[key(b, a)].backward;
    }
  for (const auto& [k, u] : uses) {
    Edge e{static_cast<int>(k >> 32), static_cast<int>(k & 0xffffffffu)};
    int n = u.forward + u.backward;
    if (n == 1) r.boundary_edges.push_back(e);
    if (n > 2) r.non_manifold_edges.push_back(e);
    if (u.forward > 1 || u.backward > 1) r.misoriented_edges.push_back(e);
  }
  std::sort(r.boundary_edges.begin(), r.boundary_edges.end());
  std::sort(r.non_manifold_edges.begin(), r.non_manifold_edges.end());
  std::sort(r.misoriented_edges.begin(), r.misoriented_edges.end());
}

int find(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// A vertex is non-manifold when the faces around it fall into more than one fan: corners of
// faces at v are joined when they share an edge v-w.
void check_vertices(std::size_t nv, const std::vector<Face>& faces, MeshReport& r) {
  std::vector<std::vector<std::pair<int, int>>> corners(nv);  // per vertex: (prev, next)
  std::vector<int> uses(nv, 0);
  for (const auto& f : faces)
    for (std::size_t i = 0; i < f.size(); ++i) {
      int v = f[i];
      corners[v].push_back({f[(i + f.size() - 1) % f.size()], f[(i + 1) % f.size()]});
      ++uses[v];
    }
  for (std::size_t v = 0; v < nv; ++v) {
    if (uses[v] == 0) {
      r.isolated_vertices.push_back(static_cast<int>(v));
      continue;
    }
    auto& cs = corners[v];
    std::vector<int> parent(cs.size());
    std::iota(parent.begin(), parent.end(), 0);
    std::unordered_map<int, int> first_with_neighbour;
    for (std::size_t c = 0; c < cs.size(); ++c)
      for (int w : {cs[c].first, cs[c].second}) {
        auto [it, inserted] = first_with_neighbour.emplace(w, static_cast<int>(c));
        if (!inserted) parent[find(parent, static_cast<int>(c))] = find(parent, it->second);
      }
    int roots = 0;
    for (std::size_t c = 0; c < cs.size(); ++c) roots += find(parent, static_cast<int>(c)) == static_cast<int>(c);
    if (roots > 1) r.non_manifold_vertices.push_back(static_cast<int>(v));
  }
}

void check_faces(const std::vector<Point3>& vs, const std::vector<Face>& faces,
                 const std::vector<Plane>& planes, MeshReport& r) {
  for (std::size_t fi = 0; fi < faces.size(); ++fi) {
    const auto& f = faces[fi];
    int face = static_cast<int>(fi);
    std::vector<int> sorted = f;
    std::sort(sorted.begin(), sorted.end());
    auto rep = std::adjacent_find(sorted.begin(), sorted.end());
    if (rep != sorted.end()) {
      r.degenerate_faces.push_back({face, "repeated vertex " + std::to_string(*rep)});
      continue;
    }
    const Plane& h = planes[fi];
    if (h.is_degenerate()) {
      std::vector<const Point3*> pts;
      for (int v : f) pts.push_back(&vs[v]);
      switch (zero_area_kind(pts.data(), pts.size())) {
        case ZeroAreaKind::Collinear: r.degenerate_faces.push_back({face, "collinear vertices"}); break;
        case ZeroAreaKind::Crossing: r.zero_area_crossing.push_back(face); break;  // a symmetric bow-tie
        case ZeroAreaKind::NonPlanar: r.non_planar_faces.push_back({face, f[0]}); break;
      }
      continue;
    }
    for (int v : f)
      if (side_of_plane(h, vs[v]) != Sign::Zero) {
        r.non_planar_faces.push_back({face, v});
        break;
      }
  }
}

void check_duplicates(const std::vector<Point3>& vs, MeshReport& r) {
  std::vector<int> order(vs.size());
  std::iota(order.begin(), order.end(), 0);
  auto approx_key = [&](int i) {
    const Point3& p = vs[i];
    return std::make_tuple(p.approx(0).lo, p.approx(0).hi, p.approx(1).lo, p.approx(1).hi,
                           p.approx(2).lo, p.approx(2).hi);
  };
  // Equal exact points have equal bounds; sort by bounds, then exactly within equal bounds.
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    auto ka = approx_key(a), kb = approx_key(b);
    if (ka != kb) return ka < kb;
    if (!(vs[a] == vs[b])) return vs[a] < vs[b];
    return a < b;
  });
  for (std::size_t i = 1; i < order.size(); ++i) {
    std::size_t j = i;
    while (j > 0 && approx_key(order[j - 1]) == approx_key(order[i]) && vs[order[j - 1]] == vs[order[i]]) --j;
    if (j < i) r.duplicate_vertices.push_back({order[j], order[i]});
  }
  std::sort(r.duplicate_vertices.begin(), r.duplicate_vertices.end());
}

// Vertices strictly inside a boundary edge (a T-junction leaves the long edge unmatched, so a
// closed mesh with one shows it as boundary edges). Candidates by a sort on x, exact test.
void check_t_junctions(const std::vector<Point3>& vs, MeshReport& r) {
  if (r.boundary_edges.empty()) return;
  std::vector<int> by_x(vs.size());
  std::iota(by_x.begin(), by_x.end(), 0);
  std::sort(by_x.begin(), by_x.end(), [&](int a, int b) { return vs[a].approx(0).lo < vs[b].approx(0).lo; });
  for (const Edge& e : r.boundary_edges) {
    const Point3 &a = vs[e.first], &b = vs[e.second];
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(a.approx(k).lo, b.approx(k).lo);
      hi[k] = std::max(a.approx(k).hi, b.approx(k).hi);
    }
    auto it = std::lower_bound(by_x.begin(), by_x.end(), lo[0], [&](int v, double x) { return vs[v].approx(0).hi < x; });
    for (; it != by_x.end() && vs[*it].approx(0).lo <= hi[0]; ++it) {
      int v = *it;
      if (v == e.first || v == e.second) continue;
      const Point3& p = vs[v];
      if (p.approx(1).hi < lo[1] || p.approx(1).lo > hi[1] || p.approx(2).hi < lo[2] || p.approx(2).lo > hi[2]) continue;
      if (!collinear(a, b, p)) continue;
      if (dot(p - a, b - a) > 0 && dot(p - b, a - b) > 0) r.t_junctions.push_back({v, e});
    }
  }
}

// Planar, non-degenerate faces of 4+ vertices that are not simple polygons (simple_polygon.hpp:
// a convex face is recognised in linear time, any other by a sweep, O(n log n)).
void check_self_intersections(const std::vector<Point3>& vs, const std::vector<Face>& faces,
                              const std::vector<Plane>& planes, MeshReport& r) {
  std::vector<char> skip(faces.size(), 0);
  for (const auto& d : r.degenerate_faces) skip[d.face] = 1;
  for (const auto& n : r.non_planar_faces) skip[n.face] = 1;
  for (int f : r.zero_area_crossing) skip[f] = 1;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (skip[f] || faces[f].size() < 4) continue;
    if (!polygon_is_simple(vs, faces[f], polygon_view(planes[f].normal())))
      r.self_intersecting_faces.push_back(static_cast<int>(f));
  }
  // Planar faces whose signed areas cancel (the Newell normal is zero) cross themselves too.
  r.self_intersecting_faces.insert(r.self_intersecting_faces.end(), r.zero_area_crossing.begin(), r.zero_area_crossing.end());
  std::sort(r.self_intersecting_faces.begin(), r.self_intersecting_faces.end());
}

// Closed, oriented meshes: the signed volume of every component (faces joined across edges);
// a negative one is inside out or the shell of a cavity.
void check_components(const std::vector<Point3>& vs, const std::vector<Face>& faces, MeshReport& r) {
  if (!r.closed() || !r.oriented() || faces.empty()) return;
  std::vector<int> parent(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::unordered_map<std::uint64_t, int> first_face;
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (std::size_t i = 0; i < faces[f].size(); ++i) {
      int a = faces[f][i], b = faces[f][(i + 1) % faces[f].size()];
      if (a == b) continue;
      auto [it, fresh] = first_face.emplace(key(std::min(a, b), std::max(a, b)), static_cast<int>(f));
      if (!fresh) parent[find(parent, static_cast<int>(f))] = find(parent, it->second);
    }
  std::map<int, std::vector<Face>> comps;
  for (std::size_t f = 0; f < faces.size(); ++f) comps[find(parent, static_cast<int>(f))].push_back(faces[f]);
  if (comps.size() < 2) return;
  std::map<int, int> lowest;
  for (std::size_t f = 0; f < faces.size(); ++f) lowest.emplace(find(parent, static_cast<int>(f)), static_cast<int>(f));
  for (const auto& [root, fs] : comps)
    if (six_signed_volume(vs, fs) < 0) r.negative_components.push_back(lowest[root]);
  std::sort(r.negative_components.begin(), r.negative_components.end());
}

}  // namespace

MeshReport check_mesh(const std::vector<Point3>& vertices,
                      const std::vector<Face>& faces,
                      const std::vector<Plane>& planes) {
  MeshReport r;
  check_edges(faces, r);
  check_vertices(vertices.size(), faces, r);
  check_faces(vertices, faces, planes, r);
  check_duplicates(vertices, r);
  check_t_junctions(vertices, r);
  check_self_intersections(vertices, faces, planes, r);
  check_components(vertices, faces, r);
  return r;
}

std::string to_string(const Edge& e) {
  return std::to_string(e.first) + "-" + std::to_string(e.second);
}

std::string solid_problem(const MeshReport& r) {
  auto face = [](int f) { return "face " + std::to_string(f); };
  if (!r.non_manifold_edges.empty())
    return "edge " + to_string(r.non_manifold_edges[0]) + " is in three or more faces (not manifold)";
  if (!r.non_manifold_vertices.empty())
    return "vertex " + std::to_string(r.non_manifold_vertices[0]) + " joins separate fans of faces (not manifold)";
  if (!r.boundary_edges.empty()) return "edge " + to_string(r.boundary_edges[0]) + " is in one face only (not closed)";
  if (!r.misoriented_edges.empty())
    return "edge " + to_string(r.misoriented_edges[0]) + " is traversed twice in one direction (faces not consistently oriented)";
  if (!r.non_planar_faces.empty())
    return face(r.non_planar_faces[0].face) + " is not planar (vertex " + std::to_string(r.non_planar_faces[0].vertex) + " is off its plane)";
  if (!r.degenerate_faces.empty()) return face(r.degenerate_faces[0].face) + " is degenerate (" + r.degenerate_faces[0].why + ")";
  if (!r.self_intersecting_faces.empty()) return face(r.self_intersecting_faces[0]) + " crosses itself";
  if (!r.duplicate_vertices.empty())
    return "vertices " + std::to_string(r.duplicate_vertices[0].first) + " and " + std::to_string(r.duplicate_vertices[0].second) +
           " are the same point";
  if (!r.t_junctions.empty())
    return "vertex " + std::to_string(r.t_junctions[0].vertex) + " lies inside edge " + to_string(r.t_junctions[0].edge) +
           " (a T-junction)";
  return {};
}

}  // namespace hlr
