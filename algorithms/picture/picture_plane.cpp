// The picture plane in exact numbers (course notes section 20). See picture_plane.hpp.
#include "algorithms/picture/picture_plane.hpp"

#include <algorithm>
#include <cmath>

namespace hlr {
namespace {

// Drawing coordinates may be computed in doubles from values in this range (or zero): no
// product of two of them under- or overflows. Decides only the route, never visibility.
bool comfortable(double v) { return v == 0 || (std::fabs(v) > 0x1p-400 && std::fabs(v) < 0x1p400); }

Rational dot3(const Rational& x, const Rational& y, const Rational& z, const Vector3& a) {
  return x * a.x() + y * a.y() + z * a.z();
}

}  // namespace

int orient2d(const Exact2& a, const Exact2& b, const Exact2& c) {
  // The double filter of docs/design.md ("Orientation of three points"): with every non-zero
  // coordinate's double (mpq_get_d, relative error below u = 2^-52) in [2^-400, 2^400], the
  // doubles' determinant is within 64·u·Mx·My of the exact one.
  double v[6];
  const Rational* q[6] = {&a[0], &a[1], &b[0], &b[1], &c[0], &c[1]};
  bool ok = true;
  for (int k = 0; k < 6; ++k) {
    v[k] = q[k]->get_d();
    const double m = std::fabs(v[k]);
    ok = ok && (m == 0 ? sgn(*q[k]) == 0 : (m >= 0x1p-400 && m <= 0x1p400));
  }
  if (ok) {
    const double det = (v[2] - v[0]) * (v[5] - v[1]) - (v[3] - v[1]) * (v[4] - v[0]);
    const double mx = std::max({std::fabs(v[0]), std::fabs(v[2]), std::fabs(v[4])});
    const double my = std::max({std::fabs(v[1]), std::fabs(v[3]), std::fabs(v[5])});
    const double bound = 64 * 0x1p-52 * mx * my;
    if (det > bound) return 1;
    if (det < -bound) return -1;
  }
  return orient2d_exact(a, b, c);
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

PicturePlane::PicturePlane(const Camera& c) : persp_(c.perspective), e_(c.eye) {
  Vector3 v = c.perspective ? Vector3(c.eye - c.target) : c.direction;
  r_ = cross(c.up, v);
  u_ = cross(v, r_);
  d_ = c.perspective ? Vector3(c.target - c.eye) : v;
  rr_ = dot(r_, r_);
  uu_ = dot(u_, u_);
  dd_ = dot(d_, d_);
  auto integers = [](const Vector3& v, std::array<mpz_class, 3>& n, mpz_class& den) {
    den = 1;
    for (int k = 0; k < 3; ++k) mpz_lcm(den.get_mpz_t(), den.get_mpz_t(), v[k].get_den_mpz_t());
    for (int k = 0; k < 3; ++k) n[k] = v[k].get_num() * (den / v[k].get_den());
  };
  integers(r_, ri_, rden_);
  integers(u_, ui_, uden_);
}

Exact2 PicturePlane::project(const Point3& p) const {
  if (!persp_) {
    // p = pn / pden over the least common denominator of its coordinates: x = Σ pn_k·ri_k /
    // (pden·rden), one canonicalisation (the textbook dot product canonicalises five times).
    thread_local std::array<mpz_class, 3> pn;
    thread_local mpz_class pden, t;
    const bool same = p[0].get_den() == p[1].get_den() && p[0].get_den() == p[2].get_den();
    if (same) {
      pden = p[0].get_den();
      for (int k = 0; k < 3; ++k) pn[k] = p[k].get_num();
    } else {
      pden = 1;
      for (int k = 0; k < 3; ++k) mpz_lcm(pden.get_mpz_t(), pden.get_mpz_t(), p[k].get_den_mpz_t());
      for (int k = 0; k < 3; ++k) {
        mpz_divexact(t.get_mpz_t(), pden.get_mpz_t(), p[k].get_den_mpz_t());
        mpz_mul(pn[k].get_mpz_t(), p[k].get_num_mpz_t(), t.get_mpz_t());
      }
    }
    auto axis = [&](const std::array<mpz_class, 3>& a, const mpz_class& aden) {
      Rational q;
      mpz_ptr n = q.get_num_mpz_t();
      mpz_mul(n, pn[0].get_mpz_t(), a[0].get_mpz_t());
      mpz_addmul(n, pn[1].get_mpz_t(), a[1].get_mpz_t());
      mpz_addmul(n, pn[2].get_mpz_t(), a[2].get_mpz_t());
      mpz_mul(q.get_den_mpz_t(), pden.get_mpz_t(), aden.get_mpz_t());
      q.canonicalize();
      return q;
    };
    return {axis(ri_, rden_), axis(ui_, uden_)};
  }
  Rational qx = p.x() - e_.x(), qy = p.y() - e_.y(), qz = p.z() - e_.z();
  Rational w = dot3(qx, qy, qz, d_);
  return {dot3(qx, qy, qz, r_) / w, dot3(qx, qy, qz, u_) / w};
}

// Orthographic: base(q) = x·r/|r|² + y·u/|u|² projects to q (r, u, v are orthogonal) and the
// ray is base(q) + s·v. Perspective: dir(q) = x·|d|²/|r|²·r + y·|d|²/|u|²·u + d has
// dir·r / dir·d = x and dir·u / dir·d = y, and the ray is E + l·dir(q).
std::array<PictureLinear, 2> PicturePlane::ray_parameter(const Plane& h) const {
  const Vector3 n = h.normal();
  Rational nr = dot(n, r_), nu = dot(n, u_), nd = dot(n, d_);
  if (!persp_) {
    // n·(base + s v) + d = 0: s = -(d + x n·r/|r|² + y n·u/|u|²) / n·v.
    return {PictureLinear{-h.d(), -nr / rr_, -nu / uu_}, PictureLinear{nd, 0, 0}};
  }
  // n·(E + l dir) + d = 0: l = -(n·E + d) / n·dir(q).
  Rational ne = h.value(e_);
  return {PictureLinear{-ne, 0, 0}, PictureLinear{nd, nr * dd_ / rr_, nu * dd_ / uu_}};
}

Point3 PicturePlane::lift(const Exact2& q, const std::array<PictureLinear, 2>& ray) const {
  const auto& [num, den] = ray;
  Rational s = num.at(q) / den.at(q);
  if (!persp_) {
    Rational a = q[0] / rr_, b = q[1] / uu_;
    return Point3(a * r_.x() + b * u_.x() + s * d_.x(), a * r_.y() + b * u_.y() + s * d_.y(),
                  a * r_.z() + b * u_.z() + s * d_.z());
  }
  Rational a = q[0] * dd_ / rr_, b = q[1] * dd_ / uu_;
  return Point3(e_.x() + s * (a * r_.x() + b * u_.x() + d_.x()), e_.y() + s * (a * r_.y() + b * u_.y() + d_.y()),
                e_.z() + s * (a * r_.z() + b * u_.z() + d_.z()));
}

PictureToDrawing::PictureToDrawing(const PicturePlane& pp, const DrawingFrame& frame)
    : persp_(pp.perspective()), scale_(frame.identity ? Rational(1) : frame.scale) {
  rr_ = dot(pp.r(), pp.r());
  uu_ = dot(pp.u(), pp.u());
  dd_ = dot(pp.d(), pp.d());
  if (!persp_ && !frame.identity) {
    const Point3& c = frame.centre;
    cr_ = c.x() * pp.r().x() + c.y() * pp.r().y() + c.z() * pp.r().z();
    cu_ = c.x() * pp.u().x() + c.y() * pp.u().y() + c.z() * pp.u().z();
  }
  // The scale factors in doubles: s / |r| and s / |u| (perspective: |d| / |r|, |d| / |u|).
  const double rr = to_double(rr_), uu = to_double(uu_), dd = to_double(dd_), sc = to_double(scale_);
  fx_ = persp_ ? std::sqrt(dd / rr) : sc / std::sqrt(rr);
  fy_ = persp_ ? std::sqrt(dd / uu) : sc / std::sqrt(uu);
  crd_ = to_double(cr_), cud_ = to_double(cu_);
  fast_ = comfortable(fx_) && comfortable(fy_) && fx_ != 0 && fy_ != 0 && comfortable(crd_) && comfortable(cud_);
}

std::array<double, 2> PictureToDrawing::operator()(const std::array<double, 2>& q) const {
  if (fast_ && comfortable(q[0]) && comfortable(q[1])) return {(q[0] - crd_) * fx_, (q[1] - cud_) * fy_};
  return (*this)(Exact2{Rational(q[0]), Rational(q[1])});  // the doubles' exact values, the exact route
}

std::array<double, 2> PictureToDrawing::operator()(const Exact2& q) const {
  // Drawing coordinates only (no decision): doubles, within a few ulps of the picture's size,
  // when every value is far from overflow and underflow; otherwise the exact route below.
  if (fast_) {
    const double x = q[0].get_d(), y = q[1].get_d();
    if (comfortable(x) && comfortable(y)) return {(x - crd_) * fx_, (y - cud_) * fy_};
  }
  // sign(v)·sqrt(v² / w) keeps any exact magnitude away from double overflow until the end.
  auto scaled = [](const Rational& v, const Rational& w) {
    double m = std::sqrt(to_double(v * v / w));
    return sgn(v) < 0 ? -m : m;
  };
  if (persp_) return {scaled(q[0], rr_ / dd_), scaled(q[1], uu_ / dd_)};
  return {scaled((q[0] - cr_) * scale_, rr_), scaled((q[1] - cu_) * scale_, uu_)};
}

}  // namespace hlr
