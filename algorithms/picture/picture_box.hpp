// The doubles' box of an exact picture polygon, widened beyond their error: boxes apart mean
// polygons apart, a filter that only skips work (docs/design.md, "The priority list, exact":
// get_d truncates within 2^-52 relative, the pad is 10^-9 of the largest coordinate and above
// the subnormal step). `ok` is off where the doubles cannot hold the picture (infinities).
// Shared by priority_list.cpp and transparency.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "algorithms/picture/picture_plane.hpp"

namespace hlr {

struct PictureBox {
  double lo[2], hi[2];
  bool ok = true;
};

inline PictureBox picture_box(const std::vector<Exact2>& pts) {
  PictureBox b{{INFINITY, INFINITY}, {-INFINITY, -INFINITY}, true};
  double big = 0;
  for (const Exact2& q : pts)
    for (int k = 0; k < 2; ++k) {
      double x = q[k].get_d();
      if (!std::isfinite(x)) b.ok = false;
      b.lo[k] = std::min(b.lo[k], x), b.hi[k] = std::max(b.hi[k], x);
      big = std::max(big, std::fabs(x));
    }
  double pad = box_pad({big});
  for (int k = 0; k < 2; ++k) b.lo[k] -= pad, b.hi[k] += pad;
  return b;
}

}  // namespace hlr
