// Mesh repairs (see mesh_repair.hpp).
#include "algorithms/solids/mesh_repair.hpp"

#include <algorithm>
#include <atomic>

#include "algorithms/support/parallel.hpp"
#include "kernel/predicates.hpp"

namespace hlr {
namespace {

// The positions (a, m, c) in a collinear triangle with m strictly between a and c; false when
// the triangle has area or repeated points.
bool middle_of(const std::vector<Point3>& vs, const Face& f, int& a, int& m, int& c) {
  if (f.size() != 3) return false;
  const Point3 &p0 = vs[f[0]], &p1 = vs[f[1]], &p2 = vs[f[2]];
  // The filtered collinearity test first: it settles almost every face in doubles, where
  // three exact point comparisons cost more.
  if (!collinear(p0, p1, p2) || p0 == p1 || p1 == p2 || p0 == p2) return false;
  for (int k = 0; k < 3; ++k) {
    const Point3 &x = vs[f[(k + 2) % 3]], &y = vs[f[k]], &z = vs[f[(k + 1) % 3]];
    if (dot(x - y, z - y) < 0) {
      m = f[k], a = f[(k + 1) % 3], c = f[(k + 2) % 3];  // long edge a -> c inside this face
      return true;
    }
  }
  return false;
}

}  // namespace

std::optional<MeshRepair> remove_zero_area_triangles(const Polyhedron& body) {
  const std::vector<Point3>& vs = body.vertices();
  // Most meshes have none: look on all cores first, copy the faces only to repair.
  std::atomic<bool> any{false};
  ParallelLoop().run(body.faces().size(), 8192, [&](unsigned, std::size_t b, std::size_t e) {
    int a, m, c;
    for (std::size_t f = b; f < e && !any.load(std::memory_order_relaxed); ++f)
      if (middle_of(vs, body.faces()[f], a, m, c)) any = true;
  });
  if (!any) return std::nullopt;
  std::vector<Face> faces = body.faces();
  std::vector<int> input(faces.size());  // per face of `faces`: its input number
  for (std::size_t f = 0; f < input.size(); ++f) input[f] = static_cast<int>(f);
  std::vector<int> removed, joined;
  std::string which;
  for (std::size_t f = 0; f < faces.size();) {
    int a, m, c;
    if (!middle_of(vs, faces[f], a, m, c)) {
      ++f;
      continue;
    }
    // The face that runs c -> a (the other side of the long edge a -> c).
    int other = -1, pos = -1, count = 0;
    for (std::size_t g = 0; g < faces.size(); ++g) {
      if (g == f) continue;
      for (std::size_t k = 0; k < faces[g].size(); ++k)
        if (faces[g][k] == c && faces[g][(k + 1) % faces[g].size()] == a) other = static_cast<int>(g), pos = static_cast<int>(k), ++count;
    }
    if (count != 1) {
      ++f;
      continue;
    }
    faces[other].insert(faces[other].begin() + pos + 1, m);
    joined.push_back(input[other]);
    removed.push_back(input[f]);
    which += (which.empty() ? "" : ", ") + std::to_string(input[f]);
    faces.erase(faces.begin() + static_cast<long>(f));
    input.erase(input.begin() + static_cast<long>(f));
  }
  if (removed.empty()) return std::nullopt;
  std::sort(joined.begin(), joined.end());
  joined.erase(std::unique(joined.begin(), joined.end()), joined.end());
  // A joined face removed later is named removed only.
  joined.erase(std::remove_if(joined.begin(), joined.end(),
                              [&](int g) { return std::find(removed.begin(), removed.end(), g) != removed.end(); }),
               joined.end());
  std::sort(removed.begin(), removed.end());
  const std::size_t n = removed.size();
  MeshRepair out{Polyhedron(vs, std::move(faces)), {}, std::move(input), std::move(removed), std::move(joined)};
  out.notes.push_back("has " + std::to_string(n) + " zero-area triangle" + (n > 1 ? "s" : "") + " (face " + which +
                      ": three collinear vertices): removed, the middle vertex joined to the neighbouring face");
  return out;
}

}  // namespace hlr
