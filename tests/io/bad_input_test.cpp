// Every file in data/bad/ gives its specific error (or, for files that parse, the specific
// failed check), with the file name and, where it applies, the line.
#include <gtest/gtest.h>

#include "io/readers/scene.hpp"

using namespace hlr;

namespace {
const std::string kBad = std::string(HLR_DATA_DIR) + "/bad/";

struct Case {
  const char* file;
  int line;             // 0: no line
  const char* message;  // a part of the message
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.file; }

std::string load(const std::string& path) {
  try {
    if (is_scene_file(path)) {
      load_scene(path);
    } else {
      scene_from_mesh(path);
    }
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    return std::to_string(e.line()) + ":" + e.message();
  }
  return "no error";
}
}  // namespace

class BadFile : public ::testing::TestWithParam<Case> {};

TEST_P(BadFile, GivesItsSpecificError) {
  const Case& c = GetParam();
  std::string got = load(kBad + c.file);
  EXPECT_EQ(got.substr(0, got.find(':')), std::to_string(c.line)) << got;
  EXPECT_NE(got.find(c.message), std::string::npos) << got;
}

INSTANTIATE_TEST_SUITE_P(
    Data, BadFile,
    ::testing::Values(
        Case{"missing_header.off", 1, "expected an OFF header"},
        Case{"nan_coordinate.off", 4, "bad number 'nan': not a finite number"},
        Case{"absurd_exponent.off", 4, "'1e999999': exponent out of range"},
        Case{"index_out_of_range.off", 6, "vertex index 5 is out of range"},
        Case{"face_too_few_vertices.off", 6, "face 0 has 2 vertices"},
        Case{"truncated.off", 2, "more than the file can hold"},
        Case{"huge_count.off", 2, "more than the file can hold"},
        Case{"empty.off", 0, "empty mesh: no vertices"},
        Case{"garbage_number.obj", 3, "bad number 'zero'"},
        Case{"unknown_statement.obj", 5, "unknown OBJ statement 'bogus'"},
        Case{"obj_index_out_of_range.obj", 4, "vertex index 4 is out of range"},
        Case{"stl_two_vertex_facet.stl", 7, "fewer than 3 vertices"},
        Case{"stl_ascii_broken.stl", 7, "vertex z: bad number 'endloop'"},
        Case{"stl_binary_size_mismatch.stl", 0, "declares 5 triangles (334 bytes) but the file has 134 bytes"},
        Case{"stl_binary_nan.stl", 0, "triangle 0 has a coordinate that is not finite"},
        Case{"ply_no_end_header.ply", 0, "no 'end_header'"},
        Case{"ply_bad_format.ply", 2, "unknown PLY format 'binary_middle_endian'"},
        Case{"ply_missing_z.ply", 3, "vertex element lacks x, y or z"},
        Case{"unknown_extension.xyz", 0, "unknown mesh file extension '.xyz'"},
        Case{"scene_unknown_key.yaml", 4, "unknown key 'colour' in a body"},
        Case{"scene_wrong_type.yaml", 5, "view direction must be a list of 3 numbers"},
        Case{"scene_bad_number.yaml", 3, "'1/0': zero denominator"},
        Case{"scene_missing_mesh.yaml", 3, "no_such_file.off: cannot open"},
        Case{"scene_invalid_yaml.yaml", 4, "not valid YAML/JSON"},
        Case{"scene_zero_view.yaml", 4, "view direction has zero length"},
        Case{"scene_bad_rotation.yaml", 4, "cos^2 + sin^2 = 1/2, not 1"},
        Case{"scene_flat_box.yaml", 2, "box min must be below max"},
        // Found by fuzzing (fuzz_off): a 19-digit index overflowed the integer reader.
        Case{"fuzz_long_integer.off", 6, "vertex index 9999999999999999999 is out of range"}),
    [](const auto& info) {
      std::string n = info.param.file;
      for (char& ch : n)
        if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return n;
    });

TEST(BadFile, MissingFileAndDirectory) {
  EXPECT_EQ(load(kBad + "does_not_exist.off"), "0:cannot open: No such file or directory");
  EXPECT_EQ(load(std::string(HLR_DATA_DIR) + "/bad.off").substr(0, 2), "0:");
}

// Files that parse but fail a check: each check names the indices (see polyhedron_test too).
TEST(BadFile, ParsedFilesFailTheirCheck) {
  auto report = [](const char* f) { return scene_from_mesh(kBad + f).bodies[0].body.report(); };
  EXPECT_FALSE(report("open_box.off").closed());
  EXPECT_FALSE(report("non_manifold_edge.off").manifold());
  EXPECT_FALSE(report("misoriented.off").oriented());
  EXPECT_FALSE(report("non_planar_face.off").planar());
  EXPECT_FALSE(report("degenerate_face.off").degenerate_faces.empty());
  EXPECT_FALSE(report("duplicate_vertex.off").duplicate_vertices.empty());
  EXPECT_FALSE(report("repeated_index.off").refused_faces.empty());
  auto tj = report("t_junction.off").t_junctions;
  ASSERT_EQ(tj.size(), 2u);
  EXPECT_EQ(tj[0].vertex, 9);
  EXPECT_EQ(tj[0].edge, Edge(4, 5));
  EXPECT_EQ(tj[1].vertex, 8);
  EXPECT_EQ(tj[1].edge, Edge(6, 7));
  EXPECT_EQ(report("self_intersecting_face.off").self_intersecting_faces, std::vector<int>{0});
  // A convex pentagon is not self-intersecting; nor is a quad with a vertex on the line of an edge.
  EXPECT_TRUE(report("../cube.off").self_intersecting_faces.empty());
}
