// The convex hull as triangles of the input points (see hull_triangles.hpp).
#include "algorithms/solids/hull_triangles.hpp"

#include <CGAL/Convex_hull_traits_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <tuple>
#include <unordered_map>

#include "kernel/epeck_bridge.hpp"

namespace hlr {
namespace {

// The input index of a point CGAL gives back: found by its handle (the hull's points are
// copies of the input's handles, sharing their representation), else by its exact value
// among the inputs of the same lower bounds. Reading CGAL's exact value evaluates it once under
// a lock (a system call each), so it is left for the second way.
class InputIndex {
 public:
  InputIndex(const std::vector<Point3>& points, const std::vector<Epeck::Point_3>& pts) : points_(points) {
    by_handle_.reserve(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) by_handle_.emplace(pts[i].id(), i);
  }
  std::size_t operator()(const Epeck::Point_3& p) {
    const auto found = by_handle_.find(p.id());
    if (found != by_handle_.end()) return found->second;
    if (by_bounds_.empty())
      for (std::size_t i = 0; i < points_.size(); ++i) by_bounds_.emplace(key(points_[i]), i);
    const Point3 q = from_epeck(p);
    const auto [lo, hi] = by_bounds_.equal_range(key(q));
    for (auto it = lo; it != hi; ++it)
      if (points_[it->second] == q) return it->second;
    throw std::logic_error("convex hull: a vertex that is not an input point");
  }

 private:
  using Key = std::tuple<double, double, double>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      const std::hash<double> h;
      return h(std::get<0>(k)) * 1000003u ^ h(std::get<1>(k)) * 131u ^ h(std::get<2>(k));
    }
  };
  static Key key(const Point3& p) { return {p.approx(0).lo, p.approx(1).lo, p.approx(2).lo}; }
  const std::vector<Point3>& points_;
  std::unordered_map<CGAL::Handle::Id_type, std::size_t> by_handle_;
  std::unordered_multimap<Key, std::size_t, KeyHash> by_bounds_;
};

}  // namespace

std::vector<std::array<std::size_t, 3>> hull_triangles(const std::vector<Point3>& points) {
  std::vector<std::array<std::size_t, 3>> out;
  if (points.size() < 4) return out;
  std::vector<Epeck::Point_3> pts;
  pts.reserve(points.size());
  for (const Point3& p : points) pts.push_back(to_epeck(p));
  using Mesh = CGAL::Surface_mesh<Epeck::Point_3>;
  Mesh hull;
  // Planes as point triples, sides by orientation of four points (the kernel's own traits
  // build each plane as a lazy exact construction, whose wide intervals sent most side tests to
  // exact numbers).
  CGAL::convex_hull_3(pts.begin(), pts.end(), hull, CGAL::Convex_hull_traits_3<Epeck, Mesh, CGAL::Tag_false>());
  if (hull.number_of_faces() < 4) return out;  // all in one plane (or on a line)
  InputIndex index(points, pts);
  std::vector<std::size_t> at(hull.number_of_vertices());
  for (auto v : hull.vertices()) at[v.idx()] = index(hull.point(v));
  out.reserve(hull.number_of_faces());
  for (auto f : hull.faces()) {
    std::array<std::size_t, 3> t{};
    int n = 0;
    for (auto v : CGAL::vertices_around_face(hull.halfedge(f), hull))
      if (n < 3) t[n++] = at[v.idx()];
    if (n == 3) out.push_back(t);
  }
  return out;
}

}  // namespace hlr
