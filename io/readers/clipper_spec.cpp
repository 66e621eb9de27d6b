// Clipper specifications (see clipper_spec.hpp).
#include "io/readers/clipper_spec.hpp"

#include <cctype>
#include <stdexcept>

#include "io/readers/mesh_reader.hpp"

namespace hlr {

std::vector<Rational> parse_numbers(const std::string& option, const std::string& text, std::size_t count) {
  std::vector<Rational> out;
  std::string token;
  auto flush = [&] {
    if (token.empty()) return;
    try {
      out.push_back(parse_rational(token));
    } catch (const NumberError& e) {
      throw std::invalid_argument(option + ": " + e.what());
    }
    token.clear();
  };
  for (char c : text) {
    if (c == ',' || c == ' ' || c == '\t')
      flush();
    else
      token += c;
  }
  flush();
  if (out.size() != count)
    throw std::invalid_argument(option + " needs " + std::to_string(count) + " numbers, got " + std::to_string(out.size()) +
                                " in '" + text + "'");
  return out;
}

ClipperSpec parse_clipper(const std::string& option, const std::string& text) {
  if (text.rfind("box:", 0) == 0) {
    auto v = parse_numbers(option + " box", text.substr(4), 6);
    ConvexClipper c = box_clipper(v[0], v[1], v[2], v[3], v[4], v[5]);
    return {std::move(c), Window(BoxWindow{v[0], v[1], v[2], v[3], v[4], v[5]}), text};
  }
  if (text.rfind("frustum:", 0) == 0) {
    auto v = parse_numbers(option + " frustum", text.substr(8), 7);
    ConvexClipper c = frustum_clipper(v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
    return {std::move(c), Window(FrustumWindow{v[0], v[1], v[2], v[3], v[4], v[5], v[6]}), text};
  }
  Polyhedron body = load_mesh(text);
  try {
    return {make_clipper(std::move(body), text), std::nullopt, text};
  } catch (const std::invalid_argument& e) {
    throw InputError(text, 0, e.what());
  }
}

std::vector<Plane> parse_section(const std::string& option, const std::string& text) {
  std::string t;
  for (char c : text)
    if (c != ' ' && c != '\t') t += c;
  if (t.rfind("box:", 0) == 0) {
    auto v = parse_numbers(option + " box", t.substr(4), 6);
    for (int a = 0; a < 3; ++a)
      if (!(v[2 * a] < v[2 * a + 1])) throw std::invalid_argument(option + " box: each minimum must be below its maximum");
    std::vector<Plane> out;
    for (int a = 0; a < 3; ++a) {
      Rational n[3] = {0, 0, 0};
      n[a] = -1;
      out.emplace_back(n[0], n[1], n[2], v[2 * a]);  // -x + xmin <= 0
      n[a] = 1;
      out.emplace_back(n[0], n[1], n[2], -v[2 * a + 1]);  // x - xmax <= 0
    }
    return out;
  }
  if (t.size() >= 3 && (t[0] == 'x' || t[0] == 'y' || t[0] == 'z' || t[0] == 'X' || t[0] == 'Y' || t[0] == 'Z') &&
      (t[1] == '<' || t[1] == '>' || t[1] == '=')) {
    const int a = std::tolower(static_cast<unsigned char>(t[0])) - 'x';
    const Rational h = parse_numbers(option, t.substr(2), 1)[0];
    Rational n[3] = {0, 0, 0};
    n[a] = t[1] == '>' ? -1 : 1;
    return {Plane(n[0], n[1], n[2], t[1] == '>' ? Rational(h) : Rational(-h))};
  }
  if (t.find(',') == std::string::npos)
    throw std::invalid_argument(option + ": '" + text + "' is not a plane (z<1.2, x>0, A,B,C,D or box:XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX)");
  auto v = parse_numbers(option, t, 4);
  if (v[0] == 0 && v[1] == 0 && v[2] == 0) throw std::invalid_argument(option + ": the plane's normal A,B,C is zero");
  return {Plane(v[0], v[1], v[2], v[3])};
}

}  // namespace hlr
