// The exact floating horizon (course notes section 24) against the general renderer
// on the same triangulated surface: the visible pieces of every cut must be identical, exactly,
// for surfaces with peaks, saddles and flat regions, in several views.
#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <map>
#include <tuple>

#include "algorithms/horizon/floating_horizon.hpp"
#include "algorithms/horizon/floating_horizon_classic.hpp"
#include "io/pipeline/render.hpp"

namespace hlr {
namespace {

HeightGrid grid(int n, const std::function<Rational(const Rational&, const Rational&)>& f) {
  HeightGrid g;
  for (int i = 0; i < n; ++i) {
    Rational x(2 * i - (n - 1), n - 1);  // -1 .. 1
    x.canonicalize();
    g.xs.push_back(x);
  }
  g.zs = g.xs;
  for (const Rational& z : g.zs)
    for (const Rational& x : g.xs) g.ys.push_back(f(x, z));
  return g;
}

// The surface as a mesh: vertex j * nx + i, the cell (i, j) split along (i, j)-(i+1, j+1).
Polyhedron surface(const HeightGrid& g) {
  const int nx = static_cast<int>(g.xs.size()), nz = static_cast<int>(g.zs.size());
  std::vector<Point3> vs;
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nx; ++i) vs.push_back(g.point(i, j));
  std::vector<Face> fs;
  for (int j = 0; j + 1 < nz; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      int a = j * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
      fs.push_back({a, b, c});
      fs.push_back({a, c, d});
    }
  return Polyhedron(vs, fs);
}

using Key = std::tuple<int, int, Rational, Rational>;  // curve, segment, t0, t1

// Key for an edge of the grid: z cuts (curve j, segment i) as before; x cuts (i, j) with the
// curve number offset by 1000 so both families can be compared in one list.
std::vector<Key> by_renderer(const HeightGrid& g, const Vector3& view, const Vector3& up, bool x_cuts = false) {
  const int nx = static_cast<int>(g.xs.size());
  Scene scene;
  scene.bodies.push_back(SceneBody{"surface", "grid", surface(g), identity_transform(), {}, {}, {}});
  RenderOptions o;
  o.view.direction = view;
  o.view.up = up;
  o.lines.edges = EdgeSelection::All;
  o.lines.intersections = false;
  RenderResult r = render({scene}, o);
  std::map<std::pair<int, int>, std::vector<std::pair<Rational, Rational>>> runs;
  for (const Segment& s : r.drawing.segments) {
    if (s.kind != Segment::Kind::Edge) continue;
    int a = std::min(s.v0, s.v1), b = std::max(s.v0, s.v1);
    const bool zcut = b == a + 1 && a / nx == b / nx, xcut = b == a + nx;
    if (!(zcut || (x_cuts && xcut))) continue;  // the cuts' edges (i, j)-(i+1, j), and (i, j)-(i, j+1)
    const bool flip = s.v0 > s.v1;
    for (const Piece& p : s.pieces) {
      if (!p.visible) continue;
      Rational t0 = flip ? Rational(1 - p.t1) : p.t0, t1 = flip ? Rational(1 - p.t0) : p.t1;
      if (zcut) runs[{a / nx, a % nx}].push_back({t0, t1});
      else runs[{1000 + a % nx, a / nx}].push_back({t0, t1});
    }
  }
  std::vector<Key> out;
  for (auto& [k, v] : runs) {
    std::sort(v.begin(), v.end());
    for (auto& [t0, t1] : v) out.emplace_back(k.first, k.second, t0, t1);
  }
  return out;
}

std::vector<Key> by_horizon(const HeightGrid& g, const Vector3& view, const Vector3& up, bool x_cuts = false) {
  HorizonResult h = floating_horizon(g, make_orthographic(view, up));
  std::vector<Key> out;
  for (const HorizonPiece& p : h.visible) out.emplace_back(p.curve, p.segment, p.t0, p.t1);
  if (x_cuts)
    for (const HorizonPiece& p : floating_horizon_x(g, make_orthographic(view, up)).visible)
      out.emplace_back(1000 + p.curve, p.segment, p.t0, p.t1);
  std::sort(out.begin(), out.end());
  // Runs that meet across pieces of one segment are one run.
  std::vector<Key> merged;
  for (const Key& k : out) {
    if (!merged.empty() && std::get<0>(merged.back()) == std::get<0>(k) && std::get<1>(merged.back()) == std::get<1>(k) &&
        std::get<3>(merged.back()) == std::get<2>(k))
      std::get<3>(merged.back()) = std::get<3>(k);
    else
      merged.push_back(k);
  }
  return merged;
}

TEST(FloatingHorizon, EqualsTheRendererOnTheTriangulatedSurface) {
  const std::vector<std::pair<std::string, std::function<Rational(const Rational&, const Rational&)>>> surfaces = {
      {"peak", [](const Rational& x, const Rational& z) -> Rational { return Rational(1) / (1 + 8 * (x * x + z * z)); }},
      {"saddle", [](const Rational& x, const Rational& z) -> Rational { return (x * x - z * z) / 2; }},
      {"flat with a bump", [](const Rational& x, const Rational& z) -> Rational {
         Rational d = x * x + (z - Rational(1, 3)) * (z - Rational(1, 3));
         return d < Rational(1, 4) ? Rational(1, 4) - d : Rational(0);
       }},
      {"ridges", [](const Rational& x, const Rational& z) -> Rational {
         Rational w = 3 * x + z;
         w -= Rational(static_cast<long>(mpz_class(w.get_num() / w.get_den()).get_si()));
         return w * (1 - w) / 2;
       }},
  };
  const std::vector<Vector3> views = {Vector3(1, 2, 3), Vector3(-2, 1, 5), Vector3(0, 1, 4), Vector3(3, 1, -2),
                                      Vector3(1, -1, 3), Vector3(5, 1, 1)};
  int compared = 0;
  for (const auto& [name, f] : surfaces)
    for (int n : {5, 9}) {
      HeightGrid g = grid(n, f);
      for (const Vector3& v : views) {
        Vector3 up(0, 1, 0);
        const bool both = v.x() != 0;  // the x cuts too (a grid) where they are not seen edge-on
        std::vector<Key> a = by_horizon(g, v, up, both), b = by_renderer(g, v, up, both);
        EXPECT_EQ(a, b) << name << " n=" << n << " view " << to_string(v) << ": " << a.size() << " runs against " << b.size();
        ++compared;
      }
    }
  EXPECT_EQ(compared, 48);
}

// The notes' fault of the classic method: a peak of a front cut between two columns is not in
// the horizon arrays, so the cut behind it is drawn where the peak hides it. The exact method
// keeps the peak.
TEST(FloatingHorizon, ClassicLosesThePeakTheExactMethodKeeps) {
  HeightGrid g;
  for (const char* x : {"-1", "-1/10", "0", "1/10", "1"}) g.xs.push_back(parse_rational(x));
  g.zs = {Rational(0), Rational(1, 8), Rational(1, 4)};
  // The back cut (z = 0) flat at 1/2, the middle one at 1/4; the front cut (z = 1/4, nearest
  // for this view) flat at 0 with a spike of 1 at x = 0. In the picture the back cut runs
  // between the middle cut (below) and the spike's apex (above).
  for (int i = 0; i < 5; ++i) g.ys.push_back(Rational(1, 2));
  for (int i = 0; i < 5; ++i) g.ys.push_back(Rational(1, 4));
  for (int i = 0; i < 5; ++i) g.ys.push_back(i == 2 ? Rational(1) : Rational(0));
  Camera cam = make_orthographic(Vector3(0, 1, 4), Vector3(0, 1, 0));
  auto hidden_on_back = [](const HorizonResult& h) {
    Rational visible = 0;
    for (const HorizonPiece& p : h.visible)
      if (p.curve == 0) visible += p.t1 - p.t0;
    return Rational(4 - visible);  // four segments of t length 1
  };
  HorizonResult exact = floating_horizon(g, cam);
  HorizonResult classic = floating_horizon_classic(g, cam, 0.3);  // columns at -1, -0.7, ..., -0.1, 0.2: not at 0
  EXPECT_GT(hidden_on_back(exact), 0) << "the spike hides part of the back cut";
  EXPECT_EQ(hidden_on_back(classic), 0) << "the classic arrays miss the spike";
  HorizonResult fine = floating_horizon_classic(g, cam, 0.01);  // a column near the apex: the peak is seen again
  EXPECT_GT(hidden_on_back(fine), 0);
}

// With no x component in the view, the side edges (the first and last x cuts) are visible
// whole, as render_horizon draws them: the renderer agrees.
// The side edges from the z sweep's final horizons equal the renderer's (and the x sweep's).
TEST(FloatingHorizon, SideEdgesFromTheFinalHorizons) {
  for (int n : {5, 8}) {
    HeightGrid g = grid(n, [](const Rational& x, const Rational& z) -> Rational { return (x * x - z * z) / 2 + Rational(1) / (2 + 8 * x * x); });
    for (const Vector3& v : {Vector3(1, 2, 3), Vector3(-2, 1, 5), Vector3(3, 1, -2), Vector3(5, 1, 1), Vector3(-1, -1, 3), Vector3(0, 1, 4)}) {
      std::vector<Key> want;
      for (const Key& k : by_renderer(g, v, Vector3(0, 1, 0), true))
        if (std::get<0>(k) == 1000 || std::get<0>(k) == 1000 + n - 1) want.push_back(k);
      HorizonResult h = floating_horizon(g, make_orthographic(v, Vector3(0, 1, 0)));
      std::vector<Key> got;
      for (const HorizonPiece& p : h.side) {
        Key k{1000 + p.curve, p.segment, p.t0, p.t1};
        if (!got.empty() && std::get<0>(got.back()) == std::get<0>(k) && std::get<1>(got.back()) == std::get<1>(k) &&
            std::get<3>(got.back()) == std::get<2>(k))
          std::get<3>(got.back()) = std::get<3>(k);
        else
          got.push_back(k);
      }
      std::sort(got.begin(), got.end());
      EXPECT_EQ(got, want) << "n=" << n << " view " << to_string(v);
    }
  }
}

TEST(FloatingHorizon, SideEdgesSeenEdgeOnAreVisible) {
  HeightGrid g = grid(7, [](const Rational& x, const Rational& z) -> Rational { return Rational(1) / (1 + 8 * (x * x + z * z)); });
  for (const Vector3& v : {Vector3(0, 1, 4), Vector3(0, 3, 1), Vector3(0, -1, 2)}) {
    std::vector<Key> b = by_renderer(g, v, Vector3(0, 1, 0), true);
    for (int side : {1000, 1006}) {
      Rational visible = 0;
      for (const Key& k : b)
        if (std::get<0>(k) == side) visible += std::get<3>(k) - std::get<2>(k);
      EXPECT_EQ(visible, 6) << "side " << side - 1000 << " view " << to_string(v);
    }
  }
}

TEST(FloatingHorizon, RefusesViewsItCannotTake) {
  HeightGrid g = grid(3, [](const Rational& x, const Rational&) -> Rational { return x; });
  EXPECT_THROW(floating_horizon(g, make_orthographic(Vector3(1, 1, 0))), std::invalid_argument);
  EXPECT_THROW(floating_horizon(g, make_perspective(Point3(0, 2, 5), Point3(0, 0, 0))), std::invalid_argument);
}

}  // namespace

// The notes' method (HorizonRule::Cuts, the exam page's answer) against its definition, by brute
// force: a point of a cut is visible where no cut in front of it reaches its X, or it lies on or
// above all of them there, or on or below all of them. Points at odd multiples of 1/14 of every
// segment, on random integer grids in eight views; the exact rule (the strips count) must never
// see more than the notes' and must see less somewhere.
TEST(FloatingHorizon, NotesRuleIsEachCutAgainstTheCutsInFront) {
  std::mt19937 rng(7);
  long checked = 0, fewer = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const int nx = 3 + trial % 4, nz = 2 + trial % 3;
    HeightGrid g;
    for (int i = 0; i < nx; ++i) g.xs.push_back(Rational(i));
    for (int j = 0; j < nz; ++j) g.zs.push_back(Rational(j));
    for (int k = 0; k < nx * nz; ++k) g.ys.push_back(Rational(std::uniform_int_distribution<int>(-2, 3)(rng)));
    const int views[8][3] = {{0, 1, 2}, {1, 2, 4}, {-1, 2, 3}, {2, 1, 5}, {0, 3, -2}, {1, -1, 3}, {-3, 2, -4}, {1, 5, 1}};
    for (const auto& vw : views) {
      const Camera cam = make_orthographic(Vector3(vw[0], vw[1], vw[2]), Vector3(0, 1, 0));
      const HorizonResult notes = floating_horizon_exact(g, cam, nullptr, HorizonRule::Cuts);
      const HorizonResult exact = floating_horizon_exact(g, cam, nullptr, HorizonRule::Strips);
      const std::array<Vector3, 2> ax = horizon_axes(g, cam);
      auto at = [&](int i, int j) {
        const Point3 p = g.point(i, j);
        return std::array<Rational, 2>{p.x() * ax[0].x() + p.y() * ax[0].y() + p.z() * ax[0].z(),
                                       p.x() * ax[1].x() + p.y() * ax[1].y() + p.z() * ax[1].z()};
      };
      auto seen = [](const HorizonResult& h, int j, int i, const Rational& t) {
        for (const HorizonPiece& p : h.visible)
          if (p.curve == j && p.segment == i && p.t0 <= t && t <= p.t1) return true;
        return false;
      };
      for (std::size_t k = 0; k < notes.order.size(); ++k) {
        const int j = notes.order[k];
        for (int i = 0; i + 1 < nx; ++i)
          for (int m = 1; m < 14; m += 2) {
            Rational t(m, 14);
            t.canonicalize();
            const auto a = at(i, j), b = at(i + 1, j);
            const Rational X = a[0] + t * (b[0] - a[0]), Y = a[1] + t * (b[1] - a[1]);
            bool any = false, above = true, below = true, corner = false;
            for (std::size_t f = 0; f < k; ++f)  // every cut in front, at X
              for (int s2 = 0; s2 + 1 < nx; ++s2) {
                const auto c = at(s2, notes.order[f]), d = at(s2 + 1, notes.order[f]);
                const Rational lo = std::min(c[0], d[0]), hi = std::max(c[0], d[0]);
                corner = corner || X == lo || X == hi;  // a run's end can fall on a corner: not sampled
                if (X < lo || X > hi || lo == hi) continue;
                const Rational y = c[1] + (X - c[0]) / (d[0] - c[0]) * (d[1] - c[1]);
                any = true;
                corner = corner || Y == y;  // on a cut in front: a run's end or a single point
                above = above && Y >= y;
                below = below && Y <= y;
              }
            if (corner) continue;
            const bool want = !any || above || below;
            EXPECT_EQ(seen(notes, j, i, t), want) << "trial " << trial << " view " << vw[0] << "," << vw[1] << "," << vw[2] << " cut " << j
                                                  << " segment " << i << " t " << t;
            if (seen(exact, j, i, t)) EXPECT_TRUE(want) << "the strips hide more, never less";
            fewer += want && !seen(exact, j, i, t);
            ++checked;
          }
      }
    }
  }
  EXPECT_GT(checked, 5000);
  EXPECT_GT(fewer, 0);
}
}  // namespace hlr
