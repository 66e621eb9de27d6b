// Faces' surfaces (see face_surfaces.hpp; docs/design.md, "Faces' identity").
#include "algorithms/solids/face_surfaces.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <unordered_map>

namespace hlr {

SurfaceEdge surface_edge(const FaceSurfaces& s, int f0, int f1) {
  if (s.surface.empty() || f0 < 0 || f1 < 0) return SurfaceEdge::ByAngle;
  int a = s.surface[f0], b = s.surface[f1];
  if (a == b) return SurfaceEdge::Inside;
  if (!s.sharp_between) return SurfaceEdge::ByAngle;
  if (a > b) std::swap(a, b);
  return std::binary_search(s.tangent.begin(), s.tangent.end(), std::make_pair(a, b)) ? SurfaceEdge::Tangent : SurfaceEdge::Sharp;
}

namespace {

int root(std::vector<int>& parent, int a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

}  // namespace

FaceSurfaces surfaces_from_corner_keys(const std::vector<Face>& faces, const std::vector<std::vector<std::int64_t>>& keys) {
  std::vector<int> parent(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  struct Seen {
    int face;
    std::int64_t lo, hi;  // the keys at the edge's lower and higher vertex
  };
  std::unordered_map<std::uint64_t, Seen> edges;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::size_t n = faces[f].size();
    for (std::size_t k = 0; k < n; ++k) {
      const int a = faces[f][k], b = faces[f][(k + 1) % n];
      const std::int64_t ka = keys[f][k], kb = keys[f][(k + 1) % n];
      const bool up = a < b;
      const std::uint64_t e = (static_cast<std::uint64_t>(up ? a : b) << 32) | static_cast<std::uint32_t>(up ? b : a);
      auto [it, inserted] = edges.emplace(e, Seen{static_cast<int>(f), up ? ka : kb, up ? kb : ka});
      if (!inserted && it->second.lo == (up ? ka : kb) && it->second.hi == (up ? kb : ka))
        parent[root(parent, static_cast<int>(f))] = root(parent, it->second.face);
    }
  }
  FaceSurfaces s;
  s.sharp_between = false;
  s.surface.resize(faces.size());
  std::unordered_map<int, int> number;
  for (std::size_t f = 0; f < faces.size(); ++f)
    s.surface[f] = number.emplace(root(parent, static_cast<int>(f)), static_cast<int>(number.size())).first->second;
  return s;
}

FaceSurfaces renumbered_surfaces(const FaceSurfaces& s, const std::vector<int>& part) {
  if (s.empty()) return s;
  FaceSurfaces out;
  out.tangent = s.tangent;
  out.sharp_between = s.sharp_between;
  int next = s.surface.empty() ? 0 : *std::max_element(s.surface.begin(), s.surface.end()) + 1;
  std::map<int, int> extra;  // a part with no old face: its own new surface
  out.surface.reserve(part.size());
  for (int p : part) {
    if (p >= 0 && static_cast<std::size_t>(p) < s.surface.size()) {
      out.surface.push_back(s.surface[p]);
    } else {
      auto [it, fresh] = extra.emplace(p, next);
      if (fresh) ++next;
      out.surface.push_back(it->second);
    }
  }
  return out;
}

}  // namespace hlr
