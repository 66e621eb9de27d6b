// An independent exact oracle for hidden lines: exact ray casting of sample points of every
// piece against every convex body's face planes, sharing no code with the algorithms (it builds
// its own planes from the triangles and solves its own one-variable inequalities). Used by the
// oracle tests and the torture suite.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <vector>

#include "algorithms/model/camera.hpp"
#include "algorithms/model/line_drawing.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr::test {

struct OraclePlane {
  Rational a, b, c, d;  // inward: interior positive
  Rational at(const Rational& x, const Rational& y, const Rational& z) const { return a * x + b * y + c * z + d; }
};

inline std::vector<OraclePlane> oracle_planes(const Polyhedron& p) {
  Rational cx = 0, cy = 0, cz = 0;
  for (const Point3& v : p.vertices()) {
    cx += v.x();
    cy += v.y();
    cz += v.z();
  }
  Rational n(static_cast<long>(p.num_vertices()));
  cx /= n;
  cy /= n;
  cz /= n;
  std::vector<OraclePlane> out;
  for (const Face& f : p.faces()) {
    const Point3 &A = p.vertices()[f[0]], &B = p.vertices()[f[1]], &C = p.vertices()[f[2]];
    Rational ux = B.x() - A.x(), uy = B.y() - A.y(), uz = B.z() - A.z();
    Rational vx = C.x() - A.x(), vy = C.y() - A.y(), vz = C.z() - A.z();
    OraclePlane h{uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx, 0};
    h.d = -(h.a * A.x() + h.b * A.y() + h.c * A.z());
    if (h.at(cx, cy, cz) < 0) h = {-h.a, -h.b, -h.c, -h.d};
    out.push_back(h);
  }
  return out;
}

// Does the open sight ray of (x, y, z) meet the interior of the body?
inline bool ray_enters(const std::vector<OraclePlane>& body, const Rational& x, const Rational& y, const Rational& z,
                const Camera& cam) {
  // Orthographic: Q = P + s·v, s in (0, inf). Perspective: Q = P + s·(E - P), s in (0, 1).
  Rational lo = 0;
  std::optional<Rational> hi;
  if (cam.perspective) hi = Rational(1);
  for (const OraclePlane& h : body) {
    Rational c0 = h.at(x, y, z), c1;
    if (cam.perspective)
      c1 = h.at(cam.eye.x(), cam.eye.y(), cam.eye.z()) - c0;
    else
      c1 = h.a * cam.direction.x() + h.b * cam.direction.y() + h.c * cam.direction.z();
    if (c1 == 0) {
      if (!(c0 > 0)) return false;
    } else if (c1 > 0) {
      Rational s = -c0 / c1;
      if (s > lo) lo = s;
    } else {
      Rational s = -c0 / c1;
      if (!hi || s < *hi) hi = s;
    }
  }
  return !hi || lo < *hi;
}

struct Tally {
  long samples = 0, disagreements = 0, scenes = 0, junctions = 0, hidden_samples = 0, isolated_points = 0, route_mismatches = 0;
};

inline void sample_check(const LineDrawing& r, const std::vector<std::vector<OraclePlane>>& planes, const Camera& cam, Tally& tally,
                  const char* route) {
  for (const Segment& s : r.segments) {
    for (const Piece& p : s.pieces) {
      if (p.behind_eye || p.clipped) continue;  // never drawn (behind the eye, or nearer than the near plane)
      for (Rational f : {Rational(1, 2), Rational(1, 4), Rational(3, 4)}) {
        Point3 x = s.at(p.t0 + f * (p.t1 - p.t0));
        bool hidden = false;
        for (const auto& body : planes) hidden = hidden || ray_enters(body, x.x(), x.y(), x.z(), cam);
        ++tally.samples;
        tally.hidden_samples += hidden;
        if (!hidden && !p.visible) {
          // A single visible point between hidden parts (a ray along the face shared by two
          // touching bodies) is merged into the hidden piece: a point is not a line. Accept it
          // only when the points just before and after are hidden.
          Rational t = p.t0 + f * (p.t1 - p.t0), eps = (p.t1 - p.t0) / Rational(1000000007);
          Point3 before = s.at(t - eps), after = s.at(t + eps);
          bool hb = false, ha = false;
          for (const auto& body : planes) {
            hb = hb || ray_enters(body, before.x(), before.y(), before.z(), cam);
            ha = ha || ray_enters(body, after.x(), after.y(), after.z(), cam);
          }
          if (hb && ha) {
            ++tally.isolated_points;
            continue;
          }
        }
        if (hidden == p.visible) {
          ++tally.disagreements;
          ADD_FAILURE() << route << ": piece of segment " << s.from() << "-" << s.to() << " t " << p.t0 << ".." << p.t1
                        << " says visible=" << p.visible;
        }
      }
    }
  }
}

/// The bodies as pointers for the renderers and as oracle planes, side by side.
struct OracleScene {
  std::vector<const Polyhedron*> ptrs;
  std::vector<std::vector<OraclePlane>> planes;
  explicit OracleScene(const std::vector<Polyhedron>& bodies) {
    for (const auto& b : bodies) {
      ptrs.push_back(&b);
      planes.push_back(oracle_planes(b));
    }
  }
};

}  // namespace hlr::test
