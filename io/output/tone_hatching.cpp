// Tone hatching in the render pipeline (see tone_hatching.hpp; docs/design.md, "Tone hatching").
#include "io/output/tone_hatching.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "algorithms/picture/picture_plane.hpp"
#include "algorithms/support/parallel.hpp"

namespace hlr {
static_assert(kToneLevels == kMaxToneLevels, "a line kind per tone level");
namespace {

using D3 = std::array<double, 3>;

D3 to_d3(const Point3& p) { return {to_double(p.x()), to_double(p.y()), to_double(p.z())}; }
D3 to_d3(const Vector3& p) { return {to_double(p.x()), to_double(p.y()), to_double(p.z())}; }
D3 cross_d(const D3& a, const D3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double norm_d(const D3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
D3 unit_d(const D3& a) {
  const double n = norm_d(a);
  return {a[0] / n, a[1] / n, a[2] / n};
}

// The scene's two families of planes (the second at right angles to the first, for
// cross-hatching and for faces parallel to the first) and the page distance per unit across
// each, at the view's centre.
struct Families {
  std::array<D3, 2> m;
  std::array<double, 2> page_per_unit{0, 0};  // per unit of m·X
  /// Orthographic and not contour: the planes contain the viewing direction, m = α·r + β·u
  /// exactly (the picture plane's axes), and the lines are found in the picture.
  bool picture = false;
  std::array<std::array<double, 2>, 2> alpha_beta{};
  bool ok = false;
};

D3 page_axis(const std::array<std::array<double, 3>, 3>& ax, double degrees) {
  const double a = degrees * M_PI / 180;
  D3 e;
  for (int k = 0; k < 3; ++k) e[k] = std::cos(a) * ax[0][k] + std::sin(a) * ax[1][k];
  return e;
}

Families scene_families(const RenderResult& r, const Projector& proj, const ToneHatchOptions& o) {
  Families f;
  const auto ax = proj.axes();
  // Lines at `angle` on the page are level lines of the page direction at right angles to it.
  f.m[0] = page_axis(ax, o.angle + 90);
  f.m[1] = page_axis(ax, o.angle);
  if (o.contour) f.m[0] = unit_d(to_d3(r.camera.up));  // level planes: each face's contour lines
  f.picture = !r.camera.perspective && !o.contour;
  if (f.picture) {  // m = α·r + β·u, exactly
    const PicturePlane pp(r.camera);
    const D3 rd = to_d3(pp.r()), ud = to_d3(pp.u());
    const double rr = rd[0] * rd[0] + rd[1] * rd[1] + rd[2] * rd[2], uu = ud[0] * ud[0] + ud[1] * ud[1] + ud[2] * ud[2];
    for (int k = 0; k < 2; ++k) {
      const double a = (f.m[k][0] * rd[0] + f.m[k][1] * rd[1] + f.m[k][2] * rd[2]) / rr;
      const double b = (f.m[k][0] * ud[0] + f.m[k][1] * ud[1] + f.m[k][2] * ud[2]) / uu;
      f.alpha_beta[k] = {a, b};
      f.m[k] = to_d3(Rational(a) * pp.r() + Rational(b) * pp.u());
    }
  }
  D3 centre{0, 0, 0};
  if (r.camera.perspective) {
    centre = to_d3(r.camera.target);
  } else {
    D3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (const SceneBody* b : r.bodies)
      for (const Point3& v : b->body.vertices())
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], to_double(v[k])), hi[k] = std::max(hi[k], to_double(v[k]));
    for (int k = 0; k < 3; ++k) centre[k] = (lo[k] + hi[k]) / 2;
    const double size = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    if (!(size > 0) || !std::isfinite(size)) return f;
  }
  auto page = [&](const D3& x) {
    const auto q = proj.project(Point3(Rational(x[0]), Rational(x[1]), Rational(x[2])));
    return std::array<double, 2>{q[0], q[1]};
  };
  const double d = 1e-3 * std::max({std::fabs(centre[0]), std::fabs(centre[1]), std::fabs(centre[2]), 1e-300}) + 1e-6;
  const auto q0 = page(centre);
  auto per_unit = [&](const D3& m) {  // moving d along m's direction changes m·X by d·|m|
    const D3 u = unit_d(m);
    const auto q = page({centre[0] + d * u[0], centre[1] + d * u[1], centre[2] + d * u[2]});
    return std::hypot(q[0] - q0[0], q[1] - q0[1]) / (d * norm_d(m));
  };
  for (int k = 0; k < 2; ++k) f.page_per_unit[k] = per_unit(f.m[k]);
  // Contour lines seen from above: the height interval at the drawing's scale.
  if (o.contour && f.page_per_unit[0] < 0.2 * f.page_per_unit[1]) f.page_per_unit[0] = f.page_per_unit[1];
  f.ok = f.page_per_unit[0] > 0 && f.page_per_unit[1] > 0 && std::isfinite(f.page_per_unit[0]) && std::isfinite(f.page_per_unit[1]);
  return f;
}

PlaneFamily plane_family(const D3& m, double step) {
  PlaneFamily p;
  p.m_d = m;
  p.m = Vector3(Rational(m[0]), Rational(m[1]), Rational(m[2]));
  p.step = step;
  return p;
}

// The region's boundary: its rings as directed edges, their ends pointing into the polygon (or
// into `lifted`: its picture corners lifted into the face's plane, when it has no corners in
// space).
void region_edges(const VisiblePolygon& poly, const PicturePlane& pp, const Plane& plane, std::vector<std::vector<Point3>>& lifted,
                  std::vector<std::array<const Point3*, 2>>& edges) {
  edges.clear();
  auto ring = [&](const std::vector<Point3>& r) {
    for (std::size_t k = 0; k < r.size(); ++k) edges.push_back({&r[k], &r[(k + 1) % r.size()]});
  };
  if (!poly.outer.empty() || poly.outer_2d.empty()) {
    ring(poly.outer);
    for (const auto& h : poly.holes) ring(h);
    return;
  }
  const auto ray = pp.ray_parameter(plane);
  lifted.assign(1 + poly.holes_2d.size(), {});
  for (std::size_t k = 0; k < lifted.size(); ++k)
    for (const Exact2& q : k == 0 ? poly.outer_2d : poly.holes_2d[k - 1]) lifted[k].push_back(pp.lift(q, ray));
  for (const auto& l : lifted) ring(l);
}

void picture_edges(const VisiblePolygon& poly, std::vector<std::array<const Exact2*, 2>>& edges) {
  edges.clear();
  auto ring = [&](const std::vector<Exact2>& r) {
    for (std::size_t k = 0; k < r.size(); ++k) edges.push_back({&r[k], &r[(k + 1) % r.size()]});
  };
  ring(poly.outer_2d);
  for (const auto& h : poly.holes_2d) ring(h);
}

void add_pieces(const std::vector<std::array<Exact2, 2>>& pieces, const ToneRegion& t, std::vector<TonePiece>& out) {
  for (const auto& p : pieces) out.push_back(TonePiece{t.body, t.face, tone_kind(t.level.level), p});
}

}  // namespace

std::vector<ToneRegion> tone_regions(const RenderResult& r, const ToneOptions& tone) {
  std::vector<ToneRegion> out;
  if (r.shadows) {
    for (std::size_t k = 0; k < r.shadows->faces.size(); ++k) {
      const ShadowFace& f = r.shadows->faces[k];
      for (std::size_t j = 0; j < f.regions.size(); ++j)
        out.push_back({f.body, f.face, &f.regions[j].polygon, tone_level(luminance(r.shadow_colours[k][j]), tone)});
    }
    return out;
  }
  if (!r.surfaces) return out;
  for (const VisibleFace& f : r.surfaces->faces)
    for (const VisiblePolygon& p : f.polygons) out.push_back({f.body, f.face, &p, tone_level(luminance(r.face_colours[f.body][f.face]), tone)});
  return out;
}

std::vector<TonePiece> tone_hatching(const RenderResult& r, double mm_per_unit, const ToneHatchOptions& o) {
  if (!r.surfaces && !r.shadows) throw std::invalid_argument("tone hatching needs the visible surfaces (--surfaces)");
  if (r.transparent || r.priority)
    throw std::invalid_argument("tone hatching takes the visible surfaces, with or without shadows (not transparency or the priority list)");
  std::vector<TonePiece> out;
  if (!(mm_per_unit > 0)) return out;
  const std::vector<ToneRegion> regions = tone_regions(r, o.tone);
  for (const ToneRegion& t : regions)
    if (t.level.families && t.polygon->outer_2d.empty())
      throw std::invalid_argument("tone hatching needs the visible polygons of every face (RenderOptions::surface_faces)");
  const Projector proj = drawing_projector(r.drawing, r.camera);
  const Families fam = scene_families(r, proj, o);
  if (!fam.ok) return out;
  const PicturePlane pp(r.camera);
  std::vector<std::vector<TonePiece>> per(regions.size());
  ParallelLoop(o.threads).run(regions.size(), 64, [&](unsigned, std::size_t begin, std::size_t end) {
    std::vector<std::array<const Point3*, 2>> edges;
    std::vector<std::array<const Exact2*, 2>> edges_2d;
    std::vector<std::vector<Point3>> lifted;
    for (std::size_t i = begin; i < end; ++i) {
      const ToneRegion& t = regions[i];
      if (!t.level.families) continue;
      const Polyhedron& body = r.bodies[t.body]->body;
      const Plane& plane = body.planes()[t.face];
      if (fam.picture) {  // in the picture
        picture_edges(*t.polygon, edges_2d);
        const double page_step = t.level.spacing_mm / mm_per_unit;
        for (int k = 0; k < t.level.families; ++k) {
          const PictureFamily f{fam.alpha_beta[k][0], fam.alpha_beta[k][1], page_step / fam.page_per_unit[k]};
          add_pieces(picture_family_pieces(edges_2d, f), t, per[i]);
        }
        continue;
      }
      region_edges(*t.polygon, pp, plane, lifted, edges);
      const D3 n = unit_d({to_double(plane.a()), to_double(plane.b()), to_double(plane.c())});
      const double page_step = t.level.spacing_mm / mm_per_unit;
      // The families this face takes: the first (and the second when cross-hatched); a face
      // nearly parallel to a family's planes (within 6 degrees) takes the other one instead.
      std::vector<int> use = {0};
      if (t.level.families == 2) use.push_back(1);
      for (int& k : use)
        if (norm_d(cross_d(n, fam.m[k])) < 0.1 && (r.camera.perspective || o.contour)) k = 1 - k;
      if (use.size() == 2 && use[0] == use[1]) use.pop_back();
      for (int k : use) {  // in space, the pieces' ends projected
        std::vector<std::array<Exact2, 2>> pieces;
        for (const auto& q : family_pieces(edges, plane.normal(), plane_family(fam.m[k], page_step / fam.page_per_unit[k])))
          pieces.push_back({pp.project(q[0]), pp.project(q[1])});
        add_pieces(pieces, t, per[i]);
      }
    }
  });
  for (auto& v : per)
    for (TonePiece& p : v) out.push_back(std::move(p));
  return out;
}

Point3 tone_point(const RenderResult& r, const TonePiece& p, const Exact2& q) {
  const PicturePlane pp(r.camera);
  return pp.lift(q, pp.ray_parameter(r.bodies[p.body]->body.planes()[p.face]));
}

Plot tone_plot(const std::vector<TonePiece>& h, const RenderResult& r, const PlotOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const Projector proj = drawing_projector(r.drawing, r.camera);
  const PictureToDrawing to_drawing(PicturePlane(r.camera), proj.frame());
  const std::size_t n = 2 * h.size();
  auto end = [&](std::size_t i) -> const Exact2& { return h[i / 2].ends[i % 2]; };
  std::vector<std::array<double, 2>> d(n);
  ParallelLoop(o.threads).for_each(n, 4096, [&](std::size_t i) { d[i] = {end(i)[0].get_d(), end(i)[1].get_d()}; });
  // Equal exact points have equal doubles: sort by the doubles, then join runs of equal points.
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return d[a] < d[b]; });
  CleanDrawing c;
  c.pieces_in = h.size();
  std::vector<std::uint32_t> point_of(n);
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j < n && d[order[j]] == d[order[i]]) ++j;
    // Within a run of equal doubles, distinct exact points stay apart.
    std::vector<std::pair<const Exact2*, std::uint32_t>> seen;
    for (std::size_t k = i; k < j; ++k) {
      const Exact2& p = end(order[k]);
      std::uint32_t id = UINT32_MAX;
      for (const auto& [q, qid] : seen)
        if (*q == p) id = qid;
      if (id == UINT32_MAX) {
        id = static_cast<std::uint32_t>(c.points.size());
        const auto xy = to_drawing(d[order[k]]);
        c.points.push_back({xy[0], xy[1]});
        seen.emplace_back(&p, id);
      }
      point_of[order[k]] = id;
    }
    i = j;
  }
  for (std::size_t s = 0; s < h.size(); ++s) {
    if (point_of[2 * s] == point_of[2 * s + 1]) {
      ++c.zero_length;
      continue;
    }
    c.edges.push_back(CleanEdge{point_of[2 * s], point_of[2 * s + 1], PieceRef{static_cast<int>(s), 0}, h[s].kind, true, false, h[s].body});
  }
  return plot_from_clean(c, o, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

}  // namespace hlr
