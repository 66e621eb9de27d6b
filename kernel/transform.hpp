// 4x4 homogeneous transforms over exact rationals, in the course notes' row-vector convention
// (course notes section 20): a point transforms as [x y z 1]·M. Translation, scaling about a
// centre, rotation about OX/OY/OZ about a centre, reflection, one/two/three-point perspective
// (-1/C in the last column), composition and exact inverse.
#pragma once

#include <optional>
#include <string>

#include "kernel/geometry.hpp"
#include "kernel/matrix.hpp"
#include "kernel/rotation.hpp"

namespace hlr {


enum class Axis { X = 0, Y = 1, Z = 2 };

/// Parses "x", "y" or "z" (any case); nullopt otherwise.
std::optional<Axis> parse_axis(const std::string& s);

/// The identity.
Matrix4 identity_transform();
/// Translation by (dx, dy, dz): last row [dx dy dz 1].
Matrix4 translation(const Vector3& d);
/// Scaling by (kx, ky, kz) about `centre`: x' = x·kx + (1-kx)·xm, and so on. A zero factor
/// is allowed here (a projection) but makes the matrix singular.
Matrix4 scaling(const Vector3& k, const Point3& centre = Point3());
/// Rotation about the axis through `centre` parallel to OX/OY/OZ by an exact rotation
/// (cos, sin), with the notes' sign convention: about OZ, x' = x·cos - y·sin, y' = x·sin + y·cos.
Matrix4 rotation(Axis axis, const Rotation& r, const Point3& centre = Point3());
/// Reflection in the coordinate plane perpendicular to `axis` through `centre` (scaling by -1).
Matrix4 reflection(Axis axis, const Point3& centre = Point3());
/// Perspective with centres of projection at distance C on the axes (a zero entry means
/// none): the last column gets -1/Cx, -1/Cy, -1/Cz. One entry: one-point perspective onto the
/// projection plane through the origin; two and three: two- and three-point perspective.
/// Throws std::invalid_argument when all three are zero.
Matrix4 perspective(const Rational& cx, const Rational& cy, const Rational& cz);

/// "First a, then b" in row-vector convention: a·b.
Matrix4 compose(const Matrix4& a, const Matrix4& b);

/// Exact inverse by Gauss-Jordan elimination over rationals; nullopt when singular.
std::optional<Matrix4> inverse(const Matrix4& m);

/// [x y z 1]·M divided by the homogeneous w. Throws std::domain_error when w is zero (the
/// point goes to infinity).
Point3 apply(const Matrix4& m, const Point3& p);

/// Direction vectors transform without translation: [x y z 0]·M (affine M only).
Vector3 apply_to_direction(const Matrix4& m, const Vector3& v);

/// Whether the last column is [0 0 0 1]^T (no perspective).
bool is_affine(const Matrix4& m);

/// Rows of exact lowest-terms entries, one row per line, columns aligned.
std::string to_string(const Matrix4& m);

}  // namespace hlr
