// Crease lines of plain meshes (algorithms/hlr/face_engine_edges.cpp, docs/design.md "Crease
// lines"): OpenSCAD's example002, a cone cut by a cube's faces, whose intersection curves meet
// the cube's faces at less than the crease angle near their tangent points. Without the
// continuation a crease stroke stops in mid-face there; with it every line ends on another line,
// in every view, and the drawing stays exact (the oracle of
// tests/support/drawing_oracle.hpp). OpenSCAD's slivers (triangles with a corner of nearly 180
// degrees, from its polygons' triangulation) add no crease of their own: every crease on a
// sliver's edge lies on a fold that the faces around the sliver make.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "algorithms/solids/crease_angle.hpp"
#include "io/pipeline/render.hpp"
#include "io/readers/scene.hpp"
#include "support/drawing_oracle.hpp"

namespace hlr {
namespace {

// Vertices where exactly one line of the drawing's edges (crease, boundary, silhouette) ends.
int free_ends(const RenderResult& r) {
  std::map<int, int> degree;
  for (const Segment& s : r.drawing.segments)
    if (s.kind == Segment::Kind::Edge && (s.line == LineKind::Crease || s.line == LineKind::Boundary || s.line == LineKind::Silhouette))
      ++degree[s.v0], ++degree[s.v1];
  int ends = 0;
  for (const auto& [v, d] : degree) ends += d == 1;
  return ends;
}

RenderResult draw(const ViewRequest& v, bool continued, const std::string& file = "example002.off") {
  RenderOptions o;
  o.view = v;
  o.lines.continue_creases = continued;
  o.lines.intersections = false;
  return render({load_input(std::string(HLR_DATA_DIR) + "/openscad/" + file, "")}, o);
}

const std::vector<ViewRequest> kViews = {ViewRequest{Vector3(1, 1, 1), {}, {}, {}},
                                         ViewRequest{Vector3(-1, Rational(13, 10), Rational(17, 10)), {}, {}, {}},
                                         ViewRequest{Vector3(0, 0, 1), {}, {}, {}}};

// Face f's normal as integers (its cross product times the denominators' product).
std::array<mpz_class, 3> integer_normal(const Polyhedron& p, int f) {
  const Face& t = p.faces()[f];
  const Point3 &a = p.vertices()[t[0]], &b = p.vertices()[t[1]], &c = p.vertices()[t[2]];
  const Vector3 n = cross(b - a, c - a);
  const mpz_class den = n.x().get_den() * n.y().get_den() * n.z().get_den();
  std::array<mpz_class, 3> out;
  for (int k = 0; k < 3; ++k) {
    const Rational q = n[k] * Rational(den);
    out[k] = q.get_num();
  }
  return out;
}

// A triangle with a corner whose cosine is below -49/50 (over 168.5 degrees), exactly.
bool sliver(const Polyhedron& p, int f) {
  const Face& t = p.faces()[f];
  if (t.size() != 3) return false;
  for (int k = 0; k < 3; ++k) {
    const Vector3 u = p.vertices()[t[(k + 1) % 3]] - p.vertices()[t[k]], v = p.vertices()[t[(k + 2) % 3]] - p.vertices()[t[k]];
    const Rational d = dot(u, v);
    if (d < 0 && d * d * 2500 > dot(u, u) * dot(v, v) * 2401) return true;
  }
  return false;
}

std::uint64_t key(int u, int v) { return (static_cast<std::uint64_t>(std::min(u, v)) << 32) | static_cast<std::uint32_t>(std::max(u, v)); }

TEST(CreaseLines, ConeCutByPlanesIsDrawnWhole) {
  int stopped = 0;
  for (const ViewRequest& v : kViews) {
    stopped += free_ends(draw(v, false));
    const RenderResult r = draw(v, true);
    EXPECT_EQ(free_ends(r), 0);
    EXPECT_GT(test::check_visibility(r), 50);
  }
  EXPECT_GE(stopped, 13) << "the cone's curves stop in mid-face without the continuation (7 and 6 free ends)";
}

TEST(CreaseLines, ContinuationDoesNotRunAlongTheConesFacets) {
  // The cone's own edges (12 degrees between its 30 facets) stay undrawn: only edges over half
  // the crease angle continue a line, and only within 45 degrees of its direction.
  const RenderResult plain = draw(ViewRequest{Vector3(1, 1, 1), {}, {}, {}}, false);
  const RenderResult whole = draw(ViewRequest{Vector3(1, 1, 1), {}, {}, {}}, true);
  int added = 0;
  for (const Segment& s : whole.drawing.segments) added += s.line == LineKind::Crease;
  for (const Segment& s : plain.drawing.segments) added -= s.line == LineKind::Crease;
  EXPECT_GT(added, 0);
  EXPECT_LT(added, 40) << "a few edges per curve, not the cone's facets";
}

TEST(CreaseLines, OpenScadSliversAddNoCreases) {
  // Parts made by scripts/openscad_examples.sh: 16, 12 and 8 slivers with creases on their edges.
  const CreaseAngle angle(30);
  for (const char* file : {"example001.off", "example002.off", "example004.off"}) {
    int slivers = 0, on_slivers = 0;  // over the views (a crease seen as a silhouette is drawn as one)
    for (const ViewRequest& v : kViews) {
      const RenderResult r = draw(v, true, file);
      EXPECT_EQ(free_ends(r), 0) << file;
      const Polyhedron& p = r.bodies[0]->body;
      std::map<std::uint64_t, std::vector<int>> faces_of;  // edge -> its faces
      for (std::size_t f = 0; f < p.num_faces(); ++f) {
        const Face& t = p.faces()[f];
        for (std::size_t k = 0; k < t.size(); ++k) faces_of[key(t[k], t[(k + 1) % t.size()])].push_back(static_cast<int>(f));
      }
      std::set<std::uint64_t> lines;
      for (const Segment& s : r.drawing.segments)
        if (s.kind == Segment::Kind::Edge && s.line == LineKind::Crease) lines.insert(key(s.v0, s.v1));
      for (std::size_t f = 0; f < p.num_faces(); ++f) {
        if (!sliver(p, static_cast<int>(f))) continue;
        ++slivers;
        const Face& t = p.faces()[f];
        std::vector<int> around;  // the faces across the sliver's edges
        bool drawn = false;
        for (int k = 0; k < 3; ++k) {
          drawn = drawn || lines.count(key(t[k], t[(k + 1) % 3]));
          for (int g : faces_of[key(t[k], t[(k + 1) % 3])])
            if (g != static_cast<int>(f)) around.push_back(g);
        }
        if (!drawn) continue;
        ++on_slivers;
        bool fold = false;
        for (int a : around)
          for (int c : around) {
            const auto na = integer_normal(p, a), nc = integer_normal(p, c);
            fold = fold || angle.exceeds(na.data(), nc.data());
          }
        EXPECT_TRUE(fold) << file << ": a crease on sliver " << f << " whose neighbours lie in one smooth surface";
      }
    }
    EXPECT_GT(slivers, 0) << file;
    EXPECT_GT(on_slivers, 0) << file;
  }
}

}  // namespace
}  // namespace hlr
