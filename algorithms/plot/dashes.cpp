// Dashes as geometry (see dashes.hpp).
#include "algorithms/plot/dashes.hpp"

#include <cmath>

namespace hlr {

std::vector<std::vector<Point2>> cut_dashes(const std::vector<Point2>& in, bool closed, double dash, double gap) {
  std::vector<std::vector<Point2>> out;
  if (in.size() < 2 || !(dash > 0) || !(gap >= 0)) {
    if (in.size() >= 2) out.push_back(in);
    return out;
  }
  std::vector<Point2> pts = in;
  if (closed) pts.push_back(in.front());
  bool on = true;          // drawing a dash
  double left = dash;      // length left in the current dash or gap
  std::vector<Point2> cur{pts[0]};
  for (std::size_t i = 1; i < pts.size(); ++i) {
    Point2 a = pts[i - 1], b = pts[i];
    double len = std::hypot(b[0] - a[0], b[1] - a[1]), done = 0;
    while (len - done > left) {
      done += left;
      double u = done / len;
      Point2 p{a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])};
      if (on) {
        cur.push_back(p);
        out.push_back(std::move(cur));
        cur.clear();
      } else {
        cur = {p};
      }
      on = !on;
      left = on ? dash : gap;
    }
    left -= len - done;
    if (on) cur.push_back(b);
  }
  if (on && cur.size() >= 2) out.push_back(std::move(cur));
  return out;
}

}  // namespace hlr
