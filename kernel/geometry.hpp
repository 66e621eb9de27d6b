// Exact points, vectors and planes, each carrying a certified double interval beside its exact
// value so that predicates (kernel/predicates.hpp) run at double speed when the interval filter
// decides, and fall back to exact rationals only when it cannot. Constructions here are exact.
// Design and measurements: docs/design.md ("Kernel choice").
#pragma once

#include <array>
#include <iosfwd>
#include <string>

#include "kernel/error_bounds.hpp"
#include "kernel/number.hpp"

namespace hlr {

/// Closed interval [lo, hi] of doubles that certainly contains an exact value (the one
/// interval type, kernel/error_bounds.hpp).
using Bounds = Interval;

/// Certified interval around a rational (tight: the two neighbouring doubles at worst).
Bounds bounds_of(const Rational& q);

/// An exact 3D vector (x, y, z) with certified bounds.
class Vector3 {
 public:
  Vector3() : Vector3(Rational(0), Rational(0), Rational(0)) {}
  Vector3(Rational x, Rational y, Rational z);
  // Moves are noexcept so that vectors move their elements when they grow (mpq_class's move
  // is not declared noexcept, which made every reallocation copy three GMP numbers per
  // element). It cannot throw: GMP aborts rather than throw when memory runs out.
  Vector3(const Vector3&) = default;
  Vector3& operator=(const Vector3&) = default;
  Vector3(Vector3&&) noexcept = default;
  Vector3& operator=(Vector3&&) noexcept = default;
  const Rational& x() const { return c_[0]; }
  const Rational& y() const { return c_[1]; }
  const Rational& z() const { return c_[2]; }
  const Rational& operator[](int i) const { return c_[i]; }
  const Bounds& approx(int i) const { return b_[i]; }
  bool is_zero() const { return c_[0] == 0 && c_[1] == 0 && c_[2] == 0; }
  friend bool operator==(const Vector3& a, const Vector3& b) { return a.c_ == b.c_; }

 private:
  std::array<Rational, 3> c_;
  std::array<Bounds, 3> b_;
};

/// An exact 3D point. Same representation as Vector3, a different meaning.
class Point3 {
 public:
  Point3() {}  // the origin: zeros, whose bounds are {0, 0} (no temporaries: readers resize to millions)
  Point3(Rational x, Rational y, Rational z);
  // Moves are noexcept so that vectors move their elements when they grow (mpq_class's move
  // is not declared noexcept, which made every reallocation copy three GMP numbers per
  // element). It cannot throw: GMP aborts rather than throw when memory runs out.
  Point3(const Point3&) = default;
  Point3& operator=(const Point3&) = default;
  Point3(Point3&&) noexcept = default;
  Point3& operator=(Point3&&) noexcept = default;
  const Rational& x() const { return c_[0]; }
  const Rational& y() const { return c_[1]; }
  const Rational& z() const { return c_[2]; }
  const Rational& operator[](int i) const { return c_[i]; }
  const Bounds& approx(int i) const { return b_[i]; }
  /// Sets the coordinates in place: f(x, y, z) writes them into the point's own numbers, then
  /// the bounds are made. A reader filling millions of points then allocates one limb per
  /// number instead of building and moving temporaries (a moved-from GMP rational allocates).
  template <class F>
  void fill(F&& f) {
    f(c_[0], c_[1], c_[2]);
    for (int i = 0; i < 3; ++i) b_[i] = bounds_of(c_[i]);
  }
  friend bool operator==(const Point3& a, const Point3& b) { return a.c_ == b.c_; }
  /// Lexicographic exact order (x, then y, then z).
  friend bool operator<(const Point3& a, const Point3& b) { return a.c_ < b.c_; }

 private:
  std::array<Rational, 3> c_;
  std::array<Bounds, 3> b_;
};

/// Plane a·x + b·y + c·z + d = 0 with exact coefficients; value(p) is the course notes' test
/// function [x y z 1]·[a b c d]^T.
class Plane {
 public:
  Plane() : Plane(Rational(0), Rational(0), Rational(0), Rational(0)) {}
  Plane(Rational a, Rational b, Rational c, Rational d);
  // Moves are noexcept so that vectors move their elements when they grow (mpq_class's move
  // is not declared noexcept, which made every reallocation copy three GMP numbers per
  // element). It cannot throw: GMP aborts rather than throw when memory runs out.
  Plane(const Plane&) = default;
  Plane& operator=(const Plane&) = default;
  Plane(Plane&&) noexcept = default;
  Plane& operator=(Plane&&) noexcept = default;
  const Rational& a() const { return k_[0]; }
  const Rational& b() const { return k_[1]; }
  const Rational& c() const { return k_[2]; }
  const Rational& d() const { return k_[3]; }
  const Rational& operator[](int i) const { return k_[i]; }
  const Bounds& approx(int i) const { return b_[i]; }
  Vector3 normal() const { return Vector3(k_[0], k_[1], k_[2]); }
  /// Exact value of the test function at p.
  Rational value(const Point3& p) const;
  Plane opposite() const { return Plane(-k_[0], -k_[1], -k_[2], -k_[3]); }
  bool is_degenerate() const { return k_[0] == 0 && k_[1] == 0 && k_[2] == 0; }
  friend bool operator==(const Plane& a, const Plane& b) { return a.k_ == b.k_; }

 private:
  std::array<Rational, 4> k_;
  std::array<Bounds, 4> b_;
};

// ---- constructions (exact) ----
Vector3 operator-(const Point3& p, const Point3& q);
Point3 operator+(const Point3& p, const Vector3& v);
Vector3 operator+(const Vector3& u, const Vector3& v);
Vector3 operator*(const Rational& k, const Vector3& v);
Vector3 cross(const Vector3& u, const Vector3& v);
Rational dot(const Vector3& u, const Vector3& v);

/// Newell's normal of a polygon: sum over its edges of v_i x v_{i+1}. Exact; for a planar
/// polygon it is twice the area vector, oriented by the vertex order (counter-clockwise seen
/// from the side it points to). Zero for zero-area polygons.
Vector3 newell_normal(const Point3* const* vertices, std::size_t n);

/// Plane through a polygon: Newell normal and d = -n·v0. Degenerate (zero normal) for
/// zero-area polygons. Does not check planarity (see predicates).
Plane plane_of_polygon(const Point3* const* vertices, std::size_t n);

/// A polygon whose Newell normal is zero: its vertices all on one line (`Collinear`, truly
/// degenerate), all in one plane but not on a line (`Crossing`: the edges cross so the signed
/// areas cancel, like a symmetric bow-tie), or not in one plane (`NonPlanar`). Exact.
enum class ZeroAreaKind { Collinear, Crossing, NonPlanar };
ZeroAreaKind zero_area_kind(const Point3* const* vertices, std::size_t n);

/// The same oriented plane scaled to integer coefficients with no common factor
/// (x + 1 = 0 rather than 8x + 8 = 0), the form the course notes write body matrices in.
/// A degenerate plane is returned unchanged.
Plane primitive_plane(const Plane& h);

/// primitive_plane(plane_of_polygon(...)) computed in 128-bit integers when the polygon's
/// coordinates share a small common denominator (decimal input does), else in rationals.
/// Same exact result either way.
Plane primitive_plane_of_polygon(const Point3* const* vertices, std::size_t n);

/// Average of points (exact), e.g. the course notes' interior point of a convex body.
Point3 centroid_of_vertices(const Point3* const* points, std::size_t n);

/// "(x, y, z)" with exact lowest-terms coordinates.
std::string to_string(const Point3& p);
std::string to_string(const Vector3& v);
std::string to_string(const Plane& h);  // "[a b c d]"
std::ostream& operator<<(std::ostream& os, const Point3& p);
std::ostream& operator<<(std::ostream& os, const Vector3& v);
std::ostream& operator<<(std::ostream& os, const Plane& h);

}  // namespace hlr
