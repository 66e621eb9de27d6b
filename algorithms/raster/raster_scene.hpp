// The exact image-space model shared by the raster algorithms (course notes sections 29-35:
// Warnock, z-buffer, scan-line, ray casting; section 25 for image space against object space).
// A grid of pixel centres at exact dyadic picture points; the scene's convex picture polygons
// (scene_polygons.hpp) with the exact depth of their planes along each sight ray; and the one
// rule of which face is seen at a pixel centre: among the polygons whose closed picture
// contains the centre, the nearest; a depth tie (touching planes, an edge shared by two faces)
// goes to the face toward the viewer, then to the lower face number, as for the visible-surface
// polygons (visible_surfaces.hpp). The order is total, so any algorithm that offers every
// covering polygon to `nearer` gets the same face at every pixel. Every decision is the sign of
// an exact number, first tried with certified interval doubles (docs/design.md, "Raster").
#pragma once

#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <cstdint>
#include <memory>
#include <vector>

#include "algorithms/model/line_drawing.hpp"
#include "algorithms/picture/picture_plane.hpp"
#include "kernel/error_bounds.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr {

/// A linear function c0 + cx·x + cy·y of the picture point with certified double coefficients:
/// each exact coefficient lies within r of its double m (m = the interval's low end, r its
/// width rounded up), so a value in doubles decides a sign with a proven bound (eval_sign).
struct FilteredLinear {
  double m[3] = {0, 0, 0}, r[3] = {0, 0, 0};
  /// The sign of the exact function at the exact double point (x, y), or 2 when the doubles
  /// cannot tell (docs/design.md, "Raster": the bound).
  int sign(double x, double y) const;
};

/// The pixel grid: the centre of pixel (i, j) (column i from the left, row j from the top) is
/// the picture point (x0 + (i + 1/2)·xstep, y1 - (j + 1/2)·ystep), exact. The steps, x0 and y1
/// are dyadic with numerators of 20 bits, so every centre is also an exact double; the steps
/// make the pixels square in true lengths to 2^-19 (the picture axes have different lengths).
struct RasterGrid {
  int width = 0, height = 0;
  Rational x0, y1, xstep, ystep;
  double dx0 = 0, dy1 = 0, dxstep = 0, dystep = 0;
  double cx(int i) const { return dx0 + (i + 0.5) * dxstep; }
  double cy(int j) const { return dy1 - (j + 0.5) * dystep; }
  Exact2 centre(int i, int j) const { return {Rational(cx(i)), Rational(cy(j))}; }
  /// The columns (rows) whose centres may lie in [lo, hi] (a superset: callers test exactly).
  std::array<int, 2> columns(double lo, double hi) const;
  std::array<int, 2> rows(double lo, double hi) const;
};

/// A grid of `width` x `height` square pixels holding the picture extent [x0, x1] x [y0, y1]
/// (`extent` = {x0, y0, x1, y1}, nearest doubles of exact extremes; empty: [-1, 1]²) with a
/// margin; `x_unit`, `y_unit`: the true length of one picture unit along x and y
/// (picture_plane.hpp).
RasterGrid raster_grid(const std::array<double, 4>& extent, int width, int height, double x_unit, double y_unit, double margin = 1.04);

/// A grid of `width` x `height` square pixels whose picture is a camera's frame: the exact
/// picture rectangle |X| <= half_x, |Y| <= half_y (view_pyramid.hpp) fitted inside without a
/// margin, centred (an image of the frame's aspect shows the frame and nothing more).
RasterGrid frame_grid(const Camera& camera, const Rational& half_x, const Rational& half_y, int width, int height);

/// A convex picture polygon ready for pixel tests: a face, or a triangle of a face that is not
/// convex, counter-clockwise in the picture. Its corners are body vertices
/// (RasterScene::corner_verts[first .. first + count)); the exact picture points and the exact
/// depth function are computed on demand (RasterScene::point, RasterScene::depth) by the rare
/// decisions the certified doubles cannot take.
struct RasterPolygon {
  int body = -1, face = -1;
  int id = -1;     // global face number: faces of earlier bodies first
  int rank = 0;    // 0: the face is toward the viewer; 1: turned away or an open surface's back
  int piece = 0;   // which convex piece of the face (0 for a convex face)
  int first = 0;   // its corners and sides: RasterScene::corner_verts, RasterScene::sides
  int count = 0;
  std::array<double, 4> box{};  // x0, y0, x1, y1 of the picture polygon, certified outward
  /// Depth along the sight ray, smaller nearer: z = (n0 + nx·x + ny·y) / (d0 + dx·x + dy·y)
  /// (orthographic: the denominator is 1; perspective: the numerator is constant), as
  /// certified intervals of the exact coefficients (RasterScene::depth).
  std::array<Interval, 6> zi;
  FilteredLinear zlin;  // orthographic: the depth itself, for differences of two depths
  FilteredLinear zden;  // perspective: the denominator
};

/// Counters of exact fallbacks (the double filter could not decide).
struct RasterCounters {
  std::atomic<std::uint64_t> inside_exact{0}, depth_exact{0};
  RasterCounters() = default;
  RasterCounters(const RasterCounters& o) : inside_exact(o.inside_exact.load()), depth_exact(o.depth_exact.load()) {}
  RasterCounters& operator=(const RasterCounters& o) {
    inside_exact = o.inside_exact.load(), depth_exact = o.depth_exact.load();
    return *this;
  }
};

struct RasterScene {
  Camera camera;
  RasterGrid grid;
  std::vector<const Polyhedron*> bodies;
  std::shared_ptr<const PicturePlane> plane;
  std::vector<RasterPolygon> polygons;
  std::vector<int> corner_verts;       // polygon p's corner k: vertex corner_verts[p.first + k] of its body
  std::vector<FilteredLinear> sides;   // side k (corner k to k + 1): A + B·x + C·y >= 0 inside
  std::vector<std::array<int, 2>> faces;  // global face number -> (body, face)
  mutable RasterCounters counters;

  int vert(const RasterPolygon& p, int k) const { return corner_verts[static_cast<std::size_t>(p.first + k)]; }
  const Point3& corner(const RasterPolygon& p, int k) const { return bodies[p.body]->vertices()[vert(p, k)]; }
  const FilteredLinear& side(const RasterPolygon& p, int k) const { return sides[static_cast<std::size_t>(p.first + k)]; }
  /// The exact picture point of corner k.
  Exact2 point(const RasterPolygon& p, int k) const;
  /// All its exact picture points, counter-clockwise.
  std::vector<Exact2> points(const RasterPolygon& p) const;
  /// The exact depth coefficients (n0, nx, ny, d0, dx, dy) of RasterPolygon::zi, computed on
  /// the first call for the face and kept (safe from parallel loops).
  const std::array<Rational, 6>& depth(const RasterPolygon& p) const;
  /// The kept exact depths, one slot per global face number, filled on demand.
  struct DepthCache {
    std::vector<std::atomic<const std::array<Rational, 6>*>> slot;
    explicit DepthCache(std::size_t faces) : slot(faces) {}
    ~DepthCache() {
      for (auto& s : slot) delete s.load();
    }
  };
  std::shared_ptr<DepthCache> depth_cache;

  /// Whether the closed picture of polygon p contains the centre of pixel (i, j).
  bool covers(const RasterPolygon& p, int i, int j) const;
  /// The sign of a's side-k function at the picture point (x, y) (an exact double pair).
  int side_sign(const RasterPolygon& p, int k, double x, double y) const;
  /// The sign of z_a - z_b at the exact picture point (x, y): negative when a is nearer.
  int depth_order(const RasterPolygon& a, const RasterPolygon& b, double x, double y) const;
  /// The sign of p's depth denominator at (x, y) (perspective; 1 orthographic).
  int denominator_sign(const RasterPolygon& p, double x, double y) const;
  /// The seen-over order at (x, y): true when a is seen over b (nearer; on a tie, rank, then id).
  bool nearer(const RasterPolygon& a, const RasterPolygon& b, double x, double y) const;
};

/// The raster scene of `bodies` under `camera`: every face that can be seen (LineDrawing's
/// facing and back_faces_unseen, as the vector routes; faces seen edge-on and faces of zero
/// area left out) as convex picture polygons (scene_polygons.hpp's: a convex face as itself
/// without corners on a straight side, any other face as its exact triangles), on a grid of
/// width x height pixels (or on `grid` when given: the exam's own grid). Perspective: every
/// body must lie in front of the eye (the caller checks). The bodies must outlive the scene.
RasterScene raster_scene(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineDrawing& lines,
                         int width, int height, unsigned threads = 0, const RasterGrid* grid = nullptr);

/// The face seen at each pixel centre, row by row from the top: the global face number
/// (RasterScene::faces) or -1 for the background.
struct FaceIdBuffer {
  int width = 0, height = 0;
  std::vector<std::int32_t> ids;
  std::vector<std::int32_t> polygons;  // the polygon seen (RasterScene::polygons), -1: none
  std::int32_t& at(int i, int j) { return ids[static_cast<std::size_t>(j) * width + i]; }
  std::int32_t at(int i, int j) const { return ids[static_cast<std::size_t>(j) * width + i]; }
};

/// The seen polygon at pixel (i, j) among `candidates` (polygon indices), -1 when none covers
/// it: the reference every algorithm must equal (ray casting uses it directly).
int seen_among(const RasterScene& s, const std::vector<int>& candidates, int i, int j);

}  // namespace hlr
