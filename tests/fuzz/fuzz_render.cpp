// libFuzzer target for the render pipeline: bytes become a small scene of boxes
// (coordinates in eighths, some thin, touching or interpenetrating) and a view (orthographic
// along small integer directions, or perspective from an eye anywhere outside the bodies,
// possibly on a face plane or on a surface); both hidden-line routes run and must agree on
// every piece of every edge; the visible surfaces must be consistent in every cell
// and cover exactly the area the course's Weiler–Atherton algorithm finds; painting the
// priority list must show at the centre of every Weiler–Atherton visible piece the
// face that piece belongs to; the four raster algorithms must give the same face at
// every pixel centre, inside that face's visible polygons. A disagreement
// aborts (a finding). Exact throughout.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <tuple>

#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/plot/plot.hpp"
#include "algorithms/surfaces/priority_list.hpp"
#include "algorithms/raster/ray_casting.hpp"
#include "algorithms/raster/raster_scene.hpp"
#include "algorithms/raster/scanline.hpp"
#include "algorithms/raster/warnock.hpp"
#include "algorithms/raster/zbuffer.hpp"
#include "algorithms/hlr/roberts.hpp"
#include "algorithms/surfaces/visible_surfaces.hpp"
#include "algorithms/clip/weiler_atherton.hpp"

using namespace hlr;

namespace {

struct Bytes {
  const std::uint8_t* p;
  std::size_t n, i = 0;
  int next() { return i < n ? p[i++] : 0; }
  Rational eighths(int lo, int span) {  // lo + (0..span) in eighths
    Rational r(lo * 8 + next() % (span * 8 + 1), 8);
    r.canonicalize();
    return r;
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 8) return 0;
  Bytes b{data, size};
  const int nbodies = 1 + b.next() % 4;
  std::vector<Polyhedron> bodies;
  for (int k = 0; k < nbodies; ++k) {
    Rational lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = b.eighths(0, 6);
      hi[a] = lo[a] + b.eighths(0, 3) + Rational(1, 8);
    }
    bodies.push_back(make_box(Point3(lo[0], lo[1], lo[2]), Point3(hi[0], hi[1], hi[2])));
  }
  Camera cam;
  try {
    if (b.next() % 2) {
      int d[3];
      for (int& x : d) x = b.next() % 5 - 2;
      if (!d[0] && !d[1] && !d[2]) d[2] = 1;
      cam = make_orthographic(Vector3(d[0], d[1], d[2]));
    } else {
      Point3 eye(b.eighths(-2, 12), b.eighths(-2, 12), b.eighths(-2, 12));
      Point3 target(b.eighths(0, 8), b.eighths(0, 8), b.eighths(0, 8));
      cam = make_perspective(eye, target);
    }
  } catch (const std::invalid_argument&) {
    return 0;
  }
  std::vector<const Polyhedron*> ptrs;
  for (const Polyhedron& p : bodies) ptrs.push_back(&p);
  LineOptions o;
  o.edges = EdgeSelection::All;
  o.intersections = false;
  LineDrawing f;
  RobertsResult r;
  try {
    r = roberts(ptrs, cam, o);
  } catch (const BodyError&) {
    return 0;  // the eye inside a box
  }
  f = face_occluders(ptrs, cam, o);  // must take whatever Roberts takes
  // A finding: say what it is (the scene, the view, the edge, both routes' pieces), then abort.
  auto finding = [&](const Segment& s, const Segment* g) {
    std::fprintf(stderr, "fuzz_render: the routes differ\n");
    for (const Polyhedron& p : bodies)
      std::fprintf(stderr, "  box %s - %s\n", to_string(p.vertices()[0]).c_str(), to_string(p.vertices()[7]).c_str());
    if (cam.perspective)
      std::fprintf(stderr, "  eye %s target %s\n", to_string(cam.eye).c_str(), to_string(cam.target).c_str());
    else
      std::fprintf(stderr, "  view %s\n", to_string(cam.direction).c_str());
    std::fprintf(stderr, "  edge %s - %s of body %d\n", to_string(s.from()).c_str(), to_string(s.to()).c_str(), s.body);
    for (const Piece& p : s.pieces)
      std::fprintf(stderr, "  roberts %s..%s %s\n", to_string(p.t0).c_str(), to_string(p.t1).c_str(), p.visible ? "visible" : "hidden");
    if (g)
      for (const Piece& p : g->pieces)
        std::fprintf(stderr, "  faces   %s..%s %s\n", to_string(p.t0).c_str(), to_string(p.t1).c_str(), p.visible ? "visible" : "hidden");
    std::abort();
  };
  std::map<std::tuple<int, int, int>, const Segment*> by_edge;
  for (const Segment& s : f.segments)
    if (s.kind == Segment::Kind::Edge) by_edge[{s.body, s.v0, s.v1}] = &s;
  for (const Segment& s : r.segments) {
    if (s.kind != Segment::Kind::Edge) continue;  // Roberts always adds intersection lines
    auto it = by_edge.find({s.body, s.v0, s.v1});
    if (it == by_edge.end()) finding(s, nullptr);
    const Segment& g = *it->second;
    if (g.pieces.size() != s.pieces.size()) finding(s, &g);
    for (std::size_t i = 0; i < s.pieces.size(); ++i)
      if (!(g.pieces[i].t0 == s.pieces[i].t0) || !(g.pieces[i].t1 == s.pieces[i].t1) || g.pieces[i].visible != s.pieces[i].visible)
        finding(s, &g);
  }
  // The plotting 2D stage on the same drawing: the fewest strokes, nothing lost,
  // pen order a permutation that never lengthens the greedy travel.
  PlotOptions po;
  po.hidden = true;
  Plot plot = make_plot(f, cam, po);
  PlotOptions raw = po;
  raw.dedup = raw.chain = false;
  Plot q = make_plot(f, cam, raw);
  const double tol = 1e-9 * (q.stats.pen_down_length + 1);
  if (plot.stats.path_count != plot.stats.min_path_count ||
      std::fabs(q.stats.pen_down_length - plot.stats.pen_down_length - plot.stats.duplicate_length) > tol) {
    std::fprintf(stderr, "fuzz_render: 2D stage: paths %zu (minimum %zu), raw length %.17g, clean %.17g + duplicates %.17g\n",
                 plot.stats.path_count, plot.stats.min_path_count, q.stats.pen_down_length, plot.stats.pen_down_length,
                 plot.stats.duplicate_length);
    std::abort();
  }
  order_plot(plot, {plot.bounds[0], plot.bounds[3]});
  if (plot.stats.pen_up_length > plot.stats.pen_up_greedy * (1 + 1e-12) + 1e-12) {
    std::fprintf(stderr, "fuzz_render: 2-opt lengthened the pen-up travel\n");
    std::abort();
  }
  // Visible surfaces: every cell's probes agree, and the two routes see the same area per face.
  LineOptions all = o;
  all.intersections = true;
  LineDrawing d = face_occluders(ptrs, cam, all);
  SurfaceOptions so;
  so.check_cycles = true;
  VisibleSurfaces vs;
  try {
    vs = visible_surfaces(ptrs, cam, d, so);
  } catch (const std::invalid_argument&) {
    return 0;  // perspective with a box reaching the eye's plane
  }
  WeilerAthertonResult wa = weiler_atherton(ptrs, cam, d);
  std::vector<SurfacePiece> pieces;
  for (const WaPolygon& p : wa.visible) pieces.push_back({p.body, p.face, p.pts});
  VisibleSurfaces ws = surfaces_from_pieces(pieces, ptrs, cam, so);
  std::map<std::pair<int, int>, Rational> a, w;
  for (const VisibleFace& f2 : vs.faces)
    for (const VisiblePolygon& p : f2.polygons) a[{f2.body, f2.face}] += p.area2;
  for (const VisibleFace& f2 : ws.faces)
    for (const VisiblePolygon& p : f2.polygons) w[{f2.body, f2.face}] += p.area2;
  if (vs.stats.label_mismatches || ws.stats.label_mismatches || a != w) {
    std::fprintf(stderr, "fuzz_render: visible surfaces: mismatched cells %zu / %zu, areas %s\n", vs.stats.label_mismatches,
                 ws.stats.label_mismatches, a == w ? "equal" : "differ");
    for (const Polyhedron& p : bodies)
      std::fprintf(stderr, "  box %s - %s\n", to_string(p.vertices()[0]).c_str(), to_string(p.vertices()[7]).c_str());
    std::abort();
  }
  // The painter's list: at the centre of each visible convex piece of Weiler–Atherton, the last
  // polygon painted that contains it (strictly) belongs to the piece's face.
  PriorityResult pl = priority_list(ptrs, cam, d);
  for (const WaPolygon& p : wa.visible) {
    Exact2 c{Rational(0), Rational(0)};
    for (const Exact2& x : p.pts) c[0] += x[0], c[1] += x[1];
    Rational n(static_cast<long>(p.pts.size()));
    c[0] /= n, c[1] /= n;
    int shown = -1;
    bool border = false;
    for (auto it = pl.order.rbegin(); it != pl.order.rend() && shown < 0 && !border; ++it) {
      const auto& q = pl.polygons[*it].pts;
      int in = 1;
      for (std::size_t k = 0; k < q.size() && in >= 0; ++k) {
        int o = orient2d(q[k], q[(k + 1) % q.size()], c);
        if (o < 0) in = -1;
        else if (o == 0) in = 0;
      }
      if (in == 0) border = true;
      if (in > 0) shown = *it;
    }
    if (border) continue;
    if (shown < 0 || pl.polygons[shown].body != p.body || pl.polygons[shown].face != p.face) {
      std::fprintf(stderr, "fuzz_render: the painter's list shows %s at the centre of a visible piece of body %d face %d\n",
                   shown < 0 ? "nothing" : "another face", p.body, p.face);
      std::abort();
    }
  }
  // The raster algorithms: the same face at every pixel centre, and that face's
  // visible polygons contain the centre.
  RasterScene rs = raster_scene(ptrs, cam, d, 24, 18, 1);
  const FaceIdBuffer rz = zbuffer(rs, {1}), rl = scanline(rs, {1}), rw = warnock(rs, {1}), rr = ray_cast(rs, {1});
  if (rz.ids != rl.ids || rz.ids != rw.ids || rz.ids != rr.ids) {
    std::fprintf(stderr, "fuzz_render: the raster algorithms disagree\n");
    std::abort();
  }
  std::map<std::pair<int, int>, const VisibleFace*> of;
  for (const VisibleFace& f2 : vs.faces) of[{f2.body, f2.face}] = &f2;
  for (int j = 0; j < 18; ++j)
    for (int i = 0; i < 24; ++i) {
      const int id = rz.at(i, j);
      if (id < 0) continue;
      auto it = of.find({rs.faces[id][0], rs.faces[id][1]});
      bool in = false;
      const Exact2 c = rs.grid.centre(i, j);
      // 1 inside, 0 on the border, -1 outside a ring (even-odd).
      auto side = [&](const std::vector<Exact2>& ring) {
        bool odd = false;
        for (std::size_t k = 0; k < ring.size(); ++k) {
          const Exact2 &a2 = ring[k], &b2 = ring[(k + 1) % ring.size()];
          const int s2 = orient2d(a2, b2, c);
          if (s2 == 0 && std::min(a2[0], b2[0]) <= c[0] && c[0] <= std::max(a2[0], b2[0]) && std::min(a2[1], b2[1]) <= c[1] &&
              c[1] <= std::max(a2[1], b2[1]))
            return 0;
          if ((a2[1] > c[1]) != (b2[1] > c[1]) && ((s2 > 0) == (b2[1] > c[1]))) odd = !odd;
        }
        return odd ? 1 : -1;
      };
      if (it != of.end())
        for (const VisiblePolygon& p : it->second->polygons) {
          const int o = side(p.outer_2d);
          if (o < 0) continue;
          bool here = true;
          for (const auto& h : p.holes_2d) {
            const int hs = side(h);
            if (hs > 0) here = false;  // strictly inside a hole (its border belongs to the closed piece)
          }
          in = in || o == 0 || here;
        }
      if (!in) {
        std::fprintf(stderr, "fuzz_render: pixel (%d, %d) shows body %d face %d outside its visible polygons\n", i, j, rs.faces[id][0],
                     rs.faces[id][1]);
        std::abort();
      }
    }
  return 0;
}
