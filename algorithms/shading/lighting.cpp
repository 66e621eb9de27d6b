// Flat shading (course notes sections 36 and 39). See lighting.hpp.
#include "algorithms/shading/lighting.hpp"

#include <algorithm>
#include <cmath>

namespace hlr {
namespace {

double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3d unit(const Vec3d& a) {
  double l = std::sqrt(dot(a, a));
  return l > 0 ? Vec3d{a[0] / l, a[1] / l, a[2] / l} : a;
}

}  // namespace

Rgb shade(const Material& m, const Lighting& l, const Vec3d& p, const Vec3d& n, const Vec3d& to_viewer) {
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = m.ka * l.ambient[c] * m.colour[c];
  for (const Light& li : l.lights) {
    Vec3d L;
    double f = li.intensity;
    if (li.type == Light::Type::Directional) {
      L = unit(li.direction);
    } else {
      Vec3d d{li.position[0] - p[0], li.position[1] - p[1], li.position[2] - p[2]};
      double dist = std::sqrt(dot(d, d));
      L = unit(d);
      double att = li.attenuation[0] + li.attenuation[1] * dist + li.attenuation[2] * dist * dist;
      f /= std::max(att, 1e-300);
      if (li.type == Light::Type::Spot) {
        // cos(alpha) = V_light·V_obj (V_obj: from the light to the point); nothing outside the cone.
        double cos_a = -dot(unit(li.direction), L);
        if (cos_a < std::cos(li.cone_degrees * M_PI / 180)) continue;
        f *= std::pow(cos_a, li.exponent);
      }
    }
    double cos_t = dot(n, L);
    if (cos_t <= 0) continue;  // the light is behind the face
    double spec = 0;
    if (m.ks > 0) {
      double s;
      if (l.blinn) {
        s = dot(n, unit(Vec3d{L[0] + to_viewer[0], L[1] + to_viewer[1], L[2] + to_viewer[2]}));
      } else {
        Vec3d R{2 * cos_t * n[0] - L[0], 2 * cos_t * n[1] - L[1], 2 * cos_t * n[2] - L[2]};
        s = dot(R, to_viewer);
      }
      spec = s > 0 ? std::pow(s, m.shininess) : 0;
    }
    for (int c = 0; c < 3; ++c) out[c] += f * li.colour[c] * (m.kd * m.colour[c] * cos_t + m.ks * spec);
  }
  for (double& c : out) c = std::clamp(c, 0.0, 1.0);
  return out;
}

Lighting default_lighting(const Vec3d& v, const Vec3d& up, const Vec3d& right) {
  Lighting l;
  Light key;
  key.direction = unit(Vec3d{v[0] + 0.5 * up[0] - 0.25 * right[0], v[1] + 0.5 * up[1] - 0.25 * right[1],
                             v[2] + 0.5 * up[2] - 0.25 * right[2]});
  l.lights.push_back(key);
  return l;
}

Rgb palette_colour(int body) {
  static const Rgb kPalette[] = {{0.78, 0.80, 0.84}, {0.85, 0.72, 0.55}, {0.60, 0.75, 0.65}, {0.70, 0.66, 0.82},
                                 {0.86, 0.62, 0.62}, {0.58, 0.72, 0.84}, {0.84, 0.80, 0.58}, {0.66, 0.70, 0.70}};
  return kPalette[static_cast<std::size_t>(body) % (sizeof kPalette / sizeof kPalette[0])];
}

std::array<int, 3> rgb8(const Rgb& c) {
  std::array<int, 3> out;
  for (int i = 0; i < 3; ++i) out[i] = static_cast<int>(std::lround(std::clamp(c[i], 0.0, 1.0) * 255));
  return out;
}

double transparency_at(const Material& m, double abs_cos) {
  const double c = std::min(1.0, std::max(0.0, abs_cos));
  switch (m.transparency_model) {
    case Material::TransparencyModel::Linear: return m.transparency;
    case Material::TransparencyModel::Kay:
      return m.transparency_min + (m.transparency - m.transparency_min) * (1 - std::pow(1 - c, m.transparency_power));
    case Material::TransparencyModel::PathLength:
      if (c == 0) return 0;  // seen edge-on: an infinitely long path
      return std::pow(m.transparency, 1 / c);  // opacity 1 − (1 − a)^(1/|cos φ|), a = 1 − τ
  }
  return m.transparency;
}

Rgb surface_colour(const Material& m, const Vec3d& p, const Vec3d& n) {
  if (!(m.checker > 0)) return m.colour;
  const int drop = std::fabs(n[0]) >= std::fabs(n[1]) && std::fabs(n[0]) >= std::fabs(n[2]) ? 0 : std::fabs(n[1]) >= std::fabs(n[2]) ? 1 : 2;
  long parity = 0;
  for (int c = 0; c < 3; ++c)
    if (c != drop) parity += static_cast<long>(std::floor(p[c] / m.checker));
  return (parity & 1) ? m.colour2 : m.colour;
}

Vec3d bumped_normal(const Material& m, const Vec3d& p, const Vec3d& n) {
  if (!(m.bump > 0) || !(m.bump_size > 0)) return n;
  // Q_u: the world axis least along n, made orthogonal to n; Q_w = n × Q_u (|n| = 1).
  int a = 0;
  for (int c = 1; c < 3; ++c)
    if (std::fabs(n[c]) < std::fabs(n[a])) a = c;
  Vec3d qu{0, 0, 0};
  qu[a] = 1;
  const double d = qu[0] * n[0] + qu[1] * n[1] + qu[2] * n[2];
  for (int c = 0; c < 3; ++c) qu[c] -= d * n[c];
  const double lu = std::sqrt(qu[0] * qu[0] + qu[1] * qu[1] + qu[2] * qu[2]);
  for (double& c : qu) c /= lu;
  const Vec3d qw{n[1] * qu[2] - n[2] * qu[1], n[2] * qu[0] - n[0] * qu[2], n[0] * qu[1] - n[1] * qu[0]};
  const double u = p[0] * qu[0] + p[1] * qu[1] + p[2] * qu[2], w = p[0] * qw[0] + p[1] * qw[1] + p[2] * qw[2];
  const double k = 2 * M_PI / m.bump_size;
  const double pu = m.bump * k * std::cos(k * u) * std::sin(k * w), pw = m.bump * k * std::sin(k * u) * std::cos(k * w);
  // n × Q_w = −Q_u and Q_u × n = −Q_w for the unit frame (Q_u, Q_w, n).
  Vec3d out{n[0] - pu * qu[0] - pw * qw[0], n[1] - pu * qu[1] - pw * qw[1], n[2] - pu * qu[2] - pw * qw[2]};
  const double l = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
  for (double& c : out) c /= l;
  return out;
}

Rgb TextureImage::at(double u, double v) const {
  if (width <= 0 || height <= 0 || !std::isfinite(u) || !std::isfinite(v)) return {1, 1, 1};
  // Texel (i, j) has its centre at ((i + 1/2)/w, 1 − (j + 1/2)/h); repeat outside [0, 1].
  const double x = (u - std::floor(u)) * width - 0.5, y = (1 - (v - std::floor(v))) * height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y), ax = x - fx, ay = y - fy;
  auto texel = [&](long i, long j) {
    i = ((i % width) + width) % width, j = ((j % height) + height) % height;
    const std::uint8_t* p = &rgb[(static_cast<std::size_t>(j) * width + i) * 3];
    return Rgb{p[0] / 255.0, p[1] / 255.0, p[2] / 255.0};
  };
  const long i = static_cast<long>(fx), j = static_cast<long>(fy);
  const Rgb a = texel(i, j), b = texel(i + 1, j), c = texel(i, j + 1), d = texel(i + 1, j + 1);
  Rgb out;
  for (int k = 0; k < 3; ++k) out[k] = (1 - ay) * ((1 - ax) * a[k] + ax * b[k]) + ay * ((1 - ax) * c[k] + ax * d[k]);
  return out;
}

}  // namespace hlr
