// Roberts' algorithm through convex pieces (see roberts_pieces.hpp).
#include "algorithms/hlr/roberts_pieces.hpp"

#include "algorithms/support/progress.hpp"

#include <map>

#include "algorithms/solids/convex_decomposition.hpp"
#include "algorithms/solids/convexity.hpp"
#include "algorithms/hlr/int128_interval.hpp"
#include "algorithms/hlr/intersection_lines.hpp"
#include "algorithms/solids/triangulate.hpp"

namespace hlr {
namespace {

struct Occluder {
  BodyMatrixData V;
  FastBody fast;
};

// A glue occluder: the side planes of two opposite coplanar faces, for edges in `plane`.
struct Glue {
  Plane plane;
  BodyMatrixData V;
};

// Inward side planes of a convex face polygon: through each edge, containing the normal.
std::vector<Plane> side_planes(const Polyhedron& p, int f) {
  const Face& face = p.faces()[f];
  Vector3 n = p.planes()[f].normal();
  std::vector<Plane> out;
  for (std::size_t k = 0; k < face.size(); ++k) {
    const Point3& a = p.vertices()[face[k]];
    const Point3& b = p.vertices()[face[(k + 1) % face.size()]];
    Vector3 m = cross(n, b - a);
    Rational d = -dot(m, a - Point3());
    Plane h(m.x(), m.y(), m.z(), d);
    // Orient toward the face: some vertex of the face strictly inside.
    for (int v : face)
      if (int s = sgn(h.value(p.vertices()[v])); s != 0) {
        if (s < 0) h = h.opposite();
        break;
      }
    out.push_back(h);
  }
  return out;
}

BodyMatrixData matrix_of(const std::vector<Plane>& planes) {
  BodyMatrixData V(4, static_cast<int>(planes.size()));
  for (std::size_t j = 0; j < planes.size(); ++j)
    for (int k = 0; k < 4; ++k) V(k, static_cast<int>(j)) = planes[j][k];
  return V;
}

// Interior-positive body matrix of a convex piece (outward planes negated).
BodyMatrixData piece_matrix(const Polyhedron& p) {
  std::vector<Plane> inward;
  for (const Plane& h : p.planes()) inward.push_back(h.opposite());
  return matrix_of(inward);
}

bool edge_on(const Plane& h, const Camera& cam) {
  if (cam.perspective) return h.value(cam.eye) == 0;
  return dot(h.normal(), cam.direction) == 0;
}

bool same_plane_opposite(const Plane& a, const Plane& b) { return a == b.opposite(); }

void check_solid(const Polyhedron& p, int i) {
  const MeshReport& r = p.report();
  if (!r.valid_solid()) throw BodyError(i, "is not a valid closed solid: " + solid_problem(r));
  if (!(six_volume(p) > 0)) throw BodyError(i, "is not a valid closed solid: its volume is not positive (inside out)");
  if (!r.negative_components.empty())
    throw BodyError(i, "has a component with negative volume (the one with face " + std::to_string(r.negative_components[0]) +
                           ": inside out, or a cavity): Roberts' algorithm takes solids without; use --method faces");
}

// The convex pieces must fill the body exactly; they do not when the mesh's components overlap
// (one mesh that is two interpenetrating solids: the decomposition keeps one of them).
void check_volume(const Polyhedron& p, const std::vector<Polyhedron>& pieces, int i) {
  Rational sum = 0;
  for (const Polyhedron& q : pieces) sum += six_volume(q);
  if (sum != six_volume(p))
    throw BodyError(i, "decomposes into convex pieces of volume " + to_string(sum / 6) + " != its volume " +
                           to_string(six_volume(p) / 6) +
                           " (its components overlap: give each solid as its own body, or use --method faces)");
}

}  // namespace

LineDrawing roberts_pieces(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineOptions& opt) {
  LineDrawing res;
  res.stats.method = Method::RobertsPieces;
  const RowVector4 g = camera.viewpoint();
  std::vector<Occluder> occ;
  std::vector<Glue> glue;
  std::vector<std::vector<Polyhedron>> pieces(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const Polyhedron& p = *bodies[i];
    check_solid(p, static_cast<int>(i));
    if (convexity(p).convex()) {
      pieces[i].push_back(p);
    } else {
      if (progress_enabled()) progress("body " + std::to_string(i) + " of " + std::to_string(bodies.size()) + " is not convex: decomposing");
      for (ConvexPiece& c : convex_decomposition(p).pieces) pieces[i].push_back(std::move(c.body));
      check_volume(p, pieces[i], static_cast<int>(i));
    }
    for (const Polyhedron& q : pieces[i]) {
      if (camera.perspective) {
        bool inside = true;
        for (const Plane& h : q.planes()) inside = inside && h.value(camera.eye) < 0;
        if (inside)
          throw BodyError(static_cast<int>(i), "contains the eye " + to_string(camera.eye) + ": an eye inside a solid sees nothing");
      }
      Occluder o{piece_matrix(q), {}};
      o.fast = prepare_fast_body(o.V, g);
      occ.push_back(std::move(o));
    }
    // Glue between pieces of this body across cut planes seen edge-on.
    for (std::size_t a = 0; a < pieces[i].size(); ++a)
      for (std::size_t b = a + 1; b < pieces[i].size(); ++b)
        for (std::size_t fa = 0; fa < pieces[i][a].faces().size(); ++fa)
          for (std::size_t fb = 0; fb < pieces[i][b].faces().size(); ++fb) {
            const Plane& ha = pieces[i][a].planes()[fa];
            if (!same_plane_opposite(ha, pieces[i][b].planes()[fb]) || !edge_on(ha, camera)) continue;
            std::vector<Plane> sides = side_planes(pieces[i][a], static_cast<int>(fa));
            for (const Plane& h : side_planes(pieces[i][b], static_cast<int>(fb))) sides.push_back(h);
            glue.push_back({ha, matrix_of(sides)});
          }
    std::vector<signed char> fc;
    for (const Plane& h : p.planes()) {
      Rational e = camera.perspective ? h.value(camera.eye) : dot(h.normal(), camera.direction);
      fc.push_back(static_cast<signed char>(sgn(e)));
    }
    res.facing.push_back(std::move(fc));
  }
  auto depth_of = [&](const Segment& s) -> std::optional<std::pair<Rational, Rational>> {
    if (!camera.perspective) return std::nullopt;
    return std::make_pair(camera.depth(s.from()), camera.depth(s.to()));
  };
  auto solve = [&](Segment& s) {
    std::vector<std::pair<Rational, Rational>> hidden;
    auto add = [&](const OpenInterval& iv) {
      if (iv.empty) return;
      Rational lo = iv.lo && *iv.lo > 0 ? *iv.lo : Rational(0);
      Rational hi = iv.hi && *iv.hi < 1 ? *iv.hi : Rational(1);
      if (lo < hi) hidden.push_back({lo, hi});
    };
    for (const Occluder& o : occ) {
      ++res.stats.pairs_tested;
      if (auto iv = fast_hidden_interval(s.from(), s.to(), o.fast)) {
        add(*iv);
      } else {
        ++res.stats.pairs_rational;
        add(hidden_interval(s.from(), s.to(), o.V, g));
      }
    }
    for (const Glue& gl : glue)
      if (gl.plane.value(s.from()) == 0 && gl.plane.value(s.to()) == 0) add(hidden_interval(s.from(), s.to(), gl.V, g));
    s.pieces = pieces_from_hidden(std::move(hidden), depth_of(s));
  };
  for (std::size_t i = 0; i < bodies.size(); ++i)
    for (Segment& s : body_edge_segments(*bodies[i], static_cast<int>(i), res.facing[i], opt, res.stats)) {
      if (s.self_hidden)
        s.pieces = pieces_from_hidden({{Rational(0), Rational(1)}}, depth_of(s));
      else
        solve(s);
      res.segments.push_back(std::move(s));
    }
  // Intersection lines of different bodies: their faces' triangles, exactly; pieces of one
  // face pair's line are joined end to end.
  std::map<std::tuple<int, int, int, int>, std::vector<std::pair<Point3, Point3>>> lines;
  for (std::size_t a = 0; a < bodies.size(); ++a)
    for (std::size_t b = a + 1; b < bodies.size(); ++b)
      for (std::size_t fa = 0; fa < bodies[a]->faces().size(); ++fa)
        for (std::size_t fb = 0; fb < bodies[b]->faces().size(); ++fb) {
          const Polyhedron &A = *bodies[a], &B = *bodies[b];
          const Face &F = A.faces()[fa], &G = B.faces()[fb];
          for (const FaceTriangle& s : triangulate_face(A.vertices(), F, A.planes()[fa].normal()))
            for (const FaceTriangle& t : triangulate_face(B.vertices(), G, B.planes()[fb].normal())) {
              TriangleRef x{{&A.vertices()[F[s.v[0]]], &A.vertices()[F[s.v[1]]], &A.vertices()[F[s.v[2]]]}, s.edge};
              TriangleRef y{{&B.vertices()[G[t.v[0]]], &B.vertices()[G[t.v[1]]], &B.vertices()[G[t.v[2]]]}, t.edge};
              if (auto seg = triangle_intersection(x, y)) {
                Point3 p0 = seg->first, p1 = seg->second;
                if (p1 < p0) std::swap(p0, p1);
                lines[{static_cast<int>(a), static_cast<int>(b), static_cast<int>(fa), static_cast<int>(fb)}].push_back({p0, p1});
              }
            }
        }
  for (auto& [key, segs] : lines) {
    std::sort(segs.begin(), segs.end(), [](const auto& x, const auto& y) { return x.first < y.first || (x.first == y.first && x.second < y.second); });
    std::vector<std::pair<Point3, Point3>> joined;
    for (auto& sg : segs) {
      if (!joined.empty() && joined.back() == sg) continue;
      if (!joined.empty() && joined.back().second == sg.first &&
          cross(joined.back().second - joined.back().first, sg.second - sg.first).is_zero())
        joined.back().second = sg.second;
      else
        joined.push_back(sg);
    }
    for (auto& [p0, p1] : joined) {
      Segment s;
      s.kind = Segment::Kind::Intersection;
      s.line = LineKind::Intersection;
      s.body = std::get<0>(key);
      s.body2 = std::get<1>(key);
      s.face0 = std::get<2>(key);
      s.face1 = std::get<3>(key);
      s.set_ends(p0, p1);
      solve(s);
      ++res.stats.intersection_segments;
      res.segments.push_back(std::move(s));
    }
  }
  return res;
}

}  // namespace hlr
