// PLY reader, ASCII and binary (little and big endian). Vertex x, y, z of any numeric type
// and the face list `vertex_indices` (or `vertex_index`); other properties and elements are
// skipped. ASCII numbers keep their exact text value; binary values their stored value.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "io/readers/mesh_reader.hpp"
#include "io/readers/text_reader.hpp"

namespace hlr {
namespace {

enum class Type { I8, U8, I16, U16, I32, U32, F32, F64 };

bool parse_type(std::string_view s, Type& t) {
  if (s == "char" || s == "int8") t = Type::I8;
  else if (s == "uchar" || s == "uint8") t = Type::U8;
  else if (s == "short" || s == "int16") t = Type::I16;
  else if (s == "ushort" || s == "uint16") t = Type::U16;
  else if (s == "int" || s == "int32") t = Type::I32;
  else if (s == "uint" || s == "uint32") t = Type::U32;
  else if (s == "float" || s == "float32") t = Type::F32;
  else if (s == "double" || s == "float64") t = Type::F64;
  else return false;
  return true;
}

int size_of(Type t) {
  switch (t) {
    case Type::I8: case Type::U8: return 1;
    case Type::I16: case Type::U16: return 2;
    case Type::I32: case Type::U32: case Type::F32: return 4;
    case Type::F64: return 8;
  }
  return 0;
}

struct Property {
  std::string name;
  bool is_list = false;
  Type count_type = Type::U8, type = Type::F32;
};

struct Element {
  std::string name;
  long count = 0;
  std::vector<Property> props;
  int line = 0;
};

enum class Format { Ascii, Little, Big };

// Binary cursor over the body.
struct Cursor {
  std::string_view b;
  std::size_t pos;
  Format fmt;
  const std::string& file;
  template <class T>
  T raw() {
    if (pos + sizeof(T) > b.size()) throw InputError(file, 0, "unexpected end of binary PLY data");
    unsigned char buf[sizeof(T)];
    std::memcpy(buf, b.data() + pos, sizeof(T));
    pos += sizeof(T);
    bool swap = (fmt == Format::Big) != (std::endian::native == std::endian::big);
    if (swap) std::reverse(buf, buf + sizeof(T));
    T v;
    std::memcpy(&v, buf, sizeof(T));
    return v;
  }
  // Exact value of one binary value of type t.
  Rational value(Type t) {
    switch (t) {
      case Type::I8: return Rational(static_cast<long>(raw<std::int8_t>()));
      case Type::U8: return Rational(static_cast<unsigned long>(raw<std::uint8_t>()));
      case Type::I16: return Rational(static_cast<long>(raw<std::int16_t>()));
      case Type::U16: return Rational(static_cast<unsigned long>(raw<std::uint16_t>()));
      case Type::I32: return Rational(static_cast<long>(raw<std::int32_t>()));
      case Type::U32: return Rational(static_cast<unsigned long>(raw<std::uint32_t>()));
      case Type::F32: {
        float f = raw<float>();
        if (!std::isfinite(f)) throw InputError(file, 0, "binary PLY holds a value that is not finite");
        return Rational(static_cast<double>(f));
      }
      case Type::F64: {
        double d = raw<double>();
        if (!std::isfinite(d)) throw InputError(file, 0, "binary PLY holds a value that is not finite");
        return Rational(d);
      }
    }
    return Rational(0);
  }
  long integer(Type t) {
    Rational q = value(t);
    if (q.get_den() != 1 || !q.get_num().fits_slong_p()) throw InputError(file, 0, "binary PLY list length or index is not an integer");
    return q.get_num().get_si();
  }
};

// Reads one element instance; calls on_value(prop_index, value) for scalars and
// on_list(prop_index, values) for lists.
template <class Scalar, class List>
void read_instance_ascii(TokenStream& ts, const Element& e, Scalar on_value, List on_list) {
  for (std::size_t p = 0; p < e.props.size(); ++p) {
    const Property& pr = e.props[p];
    if (!pr.is_list) {
      on_value(p, ts.number(pr.name.c_str()));
    } else {
      long n = ts.integer("list length", 0, kMaxFaceVertices);
      std::vector<long> vals(n);
      for (long k = 0; k < n; ++k) vals[k] = ts.integer("list value", -(1L << 40), 1L << 40);
      on_list(p, vals);
    }
  }
}

template <class Scalar, class List>
void read_instance_binary(Cursor& c, const Element& e, Scalar on_value, List on_list) {
  for (std::size_t p = 0; p < e.props.size(); ++p) {
    const Property& pr = e.props[p];
    if (!pr.is_list) {
      on_value(p, c.value(pr.type));
    } else {
      long n = c.integer(pr.count_type);
      if (n < 0 || n > kMaxFaceVertices) throw InputError(c.file, 0, "binary PLY list length " + std::to_string(n) + " is out of range");
      if (c.pos + static_cast<std::size_t>(n) * size_of(pr.type) > c.b.size()) throw InputError(c.file, 0, "unexpected end of binary PLY data");
      std::vector<long> vals(n);
      for (long k = 0; k < n; ++k) vals[k] = c.integer(pr.type);
      on_list(p, vals);
    }
  }
}

}  // namespace

MeshData read_ply(std::string_view bytes, const std::string& file) {
  // ---- header ----
  std::size_t end = bytes.find("end_header");
  if (bytes.substr(0, 3) != "ply") throw InputError(file, 1, "not a PLY file: missing 'ply' magic");
  if (end == std::string_view::npos) throw InputError(file, 0, "PLY header has no 'end_header'");
  std::size_t body = bytes.find('\n', end);
  body = body == std::string_view::npos ? bytes.size() : body + 1;
  TokenStream hs(bytes.substr(0, end), file);
  std::string_view t;
  hs.next(t);  // ply
  Format fmt = Format::Ascii;
  bool have_format = false;
  std::vector<Element> elements;
  while (hs.next(t)) {
    if (t == "format") {
      std::string_view f = hs.expect("format name");
      if (f == "ascii") fmt = Format::Ascii;
      else if (f == "binary_little_endian") fmt = Format::Little;
      else if (f == "binary_big_endian") fmt = Format::Big;
      else hs.fail("unknown PLY format '" + std::string(f.substr(0, 40)) + "'");
      hs.skip_rest_of_line();
      have_format = true;
    } else if (t == "comment" || t == "obj_info") {
      hs.skip_rest_of_line();
    } else if (t == "element") {
      Element e;
      e.name = std::string(hs.expect("element name"));
      e.line = hs.line();
      e.count = hs.integer("element count", 0, static_cast<long>(bytes.size()));
      elements.push_back(e);
    } else if (t == "property") {
      if (elements.empty()) hs.fail("property before any element");
      Property p;
      std::string_view ty = hs.expect("property type");
      if (ty == "list") {
        p.is_list = true;
        if (!parse_type(hs.expect("list count type"), p.count_type)) hs.fail("unknown PLY list count type");
        if (!parse_type(hs.expect("list value type"), p.type)) hs.fail("unknown PLY list value type");
      } else if (!parse_type(ty, p.type)) {
        hs.fail("unknown PLY property type '" + std::string(ty.substr(0, 40)) + "'");
      }
      p.name = std::string(hs.expect("property name"));
      elements.back().props.push_back(p);
    } else {
      hs.fail("unknown PLY header keyword '" + std::string(t.substr(0, 40)) + "'");
    }
  }
  if (!have_format) throw InputError(file, 0, "PLY header has no 'format' line");

  // ---- body ----
  MeshData m;
  TokenStream ts(bytes, file, body);
  Cursor cur{bytes, body, fmt, file};
  const std::size_t body_bytes = bytes.size() - body;
  for (const Element& e : elements) {
    if (static_cast<std::size_t>(e.count) > body_bytes + 1)
      throw InputError(file, e.line, "element '" + e.name + "' declares " + std::to_string(e.count) +
                                         " entries, more than the file can hold");
    int ix = -1, iy = -1, iz = -1, ilist = -1;
    for (std::size_t p = 0; p < e.props.size(); ++p) {
      const auto& n = e.props[p].name;
      if (!e.props[p].is_list && n == "x") ix = static_cast<int>(p);
      if (!e.props[p].is_list && n == "y") iy = static_cast<int>(p);
      if (!e.props[p].is_list && n == "z") iz = static_cast<int>(p);
      if (e.props[p].is_list && (n == "vertex_indices" || n == "vertex_index")) ilist = static_cast<int>(p);
    }
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    if (is_vertex && (ix < 0 || iy < 0 || iz < 0)) throw InputError(file, e.line, "vertex element lacks x, y or z");
    if (is_face && ilist < 0) throw InputError(file, e.line, "face element lacks a vertex_indices list");
    for (long i = 0; i < e.count; ++i) {
      Rational xyz[3];
      auto on_value = [&](std::size_t p, Rational v) {
        if (!is_vertex) return;
        if (static_cast<int>(p) == ix) xyz[0] = std::move(v);
        if (static_cast<int>(p) == iy) xyz[1] = std::move(v);
        if (static_cast<int>(p) == iz) xyz[2] = std::move(v);
      };
      auto on_list = [&](std::size_t p, const std::vector<long>& vals) {
        if (!is_face || static_cast<int>(p) != ilist) return;
        int line = fmt == Format::Ascii ? ts.line() : 0;
        if (vals.size() < 3)
          throw InputError(file, line, "face " + std::to_string(m.faces.size()) + " has " +
                                           std::to_string(vals.size()) + " vertices; a face needs at least 3");
        Face f;
        for (long v : vals) {
          if (v < 0 || v > (1L << 31) - 1)
            throw InputError(file, line, "face " + std::to_string(m.faces.size()) + " uses vertex " + std::to_string(v) + ", out of range");
          f.push_back(static_cast<int>(v));
        }
        m.faces.push_back(std::move(f));
        m.face_lines.push_back(line);
      };
      if (fmt == Format::Ascii)
        read_instance_ascii(ts, e, on_value, on_list);
      else
        read_instance_binary(cur, e, on_value, on_list);
      if (is_vertex) m.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
  }
  return m;
}

}  // namespace hlr
