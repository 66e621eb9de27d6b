// Convex decomposition (see convex_decomposition.hpp). Heavy CGAL templates (Nef polyhedra):
// kept in this one translation unit.
#include "algorithms/solids/convex_decomposition.hpp"

#include "algorithms/support/progress.hpp"

#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/convert_nef_polyhedron_to_polygon_mesh.h>
#include <CGAL/convex_decomposition_3.h>
#include <CGAL/convex_hull_3.h>

#include <map>
#include <numeric>
#include <stdexcept>

#include "algorithms/solids/convexity.hpp"
#include "algorithms/solids/triangulate.hpp"
#include "kernel/epeck_bridge.hpp"

namespace hlr {
namespace {

using Nef = CGAL::Nef_polyhedron_3<Epeck>;
using SM = CGAL::Surface_mesh<Epeck::Point_3>;

Nef to_nef(const Polyhedron& p) {
  SM sm;
  std::vector<SM::Vertex_index> vs;
  for (const Point3& v : p.vertices()) vs.push_back(sm.add_vertex(to_epeck(v)));
  for (const Face& f : p.faces()) {
    std::vector<SM::Vertex_index> face;
    for (int v : f) face.push_back(vs[v]);
    sm.add_face(face);
  }
  return Nef(sm);
}

// The connected components (by shared edges) of a polygon mesh, each as a polyhedron.
std::vector<Polyhedron> components(const SM& sm) {
  std::map<SM::Vertex_index, int> gid;
  std::vector<Point3> pts;
  for (auto v : sm.vertices()) {
    gid[v] = static_cast<int>(pts.size());
    pts.push_back(from_epeck(sm.point(v)));
  }
  std::vector<Face> faces;
  for (auto f : sm.faces()) {
    Face face;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) face.push_back(gid[v]);
    faces.push_back(face);
  }
  // Union-find over faces sharing an (undirected) edge.
  std::vector<int> parent(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::map<std::pair<int, int>, int> first;
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (std::size_t k = 0; k < faces[f].size(); ++k) {
      int a = faces[f][k], b = faces[f][(k + 1) % faces[f].size()];
      auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = first.find(key);
      if (it == first.end()) first[key] = static_cast<int>(f);
      else parent[find(static_cast<int>(f))] = find(it->second);
    }
  std::map<int, std::vector<int>> groups;
  for (std::size_t f = 0; f < faces.size(); ++f) groups[find(static_cast<int>(f))].push_back(static_cast<int>(f));
  std::vector<Polyhedron> out;
  for (const auto& [root, fs] : groups) {
    std::map<int, int> local;
    std::vector<Point3> vs;
    std::vector<Face> lf;
    for (int f : fs) {
      Face face;
      for (int v : faces[f]) {
        auto it = local.find(v);
        if (it == local.end()) {
          it = local.emplace(v, static_cast<int>(vs.size())).first;
          vs.push_back(pts[v]);
        }
        face.push_back(it->second);
      }
      lf.push_back(face);
    }
    out.emplace_back(vs, orient_faces(vs, lf));
  }
  return out;
}

std::vector<Polyhedron> to_polyhedra(const Nef& n) {
  SM sm;
  CGAL::convert_nef_polyhedron_to_polygon_mesh(n, sm, false);
  return components(sm);
}

// The closed half-space side(x) <= 0, cut down to a box around p (Nef polyhedra on a
// non-extended kernel cannot hold unbounded sets): the convex hull of the box corners on that
// side and the points where the plane crosses the box edges, exact.
Nef half_box(const Polyhedron& p, const Plane& side) {
  Rational lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = p.vertices()[0][k];
  for (const Point3& v : p.vertices())
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
  for (int k = 0; k < 3; ++k) {
    Rational m = hi[k] - lo[k] + 1;
    lo[k] -= m;
    hi[k] += m;
  }
  std::vector<Point3> corners;
  for (int c = 0; c < 8; ++c) corners.emplace_back(c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]);
  std::vector<Epeck::Point_3> pts;
  for (int c = 0; c < 8; ++c) {
    Rational vc = side.value(corners[c]);
    if (vc <= 0) pts.push_back(to_epeck(corners[c]));
    for (int k = 0; k < 3; ++k) {
      int e = c | (1 << k);
      if (e == c) continue;
      Rational ve = side.value(corners[e]);
      if ((vc < 0 && ve > 0) || (vc > 0 && ve < 0)) {
        Rational t = vc / (vc - ve);
        pts.push_back(to_epeck(corners[c] + t * (corners[e] - corners[c])));
      }
    }
  }
  SM hull;
  CGAL::convex_hull_3(pts.begin(), pts.end(), hull);
  return Nef(hull);
}

void split(const Polyhedron& p, const Nef& n, int depth, Decomposition& d) {
  ConvexityResult cv = convexity(p);
  if (cv.convex()) {
    d.pieces.push_back({p, {}});
    if (progress_enabled()) progress("decomposing into convex pieces: " + std::to_string(d.pieces.size()) + " so far");
    return;
  }
  if (depth > 256) throw std::runtime_error("convex decomposition does not terminate (depth 256)");
  const Plane& h = p.planes()[cv.face];
  d.cuts.push_back(h);
  for (const Plane& side : {h, h.opposite()}) {
    Nef part = (n * half_box(p, side)).regularization();
    for (Polyhedron& q : to_polyhedra(part)) split(q, to_nef(q), depth + 1, d);
  }
}

// Area (times a constant) of a convex polygon clipped by a triangle, in the 2D coordinates
// (i, j) — Sutherland-Hodgman against the triangle's three sides, exact.
using P2 = std::array<Rational, 2>;
Rational area2(const std::vector<P2>& poly) {
  Rational a = 0;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const P2 &p = poly[k], &q = poly[(k + 1) % poly.size()];
    a += p[0] * q[1] - p[1] * q[0];
  }
  return a;
}
std::vector<P2> clip(std::vector<P2> poly, const P2& a, const P2& b) {  // keep left of a->b
  auto side = [&](const P2& p) -> Rational { return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]); };
  std::vector<P2> out;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const P2 &p = poly[k], &q = poly[(k + 1) % poly.size()];
    Rational sp = side(p), sq = side(q);
    if (sp >= 0) out.push_back(p);
    if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) {
      Rational t = sp / (sp - sq);
      out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
    }
  }
  return out;
}

// Where each piece face lies: the share of its area covered by original faces of the same
// oriented plane (coplanar faces of a valid solid do not overlap), exactly.
void label_faces(const Polyhedron& body, ConvexPiece& piece) {
  const auto& op = body.planes();
  for (std::size_t f = 0; f < piece.body.faces().size(); ++f) {
    const Plane& h = piece.body.planes()[f];
    Vector3 n = h.normal();
    int k = 0;
    for (int a = 1; a < 3; ++a)
      if (abs(n[a]) > abs(n[k])) k = a;
    int i = (k + 1) % 3, j = (k + 2) % 3;
    std::vector<P2> poly;
    for (int v : piece.body.faces()[f]) poly.push_back({piece.body.vertices()[v][i], piece.body.vertices()[v][j]});
    if (area2(poly) < 0) std::reverse(poly.begin(), poly.end());
    Rational whole = area2(poly), covered = 0;
    for (std::size_t g = 0; g < body.faces().size(); ++g) {
      if (!(op[g] == h)) continue;
      const Face& gf = body.faces()[g];
      for (const FaceTriangle& t : triangulate_face(body.vertices(), gf, op[g].normal())) {
        std::array<P2, 3> tri;
        for (int c = 0; c < 3; ++c) tri[c] = {body.vertices()[gf[t.v[c]]][i], body.vertices()[gf[t.v[c]]][j]};
        Rational s = (tri[1][0] - tri[0][0]) * (tri[2][1] - tri[0][1]) - (tri[1][1] - tri[0][1]) * (tri[2][0] - tri[0][0]);
        if (s < 0) std::swap(tri[1], tri[2]);
        std::vector<P2> c = poly;
        for (int e = 0; e < 3 && !c.empty(); ++e) c = clip(c, tri[e], tri[(e + 1) % 3]);
        if (c.size() >= 3) covered += area2(c);
      }
    }
    piece.faces.push_back(covered == 0 ? FaceOrigin::Cut : covered == whole ? FaceOrigin::Surface : FaceOrigin::Mixed);
  }
}

Polyhedron from_cgal(const CGAL::Polyhedron_3<Epeck>& P) {
  std::map<const void*, int> id;
  std::vector<Point3> vs;
  for (auto v = P.vertices_begin(); v != P.vertices_end(); ++v) {
    id[&*v] = static_cast<int>(vs.size());
    vs.push_back(from_epeck(v->point()));
  }
  std::vector<Face> faces;
  for (auto f = P.facets_begin(); f != P.facets_end(); ++f) {
    Face face;
    auto h = f->facet_begin();
    do face.push_back(id[&*h->vertex()]);
    while (++h != f->facet_begin());
    faces.push_back(face);
  }
  return Polyhedron(vs, orient_faces(vs, faces));
}

}  // namespace

const char* to_string(FaceOrigin o) {
  switch (o) {
    case FaceOrigin::Surface: return "surface";
    case FaceOrigin::Cut: return "cut";
    case FaceOrigin::Mixed: break;
  }
  return "surface+cut";
}

Rational six_volume(const Polyhedron& body) { return six_signed_volume(body.vertices(), body.faces()); }

Decomposition convex_decomposition(const Polyhedron& body, DecompositionMethod method) {
  const MeshReport& r = body.report();
  if (!r.valid_solid())
    throw std::invalid_argument("convex decomposition needs a valid solid: " + solid_problem(r));
  if (!(six_volume(body) > 0))
    throw std::invalid_argument("convex decomposition needs an outward-oriented solid: the volume is not positive");
  Decomposition d;
  Nef n = to_nef(body);
  if (method == DecompositionMethod::FacePlanes) {
    split(body, n, 0, d);
  } else {
    progress("decomposing into convex pieces (CGAL convex_decomposition_3)");
    CGAL::convex_decomposition_3(n);
    for (auto ci = ++n.volumes_begin(); ci != n.volumes_end(); ++ci) {
      if (!ci->mark()) continue;
      CGAL::Polyhedron_3<Epeck> P;
      n.convert_inner_shell_to_polyhedron(ci->shells_begin(), P);
      d.pieces.push_back({from_cgal(P), {}});
    }
  }
  for (ConvexPiece& p : d.pieces) label_faces(body, p);
  return d;
}

}  // namespace hlr
