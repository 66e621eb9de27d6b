// Scene-graph bodies made exact (see mesh_assembly.hpp; docs/design.md, "Models").
#include "io/models/mesh_assembly.hpp"

#include <cstdint>
#include <cstring>
#include <map>
#include <numeric>
#include <unordered_map>

namespace hlr {

namespace {

std::uint32_t float_bits(float f) {
  if (f == 0.0f) f = 0.0f;  // -0 and +0 are the same point
  std::uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

using FloatKey = std::array<std::uint32_t, 3>;

FloatKey key_of(const std::array<float, 3>& p) { return {float_bits(p[0]), float_bits(p[1]), float_bits(p[2])}; }

// Per position, its welded vertex (positions with exactly equal floats share one).
std::vector<int> weld(const std::vector<std::array<float, 3>>& positions, std::vector<int>& first) {
  std::map<FloatKey, int> index;
  std::vector<int> id(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    auto [it, inserted] = index.emplace(key_of(positions[i]), static_cast<int>(first.size()));
    if (inserted) first.push_back(static_cast<int>(i));
    id[i] = it->second;
  }
  return id;
}

Rational determinant3(const Matrix4& m) {
  return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
         m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
}

int find(std::vector<int>& parent, int a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

// Faces joined across every edge where both faces' corners carry the same normals: one smooth
// surface per group. `corner[f][k]` is the file's position index of face f's corner k.
FaceSurfaces smooth_surfaces(const std::vector<Face>& faces, const std::vector<std::array<int, 3>>& corner,
                             const std::vector<std::array<float, 3>>& normals) {
  std::vector<int> parent(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  // Per undirected edge of welded vertices: the first face on it and its two corners' normals.
  struct Seen {
    int face;
    FloatKey na, nb;  // normals at the edge's lower and higher vertex
  };
  std::unordered_map<std::uint64_t, Seen> edges;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = faces[f][k], b = faces[f][(k + 1) % 3];
      const int ca = corner[f][k], cb = corner[f][(k + 1) % 3];
      const bool up = a < b;
      const std::uint64_t e = (static_cast<std::uint64_t>(up ? a : b) << 32) | static_cast<std::uint32_t>(up ? b : a);
      const FloatKey na = key_of(normals[up ? ca : cb]), nb = key_of(normals[up ? cb : ca]);
      auto [it, inserted] = edges.emplace(e, Seen{static_cast<int>(f), na, nb});
      if (!inserted && it->second.na == na && it->second.nb == nb) parent[find(parent, static_cast<int>(f))] = find(parent, it->second.face);
    }
  }
  FaceSurfaces s;
  s.sharp_between = false;
  s.surface.resize(faces.size());
  std::unordered_map<int, int> number;
  for (std::size_t f = 0; f < faces.size(); ++f)
    s.surface[f] = number.emplace(find(parent, static_cast<int>(f)), static_cast<int>(number.size())).first->second;
  return s;
}

}  // namespace

Matrix4 quaternion_rotation(double x, double y, double z, double w) {
  const Rational qx(x), qy(y), qz(z), qw(w);
  // The column-vector matrix of the quaternion, stored transposed (row-vector convention).
  const Rational c[3][3] = {{1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)},
                            {2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)},
                            {2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)}};
  Matrix4 m = identity_transform();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = c[j][i];
  return m;
}

ModelBody assemble_body(const FloatBody& body, long& dropped) {
  ModelBody out;
  out.name = body.name;
  out.colour = body.colour;
  std::vector<int> first;
  const std::vector<int> id = weld(body.positions, first);
  out.mesh.vertices.reserve(first.size());
  for (int i : first) {
    const std::array<float, 3>& p = body.positions[i];
    out.mesh.vertices.push_back(apply(body.transform, Point3(Rational(p[0]), Rational(p[1]), Rational(p[2]))));
  }
  const bool mirrored = determinant3(body.transform) < 0;
  std::vector<std::array<int, 3>> corner;
  for (const std::array<int, 3>& t : body.triangles) {
    std::array<int, 3> c = t;
    if (mirrored) std::swap(c[1], c[2]);
    Face f{id[c[0]], id[c[1]], id[c[2]]};
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) {
      ++dropped;
      continue;
    }
    out.mesh.faces.push_back(std::move(f));
    corner.push_back(c);
  }
  out.mesh.face_lines.assign(out.mesh.faces.size(), 0);
  if (!body.normals.empty()) out.surfaces = smooth_surfaces(out.mesh.faces, corner, body.normals);
  return out;
}

void note_dropped(long dropped, std::vector<std::string>& notes) {
  if (dropped > 0) notes.push_back(std::to_string(dropped) + " triangle(s) with a repeated corner (no area) dropped");
}

}  // namespace hlr
