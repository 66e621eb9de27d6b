// Named views (see standard_views.hpp).
#include "io/views/standard_views.hpp"

#include <cctype>

namespace hlr {

std::optional<StandardView> standard_view(const std::string& name, bool z_up) {
  std::string n;
  for (char c : name) n += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  auto v = [](Rational x, Rational y, Rational z) { return Vector3(std::move(x), std::move(y), std::move(z)); };
  // y up: front looks along -z (from +z), top from +y with -z up on the paper (the front at the bottom).
  std::optional<StandardView> s;
  if (n == "front") s = StandardView{v(0, 0, 1), v(0, 1, 0)};
  else if (n == "back") s = StandardView{v(0, 0, -1), v(0, 1, 0)};
  else if (n == "top") s = StandardView{v(0, 1, 0), v(0, 0, -1)};
  else if (n == "bottom") s = StandardView{v(0, -1, 0), v(0, 0, 1)};
  else if (n == "right") s = StandardView{v(1, 0, 0), v(0, 1, 0)};
  else if (n == "left") s = StandardView{v(-1, 0, 0), v(0, 1, 0)};
  else if (n == "iso" || n == "isometric") s = StandardView{v(1, 1, 1), v(0, 1, 0)};
  else if (n == "dimetric") s = StandardView{v(1, 1, Rational(8, 3)), v(0, 1, 0)};
  if (!s || !z_up) return s;
  // z up: the same views turned by the rotation (x, y, z) -> (x, -z, y): y up becomes z up and
  // the front (+z) becomes -y.
  auto turn = [](const Vector3& a) { return Vector3(a.x(), -a.z(), a.y()); };
  return StandardView{turn(s->direction), turn(s->up)};
}

std::string standard_view_names() { return "front, back, top, bottom, left, right, iso, dimetric"; }

}  // namespace hlr
