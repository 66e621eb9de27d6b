// The picture plane in exact numbers (course notes section 20). See picture_plane.hpp.
#include "algorithms/picture/picture_plane.hpp"

#include <algorithm>
#include <cmath>

namespace hlr {
namespace {

Rational dot3(const Rational& x, const Rational& y, const Rational& z, const Vector3& a) {
  return x * a.x() + y * a.y() + z * a.z();
}

}  // namespace

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
  integers(d_, di_, dden_);
  if (!persp_) {
    const Rational k0(dden_), kx = Rational(dden_) / (Rational(rden_) * rr_), ky = Rational(dden_) / (Rational(uden_) * uu_);
    depth_k_ = {k0.get_d(), kx.get_d(), ky.get_d()};
  }
}

// n·r = Nr / rden with Nr = Σ n_k·ri_k an integer, and alike for u and d, so
// s = -(d + x·n·r/|r|² + y·n·u/|u|²) / n·v has c0 = -d·K0 / Nd, cx = -Nr·Kx / Nd,
// cy = -Nu·Ky / Nd (K as in depth_k_). Each double is three inputs within kToDoubleError
// (mpz_get_d truncates) and two roundings of half that: within 4·kToDoubleError + O(u²).
PicturePlane::DepthDoubles PicturePlane::depth_doubles(const Plane& h) const {
  if (persp_) return {};
  for (int k = 0; k < 4; ++k)
    if (h[k].get_den() != 1) return {};
  return depth_doubles(h[0].get_num_mpz_t(), h[1].get_num_mpz_t(), h[2].get_num_mpz_t(), h[3].get_num_mpz_t());
}

PicturePlane::DepthDoubles PicturePlane::depth_doubles(const PlaneInt128& h) const {
  if (persp_) return {};
  thread_local std::array<mpz_class, 4> c;
  thread_local mpz_class k;
  set_mpz(k.get_mpz_t(), h.k);
  for (int i = 0; i < 3; ++i) {
    set_mpz(c[i].get_mpz_t(), h.n[i]);
    c[i] *= k;
  }
  set_mpz(c[3].get_mpz_t(), h.d);
  return depth_doubles(c[0].get_mpz_t(), c[1].get_mpz_t(), c[2].get_mpz_t(), c[3].get_mpz_t());
}

PicturePlane::DepthDoubles PicturePlane::depth_doubles(mpz_srcptr a, mpz_srcptr b, mpz_srcptr c, mpz_srcptr d) const {
  DepthDoubles out;
  out.integers = true;
  thread_local mpz_class nr, nu, nd;
  auto sum = [&](mpz_class& s, const std::array<mpz_class, 3>& axis) {
    mpz_mul(s.get_mpz_t(), a, axis[0].get_mpz_t());
    mpz_addmul(s.get_mpz_t(), b, axis[1].get_mpz_t());
    mpz_addmul(s.get_mpz_t(), c, axis[2].get_mpz_t());
  };
  sum(nd, di_);
  out.facing = sgn(nd);
  if (out.facing == 0) return out;
  sum(nr, ri_);
  sum(nu, ui_);
  // Every input within [2^-200, 2^200] or an exact zero: no product or quotient below leaves
  // the normal doubles, so the relative bound holds.
  const double in[4] = {mpz_get_d(d), nr.get_d(), nu.get_d(), nd.get_d()};
  auto fine = [](double v, bool zero) { return zero ? v == 0 : (std::fabs(v) >= 0x1p-200 && std::fabs(v) <= 0x1p200); };
  out.ok = fine(in[0], mpz_sgn(d) == 0) && fine(in[1], sgn(nr) == 0) && fine(in[2], sgn(nu) == 0) && fine(in[3], false);
  for (double k : depth_k_) out.ok = out.ok && fine(k, false);
  out.c = {-(in[0] * depth_k_[0]) / in[3], -(in[1] * depth_k_[1]) / in[3], -(in[2] * depth_k_[2]) / in[3]};
  return out;
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
  fast_ = in_filter_range(fx_) && in_filter_range(fy_) && fx_ != 0 && fy_ != 0 && in_filter_range(crd_) && in_filter_range(cud_);
}

std::array<double, 2> PictureToDrawing::operator()(const std::array<double, 2>& q) const {
  if (fast_ && in_filter_range(q[0]) && in_filter_range(q[1])) return {(q[0] - crd_) * fx_, (q[1] - cud_) * fy_};
  return (*this)(Exact2{Rational(q[0]), Rational(q[1])});  // the doubles' exact values, the exact route
}

std::array<double, 2> PictureToDrawing::operator()(const Exact2& q) const {
  // Drawing coordinates only (no decision): doubles, within a few ulps of the picture's size,
  // when every value is far from overflow and underflow; otherwise the exact route below.
  if (fast_) {
    const double x = q[0].get_d(), y = q[1].get_d();
    if (in_filter_range(x) && in_filter_range(y)) return {(x - crd_) * fx_, (y - cud_) * fy_};
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
