// Generates test and benchmark meshes as OFF with decimal coordinates (7 places, so the exact
// value of each coordinate is the decimal the file shows):
//   gen_mesh sphere F   geodesic icosphere, 20·F² triangles (F = 22: 9,680; 71: 100,820; 224: 1,003,520)
//   gen_mesh torus N M  torus with N x M quads split into 2·N·M triangles
//   gen_mesh prism N    prism on a regular N-gon (radius 1000: the rounded caps stay convex)
//   gen_mesh star N     prism on a non-convex star polygon of 2·N vertices (radii 1000, 600)
//   gen_mesh cubes N    N unit cubes on a jittered grid with gaps (one mesh, N components)
//   gen_mesh cube-scene N  the same cubes as a YAML scene of N box bodies (Roberts' input)
//   gen_mesh triangles N S  N random triangles in the unit cube, corners k/1024 (exact as
//                           written), edges about 0.1; seed S (the visible-surfaces benchmark)
// Writes to standard output.
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace {

using P = std::array<double, 3>;

void write(const std::vector<P>& v, const std::vector<std::vector<int>>& f) {
  std::printf("OFF\n%zu %zu 0\n", v.size(), f.size());
  for (const P& p : v) std::printf("%.7f %.7f %.7f\n", p[0], p[1], p[2]);
  for (const auto& face : f) {
    std::printf("%zu", face.size());
    for (int i : face) std::printf(" %d", i);
    std::printf("\n");
  }
}

void write(const std::vector<P>& v, const std::vector<std::array<int, 3>>& f) {
  std::vector<std::vector<int>> g;
  g.reserve(f.size());
  for (const auto& t : f) g.push_back({t[0], t[1], t[2]});
  write(v, g);
}

// A prism over the polygon `ring` (counter-clockwise in the xy plane), height 100.
void prism_over(const std::vector<std::array<double, 2>>& ring) {
  const int n = static_cast<int>(ring.size());
  std::vector<P> v;
  for (double z : {0.0, 100.0})
    for (const auto& q : ring) v.push_back({q[0], q[1], z});
  std::vector<std::vector<int>> f(2);
  for (int i = n - 1; i >= 0; --i) f[0].push_back(i);  // bottom, seen from below
  for (int i = 0; i < n; ++i) f[1].push_back(n + i);
  for (int i = 0; i < n; ++i) {
    int j = (i + 1) % n;
    f.push_back({i, j, n + j, n + i});
  }
  write(v, f);
}

void prism(int N, bool star) {
  std::vector<std::array<double, 2>> ring;
  const int m = star ? 2 * N : N;
  for (int i = 0; i < m; ++i) {
    double a = 2 * M_PI * i / m, r = star && i % 2 ? 600 : 1000;
    ring.push_back({r * std::cos(a), r * std::sin(a)});
  }
  prism_over(ring);
}

void cubes(int N, bool scene) {
  int side = 1;
  while (side * side * side < N) ++side;
  std::vector<P> v;
  std::vector<std::vector<int>> f;
  unsigned seed = 12345;
  auto jitter = [&] {
    seed = seed * 1103515245u + 12345u;
    return ((seed >> 16) % 1000) / 1000.0;  // [0, 1)
  };
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (int c = 0; c < N; ++c) {
    int i = c % side, j = (c / side) % side, k = c / (side * side);
    P o{3.0 * i + jitter(), 3.0 * j + jitter(), 3.0 * k + jitter()};
    if (scene) {
      if (c == 0) std::printf("bodies:\n");
      std::printf("  - box: {min: [%.3f, %.3f, %.3f], max: [%.3f, %.3f, %.3f]}\n", o[0], o[1], o[2], o[0] + 1, o[1] + 1,
                  o[2] + 1);
      continue;
    }
    int base = static_cast<int>(v.size());
    for (int b = 0; b < 8; ++b) v.push_back({o[0] + (b & 1), o[1] + (b >> 1 & 1), o[2] + (b >> 2 & 1)});
    for (const auto& q : quads) f.push_back({base + q[0], base + q[1], base + q[2], base + q[3]});
  }
  if (!scene) write(v, f);
}

P unit(P p) {
  double l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  return {p[0] / l, p[1] / l, p[2] / l};
}

void sphere(int F) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<P> ico = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                        {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  const int faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                            {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                            {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  std::vector<P> v;
  std::vector<std::array<int, 3>> f;
  // Shared points are keyed by their barycentric position on the icosahedron's edges/vertices.
  std::map<std::array<int, 6>, int> id;
  auto point = [&](int a, int b, int c, int i, int j) {
    int k = F - i - j;  // weights i on a, j on b, k on c
    std::array<std::pair<int, int>, 3> w = {{{a, i}, {b, j}, {c, k}}};
    std::array<int, 6> key{-1, 0, -1, 0, -1, 0};
    int n = 0;
    std::sort(w.begin(), w.end());
    for (auto& [vv, ww] : w)
      if (ww > 0) key[2 * n] = vv, key[2 * n + 1] = ww, ++n;
    auto it = id.find(key);
    if (it != id.end()) return it->second;
    P p{0, 0, 0};
    for (auto& [vv, ww] : w)
      for (int d = 0; d < 3; ++d) p[d] += ico[vv][d] * ww / F;
    v.push_back(unit(p));
    return id[key] = static_cast<int>(v.size()) - 1;
  };
  for (auto& fc : faces) {
    int a = fc[0], b = fc[1], c = fc[2];
    for (int i = 0; i < F; ++i)
      for (int j = 0; j < F - i; ++j) {
        int p0 = point(a, b, c, F - i - j, j), p1 = point(a, b, c, F - i - j - 1, j + 1), p2 = point(a, b, c, F - i - j - 1, j);
        f.push_back({p0, p1, p2});
        if (i + j + 1 < F) {
          int p3 = point(a, b, c, F - i - j - 2, j + 1);
          f.push_back({p1, p3, p2});
        }
      }
  }
  write(v, f);
}

void torus(int N, int M) {
  std::vector<P> v;
  std::vector<std::array<int, 3>> f;
  const double R = 1, r = 0.4;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < M; ++j) {
      double u = 2 * M_PI * i / N, w = 2 * M_PI * j / M;
      v.push_back({(R + r * std::cos(w)) * std::cos(u), (R + r * std::cos(w)) * std::sin(u), r * std::sin(w)});
    }
  auto at = [&](int i, int j) { return (i % N) * M + (j % M); };
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < M; ++j) {
      f.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      f.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  write(v, f);
}

// N separate triangles: a corner at k/1024 in [0, 1]³, the others within ±100/1024 of it
// (a linear congruential generator: the same file on every machine).
void triangles(int n, unsigned seed) {
  std::uint64_t state = seed * 2654435761u + 1;
  auto next = [&](int lo, int hi) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return lo + static_cast<int>((state >> 33) % static_cast<std::uint64_t>(hi - lo + 1));
  };
  std::printf("OFF\n%d %d 0\n", 3 * n, n);
  for (int t = 0; t < n; ++t) {
    int x = next(0, 1024), y = next(0, 1024), z = next(0, 1024);
    std::printf("%.10f %.10f %.10f\n", x / 1024.0, y / 1024.0, z / 1024.0);
    for (int k = 0; k < 2; ++k)
      std::printf("%.10f %.10f %.10f\n", (x + next(-100, 100)) / 1024.0, (y + next(-100, 100)) / 1024.0, (z + next(-100, 100)) / 1024.0);
  }
  for (int t = 0; t < n; ++t) std::printf("3 %d %d %d\n", 3 * t, 3 * t + 1, 3 * t + 2);
}

}  // namespace

int main(int argc, char** argv) {
  std::string what = argc > 1 ? argv[1] : "";
  if (what == "sphere" && argc == 3) {
    sphere(std::atoi(argv[2]));
    return 0;
  }
  if (what == "torus" && argc == 4) {
    torus(std::atoi(argv[2]), std::atoi(argv[3]));
    return 0;
  }
  if ((what == "prism" || what == "star" || what == "cubes" || what == "cube-scene") && argc == 3) {
    int n = std::atoi(argv[2]);
    if (what == "cubes" || what == "cube-scene")
      cubes(n, what == "cube-scene");
    else
      prism(n, what == "star");
    return 0;
  }
  if (what == "triangles" && argc == 4) {
    triangles(std::atoi(argv[2]), static_cast<unsigned>(std::atoi(argv[3])));
    return 0;
  }
  std::fprintf(stderr, "usage: gen_mesh sphere F | torus N M | prism N | star N | cubes N | cube-scene N | triangles N SEED\n");
  return 2;
}
