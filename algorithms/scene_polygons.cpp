// The scene's faces as convex picture polygons with exact 3D corners. See scene_polygons.hpp.
#include "algorithms/scene_polygons.hpp"

#include <algorithm>

#include "algorithms/face_triangles.hpp"
#include "algorithms/parallel.hpp"

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

// A polygon counter-clockwise in the picture, or nothing when its picture has no area.
bool add(std::vector<ScenePolygon>& out, ScenePolygon p) {
  Rational a = picture_area2(p.pts);
  if (a == 0) return false;
  if (a < 0) {
    std::reverse(p.pts.begin(), p.pts.end());
    std::reverse(p.corners.begin(), p.corners.end());
    std::reverse(p.verts.begin(), p.verts.end());
  }
  out.push_back(std::move(p));
  return true;
}

}  // namespace

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
      ScenePolygon whole{static_cast<int>(b), static_cast<int>(f), 0, {}, {}};
      for (int v : p.faces()[f]) whole.corners.push_back(p.vertices()[v]), whole.pts.push_back(pic[v]), whole.verts.push_back(v);
      const int a = whole.pts.size() == 3 ? orient2d(whole.pts[0], whole.pts[1], whole.pts[2]) : sgn(picture_area2(whole.pts));
      if (a == 0) continue;
      if (a < 0) {
        std::reverse(whole.pts.begin(), whole.pts.end());
        std::reverse(whole.corners.begin(), whole.corners.end());
        std::reverse(whole.verts.begin(), whole.verts.end());
      }
      if (whole.pts.size() == 3) {  // a triangle with an area: convex, no corner on a straight side
        out.push_back(std::move(whole));
        continue;
      }
      if (is_convex(whole.pts)) {
        ScenePolygon clean{whole.body, whole.face, 0, {}, {}};
        const std::size_t n = whole.pts.size();
        for (std::size_t i = 0; i < n; ++i)  // drop corners on a straight side
          if (orient2d(whole.pts[(i + n - 1) % n], whole.pts[i], whole.pts[(i + 1) % n]) != 0)
            clean.pts.push_back(whole.pts[i]), clean.corners.push_back(whole.corners[i]), clean.verts.push_back(whole.verts[i]);
        out.push_back(std::move(clean));
        continue;
      }
      FaceTriangles ft = face_triangles(p, static_cast<int>(f));
      int piece = 0;
      for (const FaceTriangle& t : ft.triangles) {
        ScenePolygon tri{whole.body, whole.face, piece, {}, {}};
        for (int k = 0; k < 3; ++k) {
          const int v = p.faces()[f][t.v[k]];
          tri.corners.push_back(p.vertices()[v]);
          tri.pts.push_back(pic[v]);
          tri.verts.push_back(v);
        }
        if (add(out, std::move(tri))) ++piece;
      }
    }
  }
  return out;
}

}  // namespace hlr
