// Exact conversions between hlr::Point3 and CGAL Epeck points (see epeck_bridge.hpp).
#include "kernel/epeck_bridge.hpp"

namespace hlr {
namespace {

// Epeck's exact type is mpq_class when CGAL uses GMPXX, otherwise CGAL::Gmpq.
Rational from_exact(const mpq_class& q) { return q; }
template <class Q>
Rational from_exact(const Q& q) { return Rational(q.mpq()); }

Epeck::FT to_ft(const Rational& q) {
  using ET = Epeck::FT::ET;
  if constexpr (std::is_same_v<ET, mpq_class>)
    return Epeck::FT(q);
  else
    return Epeck::FT(ET(q.get_mpq_t()));
}

Rational from_ft(const Epeck::FT& x) { return from_exact(CGAL::exact(x)); }

}  // namespace

Epeck::FT to_epeck_ft(const Rational& q) { return to_ft(q); }

Epeck::Point_3 to_epeck(const Point3& p) {
  return Epeck::Point_3(to_ft(p.x()), to_ft(p.y()), to_ft(p.z()));
}

Point3 from_epeck(const Epeck::Point_3& p) {
  return Point3(from_ft(p.x()), from_ft(p.y()), from_ft(p.z()));
}

}  // namespace hlr
