// Body topology (see body_topology.hpp): counting sort of edge uses by their lower vertex,
// then a sort within each bucket.
#include "algorithms/body_topology.hpp"

#include <algorithm>

namespace hlr {

BodyTopology body_topology(const std::vector<Face>& faces, std::size_t nv) {
  BodyTopology t;
  std::vector<int>& fo = t.face_offset;
  fo.resize(faces.size() + 1, 0);
  for (std::size_t f = 0; f < faces.size(); ++f) fo[f + 1] = fo[f] + static_cast<int>(faces[f].size());
  t.slot_third.assign(fo.back(), -1);
  t.slot_edge.assign(fo.back(), -1);
  struct U {
    std::uint64_t key;
    int face, slot;
    bool forward;
  };
  std::vector<std::uint32_t> start(nv + 1, 0);
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (std::size_t k = 0; k < faces[f].size(); ++k) {
      int u = faces[f][k], v = faces[f][(k + 1) % faces[f].size()];
      if (u != v) ++start[std::min(u, v) + 1];
    }
  for (std::size_t i = 1; i <= nv; ++i) start[i] += start[i - 1];
  std::vector<U> uses(start[nv]);
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t f = 0; f < faces.size(); ++f)
      for (std::size_t k = 0; k < faces[f].size(); ++k) {
        int u = faces[f][k], v = faces[f][(k + 1) % faces[f].size()];
        if (u == v) continue;
        std::uint64_t key = (static_cast<std::uint64_t>(std::min(u, v)) << 32) | static_cast<std::uint32_t>(std::max(u, v));
        uses[fill[std::min(u, v)]++] = {key, static_cast<int>(f), fo[f] + static_cast<int>(k), u < v};
      }
  }
  auto less = [](const U& a, const U& c) { return a.key < c.key || (a.key == c.key && a.slot < c.slot); };
  for (std::size_t i = 0; i < nv; ++i)
    if (start[i + 1] - start[i] > 1) std::sort(uses.begin() + start[i], uses.begin() + start[i + 1], less);
  std::size_t distinct = 0;
  for (std::size_t i = 0; i < uses.size(); ++i) distinct += i == 0 || uses[i].key != uses[i - 1].key;
  t.edges.reserve(distinct);
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    BodyEdge e;
    e.u = static_cast<int>(uses[i].key >> 32);
    e.v = static_cast<int>(uses[i].key & 0xffffffffu);
    for (; j < uses.size() && uses[j].key == uses[i].key; ++j) {
      e.uses.push_back({uses[j].face, uses[j].slot, uses[j].forward});
      t.slot_edge[uses[j].slot] = static_cast<int>(t.edges.size());
    }
    t.edges.push_back(std::move(e));
    i = j;
  }
  return t;
}

}  // namespace hlr
