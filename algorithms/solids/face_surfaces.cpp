// Faces' surfaces (see face_surfaces.hpp; docs/design.md, "Faces' identity").
#include "algorithms/solids/face_surfaces.hpp"

#include <algorithm>
#include <map>

namespace hlr {

SurfaceEdge surface_edge(const FaceSurfaces& s, int f0, int f1) {
  if (s.surface.empty() || f0 < 0 || f1 < 0) return SurfaceEdge::ByAngle;
  int a = s.surface[f0], b = s.surface[f1];
  if (a == b) return SurfaceEdge::Inside;
  if (!s.sharp_between) return SurfaceEdge::ByAngle;
  if (a > b) std::swap(a, b);
  return std::binary_search(s.tangent.begin(), s.tangent.end(), std::make_pair(a, b)) ? SurfaceEdge::Tangent : SurfaceEdge::Sharp;
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
