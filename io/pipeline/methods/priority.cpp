// The course's priority-list (painter's) algorithm, Newell–Newell–Sancha (course notes, "an
// algorithm using a priority list"): the faces and their cut parts painted back to front.
#include <chrono>

#include "algorithms/surfaces/priority_list.hpp"
#include "io/pipeline/render_methods.hpp"

namespace hlr {

void priority_polygons(PolygonStep& s) {
  auto t0 = std::chrono::steady_clock::now();
  s.r.priority = priority_list(s.polys, s.r.camera, s.all);
  s.r.priority_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace hlr
