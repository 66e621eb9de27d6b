// Clipper specifications (see clipper_spec.hpp).
#include "io/readers/clipper_spec.hpp"

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

}  // namespace hlr
