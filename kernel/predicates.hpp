// Exact geometric predicates. Each is evaluated first in interval arithmetic on the certified
// bounds that points and planes carry (CGAL::Interval_nt), and exactly in rationals only when
// the interval contains zero. Answers are always exact. Counters of how often the exact
// fallback ran are kept for benchmarks (predicate_stats()).
#pragma once

#include <cstdint>

#include "kernel/geometry.hpp"

namespace hlr {

enum class Sign : int { Negative = -1, Zero = 0, Positive = 1 };

inline Sign sign_of(const Rational& q) {
  int s = sgn(q);
  return s < 0 ? Sign::Negative : (s > 0 ? Sign::Positive : Sign::Zero);
}

/// Side of p with respect to the plane: sign of a·x + b·y + c·z + d.
Sign side_of_plane(const Plane& h, const Point3& p);

/// Orientation of the tetrahedron (p, q, r, s): sign of det[q-p, r-p, s-p], as CGAL's
/// orientation(). Positive when p, q, r are counter-clockwise seen from s; zero iff the four
/// points are coplanar.
Sign orientation(const Point3& p, const Point3& q, const Point3& r, const Point3& s);

/// True iff p, q, r lie on one line (exact).
bool collinear(const Point3& p, const Point3& q, const Point3& r);

/// Sign of the dot product u·v (exact, filtered).
Sign sign_of_dot(const Vector3& u, const Vector3& v);

/// Counts of filtered evaluations and of exact fallbacks since start (per thread).
struct PredicateStats {
  std::uint64_t evaluations = 0;
  std::uint64_t exact_fallbacks = 0;
};
PredicateStats& predicate_stats();

}  // namespace hlr
