// Filled products with the eye among the bodies (see eye_cut.hpp; docs/design.md, "Filled
// products with the eye among the bodies").
#include "io/pipeline/eye_cut.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>

#include "io/pipeline/section.hpp"

namespace hlr {
namespace {

// A perspective view with some vertex on the eye's plane or behind it.
bool reaches_eye_plane(const std::vector<const Polyhedron*>& polys, const Camera& cam) {
  if (!cam.perspective) return false;
  for (const Polyhedron* p : polys)
    for (const Point3& v : p->vertices())
      if (cam.in_front(v) != Sign::Positive) return true;
  return false;
}

// With a frame: the largest power of two (as a fraction k of the eye-target distance, so the
// plane (P - E)·f = k·f·f) not beyond half the depth of the nearest point of any face inside the
// viewing pyramid; 0 when a face inside it reaches the eye's plane. No face lies inside the
// pyramid nearer than that, so every sight ray of the frame is inside the same bodies at every
// depth from the eye to there: a near cut anywhere in that range draws the same frame, and a
// farther one keeps the picture's coordinates (and the exact work on them) small.
Rational frame_clear_near(const std::vector<const Polyhedron*>& polys, const Camera& cam, const ViewPyramid& pyr) {
  const Vector3 f = cam.target - cam.eye;
  const Rational ff = dot(f, f);
  std::optional<Rational> least;  // the least (P - E)·f over the faces' parts in the pyramid
  auto consider = [&](const Point3& q) {
    const Rational d = dot(q - cam.eye, f);
    if (!least || d < *least) least = d;
  };
  for (const Polyhedron* p : polys) {
    // Per vertex: inside every side (its depth then counts as it is), else its face is clipped.
    std::vector<char> inside(p->num_vertices());
    for (std::size_t v = 0; v < inside.size(); ++v) {
      bool in = true;
      for (const Plane& side : pyr.sides) in = in && side_of_plane(side, p->vertices()[v]) != Sign::Negative;
      if ((inside[v] = in)) consider(p->vertices()[v]);
    }
    for (const Face& face : p->faces()) {
      bool all = true;
      for (int v : face) all = all && inside[v];
      if (all) continue;
      std::vector<Point3> ring;
      for (int v : face) ring.push_back(p->vertices()[v]);
      for (const Plane& side : pyr.sides) {  // Sutherland-Hodgman, keeping side >= 0
        std::vector<Point3> out;
        for (std::size_t i = 0; i < ring.size(); ++i) {
          const Point3 &a = ring[i], &b = ring[(i + 1) % ring.size()];
          const Rational va = side.value(a), vb = side.value(b);
          if (va >= 0) out.push_back(a);
          if ((va > 0 && vb < 0) || (va < 0 && vb > 0)) out.push_back(a + Rational(va / (va - vb)) * (b - a));
        }
        ring = std::move(out);
        if (ring.empty()) break;
      }
      for (const Point3& q : ring) consider(q);
    }
  }
  if (!least || *least <= 0) return 0;
  Rational k(1);
  while (k * ff * 2 > *least) k /= 2;  // k·f·f <= least / 2
  return k;
}

}  // namespace

void cut_at_eye(RenderResult& r, const Rational& near, bool shadows, std::vector<SceneBody*>& editable, std::vector<const Polyhedron*>& polys,
                std::vector<std::string>& notes) {
  if (!reaches_eye_plane(polys, r.camera)) return;
  // With a frame, as far from the eye as changes nothing in the frame (frame_clear_near).
  const Rational clear = r.pyramid ? frame_clear_near(polys, r.camera, *r.pyramid) : Rational(0);
  const Rational k = std::max(near, clear);
  const Plane n = near_plane(r.camera, k);
  const Plane keep(-n.a(), -n.b(), -n.c(), -n.d());  // keeps n >= 0: what lies in front of it
  r.eye_cut = keep;
  notes.push_back("the eye lies among the bodies: every body is cut by the near plane at " + to_string(k) + " of the way to the target (" +
                  (k > near ? "no face in the frame lies nearer" : "--near") + ") and what lies inside a body there is filled by its cap");
  std::shared_ptr<RenderResult::WholeBodies> whole;
  const std::vector<const SceneBody*> before(editable.begin(), editable.end());
  if (shadows) {  // the lights see the bodies whole
    whole = std::make_shared<RenderResult::WholeBodies>();
    for (const SceneBody* b : editable) whole->bodies.push_back(b->body);
  }
  std::vector<std::vector<int>> parent;
  cut_near(keep, editable, r.names, whole ? &parent : nullptr);
  if (editable.empty()) throw std::invalid_argument("every body lies behind the near plane: nothing is left to draw");
  if (whole) {
    for (const Polyhedron& p : whole->bodies) whole->casters.bodies.push_back(&p);
    for (const SceneBody* b : editable) whole->casters.body.push_back(static_cast<int>(std::find(before.begin(), before.end(), b) - before.begin()));
    whole->casters.face = std::move(parent);
    whole->casters.keep = keep;
    r.whole = whole;
  }
  polys.clear();
  for (SceneBody* b : editable) polys.push_back(&b->body);
}

}  // namespace hlr
