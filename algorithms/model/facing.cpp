// Facing (see facing.hpp).
#include "algorithms/model/facing.hpp"

namespace hlr {

int facing_sign(const Plane& h, const RowVector4& g) {
  Rational v = h[0] * g(0) + h[1] * g(1);
  v += h[2] * g(2);
  v += h[3] * g(3);
  return sgn(v);
}

int facing_sign(const Plane& outward, const Camera& camera) { return facing_sign(outward, camera.viewpoint()); }

}  // namespace hlr
