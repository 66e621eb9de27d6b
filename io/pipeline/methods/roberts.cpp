// Roberts' algorithm (course notes sections 26-28): convex bodies directly, non-convex solids
// through their convex pieces (section 23). Lines only; see-through bodies hide like the rest.
#include "algorithms/hlr/roberts.hpp"

#include <algorithm>

#include "algorithms/hlr/roberts_pieces.hpp"
#include "algorithms/solids/convexity.hpp"
#include "io/pipeline/render_methods.hpp"
#include "io/pipeline/render_steps.hpp"

namespace hlr {

void roberts_lines(LineStep& s) {
  bool all_convex = true;
  for (const Polyhedron* p : s.polys) all_convex = all_convex && p->report().valid_solid() && convexity(*p).convex();
  s.r.drawing = all_convex ? roberts(s.polys, s.r.camera, s.o.lines) : roberts_pieces(s.polys, s.r.camera, s.o.lines);
  const std::vector<char> see = see_through_bodies(s.r);
  if (std::find(see.begin(), see.end(), 1) != see.end())
    s.notes.push_back("transparent bodies hide the lines behind them with --method roberts (the per-face route draws those lines as seen through)");
}

}  // namespace hlr
