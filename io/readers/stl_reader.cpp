// STL reader, ASCII and binary. STL stores each triangle with its own three corners; corners
// with exactly equal coordinates are merged into one vertex (as OpenMesh's STL reader does).
// ASCII coordinates keep their exact text value; binary floats keep their stored value.
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <unordered_map>

#include "io/readers/mesh_reader.hpp"
#include "io/readers/text_reader.hpp"

namespace hlr {
namespace {

bool looks_binary(std::string_view b) {
  if (b.size() < 84) return false;
  std::uint32_t n;
  std::memcpy(&n, b.data() + 80, 4);
  return 84 + 50ull * n == b.size();
}

struct ExactLess {
  bool operator()(const Point3& a, const Point3& b) const { return a < b; }
};

MeshData read_stl_ascii(std::string_view bytes, const std::string& file) {
  TokenStream ts(bytes, file);
  MeshData m;
  std::map<Point3, int, ExactLess> index;
  auto kw = [&](const char* want) {
    std::string_view t = ts.expect(want);
    if (t != want) ts.fail(std::string("expected '") + want + "', found '" + std::string(t.substr(0, 40)) + "'");
  };
  std::string_view t;
  if (!ts.next(t) || t != "solid") ts.fail("not an STL file: expected 'solid' or a binary STL");
  ts.skip_rest_of_line();
  while (ts.next(t)) {
    if (t == "endsolid") {
      ts.skip_rest_of_line();
      if (!ts.next(t)) break;
      if (t != "solid") ts.fail("expected 'solid' after 'endsolid', found '" + std::string(t.substr(0, 40)) + "'");
      ts.skip_rest_of_line();
      continue;
    }
    if (t != "facet") ts.fail("expected 'facet' or 'endsolid', found '" + std::string(t.substr(0, 40)) + "'");
    int line = ts.line();
    kw("normal");
    for (int i = 0; i < 3; ++i) ts.number("normal component");
    kw("outer");
    kw("loop");
    Face face;
    while (true) {
      std::string_view v = ts.expect("'vertex' or 'endloop'");
      if (v == "endloop") break;
      if (v != "vertex") ts.fail("expected 'vertex' or 'endloop', found '" + std::string(v.substr(0, 40)) + "'");
      Rational x = ts.number("vertex x"), y = ts.number("vertex y"), z = ts.number("vertex z");
      Point3 p(std::move(x), std::move(y), std::move(z));
      auto [it, inserted] = index.emplace(p, static_cast<int>(m.vertices.size()));
      if (inserted) m.vertices.push_back(p);
      face.push_back(it->second);
      if (static_cast<long>(face.size()) > kMaxFaceVertices) ts.fail("facet has too many vertices");
    }
    kw("endfacet");
    if (face.size() < 3) ts.fail("facet " + std::to_string(m.faces.size()) + " has fewer than 3 vertices");
    m.faces.push_back(std::move(face));
    m.face_lines.push_back(line);
  }
  return m;
}

float read_float(const char* p) {
  std::uint32_t u;
  std::memcpy(&u, p, 4);
  if constexpr (std::endian::native == std::endian::big) u = __builtin_bswap32(u);
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

MeshData read_stl_binary(std::string_view bytes, const std::string& file) {
  std::uint32_t n;
  std::memcpy(&n, bytes.data() + 80, 4);
  MeshData m;
  // Corners welded by exact float value in an open-addressing table (vertex ids, numbered by
  // first appearance): no allocation per vertex.
  auto bits = [](float f) {
    if (f == 0.0f) f = 0.0f;  // -0 and +0 are the same point
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
  };
  std::size_t cap = 16;
  while (cap < 2 * 3 * static_cast<std::size_t>(n)) cap *= 2;
  std::vector<int> table(cap, -1);
  std::vector<std::array<float, 3>> stored;  // float value of each vertex
  stored.reserve(n / 2 + 8);
  m.vertices.reserve(n / 2 + 8);
  m.faces.reserve(n);
  m.face_lines.assign(n, 0);
  for (std::uint32_t t = 0; t < n; ++t) {
    const char* rec = bytes.data() + 84 + 50ull * t;
    Face face(3);
    for (int c = 0; c < 3; ++c) {
      float xyz[3];
      for (int k = 0; k < 3; ++k) {
        xyz[k] = read_float(rec + 12 + 12 * c + 4 * k);
        if (!std::isfinite(xyz[k]))
          throw InputError(file, 0, "triangle " + std::to_string(t) + " has a coordinate that is not finite");
      }
      std::uint64_t h = (static_cast<std::uint64_t>(bits(xyz[0])) * 0x9E3779B97F4A7C15ull) ^
                        (static_cast<std::uint64_t>(bits(xyz[1])) * 0xC2B2AE3D27D4EB4Full) ^ bits(xyz[2]);
      h ^= h >> 29;
      std::size_t at = static_cast<std::size_t>(h * 0xBF58476D1CE4E5B9ull) & (cap - 1);
      int found = -1;
      for (;; at = (at + 1) & (cap - 1)) {
        const int v = table[at];
        if (v < 0) break;
        // Float equality is exact value equality (the -0 case compares equal too).
        if (stored[v][0] == xyz[0] && stored[v][1] == xyz[1] && stored[v][2] == xyz[2]) {
          found = v;
          break;
        }
      }
      if (found < 0) {
        found = static_cast<int>(m.vertices.size());
        m.vertices.emplace_back(Rational(xyz[0]), Rational(xyz[1]), Rational(xyz[2]));
        stored.push_back({xyz[0], xyz[1], xyz[2]});
        table[at] = found;
      }
      face[c] = found;
    }
    m.faces.push_back(std::move(face));
  }
  return m;
}

}  // namespace

MeshData read_stl(std::string_view bytes, const std::string& file) {
  if (looks_binary(bytes)) return read_stl_binary(bytes, file);
  if (bytes.size() >= 5 && bytes.substr(0, 5) == "solid") return read_stl_ascii(bytes, file);
  if (bytes.size() >= 84) {
    std::uint32_t n;
    std::memcpy(&n, bytes.data() + 80, 4);
    throw InputError(file, 0, "binary STL declares " + std::to_string(n) + " triangles (" +
                                  std::to_string(84 + 50ull * n) + " bytes) but the file has " +
                                  std::to_string(bytes.size()) + " bytes");
  }
  throw InputError(file, 0, "not an STL file: too short for binary STL and no 'solid' header");
}

}  // namespace hlr
