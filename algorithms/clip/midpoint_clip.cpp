// Midpoint subdivision clipping, course notes section 21 (see midpoint_clip.hpp).
#include "algorithms/clip/midpoint_clip.hpp"

#include <optional>
#include <stdexcept>

namespace hlr {
namespace {

Rational dist2(const Point3& a, const Point3& b) {
  Vector3 d = a - b;
  return dot(d, d);
}

Point3 midpoint(const Point3& a, const Point3& b) {
  return Point3((a.x() + b.x()) / 2, (a.y() + b.y()) / 2, (a.z() + b.z()) / 2);
}

// The notes' coefficients, computed once per clip.
struct Coefficients {
  Rational a1, a2, b1, b2, g1, g2, d1, d2;
  explicit Coefficients(const FrustumWindow& f)
      : a1(f.alpha1()), a2(f.alpha2()), b1(f.beta1()), b2(f.beta2()), g1(f.gamma1()), g2(f.gamma2()), d1(f.delta1()),
        d2(f.delta2()) {}
};

unsigned frustum_code(const FrustumWindow& f, const Coefficients& k, const Point3& p) {
  unsigned c = 0;
  if (p.x() - p.z() * k.b1 - k.b2 < 0) c |= kLeft;
  if (p.x() - p.z() * k.a1 - k.a2 > 0) c |= kRight;
  if (p.y() - p.z() * k.d1 - k.d2 < 0) c |= kBelow;
  if (p.y() - p.z() * k.g1 - k.g2 > 0) c |= kAbove;
  if (p.z() - f.znear > 0) c |= kNear;
  if (p.z() - f.zfar < 0) c |= kFar;
  return c;
}

unsigned box_code(const BoxWindow& b, const Point3& p);

struct Search {
  const Window& w;
  Rational eps2;
  long subdivisions = 0;
  std::optional<Coefficients> k;
  std::vector<MidpointStep>* trace = nullptr;

  Search(const Window& win, Rational e2) : w(win), eps2(std::move(e2)) {
    if (const auto* f = std::get_if<FrustumWindow>(&w)) k.emplace(*f);
  }
  unsigned code(const Point3& p) const {
    if (k) return frustum_code(std::get<FrustumWindow>(w), *k, p);
    return box_code(std::get<BoxWindow>(w), p);
  }

  // An inside point of [a, b] found by recursive subdivision, if the visible part is long
  // enough to be met (see the bound in the header).
  std::optional<Point3> find_inside(const Point3& a, unsigned ca, const Point3& b, unsigned cb) {
    if (ca & cb) return std::nullopt;  // trivially invisible
    if (dist2(a, b) <= eps2) return std::nullopt;
    Point3 m = midpoint(a, b);
    ++subdivisions;
    unsigned cm = code(m);
    if (trace) trace->push_back({"search", m, cm});
    if (cm == 0) return m;
    if (auto left = find_inside(a, ca, m, cm)) return left;
    return find_inside(m, cm, b, cb);
  }

  // From an inside point toward an outside one: the last inside point within eps of the
  // boundary crossing (a convex clipper is crossed once between them).
  Point3 bisect(Point3 in, Point3 out, const char* phase) {
    while (dist2(in, out) > eps2) {
      Point3 m = midpoint(in, out);
      ++subdivisions;
      unsigned cm = code(m);
      if (trace) trace->push_back({phase, m, cm});
      if (cm == 0)
        in = m;
      else
        out = m;
    }
    return in;
  }
};

unsigned box_code(const BoxWindow& b, const Point3& p) {
  unsigned c = 0;
  if (p.x() < b.xl) c |= kLeft;
  if (p.x() > b.xr) c |= kRight;
  if (p.y() < b.yb) c |= kBelow;
  if (p.y() > b.yt) c |= kAbove;
  if (p.z() > b.znear) c |= kNear;
  if (p.z() < b.zfar) c |= kFar;
  return c;
}


}  // namespace

unsigned outcode(const Window& w, const Point3& p) { return Search(w, Rational(0)).code(p); }

unsigned notes_outcode(const Window& w, const Point3& p) {
  unsigned c = outcode(w, p);
  if (const auto* f = std::get_if<FrustumWindow>(&w))
    if (p.z() > f->zcp) c ^= (kLeft | kRight | kBelow | kAbove);
  return c;
}

std::string outcode_bits(unsigned code) {
  std::string s;
  for (unsigned bit : {kLeft, kRight, kBelow, kAbove, kNear, kFar}) s += (code & bit) ? '1' : '0';
  return s;
}

MidpointResult midpoint_clip(const Window& w, const Point3& p1, const Point3& p2, const Rational& eps,
                             std::vector<MidpointStep>* trace) {
  if (!(eps > 0)) throw std::invalid_argument("midpoint clipping needs a tolerance eps > 0");
  MidpointResult r;
  Search s(w, eps * eps);
  s.trace = trace;
  r.code1 = s.code(p1);
  r.code2 = s.code(p2);
  if (r.code1 == 0 && r.code2 == 0) {
    r.visible = r.trivially_accepted = true;
    r.from = p1;
    r.to = p2;
    return r;
  }
  if (r.code1 & r.code2) {
    r.trivially_rejected = true;
    return r;
  }
  std::optional<Point3> inside;
  if (r.code1 == 0)
    inside = p1;
  else if (r.code2 == 0)
    inside = p2;
  else
    inside = s.find_inside(p1, r.code1, p2, r.code2);
  if (inside) {
    r.visible = true;
    r.from = r.code1 == 0 ? p1 : s.bisect(*inside, p1, "end 1");
    r.to = r.code2 == 0 ? p2 : s.bisect(*inside, p2, "end 2");
  }
  r.subdivisions = s.subdivisions;
  return r;
}

}  // namespace hlr
