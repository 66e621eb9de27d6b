// Face planes in 128-bit integers (docs/design.md, "Number paths"): the primitive plane of a
// polygon whose coordinates share a small common denominator, made without rationals. It is
// the fast path of primitive_plane_of_polygon (geometry.hpp), and callers that need only a
// plane's signs or doubles (the shading, the visible surfaces' probes) use it alone, so that a
// large mesh need not keep an exact plane per face.
#pragma once

#include <array>
#include <cstddef>

#include "kernel/geometry.hpp"
#include "kernel/int128.hpp"

namespace hlr {

class Polyhedron;

/// A primitive plane (k·n, d) in parts: n primitive (gcd 1), k > 0, gcd(k·n, d) = 1. n = 0:
/// a degenerate (zero-area) polygon.
struct PlaneInt128 {
  std::array<Int128, 3> n{0, 0, 0};
  Int128 k = 1, d = 0;
  bool degenerate() const { return n[0] == 0 && n[1] == 0 && n[2] == 0; }
};

/// The plane primitive_plane_of_polygon makes, when the 128-bit path's bounds hold
/// (coordinates below 2^40 after scaling by their common denominator); false otherwise.
bool plane_int128(const Point3* const* v, std::size_t count, PlaneInt128& out);
/// The same for face f of p.
bool face_plane_int128(const Polyhedron& p, std::size_t f, PlaneInt128& out);
/// The exact plane.
Plane to_plane(const PlaneInt128& h);
/// Plane::approx of the normal's three coefficients, the same doubles to_plane(h) would hold.
std::array<Bounds, 3> normal_bounds(const PlaneInt128& h);

}  // namespace hlr
