// Transparency, exactly per region (course notes section 41). See transparency.hpp.
#include "algorithms/surfaces/transparency.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "algorithms/picture/offset_point.hpp"
#include "algorithms/picture/picture_box.hpp"

namespace hlr {
namespace {

using Box = PictureBox;

bool may_hold(const Box& b, const std::array<double, 2>& m) {
  if (!b.ok || !std::isfinite(m[0]) || !std::isfinite(m[1])) return true;
  return b.lo[0] <= m[0] && m[0] <= b.hi[0] && b.lo[1] <= m[1] && m[1] <= b.hi[1];
}

}  // namespace

TransparentPicture transparent_regions(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineDrawing& lines,
                                       const std::vector<char>& see_through) {
  // The priority list with the faces turned away kept where the body lets light through.
  LineDrawing facing;
  facing.facing = lines.facing;
  facing.back_faces_unseen = lines.back_faces_unseen;
  for (std::size_t b = 0; b < facing.back_faces_unseen.size() && b < see_through.size(); ++b)
    if (see_through[b]) facing.back_faces_unseen[b] = 0;
  PriorityResult pr = priority_list(bodies, camera, facing);
  TransparentPicture out;
  out.painted = pr.order.size();
  out.cuts = pr.splits;
  // The arrangement of every painted polygon's sides.
  std::vector<Exact2> points;
  std::vector<std::array<std::uint32_t, 2>> segs;
  std::vector<Box> boxes;
  for (int i : pr.order) {
    const auto& p = pr.polygons[i].pts;
    const auto base = static_cast<std::uint32_t>(points.size());
    points.insert(points.end(), p.begin(), p.end());
    for (std::uint32_t k = 0; k < p.size(); ++k) segs.push_back({base + k, base + (k + 1) % static_cast<std::uint32_t>(p.size())});
    boxes.push_back(picture_box(p));
  }
  PlanarArrangement arr = build_arrangement(std::move(points), segs);
  // Each cycle: the painted polygons over the point beside its first half-edge, back to front,
  // from the nearest opaque one on.
  std::map<std::vector<std::pair<int, int>>, int> label_of;
  std::vector<std::vector<std::pair<int, int>>> lists;
  std::vector<int> label(arr.cycle_edge.size(), -1);
  for (std::size_t c = 0; c < arr.cycle_edge.size(); ++c) {
    const std::uint32_t h = arr.cycle_edge[c];
    const Exact2 &a = arr.points[arr.origin[h]], &b = arr.points[arr.head(h)];
    const Exact2 m{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2};
    const Exact2 n{a[1] - b[1], b[0] - a[0]};
    const std::array<double, 2> md{m[0].get_d(), m[1].get_d()};
    std::vector<std::pair<int, int>> list;
    for (std::size_t k = 0; k < pr.order.size(); ++k) {
      if (!may_hold(boxes[k], md)) continue;
      const PriorityPolygon& p = pr.polygons[pr.order[k]];
      if (!offset_inside_convex(p.pts, m, n)) continue;
      if (!see_through[p.body]) list.clear();  // opaque: nothing behind it shows
      list.emplace_back(p.body, p.face);
    }
    if (list.empty()) continue;
    auto [it, fresh] = label_of.emplace(list, static_cast<int>(lists.size()));
    if (fresh) lists.push_back(list);
    label[c] = it->second;
  }
  for (const LabelledRegion& r : merge_regions(arr, label, -1)) {
    TransparentRegion tr;
    tr.faces = lists[r.label];
    for (std::uint32_t h : r.outer) tr.polygon.outer_2d.push_back(arr.points[arr.origin[h]]);
    for (const auto& hole : r.holes) {
      tr.polygon.holes_2d.emplace_back();
      for (std::uint32_t h : hole) tr.polygon.holes_2d.back().push_back(arr.points[arr.origin[h]]);
    }
    tr.polygon.area2 = r.area2;
    out.regions.push_back(std::move(tr));
  }
  return out;
}

}  // namespace hlr
