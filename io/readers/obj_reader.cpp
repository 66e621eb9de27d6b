// Wavefront OBJ reader with exact coordinates: `v` and `f` statements (1-based and negative
// relative indices, `a/b/c` forms), `vt` texture coordinates with each face's `v/vt` corners
// (course notes 42: the texture's (u, w) space; shading data, kept as doubles); `vn` normals
// with each face's `v//vn` corners, and smoothing groups (`s`), mark smooth surfaces (docs/
// design.md, "Models"); group and material statements are skipped; polylines (`l`) and points
// (`p`) are not faces and are skipped too.
#include <functional>
#include <map>

#include "io/readers/mesh_reader.hpp"
#include "io/readers/text_reader.hpp"

namespace hlr {
namespace {

// A 1-based or negative relative index of an `f` corner's field; `what` names it in errors.
long corner_index(std::string_view ix, long defined, const std::string& what, const std::function<void(const std::string&)>& fail) {
  long k = 0;
  const bool neg = !ix.empty() && ix[0] == '-';
  std::size_t a = neg ? 1 : 0;
  if (a == ix.size() || ix.size() > 12) fail("bad " + what + " index '" + std::string(ix.substr(0, 40)) + "'");
  for (; a < ix.size(); ++a) {
    if (ix[a] < '0' || ix[a] > '9') fail("bad " + what + " index '" + std::string(ix.substr(0, 40)) + "'");
    k = k * 10 + (ix[a] - '0');
  }
  const long i = neg ? defined - k : k - 1;
  if (k == 0 || i < 0 || i >= defined) fail(what + " index " + std::string(ix) + " is out of range (" + std::to_string(defined) + " defined so far)");
  return i;
}

// The smooth surfaces of the faces: by their corners' normals where every face has them (an
// exporter splits normals at hard edges), else by smoothing groups (group 0 or off: each face on
// its own); empty when the file has neither.
FaceSurfaces obj_surfaces(const MeshData& m, const std::vector<std::vector<std::int64_t>>& normals, const std::vector<long>& groups) {
  const std::size_t n = m.faces.size();
  bool all_normals = n > 0, any_group = false;
  for (std::size_t f = 0; f < n; ++f) all_normals = all_normals && normals[f].size() == m.faces[f].size();
  for (long g : groups) any_group = any_group || g != 0;
  if (!all_normals && !any_group) return {};
  std::vector<std::vector<std::int64_t>> keys(n);
  for (std::size_t f = 0; f < n; ++f) {
    if (all_normals) {
      keys[f] = normals[f];
    } else {
      const std::int64_t own = -1 - static_cast<std::int64_t>(f);  // never equal to another face's
      keys[f].assign(m.faces[f].size(), groups[f] != 0 ? groups[f] : own);
    }
  }
  return surfaces_from_corner_keys(m.faces, keys);
}

// Splits the text into lines; returns line content without the comment.
std::string_view strip_comment(std::string_view line) {
  auto hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

}  // namespace

MeshData read_obj(std::string_view bytes, const std::string& file) {
  MeshData m;
  std::map<std::array<Rational, 3>, std::int64_t> normal_number;  // equal normals, one number
  std::vector<std::int64_t> vn;                                   // per `vn`: its number
  std::vector<std::vector<std::int64_t>> face_normals;            // per face: its corners' (or none)
  std::vector<long> face_groups;                                  // per face: its smoothing group
  long group = 0;
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
    } else if (kw == "vt") {
      std::array<double, 2> uv{0, 0};
      int n = 0;
      std::string_view t;
      while (n < 3 && ts.next(t)) {
        Rational q;
        if (!try_parse_rational(t, q)) fail("bad number '" + std::string(t.substr(0, 40)) + "' in texture coordinates");
        if (n < 2) uv[n] = to_double(q);
        ++n;
      }
      if (n < 1) fail("texture coordinates need at least u");
      m.texcoords.push_back(uv);
    } else if (kw == "vn") {
      std::array<Rational, 3> n;
      std::string_view t;
      for (Rational& c : n)
        if (!ts.next(t) || !try_parse_rational(t, c)) fail("a normal needs 3 numbers");
      vn.push_back(normal_number.emplace(n, static_cast<std::int64_t>(normal_number.size())).first->second);
    } else if (kw == "s") {
      std::string_view t;
      if (!ts.next(t)) fail("'s' needs a smoothing group number or 'off'");
      Rational q;
      if (t == "off") {
        group = 0;
      } else if (try_parse_rational(t, q) && q.get_den() == 1 && q >= 0 && q < Rational(1L << 40)) {
        group = q.get_num().get_si();
      } else {
        fail("bad smoothing group '" + std::string(t.substr(0, 40)) + "'");
      }
    } else if (kw == "f" || kw == "fo") {
      Face face;
      std::vector<int> tex;
      std::vector<std::int64_t> normals;
      std::string_view t;
      const long nv = static_cast<long>(m.vertices.size());
      const long nt = static_cast<long>(m.texcoords.size());
      while (ts.next(t)) {
        // The texture index: the part after the first '/', up to the next one (may be empty);
        // read only when the file gives texture coordinates (else the field means nothing).
        const std::size_t slash = t.find('/');
        if (slash != std::string_view::npos && nt > 0) {
          std::string_view ti = t.substr(slash + 1);
          ti = ti.substr(0, ti.find('/'));
          if (!ti.empty()) {
            long k = 0;
            const bool tneg = ti[0] == '-';
            std::size_t a = tneg ? 1 : 0;
            if (a == ti.size() || ti.size() > 12) fail("bad texture index '" + std::string(t.substr(0, 40)) + "'");
            for (; a < ti.size(); ++a) {
              if (ti[a] < '0' || ti[a] > '9') fail("bad texture index '" + std::string(t.substr(0, 40)) + "'");
              k = k * 10 + (ti[a] - '0');
            }
            const long ix = tneg ? nt - k : k - 1;
            if (k == 0 || ix < 0 || ix >= nt)
              fail("texture index " + std::string(ti) + " is out of range (" + std::to_string(nt) + " texture coordinates defined so far)");
            tex.push_back(static_cast<int>(ix));
          }
        }
        // The normal index: the part after the second '/' (read only when the file gives normals).
        const std::size_t slash2 = slash == std::string_view::npos ? slash : t.find('/', slash + 1);
        if (slash2 != std::string_view::npos && slash2 + 1 < t.size() && !vn.empty())
          normals.push_back(vn[corner_index(t.substr(slash2 + 1), static_cast<long>(vn.size()), "normal", fail)]);
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
      if (!tex.empty() && tex.size() != face.size()) fail("a face gives texture coordinates for some corners and not others");
      if (!tex.empty()) {
        m.face_texcoords.resize(m.faces.size());
        m.face_texcoords.push_back(std::move(tex));
      }
      if (!normals.empty() && normals.size() != face.size()) fail("a face gives normals for some corners and not others");
      m.faces.push_back(std::move(face));
      m.face_lines.push_back(line_no);
      face_normals.push_back(std::move(normals));
      face_groups.push_back(group);
    } else if (kw == "vp" || kw == "g" || kw == "o" || kw == "usemtl" || kw == "mtllib" || kw == "l" || kw == "p" || kw == "mg" || kw == "usemap" ||
               kw == "maplib" || kw == "lod" || kw == "shadow_obj" || kw == "trace_obj" || kw == "bevel" || kw == "c_interp" || kw == "d_interp") {
      continue;
    } else {
      fail("unknown OBJ statement '" + std::string(kw.substr(0, 40)) + "'");
    }
  }
  if (!m.face_texcoords.empty()) m.face_texcoords.resize(m.faces.size());
  m.surfaces = obj_surfaces(m, face_normals, face_groups);
  return m;
}

}  // namespace hlr
