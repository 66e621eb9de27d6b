// Tiles of the picture (algorithms/picture/picture_tiles.hpp): every point of every segment
// belongs to exactly one tile, decided exactly, and the double filters never contradict it.
#include <gtest/gtest.h>

#include <random>

#include "algorithms/picture/picture_tiles.hpp"

using namespace hlr;

namespace {

TEST(PictureTiles, GridShapes) {
  const std::vector<std::pair<int, std::array<int, 2>>> cases = {{1, {1, 1}}, {2, {2, 1}}, {4, {2, 2}}, {6, {3, 2}},
                                                                 {7, {7, 1}}, {9, {3, 3}}, {12, {4, 3}}};
  for (const auto& [n, shape] : cases) EXPECT_EQ(tile_grid(n), shape) << n;
  EXPECT_THROW(tile_grid(0), std::invalid_argument);
}

// The tile of a picture point by the definition (picture_tiles.hpp), independently of the code
// under test: columns by xs[c-1] <= X < xs[c], rows by ys[r-1] > Y >= ys[r], behind the eye: 0.
int tile_of(const Point3& p, const Camera& cam, const PicturePlane& pp, const TileSplit& s) {
  if (cam.perspective && cam.in_front(p) != Sign::Positive) return 0;
  const Exact2 q = pp.project(p);
  int col = 0, row = 0;
  for (const Rational& x : s.xs) col += x <= q[0];
  for (const Rational& y : s.ys) row += y > q[1];
  return row * s.cols + col;
}

// Small integer coordinates: many segments lie on the tile lines (they pass through vertices),
// along them, through them at vertices, and (perspective) across the eye's plane.
void check_partition(const Camera& cam, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> u(-4, 4);
  std::vector<Point3> pts;
  for (int i = 0; i < 60; ++i) pts.emplace_back(Rational(u(rng)), Rational(u(rng)), Rational(u(rng)));
  auto point = [&](std::size_t i) -> const Point3& { return pts[i]; };
  const Projector proj(cam, drawing_frame(pts.size(), point));
  const TileSplit split = split_picture(cam, proj, pts.size(), point, count);
  ASSERT_EQ(split.cols * split.rows, count);
  const PicturePlane pp(cam);
  // The outside bits of a point name sides it is beyond, exactly.
  for (const Point3& p : pts) {
    if (cam.perspective && cam.in_front(p) != Sign::Positive) continue;
    const Exact2 q = pp.project(p);
    for (int t = 0; t < count; ++t) {
      const int bits = tile_outside(split, t, locate(cam, proj, p)), col = t % split.cols, row = t / split.cols;
      if (bits & 1) EXPECT_LT(q[0], split.xs[col - 1]);
      if (bits & 2) EXPECT_GE(q[0], split.xs[col]);
      if (bits & 4) EXPECT_GE(q[1], split.ys[row - 1]);
      if (bits & 8) EXPECT_LT(q[1], split.ys[row]);
    }
  }
  int crossing = 0;
  for (std::size_t a = 0; a < pts.size(); ++a)
    for (std::size_t b = a + 1; b < pts.size(); b += 3) {
      if (pts[a] == pts[b]) continue;
      Segment s;
      s.set_ends(pts[a], pts[b]);
      std::vector<std::tuple<Rational, Rational, int>> all;
      for (int t = 0; t < count; ++t) {
        const auto iv = tile_intervals(s, pp, cam, split, t);
        // The filters never contradict the exact intervals (a point on a tile line with a
        // picture coordinate of 0 once fooled a margin relative to the coordinates).
        const LocatedPoint pa = locate(cam, proj, pts[a]), pb = locate(cam, proj, pts[b]);
        if (!tile_may_hold(split, t, pa, pb)) EXPECT_TRUE(iv.empty()) << "filter said no point of it is in tile " << t;
        if (tile_holds_wholly(split, t, pa, pb)) {
          ASSERT_EQ(iv.size(), 1u);
          EXPECT_EQ(iv[0].first, 0);
          EXPECT_EQ(iv[0].second, 1);
        }
        for (const auto& [lo, hi] : iv) {
          ASSERT_LT(lo, hi);
          // The interval's inside is the tile's: its midpoint by the definition.
          EXPECT_EQ(tile_of(s.at(Rational((lo + hi) / 2)), cam, pp, split), t);
          all.emplace_back(lo, hi, t);
        }
      }
      std::sort(all.begin(), all.end());
      crossing += all.size() > 1;
      Rational at(0);
      for (const auto& [lo, hi, t] : all) {
        EXPECT_EQ(lo, at) << "gap or overlap at tile " << t;
        at = hi;
      }
      EXPECT_EQ(at, 1);
    }
  if (count > 1) EXPECT_GT(crossing, 50) << "the scene should have segments across tile lines";
}

TEST(PictureTiles, OrthographicEverySegmentSplitExactlyOnce) {
  for (int n : {1, 4, 6, 9}) check_partition(make_orthographic(Vector3(Rational(1), Rational(2), Rational(3))), n, 5u + n);
}

TEST(PictureTiles, AxisViewSegmentsOnTileLines) {  // edges of the grid lie on the lines
  for (int n : {4, 9}) check_partition(make_orthographic(Vector3(Rational(0), Rational(0), Rational(1))), n, 17u + n);
}

TEST(PictureTiles, PerspectiveEyeAmongThePoints) {  // segments through the eye's plane: tile 0
  for (int n : {4, 9})
    check_partition(make_perspective(Point3(rational(1, 2), rational(1, 3), rational(1, 5)), Point3(Rational(3), Rational(1), Rational(0))), n,
                    29u + n);
}

TEST(PictureTiles, JoinRestoresMaximalPiecesAndFindsGaps) {
  auto piece = [](int a, int b, int d, bool visible) { return Piece{rational(a, d), rational(b, d), visible}; };
  // Tiles cut [0, 1/2] visible at 1/4 and the hidden rest at 3/4: joined back to two pieces.
  std::vector<Piece> p = {piece(3, 4, 4, false), piece(2, 3, 4, false), piece(0, 1, 4, true), piece(1, 2, 4, true)};
  EXPECT_EQ(join_tile_pieces(p), "");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].t1, rational(1, 2));
  EXPECT_FALSE(p[1].visible);
  EXPECT_EQ(p[1].t0, rational(1, 2));
  std::vector<Piece> gap = {piece(0, 1, 4, true), piece(2, 4, 4, true)};
  EXPECT_NE(join_tile_pieces(gap).find("no tile has"), std::string::npos);
  std::vector<Piece> twice = {piece(0, 2, 4, true), piece(1, 4, 4, true)};
  EXPECT_NE(join_tile_pieces(twice).find("two tiles"), std::string::npos);
  std::vector<Piece> short_end = {piece(0, 3, 4, true)};
  EXPECT_NE(join_tile_pieces(short_end).find("to 1"), std::string::npos);
}

}  // namespace
