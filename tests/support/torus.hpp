// A torus mesh for the tests (docs/design.md, "Checks"): n x m quads around the ring, each
// split into two triangles, outward; the corner coordinates come from `coordinate`, given each
// corner's double (x, y or z), so a test picks the numbers (rounded decimals, doubles' exact
// values, scaled).
#pragma once

#include <cmath>
#include <functional>
#include <vector>

#include "kernel/polyhedron.hpp"

namespace hlr::test {

inline Polyhedron torus_mesh(int n, int m, double ring, double tube, const std::function<Rational(double)>& coordinate) {
  std::vector<Point3> vs;
  std::vector<Face> fs;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * M_PI * i / n, w = 2 * M_PI * j / m;
      vs.emplace_back(coordinate((ring + tube * std::cos(w)) * std::cos(u)), coordinate((ring + tube * std::cos(w)) * std::sin(u)),
                      coordinate(tube * std::sin(w)));
    }
  auto at = [&](int i, int j) { return (i % n) * m + (j % m); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      fs.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      fs.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return Polyhedron(vs, fs);
}

}  // namespace hlr::test
