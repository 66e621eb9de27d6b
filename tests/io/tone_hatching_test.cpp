// Tone hatching (io/output/tone_hatching.hpp, algorithms/hatching/tone_hatch.hpp), checked by
// an independent exact oracle on random scenes of boxes that touch and interpenetrate, seen
// orthographically and in perspective, with and without shadows: every point of every hatch
// line is seen, on a face the sight ray meets first (so it lies on a visible region and under
// no occluder); no hatch piece crosses a visible line of the drawing; the ink per area of each
// large region is its tone level's; a face split by an occluder keeps its lines on one family.
#include "io/output/tone_hatching.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "algorithms/picture/picture_plane.hpp"
#include "io/pipeline/render.hpp"
#include "support/face_oracle.hpp"

using namespace hlr;

namespace {

Point3 P(long x, long y, long z) { return Point3(Rational(x), Rational(y), Rational(z)); }

Scene boxes_scene(const std::vector<std::array<long, 6>>& boxes) {
  Scene s;
  s.file = "boxes.yaml";
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const auto& b = boxes[i];
    s.bodies.push_back(SceneBody{
        "box" + std::to_string(i), "boxes.yaml", make_box(P(b[0], b[1], b[2]), P(b[3], b[4], b[5])), identity_transform(), {}, {}, {}, std::nullopt});
  }
  return s;
}

RenderResult render_surfaces(const Scene& s, const ViewRequest& view, bool shadows, bool corners = true) {
  RenderOptions o;
  o.view = view;
  o.lines.edges = EdgeSelection::All;
  o.surfaces = true;
  o.shadows = shadows;
  o.surface_corners = corners;  // off: the hatching lifts what it needs
  o.surface_groups = false;
  return render({s}, o);
}

ViewRequest ortho(long x, long y, long z) {
  ViewRequest v;
  v.direction = Vector3(Rational(x), Rational(y), Rational(z));
  return v;
}

ViewRequest persp(long x, long y, long z) {
  ViewRequest v;
  v.eye = P(x, y, z);
  return v;
}

// Sign of the 2D cross product (b − a) × (c − a), exactly.
int orient(const Exact2& a, const Exact2& b, const Exact2& c) {
  const Rational v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  return sgn(v);
}

// Whether the open segments pq and rs cross at one point inside both (a proper crossing).
bool cross_properly(const Exact2& p, const Exact2& q, const Exact2& r, const Exact2& s) {
  const int a = orient(p, q, r), b = orient(p, q, s), c = orient(r, s, p), d = orient(r, s, q);
  return a * b < 0 && c * d < 0;
}

struct Checked {
  std::size_t pieces = 0, points = 0;
};

// The oracle's checks of one hatched render: each piece's points at 1/4, 1/2 and 3/4 are the
// nearest point of the scene on their sight rays; no piece crosses a visible line.
Checked check_hatching(const RenderResult& r, const std::vector<TonePiece>& h) {
  Checked c;
  std::vector<const Polyhedron*> polys;
  for (const SceneBody* b : r.bodies) polys.push_back(&b->body);
  const PicturePlane pp(r.camera);
  const auto faces = test::oracle_faces(polys, pp);
  std::vector<std::array<Exact2, 2>> visible;
  std::vector<std::string> what;
  std::vector<std::array<Point3, 2>> visible_3d;
  for (const Segment& s : r.drawing.segments)
    for (const Piece& p : s.pieces)
      if (p.visible && !p.behind_eye && !p.clipped) {
        visible.push_back({pp.project(s.at(p.t0)), pp.project(s.at(p.t1))});
        visible_3d.push_back({s.at(p.t0), s.at(p.t1)});
        std::ostringstream o;
        o << "segment body " << s.body << "/" << s.body2 << " kind " << to_string(s.line) << " " << s.at(p.t0) << " - " << s.at(p.t1);
        what.push_back(o.str());
      }
  for (const TonePiece& piece : h) {
    EXPECT_TRUE(is_tone(piece.kind));
    ++c.pieces;
    const Exact2 &a = piece.ends[0], &b = piece.ends[1];
    for (const Rational t : {Rational(1, 4), Rational(1, 2), Rational(3, 4)}) {
      const Exact2 q{Rational(a[0] + t * (b[0] - a[0])), Rational(a[1] + t * (b[1] - a[1]))};
      const Point3 x = tone_point(r, piece, q);
      const auto hits = test::sight_hits(faces, r.camera, pp, q);
      EXPECT_FALSE(hits.empty());
      if (hits.empty()) continue;
      const test::SightHit& near = hits.back();
      EXPECT_TRUE(near.at[0] == x.x() && near.at[1] == x.y() && near.at[2] == x.z())
          << "a hatch point is not the nearest point on its sight ray: under an occluder or off its face";
      ++c.points;
    }
    // A line lying in the hatched face's plane (the seam where a flush coplanar body's face
    // meets it) is drawn on the face, over its hatching.
    const Plane& on = r.bodies[piece.body]->body.planes()[piece.face];
    for (std::size_t vi = 0; vi < visible.size(); ++vi) {
      const auto& v = visible[vi];
      if (on.value(visible_3d[vi][0]) == 0 && on.value(visible_3d[vi][1]) == 0) continue;
      EXPECT_FALSE(cross_properly(a, b, v[0], v[1]))
          << "a hatch piece crosses a visible line: body " << piece.body << " face " << piece.face << " against " << what[vi];
    }
  }
  return c;
}

}  // namespace

TEST(ToneHatch, LevelsSpacingAndCrossHatching) {
  ToneOptions o;  // 5 levels, pen 0.25 mm, cross-hatched over 1/2
  EXPECT_EQ(tone_level(1.0, o).level, 0);
  EXPECT_EQ(tone_level(1.0, o).families, 0);
  EXPECT_EQ(tone_level(0.95, o).level, 0);   // darkness 0.05: paper white
  const ToneLevel two = tone_level(0.6, o);  // darkness 0.4
  EXPECT_EQ(two.level, 2);
  EXPECT_EQ(two.families, 1);
  EXPECT_DOUBLE_EQ(two.coverage, 0.4);
  EXPECT_DOUBLE_EQ(two.spacing_mm, 0.25 / 0.4);
  const ToneLevel four = tone_level(0.2, o);
  EXPECT_EQ(four.level, 4);
  EXPECT_EQ(four.families, 2);
  EXPECT_NEAR(four.spacing_mm, 0.25 / (1 - std::sqrt(0.2)), 1e-12);
  // Two families at s cover 1 − (1 − p/s)² of the paper: the level's coverage.
  EXPECT_NEAR(1 - std::pow(1 - 0.25 / four.spacing_mm, 2), 0.8, 1e-12);
  EXPECT_EQ(tone_level(0.0, o).level, 4);  // black: the darkest level
  o.levels = 8;
  EXPECT_EQ(tone_level(0.0, o).level, 7);
  EXPECT_NEAR(luminance({1, 1, 1}), 1, 1e-12);
  EXPECT_NEAR(luminance({0, 1, 0}), 0.7152, 1e-12);
}

TEST(ToneHatch, OracleOnRandomBoxes) {
  std::mt19937 rng(4107);
  std::uniform_int_distribution<long> c(0, 6), len(1, 4);
  const std::vector<ViewRequest> views = {ortho(1, 2, 3), ortho(-2, 1, 1), ortho(0, 0, 1), persp(14, 11, 17), persp(-9, 12, 15)};
  Checked total;
  int renders = 0;
  for (int trial = 0; trial < 14; ++trial) {
    std::vector<std::array<long, 6>> boxes;
    for (int k = 0; k < 3; ++k) {
      std::array<long, 6> b;
      for (int a = 0; a < 3; ++a) b[a] = c(rng), b[a + 3] = b[a] + len(rng);
      boxes.push_back(b);
    }
    if (trial % 3 == 0) boxes[1] = {boxes[0][3], boxes[0][1], boxes[0][2], boxes[0][3] + 2, boxes[0][1] + 2, boxes[0][2] + 2};  // touching
    const Scene s = boxes_scene(boxes);
    const ViewRequest& v = views[trial % views.size()];
    const RenderResult r = render_surfaces(s, v, trial % 2 == 1, trial % 4 < 2);
    ToneHatchOptions o;
    o.tone.levels = 5;
    o.contour = trial % 5 == 1;  // level planes (the lines found in space, not in the picture)
    o.angle = 10 + 17 * trial;
    const double mm_per_unit = v.eye ? 400 : 20;  // several lines across every face
    const std::vector<TonePiece> h = tone_hatching(r, mm_per_unit, o);
    std::string desc = "trial " + std::to_string(trial);
    for (const auto& b : boxes)
      desc += " [" + std::to_string(b[0]) + "," + std::to_string(b[1]) + "," + std::to_string(b[2]) + " .. " + std::to_string(b[3]) + "," +
              std::to_string(b[4]) + "," + std::to_string(b[5]) + "]";
    SCOPED_TRACE(desc);
    const Checked k = check_hatching(r, h);
    total.pieces += k.pieces, total.points += k.points;
    ++renders;
  }
  EXPECT_EQ(renders, 14);
  EXPECT_GT(total.pieces, 500u);
}

TEST(ToneHatch, InkPerAreaFollowsTheLevel) {
  // One box seen orthographically: three faces of three shades, large against the spacing.
  const Scene s = boxes_scene({{0, 0, 0, 10, 10, 10}});
  const RenderResult r = render_surfaces(s, ortho(2, 3, 4), false);
  ToneHatchOptions o;
  const double mm_per_unit = 10;
  const std::vector<TonePiece> h = tone_hatching(r, mm_per_unit, o);
  const Projector proj = drawing_projector(r.drawing, r.camera);
  const PictureToDrawing to_drawing(PicturePlane(r.camera), proj.frame());
  int measured = 0;
  std::set<int> levels;
  for (const ToneRegion& t : tone_regions(r, o.tone)) {
    if (!t.level.families) continue;
    double area = 0;
    const auto& ring = t.polygon->outer_2d;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const auto a = to_drawing(ring[k]), b = to_drawing(ring[(k + 1) % ring.size()]);
      area += (a[0] * b[1] - b[0] * a[1]) / 2;
    }
    double length = 0;
    for (const TonePiece& p : h) {
      if (p.kind != tone_kind(t.level.level)) continue;
      const Exact2 mid{Rational((p.ends[0][0] + p.ends[1][0]) / 2), Rational((p.ends[0][1] + p.ends[1][1]) / 2)};
      if (test::in_rings(t.polygon->outer_2d, t.polygon->holes_2d, mid) <= 0) continue;
      const auto a = to_drawing(p.ends[0]), b = to_drawing(p.ends[1]);
      length += std::hypot(a[0] - b[0], a[1] - b[1]);
    }
    const double step = t.level.spacing_mm / mm_per_unit;  // drawing units
    const double expected = t.level.families / step;       // length per area
    EXPECT_NEAR(length / std::fabs(area), expected, 0.06 * expected) << "level " << t.level.level;
    // The ink: the pen's width times the length, per area (two families overlap at crossings).
    const double p = o.tone.pen_mm / mm_per_unit, ink = p * length / std::fabs(area);
    const double covered = t.level.families == 1 ? ink : 1 - std::pow(1 - ink / 2, 2);
    EXPECT_NEAR(covered, t.level.coverage, 0.06 * t.level.coverage);
    levels.insert(t.level.level);
    ++measured;
  }
  EXPECT_EQ(measured, 3);
  EXPECT_GE(levels.size(), 2u);  // the three faces are not all of one tone
}

TEST(ToneHatch, OneFamilyAcrossAnOccluder) {
  // A wall (the box behind) seen through a thin post in front: its front face is two regions.
  const Scene s = boxes_scene({{0, 0, 0, 20, 10, 1}, {9, -2, 3, 11, 12, 5}});
  const RenderResult r = render_surfaces(s, ortho(0, 0, 1), false);
  ToneHatchOptions o;
  o.angle = 30;
  const std::vector<TonePiece> h = tone_hatching(r, 10, o);
  // The wall's front face z = 1: its pieces, left and right of the post, by their exact line.
  std::map<std::array<Rational, 3>, std::array<int, 2>> lines;  // line in the face (a x + b y = c) -> pieces left, right
  int pieces = 0;
  for (const TonePiece& p : h) {
    if (p.body != 0) continue;
    const Point3 from = tone_point(r, p, p.ends[0]), to = tone_point(r, p, p.ends[1]);
    if (from.z() != 1 || to.z() != 1) continue;
    const Rational a = to.y() - from.y(), b = from.x() - to.x();
    const Rational k = a != 0 ? a : b;
    const Rational A = a / k, B = b / k, C = A * from.x() + B * from.y();
    const bool left = (from.x() + to.x()) / 2 < 9;
    ++lines[{A, B, C}][left ? 0 : 1];
    ++pieces;
  }
  int both = 0;
  std::set<Rational> slopes;
  for (const auto& [l, n] : lines) {
    both += n[0] > 0 && n[1] > 0;
    slopes.insert(l[0]);
  }
  EXPECT_GT(pieces, 40);
  EXPECT_GE(both, 5) << "the lines do not run on across the post";
  // One family of parallel planes: every line of the face has the same exact direction.
  EXPECT_EQ(slopes.size(), 1u);
}
