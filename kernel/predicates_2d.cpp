// Exact predicates of the picture plane (course notes section 25). See predicates_2d.hpp.
#include "kernel/predicates_2d.hpp"

namespace hlr {

bool filter_usable(const Rational& q, double d) { return in_filter_range(d) && (d != 0 || sgn(q) == 0); }

bool filter_usable(const Exact2& p, const Double2& d) { return filter_usable(p[0], d[0]) && filter_usable(p[1], d[1]); }

int orient2d(const Exact2& a, const Exact2& b, const Exact2& c, const Double2& da, const Double2& db, const Double2& dc) {
  if (filter_usable(a, da) && filter_usable(b, db) && filter_usable(c, dc))
    if (const int s = orient2d_filter(da, db, dc)) return s;
  return orient2d_exact(a, b, c);
}

int orient2d(const Exact2& a, const Exact2& b, const Exact2& c) {
  // The double filter of docs/design.md ("Orientation of three points") on mpq_get_d's values.
  return orient2d(a, b, c, {a[0].get_d(), a[1].get_d()}, {b[0].get_d(), b[1].get_d()}, {c[0].get_d(), c[1].get_d()});
}

namespace {

// u = q - p and v = d - c as numerators over positive denominators (products of the two
// denominators, no gcd), into the caller's thread-local scratch.
struct Differences {
  mpz_class un[2], ud[2], vn[2], vd[2], l, r, t;
  void set(const Exact2& p, const Exact2& q, const Exact2& c, const Exact2& d) {
    auto diff = [](const Rational& x, const Rational& y, mpz_class& n, mpz_class& den) {  // x - y
      mpz_mul(n.get_mpz_t(), x.get_num_mpz_t(), y.get_den_mpz_t());
      mpz_submul(n.get_mpz_t(), y.get_num_mpz_t(), x.get_den_mpz_t());
      mpz_mul(den.get_mpz_t(), x.get_den_mpz_t(), y.get_den_mpz_t());
    };
    for (int k = 0; k < 2; ++k) {
      diff(q[k], p[k], un[k], ud[k]);
      diff(d[k], c[k], vn[k], vd[k]);
    }
  }
  // l = un[i]·vn[j]·ud[1-i]·vd[1-j] (the term of u_i·v_j over the common denominator).
  void term(mpz_class& out, int i, int j) {
    mpz_mul(out.get_mpz_t(), un[i].get_mpz_t(), vn[j].get_mpz_t());
    mpz_mul(t.get_mpz_t(), ud[1 - i].get_mpz_t(), vd[1 - j].get_mpz_t());
    mpz_mul(out.get_mpz_t(), out.get_mpz_t(), t.get_mpz_t());
  }
};

}  // namespace

// The exact sign without canonical rationals (no gcd): with u = b - a and v = c - a written
// as n/d (d > 0), sign(ux·vy - uy·vx) = sign(ux_n·vy_n·uy_d·vx_d - uy_n·vx_n·ux_d·vy_d).
int orient2d_exact(const Exact2& a, const Exact2& b, const Exact2& c) {
  thread_local Differences w;
  w.set(a, b, a, c);
  const int sl = sgn(w.un[0]) * sgn(w.vn[1]), sr = sgn(w.un[1]) * sgn(w.vn[0]);
  if (sl != sr) return sl > sr ? 1 : -1;  // the products' signs decide (denominators > 0)
  if (sl == 0) return 0;
  w.term(w.l, 0, 1);
  w.term(w.r, 1, 0);
  const int s = cmp(w.l, w.r);
  return s > 0 ? 1 : (s < 0 ? -1 : 0);
}

int dot_sign_exact(const Exact2& p, const Exact2& q, const Exact2& a, const Exact2& b) {
  thread_local Differences w;
  w.set(p, q, a, b);
  w.term(w.l, 0, 0);
  w.term(w.r, 1, 1);
  w.l += w.r;
  return sgn(w.l);
}

}  // namespace hlr
