// The 2D stage's projection of the pieces (algorithms/picture/drawing_2d.hpp) against a serial oracle:
// which pieces become lines (the options' hidden and through, never behind the eye or
// clipped, perspective pieces wholly nearer than the near depth dropped), in segment and
// piece order, across the runs the stage splits the segments into, on 1 and 2 threads.
#include <gtest/gtest.h>

#include <random>

#include "algorithms/picture/drawing_2d.hpp"
#include "algorithms/support/parallel.hpp"

using namespace hlr;

namespace {

Point3 P(double x, double y, double z) { return Point3(Rational(x), Rational(y), Rational(z)); }

// `n` segments (runs of 4096 are crossed) of 1 to 3 pieces with mixed flags; with `near_ones`,
// every 7th segment lies just in front of the eye plane of the camera below (depth 1e-6 of
// the others' 10), so its pieces are nearer than the near depth.
LineDrawing synthetic(std::size_t n, bool near_ones, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(-1000, 1000), flags(0, 15), count(1, 3);
  LineDrawing d;
  d.segments.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Segment& s = d.segments[i];
    s.body = static_cast<int>(i % 3);
    s.line = static_cast<LineKind>(i % 5);
    s.kind = i % 11 == 0 ? Segment::Kind::Intersection : Segment::Kind::Edge;
    const double z = near_ones && i % 7 == 3 ? -10 + 1e-6 : coord(rng) / 1000.0;
    s.set_ends(P(coord(rng) / 1000.0, coord(rng) / 1000.0, z), P(coord(rng) / 1000.0, coord(rng) / 1000.0, z));
    const int k = count(rng);
    std::vector<Piece> pieces;
    for (int j = 0; j < k; ++j) {
      Piece p;
      p.t0 = Rational(j) / k;
      p.t1 = Rational(j + 1) / k;
      const int f = flags(rng);
      p.visible = f & 1;
      p.through = !p.visible && (f & 2);
      p.behind_eye = f == 4;
      p.clipped = f == 6;
      pieces.push_back(p);
    }
    s.pieces = pieces;
  }
  return d;
}

struct Expected {
  std::vector<PieceRef> sources;
  std::vector<std::array<double, 2>> points;
};

// The serial oracle: the piece ends exactly on the segment, then projected.
Expected oracle(const LineDrawing& d, const Camera& cam, const Project2DOptions& opt, double near) {
  const Projector proj = drawing_projector(d, cam);
  Expected e;
  for (std::size_t si = 0; si < d.segments.size(); ++si) {
    const Segment& s = d.segments[si];
    for (std::size_t pi = 0; pi < s.pieces.size(); ++pi) {
      const Piece& p = s.pieces[pi];
      if (p.behind_eye || p.clipped || (!p.visible && !(p.through ? opt.through : opt.hidden))) continue;
      const Point3 a = s.at(p.t0), b = s.at(p.t1);
      const auto pa = proj.project(a), pb = proj.project(b);
      if (cam.perspective && pa[2] < near && pb[2] < near) continue;
      e.sources.push_back({static_cast<int>(si), static_cast<int>(pi)});
      e.points.push_back({pa[0], pa[1]});
      e.points.push_back({pb[0], pb[1]});
    }
  }
  return e;
}

void expect_same(const Drawing2D& got, const Expected& want, const LineDrawing& d) {
  ASSERT_EQ(got.lines.size(), want.sources.size());
  ASSERT_EQ(got.sources.size(), want.sources.size());
  ASSERT_EQ(got.points.size(), want.points.size());
  for (std::size_t k = 0; k < got.lines.size(); ++k) {
    const Polyline2D& l = got.lines[k];
    ASSERT_EQ(l.first, 2 * k);
    ASSERT_EQ(l.count, 2u);
    ASSERT_EQ(l.first_edge, k);
    ASSERT_EQ(got.sources[k].segment, want.sources[k].segment) << k;
    ASSERT_EQ(got.sources[k].piece, want.sources[k].piece) << k;
    const Segment& s = d.segments[want.sources[k].segment];
    const Piece& p = s.pieces[want.sources[k].piece];
    EXPECT_EQ(l.kind, s.line);
    EXPECT_EQ(l.visible, p.visible);
    EXPECT_EQ(l.through, p.through);
    EXPECT_EQ(l.intersection, s.kind == Segment::Kind::Intersection);
    EXPECT_EQ(l.body, s.body);
    EXPECT_FALSE(l.pulled);  // no piece here crosses the near depth
  }
  for (std::size_t k = 0; k < got.points.size(); ++k)
    for (int c = 0; c < 2; ++c) ASSERT_NEAR(got.points[k][c], want.points[k][c], 1e-9 * (1 + std::fabs(want.points[k][c]))) << k;
}

}  // namespace

TEST(ProjectDrawing, PiecesInOrderAcrossRunsOrthographic) {
  const LineDrawing d = synthetic(10000, false, 1);
  const Camera cam = make_orthographic(Vector3(1, 2, 3));
  for (bool hidden : {true, false})
    for (bool through : {true, false})
      for (unsigned threads : {1u, 2u}) {
        ThreadLimit limit(threads);
        Project2DOptions opt;
        opt.hidden = hidden;
        opt.through = through;
        expect_same(project_drawing(d, cam, opt), oracle(d, cam, opt, 0), d);
      }
}

// Every 7th segment is wholly nearer than the near depth: the runs are left with gaps that
// the stage closes, keeping the order and the sources.
TEST(ProjectDrawing, PerspectivePiecesNearerThanTheNearDepthLeaveNoGap) {
  const LineDrawing d = synthetic(10000, true, 2);
  const Camera cam = make_perspective(P(0, 0, -10), P(0, 0, 0));
  const Projector proj = drawing_projector(d, cam);
  double far = 0;
  for (const Segment& s : d.segments)
    for (const Point3* p : {&s.from(), &s.to()}) far = std::max(far, proj.project(*p)[2]);
  const double near = 1e-4 * far;
  ASSERT_GT(near, 1e-4);  // the near segments' depth (1e-6) is far below it, the rest far above
  for (unsigned threads : {1u, 2u}) {
    ThreadLimit limit(threads);
    const Expected want = oracle(d, cam, Project2DOptions{}, near);
    std::size_t near_segments = 0;
    for (std::size_t i = 3; i < d.segments.size(); i += 7) near_segments += 1;
    ASSERT_LT(want.sources.size() + near_segments, 3 * d.segments.size());
    for (const PieceRef& r : want.sources) ASSERT_NE(r.segment % 7, 3);
    expect_same(project_drawing(d, cam), want, d);
  }
}

// The drawing's frame comes from the segments' ends, each borrowed vertex once: on a scene far
// from the origin (so the frame is not the identity) with segments of two bodies' vertex
// arrays, owned ends and vertices no segment uses, it is the frame of every end read in turn.
TEST(ProjectDrawing, FrameOfBorrowedAndOwnedEndsIsTheFrameOfEveryEnd) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> coord(-1000, 1000);
  const Rational far = Rational(mpz_class(1) << 120);
  auto point = [&] { return Point3(far + coord(rng), Rational(coord(rng), 7), far * 3 + Rational(coord(rng), 1000)); };
  std::vector<Point3> a(5000), b(300);
  for (Point3& p : a) p = point();
  for (Point3& p : b) p = point();
  a[4999] = Point3(far * 2, Rational(0), Rational(0));  // used by no segment: outside the ends' hull
  LineDrawing d;
  for (int i = 0; i < 200000; ++i) {
    Segment s;
    if (i % 17 == 0) {
      s.set_ends(point(), point());
    } else {
      const std::vector<Point3>& v = i % 5 == 0 ? b : a;
      const int n = static_cast<int>(v.size()) - (&v == &a ? 1 : 0);
      s.v0 = static_cast<int>(rng() % static_cast<unsigned>(n));
      s.v1 = static_cast<int>(rng() % static_cast<unsigned>(n));
      s.borrow_ends(v);
    }
    d.segments.push_back(std::move(s));
  }
  const Camera cam = make_orthographic(Vector3(Rational(1), Rational(2), Rational(3)));
  const auto& segs = d.segments;
  const DrawingFrame want =
      drawing_frame(2 * segs.size(), [&](std::size_t i) -> const Point3& { return i % 2 ? segs[i / 2].to() : segs[i / 2].from(); });
  ASSERT_FALSE(want.identity);
  for (unsigned threads : {1u, 2u}) {
    const ThreadLimit limit(threads);
    const DrawingFrame got = drawing_projector(d, cam).frame();
    EXPECT_EQ(got.identity, want.identity);
    EXPECT_EQ(got.centre, want.centre);
    EXPECT_EQ(got.scale, want.scale);
  }
}
