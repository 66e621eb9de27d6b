// Scene-graph bodies made exact (see mesh_assembly.hpp; docs/design.md, "Models").
#include "io/models/mesh_assembly.hpp"

#include <cstdint>
#include <cstring>
#include <map>

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

// Per face and corner, the number of its normal (equal floats, one number).
std::vector<std::vector<std::int64_t>> normal_keys(const std::vector<std::array<int, 3>>& corner, const std::vector<std::array<float, 3>>& normals) {
  std::map<FloatKey, std::int64_t> number;
  std::vector<std::vector<std::int64_t>> keys;
  keys.reserve(corner.size());
  for (const std::array<int, 3>& c : corner) {
    std::vector<std::int64_t> k(3);
    for (int i = 0; i < 3; ++i) k[i] = number.emplace(key_of(normals[c[i]]), static_cast<std::int64_t>(number.size())).first->second;
    keys.push_back(std::move(k));
  }
  return keys;
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
  if (!body.normals.empty()) out.surfaces = surfaces_from_corner_keys(out.mesh.faces, normal_keys(corner, body.normals));
  return out;
}

void note_dropped(long dropped, std::vector<std::string>& notes) {
  if (dropped > 0) notes.push_back(std::to_string(dropped) + " triangle(s) with a repeated corner (no area) dropped");
}

}  // namespace hlr
