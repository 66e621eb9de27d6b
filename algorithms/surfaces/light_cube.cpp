// The six views of a point light among the bodies (see light_cube.hpp; docs/design.md, "Lights
// among the bodies").
#include "algorithms/surfaces/light_cube.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "algorithms/sections/section_cut.hpp"

namespace hlr {
namespace {

using Box = std::array<Rational, 6>;  // min x, y, z, max x, y, z

Box box_of(const Polyhedron& p) {
  Box b;
  bool first = true;
  for (const Point3& v : p.vertices()) {
    for (int k = 0; k < 3; ++k) {
      if (first || v[k] < b[k]) b[k] = v[k];
      if (first || v[k] > b[k + 3]) b[k + 3] = v[k];
    }
    first = false;
  }
  return b;
}

// The plane s·(X_k - L_k)·a + t·(X_j - L_j) + d: coefficients along the axes, value <= 0 kept.
Plane plane(const Point3& l, const std::array<Rational, 3>& n, const Rational& d) {
  return Plane(n[0], n[1], n[2], d - n[0] * l.x() - n[1] * l.y() - n[2] * l.z());
}

// Does body p (its box b) meet the closed cube of half-size h around l?
bool meets_cube(const Polyhedron& p, const Box& b, const Point3& l, const Rational& h) {
  for (int k = 0; k < 3; ++k)
    if (b[k] > l[k] + h || b[k + 3] < l[k] - h) return false;
  std::vector<Plane> sides;
  for (int k = 0; k < 3; ++k)
    for (int s : {1, -1}) {
      std::array<Rational, 3> n{0, 0, 0};
      n[k] = s;
      sides.push_back(plane(l, n, -h));  // s·(X_k - L_k) - h <= 0
    }
  return cut_solid(p, sides).state != CutSolid::State::Removed;
}

// The largest power of two, from the scene's size down, whose cube around l no body meets; the
// views' near planes lie at half of it.
Rational clear_half_size(const std::vector<const Polyhedron*>& bodies, const std::vector<Box>& boxes, const Point3& l) {
  double size = 1;
  for (const Box& b : boxes)
    for (int k = 0; k < 3; ++k)
      size = std::max({size, std::fabs(to_double(b[k + 3] - b[k])), std::fabs(to_double(b[k] - l[k])), std::fabs(to_double(b[k + 3] - l[k]))});
  int e = 0;
  std::frexp(size, &e);
  Rational h = e >= 0 ? Rational(mpz_class(1) << e) : Rational(mpz_class(1), mpz_class(1) << -e);
  for (int step = 0; step < 160; ++step, h /= 2) {
    bool clear = true;
    for (std::size_t b = 0; b < bodies.size() && clear; ++b) clear = !meets_cube(*bodies[b], boxes[b], l, h);
    if (clear) return h;
  }
  throw std::invalid_argument("shadows: a point light lies on or inside a body (it lights nothing there)");
}

// The face's plane (Newell's, exact) passes through the light.
bool holds_light(const std::vector<Point3>& vertices, const Face& face, const Point3& light) {
  std::vector<const Point3*> corners;
  for (int v : face) corners.push_back(&vertices[v]);
  const Plane h = plane_of_polygon(corners.data(), corners.size());
  return !h.is_degenerate() && h.value(light) == 0;
}

}  // namespace

std::vector<LightCubeView> light_cube(const std::vector<const Polyhedron*>& bodies, const Point3& light) {
  std::vector<Box> boxes;
  for (const Polyhedron* p : bodies) boxes.push_back(box_of(*p));
  const Rational near = clear_half_size(bodies, boxes, light) / 2;
  std::vector<LightCubeView> views;
  for (int k = 0; k < 3; ++k)
    for (int s : {1, -1}) {
      LightCubeView v;
      std::array<Rational, 3> axis{0, 0, 0};
      axis[k] = s;
      v.camera = make_perspective(light, Point3(light.x() + axis[0], light.y() + axis[1], light.z() + axis[2]));
      // The bodies beyond the near plane s·(X_k - L_k) >= near (their caps there lie outside the
      // cube, so no segment from the light into the pyramid meets them); the pyramid
      // |X_j - L_j| <= s·(X_k - L_k) for the other two axes.
      const std::vector<Plane> beyond{plane(light, {-axis[0], -axis[1], -axis[2]}, near)};
      for (int j = 0; j < 3; ++j)
        for (int t : {1, -1}) {
          if (j == k) continue;
          std::array<Rational, 3> n{-axis[0], -axis[1], -axis[2]};
          n[j] = t;
          v.pyramid.push_back(plane(light, n, 0));
        }
      for (std::size_t b = 0; b < bodies.size(); ++b) {
        CutSolid c = cut_solid(*bodies[b], beyond);
        if (c.state == CutSolid::State::Removed) continue;
        const int nf = static_cast<int>(bodies[b]->num_faces());
        if (c.state == CutSolid::State::Whole) {
          c.vertices = bodies[b]->vertices();
          c.faces = bodies[b]->faces();
          c.part.clear();
          for (int f = 0; f < nf; ++f) c.part.push_back(f);
        }
        // A face whose plane holds the light is seen edge-on: it hides nothing from the light
        // (a ray from the light meets it only within its plane) and is in the light's shadow, so
        // it is left out of the view (the part may then be open; nothing is seen through the gap).
        std::vector<Face> kept;
        std::vector<int> face;
        for (std::size_t f = 0; f < c.faces.size(); ++f) {
          const Face& fc = c.faces[f];
          if (holds_light(c.vertices, fc, light)) continue;
          kept.push_back(fc);
          face.push_back(c.part[f] < nf ? c.part[f] : -1);
        }
        if (kept.empty()) continue;
        v.parts.emplace_back(std::move(c.vertices), std::move(kept));
        v.body.push_back(static_cast<int>(b));
        v.face.push_back(std::move(face));
      }
      views.push_back(std::move(v));
    }
  return views;
}

}  // namespace hlr
