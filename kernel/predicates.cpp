// Filtered exact predicates (see predicates.hpp): interval arithmetic first, rationals second.
#include "kernel/predicates.hpp"

#include <CGAL/Interval_nt.h>

namespace hlr {
namespace {

using I = CGAL::Interval_nt<false>;  // needs CGAL::Protect_FPU_rounding in scope

I iv(const Bounds& b) { return I(b.lo, b.hi); }

// Sign of an interval if it is certain; Zero with `certain=false` otherwise.
bool certain_sign(const I& v, Sign& out) {
  if (v.inf() > 0) {
    out = Sign::Positive;
    return true;
  }
  if (v.sup() < 0) {
    out = Sign::Negative;
    return true;
  }
  if (v.inf() == 0 && v.sup() == 0) {
    out = Sign::Zero;
    return true;
  }
  return false;
}

}  // namespace

PredicateStats& predicate_stats() {
  thread_local PredicateStats stats;
  return stats;
}

Sign side_of_plane(const Plane& h, const Point3& p) {
  ++predicate_stats().evaluations;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    I v = iv(h.approx(0)) * iv(p.approx(0)) + iv(h.approx(1)) * iv(p.approx(1)) +
          iv(h.approx(2)) * iv(p.approx(2)) + iv(h.approx(3));
    Sign s;
    if (certain_sign(v, s)) return s;
  }
  ++predicate_stats().exact_fallbacks;
  return sign_of(h.value(p));
}

Sign orientation(const Point3& p, const Point3& q, const Point3& r, const Point3& s) {
  ++predicate_stats().evaluations;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    I ax = iv(q.approx(0)) - iv(p.approx(0)), ay = iv(q.approx(1)) - iv(p.approx(1)),
      az = iv(q.approx(2)) - iv(p.approx(2));
    I bx = iv(r.approx(0)) - iv(p.approx(0)), by = iv(r.approx(1)) - iv(p.approx(1)),
      bz = iv(r.approx(2)) - iv(p.approx(2));
    I cx = iv(s.approx(0)) - iv(p.approx(0)), cy = iv(s.approx(1)) - iv(p.approx(1)),
      cz = iv(s.approx(2)) - iv(p.approx(2));
    I det = ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
    Sign out;
    if (certain_sign(det, out)) return out;
  }
  ++predicate_stats().exact_fallbacks;
  Vector3 a = q - p, b = r - p, c = s - p;
  return sign_of(dot(a, cross(b, c)));
}

bool collinear(const Point3& p, const Point3& q, const Point3& r) {
  ++predicate_stats().evaluations;
  {
    // Collinear iff every component of (q − p) × (r − p) is zero: one certainly non-zero
    // component settles it (almost every triangle of a mesh).
    CGAL::Protect_FPU_rounding<true> guard;
    I ax = iv(q.approx(0)) - iv(p.approx(0)), ay = iv(q.approx(1)) - iv(p.approx(1)), az = iv(q.approx(2)) - iv(p.approx(2));
    I bx = iv(r.approx(0)) - iv(p.approx(0)), by = iv(r.approx(1)) - iv(p.approx(1)), bz = iv(r.approx(2)) - iv(p.approx(2));
    for (const I& c : {ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx}) {
      Sign s;
      if (certain_sign(c, s) && s != Sign::Zero) return false;
    }
  }
  ++predicate_stats().exact_fallbacks;
  return cross(q - p, r - p).is_zero();
}

Sign sign_of_dot(const Vector3& u, const Vector3& v) {
  ++predicate_stats().evaluations;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    I d = iv(u.approx(0)) * iv(v.approx(0)) + iv(u.approx(1)) * iv(v.approx(1)) +
          iv(u.approx(2)) * iv(v.approx(2));
    Sign s;
    if (certain_sign(d, s)) return s;
  }
  ++predicate_stats().exact_fallbacks;
  return sign_of(dot(u, v));
}

}  // namespace hlr
