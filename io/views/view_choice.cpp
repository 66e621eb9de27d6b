// The camera choice (see view_choice.hpp).
#include "io/views/view_choice.hpp"

#include <stdexcept>

#include "io/views/standard_views.hpp"

namespace hlr {

Point3 bounding_box_centre(const std::vector<const Polyhedron*>& bodies) {
  Rational lo[3], hi[3];
  bool first = true;
  for (const Polyhedron* b : bodies)
    for (const Point3& p : b->vertices())
      for (int k = 0; k < 3; ++k) {
        if (first || p[k] < lo[k]) lo[k] = p[k];
        if (first || p[k] > hi[k]) hi[k] = p[k];
        if (k == 2) first = false;
      }
  return Point3((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
}

Camera choose_camera(const ViewRequest& req, const View* sv, const std::vector<const Polyhedron*>& bodies) {
  if (req.direction && req.eye) throw std::invalid_argument("give --view (orthographic) or --eye (perspective), not both");
  std::optional<Vector3> up = req.up;
  if (req.eye || (!req.direction && sv && sv->type == View::Type::Perspective)) {
    Point3 eye = req.eye ? *req.eye : sv->eye;
    std::optional<Point3> target = req.target;
    if (!target && sv && sv->type == View::Type::Perspective && sv->target) target = sv->target;
    const bool default_target = !target;
    if (!target) target = bounding_box_centre(bodies);
    if (!up && sv && sv->up_given) up = sv->up;
    if (default_target && eye == *target)
      throw std::invalid_argument("the eye " + to_string(eye) +
                                  " is the default target, the centre of the scene's bounding box: give a target (--target)");
    return make_perspective(eye, *target, up);
  }
  if (req.target) throw std::invalid_argument("--target needs --eye (a perspective view)");
  if (!up && sv && sv->up_given) up = sv->up;
  Vector3 dir = req.direction ? *req.direction : sv ? sv->direction : Vector3(0, 0, 1);
  return make_orthographic(dir, up);
}

Vector3 parse_vector3(const std::string& option, const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    std::size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (parts.size() != 3) throw std::invalid_argument(option + " needs three numbers X,Y,Z, got '" + text + "'");
  Rational c[3];
  for (int i = 0; i < 3; ++i) {
    try {
      c[i] = parse_rational(parts[i]);
    } catch (const NumberError& e) {
      throw std::invalid_argument(option + ": " + e.what());
    }
  }
  return Vector3(c[0], c[1], c[2]);
}

ViewRequest parse_view_request(const std::string& view, const std::string& eye, const std::string& target, const std::string& up,
                               const std::string& up_axis) {
  ViewRequest v;
  auto point = [](const Vector3& x) { return Point3(x.x(), x.y(), x.z()); };
  if (!view.empty()) {
    if (auto named = standard_view(view, up_axis == "z")) {
      v.direction = named->direction;
      if (up.empty()) v.up = named->up;
    } else {
      v.direction = parse_vector3("--view", view);
    }
  }
  if (!eye.empty()) v.eye = point(parse_vector3("--eye", eye));
  if (!target.empty()) v.target = point(parse_vector3("--target", target));
  if (!up.empty()) v.up = parse_vector3("--up", up);
  return v;
}

}  // namespace hlr
