// Whitted ray tracing (course notes sections 43-45, the global illumination model): at a
// surface point the intensity is I = (1 - kr - kt)·I_local + kr·I_reflected + kt·I_refracted,
// the local part shaded by the lights that the point sees (shadow rays; a transparent body
// lets kt of the light through), the reflected ray r = d - 2(d·n)n, the refracted ray by
// Snell's law in the notes' form t = η·d + (η·c - √k)·n with c = -d·n, k = 1 - η²(1 - c²),
// and total internal reflection where k < 0.
//
// Where exact numbers stop: the first hit of every primary ray is the exact face at the pixel
// centre (raster_scene.hpp); total internal reflection at that first surface is decided
// exactly from the squared form of Snell's law (rational for the rational sight ray, normal and
// ior: exact_total_internal_reflection). From there on (the refracted and reflected directions
// involve a square root) every ray, hit and shadow ray is in doubles over a BVH, as shading:
// it colours the picture, it does not decide which face a pixel shows.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "algorithms/shading/lighting.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr {

/// Total internal reflection of a ray along d meeting a surface of normal n (either side),
/// passing from a medium of index n1 into one of n2 (eta = n1/n2): η²(1 - cos²θ) > 1 with
/// cos²θ = (d·n)²/(|d|²|n|²), decided exactly. At the critical angle (= 1) the ray grazes: no.
bool exact_total_internal_reflection(const std::array<Rational, 3>& d, const std::array<Rational, 3>& n, const Rational& eta);

/// The refracted unit direction (notes 45) of the unit direction d at a surface whose unit
/// normal n faces the incoming ray (d·n <= 0), eta = n1/n2; false on total internal reflection.
bool refract(const Vec3d& d, const Vec3d& n, double eta, Vec3d& t);

struct WhittedOptions {
  int depth = 5;            // reflection and refraction levels after the first hit
  Rgb background{1, 1, 1};  // what a ray that leaves the scene sees
};

/// The scene in doubles for the rays after the first hit: every face's triangles, a BVH, the
/// bodies' materials and the lights.
class WhittedScene {
 public:
  WhittedScene(const std::vector<const Polyhedron*>& bodies, std::vector<Material> materials, Lighting lighting,
               const WhittedOptions& options);
  ~WhittedScene();
  WhittedScene(const WhittedScene&) = delete;
  WhittedScene& operator=(const WhittedScene&) = delete;

  /// The colour seen along a ray from `from` in unit direction `dir` that first meets face
  /// `face` of body `body` at `at` (the exact first hit, in doubles); `exact_tir`: the exact
  /// decision of total internal reflection there (refracting materials only).
  Rgb shade_first(int body, int face, const Vec3d& at, const Vec3d& dir, bool exact_tir) const;

  /// The colour seen along any ray (after the first hit) leaving a surface of body `from_body`.
  Rgb trace(const Vec3d& from, const Vec3d& dir, int depth, int from_body = -1) const;

  /// The nearest hit beyond the offset (a face of another body than `from_body` also at the
  /// start: bodies that touch pass the ray on): its distance, body and face; false when none.
  bool hit(const Vec3d& from, const Vec3d& dir, double& t, int& body, int& face, int from_body = -1) const;

 private:
  struct Impl;
  Rgb shade(int body, int face, const Vec3d& at, const Vec3d& dir, int depth, int tir) const;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hlr
