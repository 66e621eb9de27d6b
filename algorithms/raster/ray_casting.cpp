// Ray casting, exact (course notes section 35). See ray_casting.hpp.
#include "algorithms/raster/ray_casting.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>

#include "algorithms/support/parallel.hpp"
#include "algorithms/raster/zbuffer.hpp"

namespace hlr {
namespace {

// A BVH over picture boxes: nodes hold their box and either two children or a run of leaves.
struct Node {
  std::array<double, 4> box;
  int left = -1, right = -1;  // children (inner node)
  int first = 0, count = 0;   // leaf: order[first, first + count)
};

class Bvh {
 public:
  explicit Bvh(const RasterScene& s) : s_(s) {
    order_.resize(s.polygons.size());
    std::iota(order_.begin(), order_.end(), 0);
    if (!order_.empty()) build(0, static_cast<int>(order_.size()));
  }
  std::size_t size() const { return nodes_.size(); }

  // Polygons whose boxes contain (x, y).
  void query(double x, double y, std::vector<int>& out) const {
    out.clear();
    if (nodes_.empty()) return;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (x < n.box[0] || x > n.box[2] || y < n.box[1] || y > n.box[3]) continue;
      if (n.left < 0) {
        for (int k = n.first; k < n.first + n.count; ++k) {
          const auto& b = s_.polygons[order_[k]].box;
          if (x >= b[0] && x <= b[2] && y >= b[1] && y <= b[3]) out.push_back(order_[k]);
        }
        continue;
      }
      stack[top++] = n.left;
      stack[top++] = n.right;
    }
    std::sort(out.begin(), out.end());
  }

 private:
  int build(int first, int end) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.push_back(Node{});
    std::array<double, 4> box{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (int k = first; k < end; ++k) {
      const auto& b = s_.polygons[order_[k]].box;
      box = {std::min(box[0], b[0]), std::min(box[1], b[1]), std::max(box[2], b[2]), std::max(box[3], b[3])};
    }
    nodes_[id].box = box;
    if (end - first <= 4 || depth_ >= 60) {
      nodes_[id].first = first, nodes_[id].count = end - first;
      return id;
    }
    const int axis = box[2] - box[0] >= box[3] - box[1] ? 0 : 1;
    const int mid = (first + end) / 2;
    std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + end, [&](int a, int b) {
      const auto &p = s_.polygons[a].box, &q = s_.polygons[b].box;
      return p[axis] + p[axis + 2] < q[axis] + q[axis + 2];
    });
    ++depth_;
    int l = build(first, mid), r = build(mid, end);
    --depth_;
    nodes_[id].left = l, nodes_[id].right = r;
    return id;
  }

  const RasterScene& s_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
  int depth_ = 0;
};

}  // namespace

FaceIdBuffer ray_cast(const RasterScene& s, const RayCastOptions& o, RayCastStats* stats) {
  const RasterGrid& g = s.grid;
  Bvh bvh(s);
  std::vector<int> frame(static_cast<std::size_t>(g.width) * g.height, -1);
  std::atomic<std::size_t> candidates{0};
  ParallelLoop(o.threads).for_each(g.height, 1, [&](std::size_t j) {
    std::vector<int> cand;
    std::size_t n = 0;
    for (int i = 0; i < g.width; ++i) {
      bvh.query(g.cx(i), g.cy(static_cast<int>(j)), cand);
      n += cand.size();
      frame[j * g.width + i] = seen_among(s, cand, i, static_cast<int>(j));
    }
    candidates += n;
  });
  if (stats) stats->nodes = bvh.size(), stats->candidates = candidates;
  return face_ids(s, frame);
}

}  // namespace hlr
