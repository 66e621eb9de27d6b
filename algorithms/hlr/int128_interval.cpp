// Exact 128-bit integer path for Roberts' hidden interval (see int128_interval.hpp).
#include "algorithms/hlr/int128_interval.hpp"
#include "kernel/exact_int.hpp"

#include <cstdint>

namespace hlr {
namespace {

using i128 = Int128;

constexpr i128 kInputLimit = bounds::kWideCoordinateLimit;  // plane coefficients, scaled coordinates
constexpr i128 kValueLimit = static_cast<i128>(1) << 62;  // p, q, w

// Rational -> integer if it is one and small.
bool small_integer(const Rational& q, i128& out) {
  if (q.get_den() != 1 || !q.get_num().fits_slong_p()) return false;
  out = q.get_num().get_si();
  return abs128(out) < kInputLimit;
}

// A fraction n/d with d > 0.
struct Ratio128 {
  i128 n, d;
};
int cmp(const Ratio128& x, const Ratio128& y) { return compare_products(x.n, y.d, y.n, x.d); }

Rational to_rational(const Ratio128& f) {
  Rational q(to_mpz(f.n), to_mpz(f.d));
  q.canonicalize();
  return q;
}

}  // namespace

FastBody prepare_fast_body(const BodyMatrixData& V, const RowVector4& g) {
  FastBody fb;
  // The viewpoint scaled to integers (a positive factor changes no t).
  std::uint64_t L;
  const Rational* gs[4] = {&g(0), &g(1), &g(2), &g(3)};
  if (!common_denominator(gs, 4, kInputLimit, L)) return fb;
  i128 G[4];
  for (int k = 0; k < 4; ++k)
    if (!scaled_integer(g(k), L, kInputLimit, G[k])) return fb;
  for (int j = 0; j < V.cols(); ++j) {
    std::array<i128, 4> h;
    for (int k = 0; k < 4; ++k)
      if (!small_integer(V(k, j), h[k])) return fb;
    i128 w = h[0] * G[0] + h[1] * G[1] + h[2] * G[2] + h[3] * G[3];
    if (abs128(w) >= kValueLimit) return fb;
    fb.planes.push_back(h);
    fb.w.push_back(w);
  }
  fb.usable = true;
  return fb;
}

std::optional<OpenInterval> fast_hidden_interval(const Point3& p1, const Point3& p2, const FastBody& body) {
  if (!body.usable) return std::nullopt;
  const Rational* qs[6] = {&p1.x(), &p1.y(), &p1.z(), &p2.x(), &p2.y(), &p2.z()};
  std::uint64_t L;
  if (!common_denominator(qs, 6, kInputLimit, L)) return std::nullopt;
  i128 A[3], B[3];
  for (int k = 0; k < 3; ++k) {
    i128 b;
    if (!scaled_integer(p1[k], L, kInputLimit, A[k]) || !scaled_integer(p2[k], L, kInputLimit, b)) return std::nullopt;
    B[k] = b - A[k];
  }
  const std::size_t n = body.planes.size();
  // p_j·L, q_j·L (a positive factor L on both changes no t).
  std::vector<i128> p(n), q(n);
  for (std::size_t j = 0; j < n; ++j) {
    const auto& h = body.planes[j];
    p[j] = h[0] * A[0] + h[1] * A[1] + h[2] * A[2] + h[3] * static_cast<i128>(L);
    q[j] = h[0] * B[0] + h[1] * B[1] + h[2] * B[2];
    if (abs128(p[j]) >= kValueLimit || abs128(q[j]) >= kValueLimit) return std::nullopt;
  }
  std::optional<Ratio128> lo, hi;
  OpenInterval r;
  auto add = [&](i128 alpha, i128 beta) -> bool {
    if (beta == 0) return alpha > 0;
    Ratio128 t = beta > 0 ? Ratio128{-alpha, beta} : Ratio128{alpha, -beta};
    if (beta > 0) {
      if (!lo || cmp(t, *lo) > 0) lo = t;
    } else {
      if (!hi || cmp(t, *hi) < 0) hi = t;
    }
    return true;
  };
  std::vector<std::size_t> lower, upper;
  for (std::size_t j = 0; j < n; ++j) {
    const i128 w = body.w[j];
    if (w > 0) lower.push_back(j);
    else if (w < 0) upper.push_back(j);
    else if (!add(p[j], q[j])) return r;
  }
  for (std::size_t k : upper) {
    if (!add(p[k], q[k])) return r;
    for (std::size_t j : lower)
      if (!add(p[k] * body.w[j] - p[j] * body.w[k], q[k] * body.w[j] - q[j] * body.w[k])) return r;
  }
  if (lo && hi && cmp(*lo, *hi) >= 0) return r;
  r.empty = false;
  if (lo) r.lo = to_rational(*lo);
  if (hi) r.hi = to_rational(*hi);
  return r;
}

}  // namespace hlr
