// Crease lines of plain meshes (algorithms/hlr/face_engine_edges.cpp, docs/design.md "Crease
// lines"): OpenSCAD's example002, a cone cut by a cube's faces, whose intersection curves meet
// the cube's faces at less than the crease angle near their tangent points. Without the
// continuation a crease stroke stops in mid-face there; with it every line ends on another line,
// in every view, and the drawing stays exact (the oracle of
// tests/support/drawing_oracle.hpp).
#include <gtest/gtest.h>

#include <map>

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

RenderResult draw(const ViewRequest& v, bool continued) {
  RenderOptions o;
  o.view = v;
  o.lines.continue_creases = continued;
  o.lines.intersections = false;
  return render({load_input(std::string(HLR_DATA_DIR) + "/openscad/example002.off", "")}, o);
}

TEST(CreaseLines, ConeCutByPlanesIsDrawnWhole) {
  int stopped = 0;
  for (ViewRequest v : {ViewRequest{Vector3(1, 1, 1), {}, {}, {}}, ViewRequest{Vector3(-1, Rational(13, 10), Rational(17, 10)), {}, {}, {}},
                        ViewRequest{Vector3(0, 0, 1), {}, {}, {}}}) {
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

}  // namespace
}  // namespace hlr
