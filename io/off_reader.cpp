// OFF reader with exact coordinates (Geomview OFF: header, counts, vertices, faces; extra
// per-vertex and per-face values such as colours are skipped).
#include <algorithm>

#include "io/mesh_reader.hpp"
#include "io/text_reader.hpp"

namespace hlr {

MeshData read_off(std::string_view bytes, const std::string& file) {
  TokenStream ts(bytes, file);
  std::string_view header;
  if (!ts.next(header)) ts.fail("empty file: expected an OFF header");
  std::string h(header);
  bool ok = h.size() >= 3 && h.compare(h.size() - 3, 3, "OFF") == 0 &&
            h.find_first_not_of("STCN") == h.size() - 3;
  if (!ok) ts.fail("expected an OFF header (OFF, COFF, NOFF, STOFF...), found '" + h.substr(0, 40) + "'");
  long nv = ts.integer("vertex count", 0, 1L << 40);
  long nf = ts.integer("face count", 0, 1L << 40);
  ts.integer("edge count", 0, 1L << 62);
  ts.skip_rest_of_line();
  // Each vertex needs at least "x y z" (5 bytes), each face at least "3 a b c" (7 bytes).
  if (nv * 5 + nf * 7 > static_cast<long>(ts.remaining_bytes()) + 1)
    ts.fail("declared " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
            " faces, more than the file can hold");
  MeshData m;
  m.vertices.reserve(nv);
  for (long i = 0; i < nv; ++i) {
    Rational x = ts.number("vertex x"), y = ts.number("vertex y"), z = ts.number("vertex z");
    m.vertices.emplace_back(std::move(x), std::move(y), std::move(z));
    ts.skip_rest_of_line();
  }
  m.faces.reserve(nf);
  for (long f = 0; f < nf; ++f) {
    long n = ts.integer("face vertex count", 0, kMaxFaceVertices);
    int line = ts.line();
    if (n < 3) ts.fail("face " + std::to_string(f) + " has " + std::to_string(n) + " vertices; a face needs at least 3");
    Face face(n);
    for (long k = 0; k < n; ++k) {
      face[k] = static_cast<int>(ts.integer("vertex index", 0, std::max(0L, nv - 1)));
    }
    m.faces.push_back(std::move(face));
    m.face_lines.push_back(line);
    ts.skip_rest_of_line();
  }
  return m;
}

}  // namespace hlr
