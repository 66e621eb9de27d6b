// Loads every OFF mesh of Debian's libcgal-demo data archive (extracted by
// scripts/extract_corpus.sh) with our exact reader and with OpenMesh's own reader, and checks
// that counts and the closed / manifold verdicts agree.
#include <OpenMesh/Core/IO/MeshIO.hh>
// MeshIO must come before the mesh kernel headers.
#include <gtest/gtest.h>

#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "io/readers/mesh_reader.hpp"
#include "kernel/openmesh_mesh.hpp"

using namespace hlr;

namespace {

std::vector<std::string> corpus() {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(HLR_CORPUS_DIR, ec))
    if (e.path().extension() == ".off") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

bool has_boundary(const Mesh& m) {
  for (auto h : m.halfedges())
    if (m.is_boundary(h)) return true;
  return false;
}

}  // namespace

TEST(Corpus, IsThere) {
  // The archive ships about 140 OFF meshes; fewer means the extraction failed.
  EXPECT_GE(corpus().size(), 100u) << "run scripts/extract_corpus.sh (corpus folder: " << HLR_CORPUS_DIR << ")";
}

TEST(Corpus, CountsAndVerdictsAgreeWithOpenMesh) {
  omerr().disable();
  omlog().disable();
  int checked = 0, openmesh_fixed = 0, closed = 0;
  std::string unreadable;
  for (const auto& path : corpus()) {
    SCOPED_TRACE(path);
    MeshData data;
    try {
      data = read_mesh_file(path);
    } catch (const InputError& e) {
      // Only files OpenMesh cannot read either may be refused.
      Mesh om;
      EXPECT_FALSE(OpenMesh::IO::read_mesh(om, path) && om.n_faces() > 0) << e.what();
      continue;
    }
    const std::size_t nv = data.num_vertices(), nf = data.faces.size();
    Polyhedron ours = make_polyhedron(std::move(data), path);
    Mesh om;
    // OpenMesh's OFF reader cannot read a few files (CGAL's comment header, colour values
    // such as ".7"): it fails or drops faces as "invalid vertex index". Those are listed, not
    // compared. When OpenMesh repairs a non-manifold face it keeps the face count and adds
    // vertices.
    if (!OpenMesh::IO::read_mesh(om, path) || om.n_faces() != nf) {
      unreadable += std::filesystem::path(path).filename().string() + " ";
      continue;
    }
    const MeshReport& r = ours.report();
    bool repeated = std::any_of(r.degenerate_faces.begin(), r.degenerate_faces.end(),
                                [](const DegenerateFace& d) { return d.why.rfind("repeated", 0) == 0; });
    bool om_took_all = om.n_vertices() == nv && om.n_faces() == nf;
    // OpenMesh accepted every face as given exactly when we found nothing it refuses.
    EXPECT_EQ(om_took_all, ours.refused_faces().empty());
    if (r.non_manifold_edges.empty() && r.oriented() && !repeated) {
      EXPECT_TRUE(om_took_all);
    }
    if (om_took_all) {
      EXPECT_TRUE(r.non_manifold_edges.empty());
      EXPECT_TRUE(r.oriented());
      EXPECT_EQ(om.n_edges(), ours.edges().size());
      // Same vertices in the same order, up to OpenMesh's rounding of coordinates to float.
      for (std::size_t i = 0; i < nv; i += std::max<std::size_t>(1, nv / 97)) {
        auto p = om.point(Mesh::VertexHandle(static_cast<int>(i)));
        for (int k = 0; k < 3; ++k) {
          double exact = to_double(ours.vertices()[i][k]);
          EXPECT_LE(std::fabs(p[k] - exact), 1e-6 * std::max(1.0, std::fabs(exact))) << i;
        }
      }
      // Closed: no boundary edges here, no boundary halfedges there.
      EXPECT_EQ(r.closed(), !has_boundary(om));
      EXPECT_EQ(r.closed(), !has_boundary(ours.mesh()));
      closed += r.closed();
    } else {
      ++openmesh_fixed;
      EXPECT_TRUE(!r.manifold() || !r.oriented() || repeated);
    }
    ++checked;
  }
  EXPECT_GE(checked, 100);
  std::cout << "[corpus] " << checked << " meshes checked, " << closed << " closed, " << openmesh_fixed
            << " that OpenMesh had to repair; OpenMesh misreads: " << unreadable << "\n";
}
