// Shadows as exact polygons (course notes section 40, Atherton–Weiler–Greenberg). See
// shadows.hpp; why the labels are exact: docs/design.md, "Shadows as exact polygons".
#include "algorithms/surfaces/shadows.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <optional>
#include <stdexcept>

#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/picture/offset_point.hpp"
#include "algorithms/picture/picture_plane.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/surfaces/light_cube.hpp"

namespace hlr {
namespace {

using Ring = std::vector<Exact2>;

bool inside(const std::vector<Ring>& rings, const Exact2& m, const Exact2& n) { return offset_inside(rings, m, n); }

void add_rings(const VisiblePolygon& p, std::vector<Ring>& out) {
  out.push_back(p.outer_2d);
  for (const auto& h : p.holes_2d) out.push_back(h);
}

// A ring of 3D corners clipped to keep.value <= 0 (Sutherland-Hodgman, exact): the even-odd
// region of the clipped rings of a polygon with holes is the polygon's part on that side.
std::vector<Point3> clipped(const std::vector<Point3>& ring, const Plane& keep) {
  std::vector<Point3> out;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point3 &a = ring[i], &b = ring[(i + 1) % ring.size()];
    const Rational va = keep.value(a), vb = keep.value(b);
    if (va <= 0) out.push_back(a);
    if ((va < 0 && vb > 0) || (va > 0 && vb < 0)) out.push_back(a + Rational(va / (va - vb)) * (b - a));
  }
  return out.size() >= 3 ? out : std::vector<Point3>{};
}

// The lit polygons of a face from the light, carried into the viewer's picture (clipped to
// `keep` first: the part of the light's bodies the viewer sees, a cube view's pyramid).
std::vector<Ring> carried(const std::vector<VisiblePolygon>& lit, const PicturePlane& viewer, const std::vector<Plane>& keep) {
  std::vector<Ring> out;
  auto add = [&](const std::vector<Point3>& corners) {
    std::vector<Point3> ring = corners;
    for (const Plane& h : keep)
      if (!ring.empty()) ring = clipped(ring, h);
    if (ring.empty()) return;
    Ring r;
    for (const Point3& c : ring) r.push_back(viewer.project(c));
    out.push_back(std::move(r));
  };
  for (const VisiblePolygon& p : lit) {
    add(p.outer);
    for (const auto& h : p.holes) add(h);
  }
  return out;
}

// A set of rings in a canonical form: each ring started at its smallest point, the rings sorted.
std::vector<Ring> canonical(std::vector<Ring> rings) {
  for (Ring& r : rings) {
    auto lowest = std::min_element(r.begin(), r.end());
    std::rotate(r.begin(), lowest, r.end());
  }
  std::sort(rings.begin(), rings.end());
  return rings;
}

// The common case without an arrangement: each light lights none of the face or exactly the
// part seen (the same rings). Empty when some light lights a part that differs.
std::optional<ShadowFace> whole_face(const VisibleFace& vf, const std::vector<Ring>& seen, const std::vector<std::vector<Ring>>& lit) {
  unsigned mask = 0;
  std::vector<Ring> key;
  for (std::size_t i = 0; i < lit.size(); ++i) {
    if (lit[i].empty()) continue;
    if (key.empty()) key = canonical(seen);
    if (canonical(lit[i]) != key) return std::nullopt;
    mask |= 1u << i;
  }
  ShadowFace out;
  out.body = vf.body, out.face = vf.face, out.front = vf.front, out.whole = true;
  out.area2 = 0, out.shadow_area2 = 0;
  out.by_light.resize(lit.size());
  for (const VisiblePolygon& p : vf.polygons) {
    out.regions.push_back({mask, p});
    out.area2 += p.area2;
    if (mask == 0) out.shadow_area2 += p.area2;
    for (std::size_t i = 0; i < lit.size(); ++i) out.by_light[i][(mask >> i) & 1u ? 0 : 1].push_back(p);
  }
  return out;
}

// One visible face cut by the lit sets: the arrangement of all rings, each cycle labelled by
// the lights whose lit set holds the point beside its first half-edge.
ShadowFace cut_face(const VisibleFace& vf, const std::vector<std::vector<Ring>>& lit, const PicturePlane& pp, const Plane& plane) {
  ShadowFace out;
  out.body = vf.body, out.face = vf.face, out.front = vf.front;
  std::vector<Ring> seen;
  for (const VisiblePolygon& p : vf.polygons) add_rings(p, seen);
  if (auto whole = whole_face(vf, seen, lit)) return std::move(*whole);
  std::vector<Exact2> points;
  std::vector<std::array<std::uint32_t, 2>> segs;
  auto put = [&](const std::vector<Ring>& rings) {
    for (const Ring& r : rings) {
      const auto base = static_cast<std::uint32_t>(points.size());
      points.insert(points.end(), r.begin(), r.end());
      for (std::uint32_t i = 0; i < r.size(); ++i) segs.push_back({base + i, base + (i + 1) % static_cast<std::uint32_t>(r.size())});
    }
  };
  put(seen);
  for (const auto& l : lit) put(l);
  ArrangementOptions ao;
  ao.threads = 1;
  PlanarArrangement arr = build_arrangement(std::move(points), segs, ao);
  const std::size_t nc = arr.cycle_edge.size();
  std::vector<int> label(nc, -1);
  for (std::size_t c = 0; c < nc; ++c) {
    const std::uint32_t h = arr.cycle_edge[c];
    const Exact2 &a = arr.points[arr.origin[h]], &b = arr.points[arr.head(h)];
    const Exact2 m{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2};
    const Exact2 n{a[1] - b[1], b[0] - a[0]};  // the left of a -> b
    if (!inside(seen, m, n)) continue;
    unsigned mask = 0;
    for (std::size_t i = 0; i < lit.size(); ++i)
      if (!lit[i].empty() && inside(lit[i], m, n)) mask |= 1u << i;
    label[c] = static_cast<int>(mask);
  }
  const auto ray = pp.ray_parameter(plane);
  auto polygon = [&](const LabelledRegion& r) {
    VisiblePolygon vp;
    auto ring = [&](const std::vector<std::uint32_t>& hs, std::vector<Point3>& p3, std::vector<Exact2>& p2) {
      for (std::uint32_t h : hs) {
        p2.push_back(arr.points[arr.origin[h]]);
        p3.push_back(pp.lift(p2.back(), ray));
      }
    };
    ring(r.outer, vp.outer, vp.outer_2d);
    for (const auto& hole : r.holes) {
      vp.holes.emplace_back();
      vp.holes_2d.emplace_back();
      ring(hole, vp.holes.back(), vp.holes_2d.back());
    }
    vp.area2 = r.area2;
    return vp;
  };
  out.area2 = 0, out.shadow_area2 = 0;
  for (const LabelledRegion& r : merge_regions(arr, label, -1)) {
    out.regions.push_back({static_cast<unsigned>(r.label), polygon(r)});
    out.area2 += r.area2;
    if (r.label == 0) out.shadow_area2 += r.area2;
  }
  // Per light: its lit part (label 1) and its shadow (label 0) of the visible part.
  out.by_light.resize(lit.size());
  for (std::size_t i = 0; i < lit.size(); ++i) {
    std::vector<int> l(nc, -1);
    for (std::size_t c = 0; c < nc; ++c)
      if (label[c] >= 0) l[c] = (static_cast<unsigned>(label[c]) >> i) & 1u ? 0 : 1;
    for (const LabelledRegion& r : merge_regions(arr, l, -1)) out.by_light[i][r.label].push_back(polygon(r));
  }
  return out;
}

}  // namespace

namespace {

// The one view a light needs, if one serves (every body in front of a point light).
std::optional<Camera> single_light_view(const std::vector<const Polyhedron*>& bodies, const LightPlace& light) {
  if (light.directional) return make_orthographic(light.toward);
  bool first = true;
  std::array<Rational, 3> lo, hi;
  for (const Polyhedron* p : bodies)
    for (const Point3& v : p->vertices())
      for (int k = 0; k < 3; ++k) {
        if (first || v[k] < lo[k]) lo[k] = v[k];
        if (first || v[k] > hi[k]) hi[k] = v[k];
        if (k == 2) first = false;
      }
  Point3 centre((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
  // Look at the scene's centre, else along an axis (a light above a ground plane looks down):
  // the first view with every vertex in front of the light.
  std::vector<Vector3> looks;
  if (!(centre == light.position)) looks.push_back(centre - light.position);
  for (int k = 0; k < 3; ++k)
    for (int sgn_k : {-1, 1}) {
      std::array<Rational, 3> d{0, 0, 0};
      d[k] = sgn_k;
      looks.emplace_back(d[0], d[1], d[2]);
    }
  for (const Vector3& look : looks) {
    Camera cam = make_perspective(light.position, light.position + look);
    bool all = true;
    for (const Polyhedron* p : bodies)
      for (const Point3& v : p->vertices())
        if (all && cam.in_front(v) != Sign::Positive) all = false;
    if (all) return cam;
  }
  return std::nullopt;
}

}  // namespace

Camera light_camera(const std::vector<const Polyhedron*>& bodies, const LightPlace& light) {
  if (auto cam = single_light_view(bodies, light)) return *cam;
  throw std::invalid_argument("shadows: a point light among the bodies (no view from it has every body in front: see light_cube.hpp)");
}

Shadows shadows(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const VisibleSurfaces& seen,
                const std::vector<LightPlace>& lights, const ShadowOptions& options) {
  auto t0 = std::chrono::steady_clock::now();
  if (lights.size() > 16) throw std::invalid_argument("shadows: at most 16 lights");
  Shadows out;
  const ShadowCasters* casters = options.casters;
  const std::vector<const Polyhedron*>& lit_bodies = casters ? casters->bodies : bodies;
  // Pass 1: what each light sees, lit polygons lifted to exact 3D corners; a point light among
  // the bodies by the six views of a cube around it (light_cube.hpp).
  auto seen_from = [&](const std::vector<const Polyhedron*>& b, const Camera& lc) {
    LineOptions lo;
    lo.edges = EdgeSelection::All;
    lo.classify_all = true;
    lo.threads = options.threads;
    LineDrawing d = face_occluders(b, lc, lo);
    SurfaceOptions so;
    so.threads = options.threads;
    return visible_surfaces(b, lc, d, so);
  };
  std::vector<std::vector<LightCubeView>> cubes(lights.size());
  out.cube_views.resize(lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const std::optional<Camera> lc = single_light_view(lit_bodies, lights[i]);
    out.from_light.push_back(lc ? seen_from(lit_bodies, *lc) : VisibleSurfaces{});
    if (lc) continue;
    cubes[i] = light_cube(lit_bodies, lights[i].position);
    for (const LightCubeView& v : cubes[i]) {
      std::vector<const Polyhedron*> parts;
      for (const Polyhedron& p : v.parts) parts.push_back(&p);
      out.cube_views[i].push_back(seen_from(parts, v.camera));
    }
  }
  // Per light, per face of the lights' bodies: the faces seen lit (one, or a part per cube view
  // with the view's pyramid, whose lit polygons count inside it only).
  using Lit = std::pair<const VisibleFace*, const std::vector<Plane>*>;
  static const std::vector<Plane> everywhere;
  std::vector<std::map<std::pair<int, int>, std::vector<Lit>>> lit_face(lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) {
    for (const VisibleFace& f : out.from_light[i].faces) lit_face[i][{f.body, f.face}].push_back({&f, &everywhere});
    for (std::size_t k = 0; k < out.cube_views[i].size(); ++k)
      for (const VisibleFace& f : out.cube_views[i][k].faces) {
        const LightCubeView& v = cubes[i][k];
        const int face = v.face[f.body][f.face];
        if (face >= 0) lit_face[i][{v.body[f.body], face}].push_back({&f, &v.pyramid});
      }
  }
  out.seconds_lights = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Pass 2: each visible face cut by the lit parts on the side the viewer sees.
  PicturePlane pp(camera);
  out.faces.resize(seen.faces.size());
  ParallelLoop(options.threads).for_each(seen.faces.size(), 4, [&](std::size_t k) {
    const VisibleFace& vf = seen.faces[k];
    const std::pair<int, int> key = casters ? std::pair{casters->body[vf.body], casters->face[vf.body][vf.face]} : std::pair{vf.body, vf.face};
    std::vector<std::vector<Ring>> lit(lights.size());
    for (std::size_t i = 0; i < lights.size() && key.second >= 0; ++i) {
      auto it = lit_face[i].find(key);
      if (it == lit_face[i].end()) continue;
      for (const auto& [f, pyramid] : it->second)  // the cube views' pieces have disjoint insides: their rings' even-odd union
        if (f->front == vf.front) {
          std::vector<Plane> keep = *pyramid;
          if (casters) keep.push_back(casters->keep);
          std::vector<Ring> rings = carried(f->polygons, pp, keep);
          lit[i].insert(lit[i].end(), std::make_move_iterator(rings.begin()), std::make_move_iterator(rings.end()));
        }
    }
    out.faces[k] = cut_face(vf, lit, pp, bodies[vf.body]->planes()[vf.face]);
  });
  for (const ShadowFace& f : out.faces) out.whole_faces += f.whole;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace hlr
