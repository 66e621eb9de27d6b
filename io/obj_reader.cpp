// Wavefront OBJ reader with exact coordinates: `v` and `f` statements (1-based and negative
// relative indices, `a/b/c` forms); texture, normal, group and material statements are
// skipped; polylines (`l`) and points (`p`) are not faces and are skipped too.
#include "io/mesh_reader.hpp"
#include "io/text_reader.hpp"

namespace hlr {
namespace {

// Splits the text into lines; returns line content without the comment.
std::string_view strip_comment(std::string_view line) {
  auto hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

}  // namespace

MeshData read_obj(std::string_view bytes, const std::string& file) {
  MeshData m;
  std::size_t pos = 0;
  int line_no = 0;
  while (pos < bytes.size()) {
    std::size_t end = bytes.find('\n', pos);
    if (end == std::string_view::npos) end = bytes.size();
    std::string_view line = strip_comment(bytes.substr(pos, end - pos));
    pos = end + 1;
    ++line_no;
    // Line continuation with a trailing backslash is rare; not supported (reported below).
    TokenStream ts(line, file);
    std::string_view kw;
    if (!ts.next(kw)) continue;
    auto fail = [&](const std::string& msg) { throw InputError(file, line_no, msg); };
    if (kw == "v") {
      Rational c[4];
      int n = 0;
      std::string_view t;
      while (n < 7 && ts.next(t)) {
        Rational q;
        if (!try_parse_rational(t, q)) fail("bad number '" + std::string(t.substr(0, 40)) + "' in vertex");
        if (n < 4) c[n] = q;
        ++n;
      }
      if (n < 3) fail("a vertex needs 3 coordinates");
      if (n == 4) {  // x y z w
        if (c[3] == 0) fail("vertex weight w is 0");
        for (int i = 0; i < 3; ++i) c[i] /= c[3];
      }
      m.vertices.emplace_back(c[0], c[1], c[2]);
    } else if (kw == "f" || kw == "fo") {
      Face face;
      std::string_view t;
      const long nv = static_cast<long>(m.vertices.size());
      while (ts.next(t)) {
        std::string_view idx = t.substr(0, t.find('/'));
        long v = 0;
        bool neg = !idx.empty() && idx[0] == '-';
        std::size_t i = neg ? 1 : 0;
        if (i == idx.size() || idx.size() > 12) fail("bad vertex index '" + std::string(t.substr(0, 40)) + "'");
        for (; i < idx.size(); ++i) {
          if (idx[i] < '0' || idx[i] > '9') fail("bad vertex index '" + std::string(t.substr(0, 40)) + "'");
          v = v * 10 + (idx[i] - '0');
        }
        long index = neg ? nv - v : v - 1;
        if (v == 0 || index < 0 || index >= nv)
          fail("vertex index " + std::string(idx) + " is out of range (" + std::to_string(nv) +
               " vertices defined so far)");
        if (static_cast<long>(face.size()) >= kMaxFaceVertices) fail("face has too many vertices");
        face.push_back(static_cast<int>(index));
      }
      if (face.size() < 3)
        fail("face " + std::to_string(m.faces.size()) + " has " + std::to_string(face.size()) +
             " vertices; a face needs at least 3");
      m.faces.push_back(std::move(face));
      m.face_lines.push_back(line_no);
    } else if (kw == "vt" || kw == "vn" || kw == "vp" || kw == "g" || kw == "o" || kw == "s" ||
               kw == "usemtl" || kw == "mtllib" || kw == "l" || kw == "p" || kw == "mg" ||
               kw == "usemap" || kw == "maplib" || kw == "lod" || kw == "shadow_obj" ||
               kw == "trace_obj" || kw == "bevel" || kw == "c_interp" || kw == "d_interp") {
      continue;
    } else {
      fail("unknown OBJ statement '" + std::string(kw.substr(0, 40)) + "'");
    }
  }
  return m;
}

}  // namespace hlr
