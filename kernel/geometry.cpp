// Exact constructions on points, vectors and planes (see geometry.hpp).
#include "kernel/geometry.hpp"

#include <CGAL/Interval_nt.h>
#include <CGAL/mpq_class.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <vector>

#include "kernel/exact_int.hpp"
#include "kernel/int128.hpp"
#include "kernel/plane_int128.hpp"

namespace hlr {

namespace {

// The tightest interval of doubles around ±n/d for n and d below 2^128 (an exporter's 17 to 19
// digit decimals: a numerator of one limb over 10^19 to 10^23), by one division of GMP limbs on
// the stack: a = n·2^s / d truncated lies in [2^54, 2^56); cut to 53 significant bits it is the
// double below (times 2^-s, exact for a normal double), the next one up bounds it above unless
// the division left no remainder and no cut bits (then q is that double). The same interval as
// CGAL::to_interval's (rounding away from zero, then the neighbour toward zero), without MPFR.
// False outside that range or for a result that is not a normal double.
bool bounds_by_division(const Rational& q, Bounds& out) {
  mpz_srcptr n = q.get_num_mpz_t(), d = q.get_den_mpz_t();
  const std::size_t nl = mpz_size(n), dl = mpz_size(d);
  if (nl == 0 || nl > 2 || dl == 0 || dl > 2) return false;
  const long nb = static_cast<long>(mpz_sizeinbase(n, 2)), db = static_cast<long>(mpz_sizeinbase(d, 2));
  const long s = 55 - nb + db;  // in [55 - 128 + 1, 55 + 128 - 1]
  // a = |n|·2^max(s, 0), b = d·2^max(-s, 0): at most 5 and 4 limbs.
  mp_limb_t a[6] = {0, 0, 0, 0, 0, 0}, b[5] = {0, 0, 0, 0, 0}, quo[6], rem[5];
  auto shifted = [](mp_limb_t* to, mpz_srcptr x, std::size_t xl, long by) {
    const std::size_t limbs = static_cast<std::size_t>(by / GMP_NUMB_BITS);
    const unsigned bits = static_cast<unsigned>(by % GMP_NUMB_BITS);
    const mp_limb_t* xp = mpz_limbs_read(x);
    if (bits == 0) {
      std::copy(xp, xp + xl, to + limbs);
      return limbs + xl;
    }
    to[limbs + xl] = mpn_lshift(to + limbs, xp, static_cast<mp_size_t>(xl), bits);
    return limbs + xl + 1;
  };
  std::size_t an = shifted(a, n, nl, std::max(s, 0L)), bn = shifted(b, d, dl, std::max(-s, 0L));
  while (an > 0 && a[an - 1] == 0) --an;
  while (bn > 0 && b[bn - 1] == 0) --bn;
  mpn_tdiv_qr(quo, rem, 0, a, static_cast<mp_size_t>(an), b, static_cast<mp_size_t>(bn));
  const std::uint64_t m = quo[0];  // in [2^54, 2^56): the higher limbs are zero
  bool exact = true;
  for (std::size_t i = 0; i < bn; ++i) exact = exact && rem[i] == 0;
  const int drop = m >= (std::uint64_t{1} << 55) ? 3 : 2;  // bits below the 53 kept
  const std::uint64_t low = m & ((std::uint64_t{1} << drop) - 1), base = m - low;
  exact = exact && low == 0;
  const double lo = std::ldexp(static_cast<double>(base), static_cast<int>(-s));
  const double hi = exact ? lo : std::ldexp(static_cast<double>(base + (std::uint64_t{1} << drop)), static_cast<int>(-s));
  if (!(lo >= 0x1p-1022) || !std::isfinite(hi)) return false;
  out = mpz_sgn(n) < 0 ? Bounds{-hi, -lo} : Bounds{lo, hi};
  return true;
}

}  // namespace

Bounds bounds_of(const Rational& q) {
  // Fast path: numerator and denominator exact in doubles; IEEE division is correctly rounded,
  // so the quotient is within one unit in the last place (exact for integers).
  const mpz_class& n = q.get_num();
  const mpz_class& d = q.get_den();
  if (mpz_sizeinbase(n.get_mpz_t(), 2) <= 53 && mpz_sizeinbase(d.get_mpz_t(), 2) <= 53) {
    double x = n.get_d(), y = d.get_d();
    if (y == 1) return {x, x};
    double v = x / y;
    return {std::nextafter(v, -HUGE_VAL), std::nextafter(v, HUGE_VAL)};
  }
  Bounds b;
  if (bounds_by_division(q, b)) return b;
  std::pair<double, double> iv = CGAL::to_interval(q);
  return {iv.first, iv.second};
}

Vector3::Vector3(Rational x, Rational y, Rational z) : c_{std::move(x), std::move(y), std::move(z)} {
  for (int i = 0; i < 3; ++i) b_[i] = bounds_of(c_[i]);
}

Point3::Point3(Rational x, Rational y, Rational z) : c_{std::move(x), std::move(y), std::move(z)} {
  for (int i = 0; i < 3; ++i) b_[i] = bounds_of(c_[i]);
}

Plane::Plane(Rational a, Rational b, Rational c, Rational d)
    : k_{std::move(a), std::move(b), std::move(c), std::move(d)} {
  for (int i = 0; i < 4; ++i) b_[i] = bounds_of(k_[i]);
}

Rational Plane::value(const Point3& p) const {
  Rational v = k_[0] * p.x() + k_[1] * p.y();
  v += k_[2] * p.z();
  v += k_[3];
  return v;
}

Vector3 operator-(const Point3& p, const Point3& q) {
  return Vector3(p.x() - q.x(), p.y() - q.y(), p.z() - q.z());
}
Point3 operator+(const Point3& p, const Vector3& v) {
  return Point3(p.x() + v.x(), p.y() + v.y(), p.z() + v.z());
}
Vector3 operator+(const Vector3& u, const Vector3& v) {
  return Vector3(u.x() + v.x(), u.y() + v.y(), u.z() + v.z());
}
Vector3 operator*(const Rational& k, const Vector3& v) {
  return Vector3(k * v.x(), k * v.y(), k * v.z());
}
Vector3 cross(const Vector3& u, const Vector3& v) {
  return Vector3(u.y() * v.z() - u.z() * v.y(), u.z() * v.x() - u.x() * v.z(),
                 u.x() * v.y() - u.y() * v.x());
}
Rational dot(const Vector3& u, const Vector3& v) {
  Rational r = u.x() * v.x() + u.y() * v.y();
  r += u.z() * v.z();
  return r;
}

Vector3 newell_normal(const Point3* const* v, std::size_t n) {
  // Relative to v[0] to keep numbers small; the sum of cross products of a fan is the same.
  Rational nx = 0, ny = 0, nz = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    Rational ax = v[i]->x() - v[0]->x(), ay = v[i]->y() - v[0]->y(), az = v[i]->z() - v[0]->z();
    Rational bx = v[i + 1]->x() - v[0]->x(), by = v[i + 1]->y() - v[0]->y(),
             bz = v[i + 1]->z() - v[0]->z();
    nx += ay * bz - az * by;
    ny += az * bx - ax * bz;
    nz += ax * by - ay * bx;
  }
  return Vector3(nx, ny, nz);
}

Plane plane_of_polygon(const Point3* const* v, std::size_t n) {
  Vector3 nrm = newell_normal(v, n);
  Rational d = -(nrm.x() * v[0]->x() + nrm.y() * v[0]->y() + nrm.z() * v[0]->z());
  return Plane(nrm.x(), nrm.y(), nrm.z(), d);
}

Plane primitive_plane(const Plane& h) {
  if (h.is_degenerate()) return h;
  mpz_class l = 1, g = 0;
  for (int i = 0; i < 4; ++i) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), h[i].get_den().get_mpz_t());
  mpz_class k[4];
  for (int i = 0; i < 4; ++i) {
    k[i] = h[i].get_num() * (l / h[i].get_den());
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), k[i].get_mpz_t());
  }
  for (int i = 0; i < 4; ++i) k[i] /= g;
  return Plane(Rational(k[0]), Rational(k[1]), Rational(k[2]), Rational(k[3]));
}

Plane primitive_plane_of_polygon(const Point3* const* v, std::size_t n) {
  PlaneInt128 fast;
  if (plane_int128(v, n, fast)) return to_plane(fast);
  return primitive_plane(plane_of_polygon(v, n));
}

Point3 centroid_of_vertices(const Point3* const* p, std::size_t n) {
  Rational sx = 0, sy = 0, sz = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sx += p[i]->x();
    sy += p[i]->y();
    sz += p[i]->z();
  }
  Rational k(static_cast<long>(n));
  return Point3(sx / k, sy / k, sz / k);
}

namespace {
std::string join(const char* open, const Rational* c, int n, const char* sep, const char* close) {
  std::string s = open;
  for (int i = 0; i < n; ++i) {
    if (i) s += sep;
    s += c[i].get_str();
  }
  s += close;
  return s;
}
}  // namespace

std::string to_string(const Point3& p) {
  const Rational c[3] = {p.x(), p.y(), p.z()};
  return join("(", c, 3, ", ", ")");
}
std::string to_string(const Vector3& v) {
  const Rational c[3] = {v.x(), v.y(), v.z()};
  return join("(", c, 3, ", ", ")");
}

std::string to_string(const Plane& h) {
  const Rational c[4] = {h.a(), h.b(), h.c(), h.d()};
  return join("[", c, 4, " ", "]");
}
std::ostream& operator<<(std::ostream& os, const Point3& p) { return os << to_string(p); }
std::ostream& operator<<(std::ostream& os, const Vector3& v) { return os << to_string(v); }
std::ostream& operator<<(std::ostream& os, const Plane& h) { return os << to_string(h); }

ZeroAreaKind zero_area_kind(const Point3* const* v, std::size_t n) {
  // Three vertices not on one line span the plane the others must lie in.
  for (std::size_t i = 2; i < n; ++i) {
    Vector3 m = cross(*v[1] - *v[0], *v[i] - *v[0]);
    if (m.is_zero()) continue;
    for (std::size_t k = 0; k < n; ++k)
      if (dot(m, *v[k] - *v[0]) != 0) return ZeroAreaKind::NonPlanar;
    return ZeroAreaKind::Crossing;
  }
  return ZeroAreaKind::Collinear;
}

}  // namespace hlr
