// Face planes in 128-bit integers (docs/design.md, "Number paths"). See plane_int128.hpp.
#include "kernel/plane_int128.hpp"

#include <algorithm>
#include <vector>

#include "kernel/exact_int.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr {

bool plane_int128(const Point3* const* v, std::size_t count, PlaneInt128& out) {
  constexpr Int128 kLimit = bounds::kWideCoordinateLimit;
  if (count > 1024) return false;
  // Faces of up to 8 vertices (nearly all) without allocating.
  constexpr std::size_t kSmall = 8;
  const Rational* qs_small[3 * kSmall];
  std::array<Int128, 3> x_small[kSmall];
  std::vector<const Rational*> qs_big;
  std::vector<std::array<Int128, 3>> x_big;
  if (count > kSmall) qs_big.resize(3 * count), x_big.resize(count);
  const Rational** qs = count > kSmall ? qs_big.data() : qs_small;
  std::array<Int128, 3>* X = count > kSmall ? x_big.data() : x_small;
  for (std::size_t i = 0; i < count; ++i)
    for (int k = 0; k < 3; ++k) qs[3 * i + k] = &(*v[i])[k];
  std::uint64_t L;
  if (!common_denominator(qs, static_cast<int>(3 * count), static_cast<std::uint64_t>(kLimit), L)) return false;
  for (std::size_t i = 0; i < count; ++i)
    for (int k = 0; k < 3; ++k)
      if (!scaled_integer((*v[i])[k], L, kLimit, X[i][k])) return false;
  // Newell's normal as a fan from X[0]: differences < 2^41, products < 2^83, at most 2^10 terms.
  std::array<Int128, 3> nrm{0, 0, 0};
  for (std::size_t i = 1; i + 1 < count; ++i) {
    Int128 a[3], b[3];
    for (int k = 0; k < 3; ++k) {
      a[k] = X[i][k] - X[0][k];
      b[k] = X[i + 1][k] - X[0][k];
    }
    nrm[0] += a[1] * b[2] - a[2] * b[1];
    nrm[1] += a[2] * b[0] - a[0] * b[2];
    nrm[2] += a[0] * b[1] - a[1] * b[0];
  }
  out = PlaneInt128{};
  if (nrm[0] == 0 && nrm[1] == 0 && nrm[2] == 0) return true;
  const int nb = std::max({bit_length(nrm[0]), bit_length(nrm[1]), bit_length(nrm[2])});
  const int xb = std::max({bit_length(X[0][0]), bit_length(X[0][1]), bit_length(X[0][2])});
  if (nb + xb + 2 > 125) return false;
  // n·X + d = 0 with X = L·x: the plane (n·L, d) in x. Reduce to primitive form.
  Int128 d = -(nrm[0] * X[0][0] + nrm[1] * X[0][1] + nrm[2] * X[0][2]);
  Int128 h = gcd128(nrm[0], nrm[1]);  // usually 1 at once or after the next
  if (h != 1) h = gcd128(h, nrm[2]);
  if (h != 1) h = gcd128(h, d);
  for (Int128& c : nrm) c /= h;
  d /= h;
  // gcd(n) and d are now coprime, so gcd(n·L, d) = gcd(L, d).
  const Int128 r = gcd128(static_cast<Int128>(L), d);
  out.n = nrm;
  out.k = static_cast<Int128>(L) / r;
  out.d = d / r;
  return true;
}

bool face_plane_int128(const Polyhedron& p, std::size_t f, PlaneInt128& out) {
  const Face& face = p.faces()[f];
  if (face.size() > 8) {
    std::vector<const Point3*> pts;
    for (int v : face) pts.push_back(&p.vertices()[v]);
    return plane_int128(pts.data(), pts.size(), out);
  }
  const Point3* pts[8];
  for (std::size_t i = 0; i < face.size(); ++i) pts[i] = &p.vertices()[face[i]];
  return plane_int128(pts, face.size(), out);
}

Plane to_plane(const PlaneInt128& h) {
  if (h.degenerate()) return Plane(0, 0, 0, 0);
  const mpz_class kz = to_mpz(h.k);
  return Plane(Rational(to_mpz(h.n[0]) * kz), Rational(to_mpz(h.n[1]) * kz), Rational(to_mpz(h.n[2]) * kz), Rational(to_mpz(h.d)));
}

std::array<Bounds, 3> normal_bounds(const PlaneInt128& h) {
  std::array<Bounds, 3> out;
  const int kb = bit_length(h.k);
  for (int i = 0; i < 3; ++i) {
    if (bit_length(h.n[i]) + kb <= 53) {  // |k·n| < 2^53: the double is exact, as bounds_of gives it
      const double x = static_cast<double>(h.n[i] * h.k);
      out[i] = {x, x};
    } else {
      out[i] = bounds_of(Rational(to_mpz(h.n[i]) * to_mpz(h.k)));
    }
  }
  return out;
}

}  // namespace hlr
