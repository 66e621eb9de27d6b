// Exact 3D Cyrus-Beck clipping, course notes section 22 (see cyrus_beck.hpp).
#include "algorithms/clip/cyrus_beck.hpp"
#include "kernel/exact_int.hpp"

#include <optional>
#include <stdexcept>

#include "algorithms/solids/convexity.hpp"

namespace hlr {

ConvexClipper make_clipper(Polyhedron body, std::string name) {
  const MeshReport& r = body.report();
  if (!r.valid_solid())
    throw std::invalid_argument("the clipper '" + name +
                                "' is not a closed, manifold, oriented solid with planar non-degenerate faces");
  ConvexityResult cv = convexity(body);
  if (!cv.convex()) throw std::invalid_argument("the clipper '" + name + "' is " + describe(cv) + "; Cyrus-Beck needs a convex clipper");
  BodyMatrix bm = body_matrix(body);
  std::vector<std::array<Int128, 4>> ints;
  const Int128 limit = bounds::kWideCoordinateLimit;
  for (int j = 0; j < bm.V.cols(); ++j) {
    std::array<Int128, 4> h;
    for (int k = 0; k < 4; ++k) {
      const Rational& q = bm.V(k, j);
      if (q.get_den() != 1 || !q.get_num().fits_slong_p() || abs128(q.get_num().get_si()) >= limit) {
        ints.clear();
        j = static_cast<int>(bm.V.cols());
        break;
      }
      h[k] = q.get_num().get_si();
    }
    if (j < bm.V.cols()) ints.push_back(h);
  }
  return ConvexClipper{std::move(name), std::move(body), std::move(bm), std::move(ints)};
}

ConvexClipper box_clipper(const Rational& xmin, const Rational& xmax, const Rational& ymin, const Rational& ymax,
                          const Rational& zmin, const Rational& zmax) {
  if (!(xmin < xmax && ymin < ymax && zmin < zmax))
    throw std::invalid_argument("box clipper: need XMIN < XMAX, YMIN < YMAX, ZMIN < ZMAX");
  return make_clipper(make_box(Point3(xmin, ymin, zmin), Point3(xmax, ymax, zmax)), "box");
}

ConvexClipper frustum_clipper(const Rational& xl, const Rational& xr, const Rational& yb, const Rational& yt,
                              const Rational& znear, const Rational& zfar, const Rational& zcp) {
  if (!(xl < xr && yb < yt)) throw std::invalid_argument("frustum clipper: need XL < XR and YB < YT");
  if (!(zcp > znear && znear > zfar)) throw std::invalid_argument("frustum clipper: need ZCP > ZNEAR > ZFAR (viewer on +z)");
  // Side planes pass through (0, 0, zcp); the window is at the far plane; at the near plane it
  // shrinks by s = (znear - zcp) / (zfar - zcp).
  Rational s = (znear - zcp) / (zfar - zcp);
  std::vector<Point3> vs = {Point3(xl, yb, zfar), Point3(xr, yb, zfar), Point3(xr, yt, zfar), Point3(xl, yt, zfar),
                            Point3(xl * s, yb * s, znear), Point3(xr * s, yb * s, znear), Point3(xr * s, yt * s, znear),
                            Point3(xl * s, yt * s, znear)};
  // Faces in the notes' order: left, right, bottom, top, near, far; counter-clockwise from outside.
  std::vector<Face> faces = {{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}, {4, 5, 6, 7}, {0, 3, 2, 1}};
  return make_clipper(Polyhedron(std::move(vs), std::move(faces)), "frustum");
}

namespace {

// The table-free clip in 128-bit integers: the segment scaled by the common denominator L of
// its ends, W·n·L and D·n·L integers below 2^83, limits compared by 256-bit products.
std::optional<CyrusBeckResult> cyrus_beck_int128(const ConvexClipper& c, const Point3& p1, const Point3& p2) {
  if (c.int_planes.empty()) return std::nullopt;
  const Int128 limit = bounds::kWideCoordinateLimit;
  const Rational* qs[6] = {&p1.x(), &p1.y(), &p1.z(), &p2.x(), &p2.y(), &p2.z()};
  std::uint64_t L;
  if (!common_denominator(qs, 6, static_cast<std::uint64_t>(limit), L)) return std::nullopt;
  Int128 A[3], B[3];
  for (int k = 0; k < 3; ++k) {
    Int128 b;
    if (!scaled_integer(p1[k], L, limit, A[k]) || !scaled_integer(p2[k], L, limit, b)) return std::nullopt;
    B[k] = b - A[k];
  }
  CyrusBeckResult r;
  r.degenerate_point = B[0] == 0 && B[1] == 0 && B[2] == 0;
  // Limits as fractions n/d with d > 0; lower starts at 0/1, upper at 1/1.
  Int128 ln = 0, ld = 1, un = 1, ud = 1;
  bool outside = false, on_boundary = false;
  for (const auto& h : c.int_planes) {
    Int128 wn = h[0] * A[0] + h[1] * A[1] + h[2] * A[2] + h[3] * static_cast<Int128>(L);
    Int128 dn = h[0] * B[0] + h[1] * B[1] + h[2] * B[2];
    if (dn == 0) {
      if (wn < 0) outside = true;
      if (wn == 0) on_boundary = true;
    } else if (dn > 0) {  // t >= -wn/dn
      if (compare_products(-wn, ld, ln, dn) > 0) ln = -wn, ld = dn;
    } else {  // t <= wn/(-dn)
      if (compare_products(wn, ud, un, -dn) < 0) un = wn, ud = -dn;
    }
  }
  auto frac = [](Int128 n, Int128 d) {
    Rational q(to_mpz(n), to_mpz(d));
    q.canonicalize();
    return q;
  };
  r.t_lower = frac(ln, ld);
  r.t_upper = frac(un, ud);
  if (r.degenerate_point)
    r.point_class = outside ? CyrusBeckResult::PointClass::Outside
                            : on_boundary ? CyrusBeckResult::PointClass::OnBoundary : CyrusBeckResult::PointClass::Inside;
  int order = compare_products(ln, ud, un, ld);
  if (outside || order > 0)
    r.status = CyrusBeckResult::Status::Outside;
  else if (order == 0 || r.degenerate_point)
    r.status = CyrusBeckResult::Status::Point;
  else
    r.status = CyrusBeckResult::Status::Visible;
  return r;
}

}  // namespace

CyrusBeckResult cyrus_beck(const ConvexClipper& c, const Point3& p1, const Point3& p2, bool table) {
  if (!table)
    if (auto fast = cyrus_beck_int128(c, p1, p2)) return *fast;
  CyrusBeckResult r;
  const BodyMatrixData& V = c.planes.V;
  Vector3 d = p2 - p1;
  r.degenerate_point = d.is_zero();
  Rational tl = 0, tu = 1;
  bool outside = false, on_boundary = false;
  for (int j = 0; j < V.cols(); ++j) {
    CyrusBeckRow row;
    row.face = j;
    row.n = Vector3(V(0, j), V(1, j), V(2, j));
    // W·n = n·P1 + d_j: the face's test function at P1 (W = P1 - f for any f on the face).
    row.wn = dot(row.n, Vector3(p1.x(), p1.y(), p1.z())) + V(3, j);
    row.dn = dot(row.n, d);
    if (row.dn == 0) {
      row.kind = row.wn < 0 ? CyrusBeckRow::Kind::ParallelOutside : CyrusBeckRow::Kind::ParallelInside;
      if (row.wn < 0) outside = true;
      if (row.wn == 0) on_boundary = true;
    } else {
      Rational t = -row.wn / row.dn;
      row.t = t;
      if (row.dn > 0) {
        row.kind = CyrusBeckRow::Kind::Lower;
        if (t > tl) tl = t;
      } else {
        row.kind = CyrusBeckRow::Kind::Upper;
        if (t < tu) tu = t;
      }
    }
    r.table.push_back(row);
  }
  if (r.degenerate_point)
    r.point_class = outside ? CyrusBeckResult::PointClass::Outside
                            : on_boundary ? CyrusBeckResult::PointClass::OnBoundary : CyrusBeckResult::PointClass::Inside;
  r.t_lower = tl;
  r.t_upper = tu;
  if (outside || tl > tu)
    r.status = CyrusBeckResult::Status::Outside;
  else if (tl == tu || r.degenerate_point)
    r.status = CyrusBeckResult::Status::Point;
  else
    r.status = CyrusBeckResult::Status::Visible;
  return r;
}

namespace {

// Keeps the pieces' kinds inside [a, b] (a < b) and marks the rest clipped.
void keep_only(Segment& s, const std::optional<std::pair<Rational, Rational>>& keep) {
  std::vector<Piece> out;
  auto push = [&](Piece p) {
    if (!(p.t0 < p.t1)) return;
    if (!out.empty() && out.back().same_kind(p))
      out.back().t1 = p.t1;
    else
      out.push_back(p);
  };
  for (const Piece& p : s.pieces) {
    Piece clipped = p;
    clipped.visible = false;
    clipped.clipped = true;
    if (!keep) {
      push(clipped);
      continue;
    }
    const Rational& a = keep->first;
    const Rational& b = keep->second;
    Piece before = clipped, inside = p, after = clipped;
    before.t1 = std::min(p.t1, a);
    inside.t0 = std::max(p.t0, a);
    inside.t1 = std::min(p.t1, b);
    after.t0 = std::max(p.t0, b);
    push(before);
    push(inside);
    push(after);
  }
  s.pieces = std::move(out);
}

}  // namespace

void clip_pieces(Segment& s, const ConvexClipper& c) {
  CyrusBeckResult r = cyrus_beck(c, s.from(), s.to(), false);
  if (r.visible())
    keep_only(s, std::make_pair(r.t_lower, r.t_upper));
  else
    keep_only(s, std::nullopt);  // outside, or a single point: drawn as nothing
}

Plane near_plane(const Camera& cam, const Rational& k) {
  // (P - E)·f - k·f·f >= 0 with f = target - eye.
  const Vector3 f = cam.target - cam.eye;
  return Plane(f.x(), f.y(), f.z(), -dot(f, cam.eye - Point3()) - k * dot(f, f));
}

void clip_near(Segment& s, const Plane& near) {
  const Sign s0 = side_of_plane(near, s.from()), s1 = side_of_plane(near, s.to());
  if (s0 != Sign::Negative && s1 != Sign::Negative) return;
  if (s0 == Sign::Negative && s1 == Sign::Negative) return keep_only(s, std::nullopt);
  const Rational d0 = near.value(s.from()), d1 = near.value(s.to());
  Rational t = d0 / (d0 - d1);
  if (d0 < 0)
    keep_only(s, std::make_pair(t, Rational(1)));
  else
    keep_only(s, std::make_pair(Rational(0), t));
}

void clip_near(Segment& s, const Camera& cam, const Rational& k) {
  if (!cam.perspective) return;
  clip_near(s, near_plane(cam, k));
}

}  // namespace hlr
