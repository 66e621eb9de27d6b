// Exact convexity test, course notes section 23 (see convexity.hpp).
#include "algorithms/convexity.hpp"

#include "kernel/predicates.hpp"

namespace hlr {

ConvexityResult convexity(const Polyhedron& body) {
  ConvexityResult r;
  const auto& planes = body.planes();
  const auto& vs = body.vertices();
  bool any_plane = false, any_off = false;
  for (std::size_t f = 0; f < planes.size(); ++f) {
    if (planes[f].is_degenerate()) continue;
    any_plane = true;
    int pos = -1, neg = -1;
    for (std::size_t v = 0; v < vs.size(); ++v) {
      Sign s = side_of_plane(planes[f], vs[v]);
      if (s == Sign::Positive && pos < 0) pos = static_cast<int>(v);
      if (s == Sign::Negative && neg < 0) neg = static_cast<int>(v);
    }
    if (pos >= 0 || neg >= 0) any_off = true;
    if (pos >= 0 && neg >= 0) {
      r.verdict = ConvexityResult::Verdict::NonConvex;
      r.face = static_cast<int>(f);
      r.vertex_positive = pos;
      r.vertex_negative = neg;
      return r;
    }
  }
  if (planes.empty())
    r.verdict = ConvexityResult::Verdict::NoFaces;
  else if (!any_plane || !any_off)
    r.verdict = ConvexityResult::Verdict::Flat;
  else
    r.verdict = ConvexityResult::Verdict::Convex;
  return r;
}

std::string describe(const ConvexityResult& r) {
  switch (r.verdict) {
    case ConvexityResult::Verdict::Convex: return "convex";
    case ConvexityResult::Verdict::Flat: return "flat (degenerate): every vertex lies in every face plane";
    case ConvexityResult::Verdict::NoFaces: return "no faces";
    case ConvexityResult::Verdict::NonConvex:
      return "not convex: face " + std::to_string(r.face) + " has vertex " +
             std::to_string(r.vertex_positive) + " on one side of its plane and vertex " +
             std::to_string(r.vertex_negative) + " on the other";
  }
  return {};
}

}  // namespace hlr
