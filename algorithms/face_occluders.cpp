// Per-face occluders (see face_occluders.hpp): the scene scaled to integers under the
// narrowest number policy whose bound holds (exact_int.hpp), then the engine (face_engine.hpp).
#include "algorithms/face_occluders.hpp"

#include <limits>

#include "algorithms/face_engine.hpp"
#include "kernel/exact_int.hpp"

namespace hlr {
namespace {

// Scale every coordinate (and the eye) by a common denominator; the view direction by its own.
// False when a scaled value reaches `bits` bits (then a wider policy takes the scene).
template <class P>
bool scale_fast(const std::vector<const Polyhedron*>& bodies, const Camera& cam, int bits, std::vector<Vec<P>>& pts,
                Vec<P>& view, Rational& scale) {
  const Int128 kLimit = Int128(1) << bits;
  std::vector<const Rational*> qs;
  for (const Polyhedron* p : bodies)
    for (const Point3& v : p->vertices())
      for (int k = 0; k < 3; ++k) qs.push_back(&v[k]);
  if (cam.perspective)
    for (int k = 0; k < 3; ++k) qs.push_back(&cam.eye[k]);
  std::uint64_t L = 1;
  if (qs.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) return false;
  if (!common_denominator(qs.data(), static_cast<int>(qs.size()), std::uint64_t(1) << bounds::kDenominatorBits, L)) return false;
  pts.clear();
  pts.reserve(qs.size() / 3);
  for (const Polyhedron* p : bodies)
    for (const Point3& v : p->vertices()) {
      Vec<P> x;
      for (int k = 0; k < 3; ++k) {
        Int128 s;
        if (!scaled_integer(v[k], L, kLimit, s)) return false;
        x[k] = static_cast<typename P::C>(s);
      }
      pts.push_back(x);
    }
  if (cam.perspective) {
    for (int k = 0; k < 3; ++k) {
      Int128 s;
      if (!scaled_integer(cam.eye[k], L, kLimit, s)) return false;
      view[k] = static_cast<typename P::C>(s);
    }
  } else {
    const Rational* d[3] = {&cam.direction[0], &cam.direction[1], &cam.direction[2]};
    std::uint64_t Ld = 1;
    if (!common_denominator(d, 3, std::uint64_t(1) << bounds::kDenominatorBits, Ld)) return false;
    Int128 s[3];
    for (int k = 0; k < 3; ++k)
      if (!scaled_integer(*d[k], Ld, Int128(1) << 62, s[k])) return false;
    Int128 g = gcd128(gcd128(s[0], s[1]), s[2]);
    for (int k = 0; k < 3; ++k) {
      s[k] /= g;
      if (abs128(s[k]) >= kLimit) return false;
      view[k] = static_cast<typename P::C>(s[k]);
    }
  }
  scale = Rational(static_cast<unsigned long>(L));
  return true;
}

void scale_big(const std::vector<const Polyhedron*>& bodies, const Camera& cam, std::vector<Vec<Big>>& pts,
               Vec<Big>& view, Rational& scale) {
  mpz_class L = 1;
  auto acc = [&](const Rational& q) { mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), q.get_den_mpz_t()); };
  for (const Polyhedron* p : bodies)
    for (const Point3& v : p->vertices())
      for (int k = 0; k < 3; ++k) acc(v[k]);
  if (cam.perspective)
    for (int k = 0; k < 3; ++k) acc(cam.eye[k]);
  auto sc = [&](const Rational& q) { return mpz_class(q.get_num() * (L / q.get_den())); };
  for (const Polyhedron* p : bodies)
    for (const Point3& v : p->vertices()) pts.push_back({sc(v[0]), sc(v[1]), sc(v[2])});
  if (cam.perspective) {
    view = {sc(cam.eye[0]), sc(cam.eye[1]), sc(cam.eye[2])};
  } else {
    mpz_class Ld = 1;
    for (int k = 0; k < 3; ++k) mpz_lcm(Ld.get_mpz_t(), Ld.get_mpz_t(), cam.direction[k].get_den_mpz_t());
    for (int k = 0; k < 3; ++k) view[k] = cam.direction[k].get_num() * (Ld / cam.direction[k].get_den());
  }
  scale = Rational(L);
}

}  // namespace

LineDrawing face_occluders(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineOptions& opt) {
  {
    std::vector<Vec<Fast>> pts;
    Vec<Fast> view{};
    Rational scale;
    if (scale_fast<Fast>(bodies, camera, Fast::kBits, pts, view, scale))
      return face_route::Engine<Fast>(bodies, camera, opt, std::move(pts), view, scale).run();
  }
  {
    std::vector<Vec<Fast40>> pts;
    Vec<Fast40> view{};
    Rational scale;
    if (scale_fast<Fast40>(bodies, camera, Fast40::kBits, pts, view, scale))
      return face_route::Engine<Fast40>(bodies, camera, opt, std::move(pts), view, scale).run();
  }
  std::vector<Vec<Big>> pts;
  Vec<Big> view;
  Rational scale;
  scale_big(bodies, camera, pts, view, scale);
  return face_route::Engine<Big>(bodies, camera, opt, std::move(pts), view, scale).run();
}

}  // namespace hlr
