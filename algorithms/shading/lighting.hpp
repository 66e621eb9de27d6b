// Flat shading of faces (course notes sections 36 and 39): the illumination
// model I = ka·Ia·C + sum over lights of f_rad·f_ang·Il·(kd·C·cos(theta) + ks·spec), with
// directional lights (at infinity), point lights with the radial attenuation
// 1 / (a0 + a1·d + a2·d²) and spot lights that also attenuate by the angle from their axis
// (cos^a of it, nothing outside the cone), spec = cos^n of the angle between the reflected ray
// and the viewer (Phong) or between the normal and the half vector (Blinn). Doubles: shading
// comes after every visibility decision and decides nothing (docs/design.md).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "kernel/number.hpp"

namespace hlr {

using Rgb = std::array<double, 3>;  // 0..1 per channel
using Vec3d = std::array<double, 3>;

/// An image texture (notes 42: the pattern in texture space (u, w), mapped onto a face by its
/// corners' coordinates): 8-bit RGB rows from the top; (u, v) = (0, 0) is the bottom-left
/// corner, repeating outside [0, 1].
struct TextureImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  /// The colour at (u, v), bilinear between the texel centres.
  Rgb at(double u, double v) const;
};

struct Material {
  Rgb colour{0.78, 0.80, 0.84};
  double ka = 0.3, kd = 0.7, ks = 0.15, shininess = 20;
  /// Transparency (course notes section 41): the fraction of the light from
  /// behind that passes, 0 opaque (the default) to 1 clear. Linear: I = (1 − τ)·I1 + τ·I2
  /// (the notes' t is 1 − τ); Kay: τ = τmin + (τ − τmin)·(1 − (1 − |n_z|)^p) with n_z the
  /// normal's component toward the viewer; path length: opacity 1 − (1 − a)^(1/|cos φ|) with
  /// a = 1 − τ the opacity at normal incidence and φ the angle between normal and view.
  enum class TransparencyModel { Linear, Kay, PathLength };
  double transparency = 0, transparency_min = 0, transparency_power = 2;
  TransparencyModel transparency_model = TransparencyModel::Linear;
  /// Ray tracing (course notes 43-45, `hlr raster --bounces`): the fraction of light mirrored
  /// (k_r), and the refractive index for the light that passes (the transparency, k_t), exact
  /// as the scene gave it (total internal reflection at the first surface is decided with it).
  double reflection = 0;
  double ior = 1.5;
  Rational ior_exact = Rational(3, 2);
  /// A solid checker texture (notes 42: a procedural texture): cells of this size alternate
  /// between the colour and colour2 by the parity of floor(x/s) + floor(y/s) + floor(z/s).
  double checker = 0;
  Rgb colour2{0.1, 0.1, 0.1};
  /// Blinn's bump map (notes 42): the perturbation P(u, w) = bump·sin(2πu/s)·sin(2πw/s) along
  /// the normal over the face's own coordinates (s = bump_size); 0: none.
  double bump = 0, bump_size = 1;
  /// An image texture (a body whose mesh has texture coordinates): its colour replaces the
  /// material's colour at each pixel (hlr raster).
  std::shared_ptr<const TextureImage> texture;
};

/// The transparency τ of a face of material m whose unit normal makes |cos φ| = abs_cos with
/// the direction to the viewer (linear: m.transparency itself).
double transparency_at(const Material& m, double abs_cos);

struct Light {
  enum class Type { Directional, Point, Spot };
  Type type = Type::Directional;
  Vec3d direction{0, 0, 1};  // directional: toward the light; spot: where the spot points
  Vec3d position{0, 0, 0};   // point and spot
  Rgb colour{1, 1, 1};
  double intensity = 1;
  std::array<double, 3> attenuation{1, 0, 0};  // a0, a1, a2 (point and spot)
  double cone_degrees = 30;                     // spot: half-angle of the cone
  double exponent = 2;                          // spot: angular attenuation cos^exponent
  /// The same direction and position exactly, as the scene file gave them (shadows decide with
  /// these; unset: the binary values of the doubles above).
  bool exact = false;
  std::array<Rational, 3> exact_direction, exact_position;
};

struct Lighting {
  Rgb ambient{1, 1, 1};  // Ia
  bool blinn = false;    // specular by the half vector (Blinn) instead of the reflected ray (Phong)
  std::vector<Light> lights;
};

/// The colour of a flat face at point `p` with unit normal `n` turned toward the viewer,
/// `to_viewer` the unit vector from p toward the viewer. Channels clamped to [0, 1].
Rgb shade(const Material& m, const Lighting& l, const Vec3d& p, const Vec3d& n, const Vec3d& to_viewer);

/// The lighting when a scene gives none: one white directional light from above, left and
/// behind the viewer (`toward_viewer`, `up`, `right`: unit vectors of the view).
Lighting default_lighting(const Vec3d& toward_viewer, const Vec3d& up, const Vec3d& right);

/// Default material colours per body (a muted palette, repeating).
Rgb palette_colour(int body);

/// The material's colour at point p of a face with normal n: its checker texture's cell
/// colour (the two coordinates across the normal's dominant axis, so that a face lying in a
/// cell boundary plane does not flicker), else its colour.
Rgb surface_colour(const Material& m, const Vec3d& p, const Vec3d& n);

/// The notes' perturbed normal n' = n + P_u·(n × Q_w)/|n| + P_w·(Q_u × n)/|n| of the material's
/// bump map at point p of a face with unit normal n (Q_u, Q_w: unit axes in the face's plane,
/// the first across the normal's dominant axis), made unit; n itself without a bump map.
Vec3d bumped_normal(const Material& m, const Vec3d& p, const Vec3d& n);

/// "#rrggbb" of a colour (rounded to 8 bits per channel).
std::array<int, 3> rgb8(const Rgb& c);

}  // namespace hlr
