// Height grids for the floating-horizon tests: nx x nz samples evenly over [-1, 1]^2, heights
// from f(x, z).
#pragma once

#include <functional>

#include "algorithms/horizon/floating_horizon.hpp"

namespace hlr::test {

inline HeightGrid uniform_grid(int nx, int nz, const std::function<Rational(const Rational&, const Rational&)>& f) {
  HeightGrid g;
  for (int i = 0; i < nx; ++i) g.xs.push_back(rational(2 * i - (nx - 1), nx - 1));
  for (int j = 0; j < nz; ++j) g.zs.push_back(rational(2 * j - (nz - 1), nz - 1));
  for (const Rational& z : g.zs)
    for (const Rational& x : g.xs) g.ys.push_back(f(x, z));
  return g;
}

}  // namespace hlr::test
