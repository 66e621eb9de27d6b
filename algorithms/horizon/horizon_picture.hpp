// The certified numbers and the picture of the exact floating horizon on doubles (course
// notes section 24; docs/design.md, "The floating horizon on certified doubles"): an
// approximation with its proven error (Ad), the picture's lines and abscissae, and the grid in
// the picture with every decision on it (Picture). Used only by floating_horizon_filtered.cpp.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "algorithms/horizon/floating_horizon.hpp"
#include "algorithms/support/parallel.hpp"
#include "kernel/error_bounds.hpp"
#include "kernel/int128.hpp"

namespace hlr::horizon_filtered {


// The unit roundoff, the error of an underflow and the bounds' own roundings: kernel/error_bounds.hpp.

// An approximation v of an exact number x with |x - v| <= e (docs/design.md).
struct Ad {
  double v = 0, e = 0;
};
inline Ad operator+(Ad a, Ad b) {
  const double v = a.v + b.v;
  return {v, a.e + b.e + std::fabs(v) * kUnitRoundoff + kUnderflowError};
}
inline Ad operator-(Ad a, Ad b) {
  const double v = a.v - b.v;
  return {v, a.e + b.e + std::fabs(v) * kUnitRoundoff + kUnderflowError};
}
inline Ad operator*(Ad a, Ad b) {
  const double v = a.v * b.v;
  return {v, std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e + std::fabs(v) * kUnitRoundoff + kUnderflowError};
}
inline Ad operator/(Ad a, Ad b) {
  const double m = std::fabs(b.v) - b.e * kBoundSafety;  // a lower bound of |b's exact value|
  if (!(m > 0)) return {0, HUGE_VAL};
  const double v = a.v / b.v;
  return {v, (a.e + std::fabs(v) * b.e) / m * kBoundSafety + std::fabs(v) * kUnitRoundoff + kUnderflowError};
}
// A rational's double (GMP truncates: within one ulp; below the normal range, whether it
// gives a subnormal or zero, within the smallest normal 2^-1022).
Ad approx(const Rational& q) {
  const double v = q.get_d();
  if (!std::isfinite(v)) return {0, HUGE_VAL};
  return {v, std::fabs(v) * kToDoubleError + 0x1p-1022};
}
// The exact number's sign, or 2 when the bound does not tell.
inline int sign(Ad a) {
  const double b = a.e * kBoundSafety;
  if (a.v > b) return 1;
  if (a.v < -b) return -1;
  if (a.e == 0 && a.v == 0) return 0;
  return 2;
}
inline int sgn(const Rational& q) { return q > 0 ? 1 : q < 0 ? -1 : 0; }
template <class T>
inline int sgn_int(T v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }

// A line of the picture through samples p and q (X_p < X_q): y = s·x + c.
struct Line {
  int p = -1, q = -1;
  Ad s, c;
  int moved = -1;  // where compact() copied it (scratch lines only)
};
// An abscissa: a sample's X, or the crossing of two lines.
struct Abs {
  Ad x;
  int sample = -1;
  const Line *l1 = nullptr, *l2 = nullptr;
};
struct Seg {
  Abs x0, x1;
  const Line* line;
};
using Env = std::vector<Seg>;

// Lines with stable addresses, allocated in large blocks; reset() reuses the blocks (a
// strip's scratch lines: most sides of its triangles end up below its envelopes, and fresh
// memory for each strip cost more in page faults than the sweep itself).
class LinePool {
 public:
  Line* add() {
    if (block_ == blocks_.size() || used_ == kBlock) {
      if (used_ == kBlock) ++block_, used_ = 0;
      if (block_ == blocks_.size()) blocks_.push_back(std::make_unique<Line[]>(kBlock));
    }
    return &blocks_[block_][used_++];
  }
  void reset() { block_ = 0, used_ = 0; }

 private:
  static constexpr std::size_t kBlock = 4096;
  std::vector<std::unique_ptr<Line[]>> blocks_;
  std::size_t block_ = 0, used_ = 0;
};

inline bool same_pair(const Line* a, const Line* b) { return a == b || (a->p == b->p && a->q == b->q); }
inline bool on(int sample, const Line* l) { return l->p == sample || l->q == sample; }

// The grid in the picture and every decision on it.
class Picture {
 public:
  Picture(const HeightGrid& g, const Vector3& v, int sx, int sy, unsigned threads) : g_(g), nx_(g.xs.size()), sx_(sx), sy_(sy) {
    a_ = v.x(), b_ = v.y(), c_ = v.z();
    sa_ = sgn(a_), sc_ = sgn(c_);
    const Ad a = approx(a_), b = approx(b_), c = approx(c_);
    const std::size_t nz = g.zs.size();
    std::vector<Ad> xs(nx_), zs(nz);
    for (std::size_t i = 0; i < nx_; ++i) xs[i] = approx(g.xs[i]);
    for (std::size_t j = 0; j < nz; ++j) zs[j] = approx(g.zs[j]);
    X_.resize(nx_ * nz);
    Y_.resize(nx_ * nz);
    const Ad fx{static_cast<double>(sx), 0}, fy{static_cast<double>(sy), 0};
    ParallelLoop loop(threads);
    loop.for_each(nz, 1, [&](std::size_t j) {
      for (std::size_t i = 0; i < nx_; ++i) {
        X_[j * nx_ + i] = fx * (c * xs[i] - a * zs[j]);
        const Ad y = g.yd.empty() ? approx(g.ys[j * nx_ + i]) : Ad{g.yd[j * nx_ + i], 0};  // a double height is exact
        Y_[j * nx_ + i] = fy * (c * y - b * zs[j]);
      }
    });
    uniform_order();
  }

  std::uint64_t exact_count() const { return exact_.load(); }
  Abs at(int k) const { return Abs{X_[static_cast<std::size_t>(k)], k, nullptr, nullptr}; }

  const Line* through(LinePool& pool, int p, int q) const {
    const Ad s = (Y_[q] - Y_[p]) / (X_[q] - X_[p]);
    Line* l = pool.add();
    *l = Line{p, q, s, Y_[p] - s * X_[p]};
    return l;
  }

  // The order of two samples' abscissas.
  int sample_cmp(int k, int l) const {
    if (k == l) return 0;
    if (uniform_) {
      const Int128 a = key_[static_cast<std::size_t>(k)], b = key_[static_cast<std::size_t>(l)];
      return a < b ? -1 : a > b ? 1 : 0;
    }
    return sample_cmp_slow(k, l);
  }
  [[gnu::noinline]] int sample_cmp_slow(int k, int l) const {
    const long ik = k % static_cast<long>(nx_), jk = k / static_cast<long>(nx_), il = l % static_cast<long>(nx_),
               jl = l / static_cast<long>(nx_);
    // X = sx·(c·x_i − a·z_j) with the xs and zs increasing.
    if (jk == jl || sa_ == 0) return sx_ * sc_ * sgn_int(ik - il);
    if (ik == il) return -sx_ * sa_ * sgn_int(jk - jl);
    const int f = sign(X_[k] - X_[l]);
    if (f != 2) return f;
    ++exact_;
    return sgn(Xq(k) - Xq(l));
  }

  int cmp(const Abs& x, const Abs& y) const {
    if (x.sample >= 0 && y.sample >= 0) {
      if (x.sample == y.sample) return 0;
      const int f = sign(x.x - y.x);  // the doubles at hand first, the samples' keys after
      return f != 2 ? f : sample_cmp(x.sample, y.sample);
    }
    return cmp_slow(x, y);
  }
  [[gnu::noinline]] int cmp_slow(const Abs& x, const Abs& y) const {
    if (x.sample < 0 && y.sample < 0 &&
        ((same_pair(x.l1, y.l1) && same_pair(x.l2, y.l2)) || (same_pair(x.l1, y.l2) && same_pair(x.l2, y.l1))))
      return 0;
    if (x.sample >= 0 && on(x.sample, y.l1) && on(x.sample, y.l2)) return 0;
    if (y.sample >= 0 && on(y.sample, x.l1) && on(y.sample, x.l2)) return 0;
    const int f = sign(x.x - y.x);
    if (f != 2) return f;
    ++exact_;
    return sgn(exact(x) - exact(y));
  }

  // The sign of A(x) − B(x).
  int diff(const Line& A, const Line& B, const Abs& x) const {
    if (same_pair(&A, &B)) return 0;
    Ad va, vb;
    if (x.sample >= 0) {
      const bool ina = on(x.sample, &A), inb = on(x.sample, &B);
      if (ina && inb) return 0;
      va = ina ? Y_[x.sample] : A.s * x.x + A.c;
      vb = inb ? Y_[x.sample] : B.s * x.x + B.c;
    } else {
      if ((same_pair(&A, x.l1) && same_pair(&B, x.l2)) || (same_pair(&A, x.l2) && same_pair(&B, x.l1))) return 0;
      va = A.s * x.x + A.c;
      vb = B.s * x.x + B.c;
    }
    const int f = sign(va - vb);
    return f != 2 ? f : diff_exact(A, B, x);
  }
  [[gnu::noinline]] int diff_exact(const Line& A, const Line& B, const Abs& x) const {
    ++exact_;
    Rational sa, ca, sb, cb;
    exact_line(A, sa, ca);
    exact_line(B, sb, cb);
    Rational xe = exact(x);
    return sgn((sa - sb) * xe + (ca - cb));
  }

  bool same_line(const Line* A, const Line* B) const {
    if (same_pair(A, B)) return true;
    if (sign(A->s - B->s) % 2 != 0 || sign(A->c - B->c) % 2 != 0) return false;  // ±1: certainly different
    return same_line_exact(A, B);
  }
  [[gnu::noinline]] bool same_line_exact(const Line* A, const Line* B) const {
    ++exact_;
    Rational sa, ca, sb, cb;
    exact_line(*A, sa, ca);
    exact_line(*B, sb, cb);
    return sa == sb && ca == cb;
  }

  // The turn of samples a, b, c: sign((Xc − Xa)(Yb − Ya) − (Yc − Ya)(Xb − Xa)).
  int orient(int a, int b, int c) const {
    const int f = sign((X_[c] - X_[a]) * (Y_[b] - Y_[a]) - (Y_[c] - Y_[a]) * (X_[b] - X_[a]));
    if (f != 2) return f;
    ++exact_;
    const Rational xa = Xq(a), ya = Yq(a), xb = Xq(b), yb = Yq(b), xc = Xq(c), yc = Yq(c);
    return sgn((xc - xa) * (yb - ya) - (yc - ya) * (xb - xa));
  }

  // The crossing of two lines known to cross (their difference changes sign strictly).
  Abs crossing(const Line* A, const Line* B) const {
    Abs x{(B->c - A->c) / (A->s - B->s), -1, A, B};
    if (!(x.x.e < HUGE_VAL)) x.x = approx(exact(x));
    return x;
  }

  // The exact parameter along the picture segment from sample p to sample q (X_p < X_q).
  Rational parameter(const Abs& x, int p, int q) const {
    if (x.sample == p) return Rational(0);
    if (x.sample == q) return Rational(1);
    Rational xp = Xq(p);
    return Rational((exact(x) - xp) / (Xq(q) - xp));
  }

  Rational Xq(int k) const {
    const std::size_t i = static_cast<std::size_t>(k) % nx_, j = static_cast<std::size_t>(k) / nx_;
    return Rational(sx_ * (c_ * g_.xs[i] - a_ * g_.zs[j]));
  }
  Rational Yq(int k) const {
    const std::size_t j = static_cast<std::size_t>(k) / nx_;
    return Rational(sy_ * (c_ * g_.y(static_cast<std::size_t>(k) % nx_, j) - b_ * g_.zs[j]));
  }

 private:
  void exact_line(const Line& L, Rational& s, Rational& c) const {
    const Rational xp = Xq(L.p), yp = Yq(L.p);
    s = (Yq(L.q) - yp) / (Xq(L.q) - xp);
    c = yp - s * xp;
  }
  Rational exact(const Abs& x) const {
    if (x.sample >= 0) return Xq(x.sample);
    Rational s1, c1, s2, c2;
    exact_line(*x.l1, s1, c1);
    exact_line(*x.l2, s2, c2);
    return Rational((c2 - c1) / (s1 - s2));
  }
  // Evenly spaced xs and zs: X_k − X_l = sx·(c·hx·di − a·hz·dj) has the sign of
  // sx·(k1·di − k2·dj) (di, dj: the differences of the samples' columns and cuts) with k1 = n(c·hx)·d(a·hz), k2 = n(a·hz)·d(c·hx) (positive denominators);
  // with |k1|, |k2| < 2^62 and |di|, |dj| <= 10^5 < 2^17 the products fit 128 bits.
  void uniform_order() {
    const std::size_t nz = g_.zs.size();
    if (nx_ < 2 || nz < 2) return;
    const Rational hx = g_.xs[1] - g_.xs[0], hz = g_.zs[1] - g_.zs[0];
    for (std::size_t i = 2; i < nx_; ++i)
      if (g_.xs[i] - g_.xs[i - 1] != hx) return;
    for (std::size_t j = 2; j < nz; ++j)
      if (g_.zs[j] - g_.zs[j - 1] != hz) return;
    if (nx_ > 100000 || nz > 100000) return;
    const Rational K1 = c_ * hx, K2 = a_ * hz;
    mpz_class k1 = K1.get_num() * K2.get_den(), k2 = K2.get_num() * K1.get_den();
    mpz_class g;
    mpz_gcd(g.get_mpz_t(), k1.get_mpz_t(), k2.get_mpz_t());
    if (g > 1) k1 /= g, k2 /= g;  // only the ratio matters (g > 0)
    const mpz_class lim = mpz_class(1) << 62;
    if (abs(k1) >= lim || abs(k2) >= lim) return;
    const Int128 q1 = static_cast<std::int64_t>(mpz_class(k1).get_si()), q2 = static_cast<std::int64_t>(mpz_class(k2).get_si());
    // The key of sample (i, j): sx·(k1·i − k2·j), below 2^80 in magnitude; keys order as X.
    key_.resize(nx_ * nz);
    for (std::size_t j = 0; j < nz; ++j)
      for (std::size_t i = 0; i < nx_; ++i)
        key_[j * nx_ + i] = sx_ * (q1 * static_cast<Int128>(i) - q2 * static_cast<Int128>(j));
    uniform_ = true;
  }

  const HeightGrid& g_;
  std::size_t nx_;
  int sx_, sy_, sa_ = 0, sc_ = 0;
  Rational a_, b_, c_;
  std::vector<Ad> X_, Y_;
  bool uniform_ = false;
  std::vector<Int128> key_;
  mutable std::atomic<std::uint64_t> exact_{0};
};

}  // namespace hlr::horizon_filtered
