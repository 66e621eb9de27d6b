// Loading and exact face planes on a size ladder: spheres of 1k to 1M triangles (subdivided
// octahedra, vertices pushed to the unit sphere and written with 6 decimals, like exported
// meshes), generated into a temporary folder. Stages: parse the OFF text exactly, build the
// polyhedron (OpenMesh mesh), exact face planes, all checks.
// Run: build/benchmarks/load_bench
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "io/readers/mesh_reader.hpp"

using namespace hlr;

namespace {

// Octahedron subdivided k times: 8 * 4^k triangles.
std::string sphere_off(int k) {
  std::vector<std::array<double, 3>> v = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<std::array<int, 3>> f = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int s = 0; s < k; ++s) {
    std::map<std::pair<int, int>, int> mid;
    auto m = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      std::array<double, 3> p;
      for (int i = 0; i < 3; ++i) p[i] = (v[a][i] + v[b][i]) / 2;
      double l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      for (double& c : p) c /= l;
      v.push_back(p);
      return mid[key] = static_cast<int>(v.size() - 1);
    };
    std::vector<std::array<int, 3>> g;
    for (auto& t : f) {
      int ab = m(t[0], t[1]), bc = m(t[1], t[2]), ca = m(t[2], t[0]);
      g.push_back({t[0], ab, ca});
      g.push_back({ab, t[1], bc});
      g.push_back({ca, bc, t[2]});
      g.push_back({ab, bc, ca});
    }
    f.swap(g);
  }
  std::string out = "OFF\n" + std::to_string(v.size()) + " " + std::to_string(f.size()) + " 0\n";
  char buf[96];
  for (auto& p : v) {
    std::snprintf(buf, sizeof buf, "%.6f %.6f %.6f\n", p[0], p[1], p[2]);
    out += buf;
  }
  for (auto& t : f) out += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
  return out;
}

const std::string& sphere_file(int k) {
  static std::map<int, std::string> files;
  auto it = files.find(k);
  if (it != files.end()) return it->second;
  auto dir = std::filesystem::temp_directory_path() / "hlr_load_bench";
  std::filesystem::create_directories(dir);
  std::string path = (dir / ("sphere_" + std::to_string(k) + ".off")).string();
  if (!std::filesystem::exists(path)) std::ofstream(path) << sphere_off(k);
  return files[k] = path;
}

void BM_ParseOff(benchmark::State& st) {
  const std::string& path = sphere_file(static_cast<int>(st.range(0)));
  std::size_t faces = 0;
  for (auto _ : st) faces = read_mesh_file(path).faces.size();
  st.counters["triangles"] = static_cast<double>(faces);
  st.counters["ns_per_triangle"] = benchmark::Counter(static_cast<double>(faces), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_BuildPolyhedron(benchmark::State& st) {
  MeshData data = read_mesh_file(sphere_file(static_cast<int>(st.range(0))));
  for (auto _ : st) {
    MeshData copy = data;
    Polyhedron p = make_polyhedron(std::move(copy), "sphere");
    benchmark::DoNotOptimize(p.num_faces());
  }
  st.counters["triangles"] = static_cast<double>(data.faces.size());
}

void BM_ExactFacePlanes(benchmark::State& st) {
  Polyhedron p = load_mesh(sphere_file(static_cast<int>(st.range(0))));
  std::vector<const Point3*> pts;
  for (auto _ : st) {
    std::vector<Plane> planes;
    planes.reserve(p.num_faces());
    for (const Face& f : p.faces()) {
      pts.clear();
      for (int v : f) pts.push_back(&p.vertices()[v]);
      planes.push_back(primitive_plane_of_polygon(pts.data(), pts.size()));
    }
    benchmark::DoNotOptimize(planes.data());
  }
  st.counters["triangles"] = static_cast<double>(p.num_faces());
  st.counters["ns_per_triangle"] = benchmark::Counter(static_cast<double>(p.num_faces()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_AllChecks(benchmark::State& st) {
  Polyhedron p = load_mesh(sphere_file(static_cast<int>(st.range(0))));
  p.planes();
  for (auto _ : st) benchmark::DoNotOptimize(check_mesh(p.vertices(), p.faces(), p.planes()).closed());
  st.counters["triangles"] = static_cast<double>(p.num_faces());
}

}  // namespace

// 8 * 4^k triangles: k = 4 -> 2,048; 5 -> 8,192; 6 -> 32,768; 7 -> 131,072; 8 -> 524,288;
// 9 -> 2,097,152: the ladder brackets 1k to 1M.
BENCHMARK(BM_ParseOff)->DenseRange(4, 9)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BuildPolyhedron)->DenseRange(4, 9)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_ExactFacePlanes)->DenseRange(4, 9)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_AllChecks)->DenseRange(4, 9)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();
