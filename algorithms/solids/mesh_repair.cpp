// Mesh repairs (see mesh_repair.hpp).
#include "algorithms/solids/mesh_repair.hpp"

#include <algorithm>
#include <atomic>

#include "algorithms/solids/triangulate.hpp"
#include "algorithms/support/parallel.hpp"
#include "kernel/int128.hpp"
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

// Whether a triangle of a compact store has collinear (or repeated) corners: its edge vectors'
// cross product is zero, exactly in 128-bit integers (numerators within 2^53: differences
// within 2^54, products within 2^108).
bool collinear_triangle(const PointStore& s, const Face& f) {
  if (f.size() != 3) return false;
  const auto &p = s.numerators()[f[0]], &q = s.numerators()[f[1]], &r = s.numerators()[f[2]];
  Int128 u[3], v[3];
  for (int k = 0; k < 3; ++k) u[k] = static_cast<Int128>(q[k]) - p[k], v[k] = static_cast<Int128>(r[k]) - p[k];
  return u[1] * v[2] == u[2] * v[1] && u[2] * v[0] == u[0] * v[2] && u[0] * v[1] == u[1] * v[0];
}

// Whether a face of four or more vertices has a vertex off the plane of its Newell normal; sets
// the normal.
bool nonplanar(const std::vector<Point3>& vs, const Face& f, Vector3& normal) {
  if (f.size() < 4) return false;
  std::vector<const Point3*> p(f.size());
  for (std::size_t k = 0; k < f.size(); ++k) p[k] = &vs[f[k]];
  normal = newell_normal(p.data(), p.size());
  for (std::size_t k = 1; k < f.size(); ++k)
    if (dot(normal, *p[k] - *p[0]) != 0) return true;
  return false;
}

// The triangles of a non-planar face (vertex ids); empty when it cannot be split.
std::vector<Face> split_face(const std::vector<Point3>& vs, const Face& f, const Vector3& normal) {
  if (f.size() == 4) {
    const Vector3 d02 = vs[f[2]] - vs[f[0]], d13 = vs[f[3]] - vs[f[1]];
    if (dot(d13, d13) < dot(d02, d02)) return {Face{f[0], f[1], f[3]}, Face{f[1], f[2], f[3]}};
    return {Face{f[0], f[1], f[2]}, Face{f[0], f[2], f[3]}};
  }
  std::vector<Face> out;
  if (normal.is_zero()) return out;
  const std::vector<int> poly(f.begin(), f.end());
  for (const FaceTriangle& t : triangulate_face(vs, poly, normal)) out.push_back(Face{poly[t.v[0]], poly[t.v[1]], poly[t.v[2]]});
  return out;
}

}  // namespace

std::optional<MeshRepair> split_nonplanar_faces(const Polyhedron& body) {
  // Triangles are planar: a mesh of triangles alone is not read (a compact store's exact
  // points are then not made).
  const auto polygon = [](const Face& f) { return f.size() > 3; };
  if (std::none_of(body.faces().begin(), body.faces().end(), polygon)) return std::nullopt;
  const std::vector<Point3>& vs = body.vertices();
  std::atomic<bool> any{false};
  ParallelLoop().run(body.faces().size(), 8192, [&](unsigned, std::size_t b, std::size_t e) {
    Vector3 n;
    for (std::size_t f = b; f < e && !any.load(std::memory_order_relaxed); ++f)
      if (nonplanar(vs, body.faces()[f], n)) any = true;
  });
  if (!any) return std::nullopt;
  std::vector<Face> faces;
  std::vector<int> input, split;
  long quads = 0, polygons = 0;
  for (std::size_t f = 0; f < body.faces().size(); ++f) {
    const Face& face = body.faces()[f];
    Vector3 n;
    std::vector<Face> parts;
    if (nonplanar(vs, face, n)) parts = split_face(vs, face, n);
    if (parts.empty()) {
      faces.push_back(face);
      input.push_back(static_cast<int>(f));
      continue;
    }
    (face.size() == 4 ? quads : polygons)++;
    split.push_back(static_cast<int>(f));
    for (Face& t : parts) {
      faces.push_back(std::move(t));
      input.push_back(static_cast<int>(f));
    }
  }
  if (split.empty()) return std::nullopt;
  std::string what;
  if (quads > 0) what = std::to_string(quads) + " non-planar quad" + (quads > 1 ? "s" : "") + " split along the shorter diagonal";
  if (polygons > 0)
    what += (what.empty() ? "" : ", ") + std::to_string(polygons) + " non-planar polygon" + (polygons > 1 ? "s" : "") + " split into triangles";
  MeshRepair out{Polyhedron(vs, std::move(faces)), {}, std::move(input), {}, std::move(split)};
  out.notes.push_back("had " + what + " (first: face " + std::to_string(out.joined[0]) +
                      "); the drawing is exact for those triangles, the diagonals are not creases");
  return out;
}

std::optional<MeshRepair> remove_zero_area_triangles(const Polyhedron& body) {
  // Most meshes have none: look on all cores first, copy the faces only to repair. A compact
  // store's triangles are tested in its integers (collinear is necessary for a middle vertex),
  // its exact points made only when one is collinear.
  const PointStore& store = body.vertex_store();
  std::atomic<bool> any{false};
  ParallelLoop().run(body.faces().size(), 8192, [&](unsigned, std::size_t b, std::size_t e) {
    int a, m, c;
    for (std::size_t f = b; f < e && !any.load(std::memory_order_relaxed); ++f)
      if (store.compact() ? collinear_triangle(store, body.faces()[f]) : middle_of(store.points(), body.faces()[f], a, m, c)) any = true;
  });
  if (!any) return std::nullopt;
  const std::vector<Point3>& vs = body.vertices();
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
