// libFuzzer target for one mesh reader, chosen at build time by HLR_FUZZ_FORMAT (off, obj,
// stl, ply): any bytes give an InputError or a mesh whose checks, planes and convexity test
// run to the end.
#include <cstdint>
#include <string_view>

#include "algorithms/solids/convexity.hpp"
#include "io/readers/mesh_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    hlr::MeshData m = HLR_FUZZ_READER(bytes, "fuzz");
    if (m.vertices.empty() || m.faces.empty()) return 0;
    hlr::Polyhedron p = hlr::make_polyhedron(std::move(m), "fuzz");
    (void)p.report();
    if (p.num_vertices() * p.num_faces() < 100000) (void)hlr::convexity(p);
  } catch (const hlr::InputError&) {
  }
  return 0;
}
