// The scene's faces as convex picture polygons with exact 3D corners. See scene_polygons.hpp.
#include "algorithms/picture/scene_polygons.hpp"

#include <algorithm>

#include "algorithms/solids/face_triangles.hpp"
#include "algorithms/support/parallel.hpp"

namespace hlr {

Rational picture_area2(const std::vector<Exact2>& p) {
  Rational s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Exact2 &a = p[i], &b = p[(i + 1) % p.size()];
    s += a[0] * b[1] - a[1] * b[0];
  }
  return s;
}

namespace {

bool is_convex(const std::vector<Exact2>& poly) {
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (orient2d(poly[i], poly[(i + 1) % poly.size()], poly[(i + 2) % poly.size()]) < 0) return false;
  return true;
}

}  // namespace

std::vector<std::vector<int>> face_pieces(const Polyhedron& p, int f, const std::vector<Exact2>& pic) {
  std::vector<std::vector<int>> out;
  const std::size_t n = pic.size();
  std::vector<int> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<int>(i);
  const int a = n == 3 ? orient2d(pic[0], pic[1], pic[2]) : sgn(picture_area2(pic));
  if (a == 0) return out;
  if (a < 0) std::reverse(order.begin(), order.end());
  std::vector<Exact2> ccw;
  for (int i : order) ccw.push_back(pic[i]);
  if (n == 3) {  // a triangle with an area: convex, no corner on a straight side
    out.push_back(order);
    return out;
  }
  if (is_convex(ccw)) {
    std::vector<int> clean;
    for (std::size_t i = 0; i < n; ++i)  // drop corners on a straight side
      if (orient2d(ccw[(i + n - 1) % n], ccw[i], ccw[(i + 1) % n]) != 0) clean.push_back(order[i]);
    out.push_back(std::move(clean));
    return out;
  }
  for (const FaceTriangle& t : face_triangles(p, f).triangles) {
    std::vector<int> tri{t.v[0], t.v[1], t.v[2]};
    const int o = orient2d(pic[tri[0]], pic[tri[1]], pic[tri[2]]);
    if (o == 0) continue;
    if (o < 0) std::reverse(tri.begin(), tri.end());
    out.push_back(std::move(tri));
  }
  return out;
}

std::vector<ScenePolygon> scene_polygons(const std::vector<const Polyhedron*>& bodies, const PicturePlane& pp,
                                         const LineDrawing& lines) {
  std::vector<ScenePolygon> out;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Polyhedron& p = *bodies[b];
    std::vector<Exact2> pic(p.num_vertices());  // every vertex projected once, on all cores
    ParallelLoop().for_each(pic.size(), 1024, [&](std::size_t i) { pic[i] = pp.project(p.vertices()[i]); });
    for (std::size_t f = 0; f < p.num_faces(); ++f) {
      if (p.planes()[f].is_degenerate()) continue;
      if (b < lines.back_faces_unseen.size() && lines.back_faces_unseen[b] && lines.facing[b][f] < 0) continue;
      const Face& face = p.faces()[f];
      std::vector<Exact2> fp;
      for (int v : face) fp.push_back(pic[v]);
      int piece = 0;
      for (const std::vector<int>& q : face_pieces(p, static_cast<int>(f), fp)) {
        ScenePolygon sp{static_cast<int>(b), static_cast<int>(f), piece++, {}, {}, {}};
        for (int i : q) sp.corners.push_back(p.vertices()[face[i]]), sp.pts.push_back(fp[i]), sp.verts.push_back(face[i]);
        out.push_back(std::move(sp));
      }
    }
  }
  return out;
}

}  // namespace hlr
