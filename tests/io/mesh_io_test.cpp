// Mesh readers with exact coordinates (io/readers/mesh_reader.hpp): OFF, OBJ, STL, PLY.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "io/pipeline/render.hpp"
#include "io/readers/mesh_reader.hpp"
#include "io/readers/scene.hpp"
#include "support/numbers.hpp"

using namespace hlr;

namespace {
const std::string kData = HLR_DATA_DIR;
using hlr::test::Q;

std::string temp_file(const std::string& name, const std::string& bytes) {
  auto dir = std::filesystem::temp_directory_path() / ("hlr_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::string path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

std::string binary_stl(const std::vector<std::array<float, 9>>& tris) {
  std::string b(80, '\0');
  std::uint32_t n = static_cast<std::uint32_t>(tris.size());
  b.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : tris) {
    float normal[3] = {0, 0, 0};
    b.append(reinterpret_cast<const char*>(normal), 12);
    b.append(reinterpret_cast<const char*>(t.data()), 36);
    b.append(2, '\0');
  }
  return b;
}

const char* kTetraOff = "OFF\n4 4 0\n0.1 0.2 0.3\n1.1 0.2 0.3\n0.1 1.2 0.3\n0.1 0.2 1.3\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
}  // namespace

TEST(MeshIO, OffKeepsDecimalsExact) {
  Polyhedron p = make_polyhedron(read_off(kTetraOff, "t.off"), "t.off");
  EXPECT_EQ(p.vertices()[0], Point3(Q("1/10"), Q("1/5"), Q("3/10")));
  EXPECT_EQ(p.vertices()[1].x(), Q("11/10"));
  EXPECT_TRUE(p.report().valid_solid());
}

TEST(MeshIO, OffSkipsColoursAndComments) {
  MeshData m = read_off("COFF # comment\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 1 1 1 1\n0 1 0 # c\n3 0 1 2 0.5 0.5 0.5\n", "c.off");
  ASSERT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.faces[0], (Face{0, 1, 2}));
  EXPECT_EQ(m.face_lines[0], 6);
}

TEST(MeshIO, ObjExactWithNegativeAndSlashIndices) {
  MeshData m = read_obj("v 0.1 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf -3/1 -1 -2\n", "t.obj");
  ASSERT_EQ(m.faces.size(), 2u);
  EXPECT_EQ(m.faces[0], (Face{0, 1, 2}));
  EXPECT_EQ(m.faces[1], (Face{0, 2, 1}));
  EXPECT_EQ(m.vertices[0].x(), Q("0.1"));
  Polyhedron t = load_mesh(kData + "/tetra_decimal.obj");
  EXPECT_EQ(t.vertices()[3], Point3(Q("0.1"), Q("0.2"), Q("1.3")));
  EXPECT_TRUE(t.report().valid_solid());
}

TEST(MeshIO, ObjTextureCoordinatesPerCorner) {
  MeshData m = read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0.5 1\nf 1/1 2/2 3/3\nf 2 4 3\nf -3/-3/1 -1/-2 -2/-1\n", "t.obj");
  ASSERT_EQ(m.texcoords.size(), 3u);
  EXPECT_EQ(m.texcoords[2], (std::array<double, 2>{0.5, 1}));
  ASSERT_EQ(m.face_texcoords.size(), 3u);
  EXPECT_EQ(m.face_texcoords[0], (std::vector<int>{0, 1, 2}));
  EXPECT_TRUE(m.face_texcoords[1].empty());  // a face without them
  EXPECT_EQ(m.face_texcoords[2], (std::vector<int>{0, 1, 2}));
  auto fails = [](const std::string& text, const std::string& what, int line) {
    try {
      read_obj(text, "t.obj");
      ADD_FAILURE() << "accepted: " << what;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("t.obj:" + std::to_string(line)), std::string::npos) << e.what();
    }
  };
  fails("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n", "texture index 2 is out of range", 5);
  fails("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2 3/1\n", "some corners and not others", 5);
  fails("v 0 0 0\nvt zero 0\n", "bad number 'zero' in texture coordinates", 2);
}

// A hexagonal prism as OBJ exporters write a shaded cylinder: its side smooth (one smoothing
// group, or normals shared along the side's edges), its caps flat.
std::string obj_prism(bool with_normals) {
  std::ostringstream o;
  const char* xy[6] = {"1 0", "0.5 0.866", "-0.5 0.866", "-1 0", "-0.5 -0.866", "0.5 -0.866"};
  for (const char* p : xy) o << "v " << p << " 0\nv " << p << " 2\n";  // vertex 2k+1 low, 2k+2 high
  if (with_normals) {
    for (const char* p : xy) o << "vn " << p << " 0\n";  // 1..6: the side's
    o << "vn 0 0 -1\nvn 0 0 1\n";                        // 7, 8: the caps'
  }
  o << (with_normals ? "" : "s 1\n");
  for (int k = 0; k < 6; ++k) {
    const int j = (k + 1) % 6, lo = 2 * k + 1, hi = 2 * k + 2, lo2 = 2 * j + 1, hi2 = 2 * j + 2;
    if (with_normals)
      o << "f " << lo << "//" << k + 1 << " " << lo2 << "//" << j + 1 << " " << hi2 << "//" << j + 1 << " " << hi << "//" << k + 1 << "\n";
    else o << "f " << lo << " " << lo2 << " " << hi2 << " " << hi << "\n";
  }
  o << (with_normals ? "" : "s off\n");
  o << "f";
  for (int k = 5; k >= 0; --k) o << " " << 2 * k + 1 << (with_normals ? "//7" : "");
  o << "\nf";
  for (int k = 0; k < 6; ++k) o << " " << 2 * k + 2 << (with_normals ? "//8" : "");
  o << "\n";
  return o.str();
}

TEST(MeshIO, ObjNormalsAndSmoothingGroupsMarkSmoothSurfaces) {
  for (bool normals : {true, false}) {
    MeshData m = read_obj(obj_prism(normals), "prism.obj");
    ASSERT_EQ(m.surfaces.surface.size(), 8u) << normals;
    for (int f = 1; f < 6; ++f) EXPECT_EQ(m.surfaces.surface[f], m.surfaces.surface[0]) << "the side is one surface";
    EXPECT_NE(m.surfaces.surface[6], m.surfaces.surface[0]);
    EXPECT_NE(m.surfaces.surface[7], m.surfaces.surface[0]);
    EXPECT_NE(m.surfaces.surface[6], m.surfaces.surface[7]);
    EXPECT_FALSE(m.surfaces.sharp_between);
  }
  // Drawn through a scene: no crease across the smooth side (its 60-degree edges are creases in
  // the same prism without smoothing: the OBJ with its `s` lines taken out).
  auto across_side = [](const std::string& text) {
    const std::string path = (std::filesystem::temp_directory_path() / "hlr_prism.obj").string();
    std::ofstream(path) << text;
    RenderOptions o;
    o.view.direction = Vector3(1, Rational(13, 10), Rational(17, 10));
    int n = 0;
    for (const Segment& s : render({load_input(path, "")}, o).drawing.segments) n += s.line == LineKind::Crease && s.from().z() != s.to().z();
    return n;
  };
  std::string plain = obj_prism(false);
  for (std::size_t at; (at = plain.find("s ")) != std::string::npos;) plain.erase(at, plain.find('\n', at) + 1 - at);
  EXPECT_EQ(across_side(obj_prism(true)), 0);
  EXPECT_EQ(across_side(obj_prism(false)), 0);
  EXPECT_GT(across_side(plain), 0);
  // Without either, no surfaces: every edge goes by the crease angle.
  EXPECT_TRUE(read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "t.obj").surfaces.empty());
  EXPECT_THROW(read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n", "t.obj"), InputError);
  EXPECT_THROW(read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\ns one\nf 1 2 3\n", "t.obj"), InputError);
}

TEST(MeshIO, AsciiStlMergesEqualCornersExactly) {
  std::string stl = "solid t\n";
  const char* tris[4][3] = {{"0.1 0.2 0.3", "0.1 1.2 0.3", "1.1 0.2 0.3"},
                            {"0.1 0.2 0.3", "1.1 0.2 0.3", "0.1 0.2 1.3"},
                            {"0.10 0.2 0.3", "0.1 0.2 1.3", "0.1 1.2 0.3"},  // 0.10 == 0.1
                            {"1.1 0.2 0.3", "0.1 1.2 0.3", "0.1 0.2 1.3"}};
  for (auto& t : tris) {
    stl += "facet normal 0 0 0\nouter loop\n";
    for (auto* v : t) stl += std::string("vertex ") + v + "\n";
    stl += "endloop\nendfacet\n";
  }
  stl += "endsolid t\n";
  Polyhedron p = load_mesh(temp_file("t.stl", stl));
  EXPECT_EQ(p.num_vertices(), 4u);
  EXPECT_TRUE(p.report().valid_solid());
  EXPECT_EQ(p.vertices()[0].x(), Q("1/10"));
}

TEST(MeshIO, BinaryStlKeepsFloatsExactly) {
  const float a = 0.1f;
  std::vector<std::array<float, 9>> tris = {{a, 0, 0, 0, 1, 0, 1, 0, 0}, {a, 0, 0, 1, 0, 0, 0, 0, 1},
                                            {a, 0, 0, 0, 0, 1, 0, 1, 0}, {1, 0, 0, 0, 1, 0, 0, 0, 1}};
  // A binary file that starts with "solid" is still binary when its size matches.
  std::string b = binary_stl(tris);
  std::memcpy(b.data(), "solid binary", 12);
  Polyhedron p = load_mesh(temp_file("b.stl", b));
  EXPECT_EQ(p.num_vertices(), 4u);
  EXPECT_EQ(p.vertices()[0].x(), Rational(static_cast<double>(a)));  // 13421773/134217728
  EXPECT_EQ(p.vertices()[0].x(), Q("13421773/134217728"));
  EXPECT_TRUE(p.report().closed());
}

TEST(MeshIO, AsciiPly) {
  std::string ply =
      "ply\nformat ascii 1.0\ncomment t\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "property uchar red\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
      "0.1 0.2 0.3 9\n1.1 0.2 0.3 9\n0.1 1.2 0.3 9\n0.1 0.2 1.3 9\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  MeshData m = read_ply(ply, "t.ply");
  EXPECT_EQ(m.vertices[0].x(), Q("0.1"));  // the text's value, not the float's
  EXPECT_EQ(m.faces[3], (Face{1, 2, 3}));
  EXPECT_TRUE(make_polyhedron(m, "t.ply").report().valid_solid());
}

TEST(MeshIO, BinaryPlyBothEndians) {
  for (bool big : {false, true}) {
    std::string h = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty float z\n"
                    "element face 1\nproperty list uchar uint vertex_indices\nend_header\n";
    auto put = [&](const void* p, int n) {
      std::string s(static_cast<const char*>(p), n);
      if (big) std::reverse(s.begin(), s.end());
      h += s;
    };
    double xs[3] = {0.1, 1, 0};
    for (int i = 0; i < 3; ++i) {
      double y = i == 2 ? 1 : 0;
      float z = 0.5f;
      put(&xs[i], 8);
      put(&y, 8);
      put(&z, 4);
    }
    unsigned char n = 3;
    h += static_cast<char>(n);
    for (std::uint32_t v : {0u, 1u, 2u}) put(&v, 4);
    MeshData m = read_ply(h, "b.ply");
    ASSERT_EQ(m.vertices.size(), 3u);
    EXPECT_EQ(m.vertices[0].x(), rational_from_double(0.1));  // the stored double, exactly
    EXPECT_EQ(m.vertices[2].y(), 1);
    EXPECT_EQ(m.vertices[1].z(), Q("1/2"));
    EXPECT_EQ(m.faces[0], (Face{0, 1, 2}));
  }
}

TEST(MeshIO, FileExtensionCaseInsensitive) {
  std::string p = temp_file("UP.OFF", kTetraOff);
  EXPECT_EQ(load_mesh(p).num_faces(), 4u);
}

// Large OFF files are read in chunks of lines on every core (io/readers/off_reader.cpp); the result
// and each error must be the in-order reader's: comments, blank lines, CRLF, colours, and a
// vertex spread over two lines (which sends the file to the in-order reader).
namespace {
struct BigOff {
  std::string text;
  std::vector<int> face_line, vertex_line;  // expected line of each face and vertex
};
BigOff big_off(int n, int split_vertex, const std::string& bad_vertex_token, int bad_vertex, int bad_face) {
  BigOff b;
  int line = 1;
  auto add = [&](const std::string& l) { b.text += l + "\n", ++line; };
  add("OFF");
  add(std::to_string(n) + " " + std::to_string(n) + " 0");
  for (int i = 0; i < n; ++i) {
    if (i % 1000 == 7) add("# a comment line");
    if (i % 3000 == 11) add("");
    const std::string x = std::to_string(i) + "/7", y = "0." + std::to_string(i % 97), z = std::to_string(-i);
    b.vertex_line.push_back(line);
    if (i == split_vertex) {
      add(x + " " + y);
      add(z);
    } else if (i == bad_vertex) {
      add(x + " " + bad_vertex_token + " " + z);
    } else if (i % 5 == 0) {
      add(x + " " + y + " " + z + " 255 0 0 # coloured\r");
    } else {
      add(x + " " + y + " " + z);
    }
  }
  for (int f = 0; f < n; ++f) {
    if (f % 2000 == 3) add("   # indented comment");
    b.face_line.push_back(line);
    if (f == bad_face) add("3 0 1 " + std::to_string(n));
    else add("3 " + std::to_string(f) + " " + std::to_string((f + 1) % n) + " " + std::to_string((f + 2) % n));
  }
  return b;
}
void expect_big(const MeshData& m, const BigOff& b, int n) {
  ASSERT_EQ(m.vertices.size(), static_cast<std::size_t>(n));
  ASSERT_EQ(m.faces.size(), static_cast<std::size_t>(n));
  for (int i = 0; i < n; i += 1) {
    ASSERT_EQ(m.vertices[i].x(), Rational(i) / 7) << i;
    ASSERT_EQ(m.vertices[i].y(), Q(("0." + std::to_string(i % 97)).c_str())) << i;
    ASSERT_EQ(m.vertices[i].z(), Rational(-i)) << i;
    ASSERT_EQ(m.faces[i], (Face{i, (i + 1) % n, (i + 2) % n})) << i;
    ASSERT_EQ(m.face_lines[i], b.face_line[i]) << i;
  }
}
std::string off_error(const std::string& text) {
  try {
    read_off(text, "big.off");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(MeshIO, LargeOffReadInChunksExactly) {
  const int n = 40000;
  BigOff plain = big_off(n, -1, "", -1, -1);
  expect_big(read_off(plain.text, "big.off"), plain, n);
  BigOff split = big_off(n, 23456, "", -1, -1);  // in order: the same numbers
  expect_big(read_off(split.text, "big.off"), split, n);
}

// The chunks' line marks are counted on all cores in blocks of about a MiB (mark_records):
// blocks that end inside the vertices, at their last line and inside the faces, a last line
// without its newline, comments and blank lines after the faces, and a token after them
// (left to the in-order reader, which ignores it) read as the in-order reader does.
TEST(MeshIO, LargeOffTailsReadExactly) {
  const int n = 120000;  // about 5 MB: several blocks
  BigOff plain = big_off(n, -1, "", -1, -1);
  BigOff no_newline = plain;
  no_newline.text.pop_back();
  expect_big(read_off(no_newline.text, "big.off"), no_newline, n);
  BigOff tail = plain;
  tail.text += "\n# the end\n   \n\r\n";
  expect_big(read_off(tail.text, "big.off"), tail, n);
  BigOff extra = plain;
  extra.text += "# more\n7 7 7\n";
  expect_big(read_off(extra.text, "big.off"), extra, n);
  BigOff short_file = plain;
  short_file.text.resize(short_file.text.rfind("3 ", short_file.text.size() - 2));  // the last face missing
  EXPECT_NE(off_error(short_file.text), "");
}

TEST(MeshIO, LargeOffErrorsNameTheLine) {
  const int n = 40000;
  BigOff bad = big_off(n, -1, "0.5.5", 30001, -1);
  std::string e = off_error(bad.text);
  EXPECT_NE(e.find("big.off:" + std::to_string(bad.vertex_line[30001]) + ": vertex y: bad number '0.5.5'"), std::string::npos) << e;
  EXPECT_EQ(bad.vertex_line[30001], 30044);  // 2 header lines, 30,001 vertices, 30 comments and 10 blank lines before it
  BigOff bad_face = big_off(n, -1, "", -1, 39000);
  e = off_error(bad_face.text);
  EXPECT_NE(e.find("big.off:" + std::to_string(bad_face.face_line[39000]) + ": vertex index 40000 is out of range"), std::string::npos) << e;
}

// A large OFF whose coordinates are all short decimals is read into a compact store
// (kernel/point_store.hpp): every point is the exact value of its text, whatever its sign,
// point or number of places; one coordinate that is not such a decimal (an exponent, a
// fraction, 16 places, 19 digits, 15 places that bring the others past 2^53, a value whose
// numerator over the file's denominator 10^7 is 2^53) reads
// the whole file as exact rationals, with the same values; bad text keeps its message.
namespace {
std::string decimal_off(int n, int odd_vertex, const std::string& odd_token, std::vector<std::array<std::string, 3>>& tokens) {
  const char* forms[] = {"1", "-0.5", "+2.25", ".5", "5.", "-0", "123.4567", "-0.0000001", "0.0", "-17"};
  std::string t = "OFF\n" + std::to_string(n) + " " + std::to_string(n) + " 0\n";
  tokens.clear();
  for (int i = 0; i < n; ++i) {
    std::array<std::string, 3> c = {std::to_string(i % 1000) + "." + std::to_string(i % 97), forms[i % 10], "-" + std::to_string(i) + ".25"};
    if (i == odd_vertex) c[1] = odd_token;
    tokens.push_back(c);
    if (i % 1000 == 7) t += "# a comment line\n";
    t += c[0] + " " + c[1] + " " + c[2] + (i % 5 == 0 ? " 255 0 0 # coloured\r\n" : "\n");
  }
  for (int f = 0; f < n; ++f) t += "3 " + std::to_string(f) + " " + std::to_string((f + 1) % n) + " " + std::to_string((f + 2) % n) + "\n";
  return t;
}
}  // namespace

TEST(MeshIO, LargeOffOfShortDecimalsReadsCompactly) {
  const int n = 40000;
  std::vector<std::array<std::string, 3>> tokens;
  struct Case {
    int vertex;
    std::string token;
    bool compact;
  };
  for (const Case& c : {Case{-1, "", true}, Case{31234, "1e-3", false}, Case{5, "3/7", false}, Case{39999, "0.1234567890123456", false},
                        Case{17, "0.123456789012345", false}, Case{20000, "900719925.4740992", false}, Case{20001, "-900719925.4740991", true},
                        Case{3, "1234567890123456789", false}}) {
    SCOPED_TRACE(c.token);
    const std::string text = decimal_off(n, c.vertex, c.token, tokens);
    const MeshData m = read_off(text, "dec.off");
    ASSERT_EQ(m.compact.compact(), c.compact);
    ASSERT_EQ(m.num_vertices(), static_cast<std::size_t>(n));
    ASSERT_EQ(m.vertices.size(), c.compact ? 0u : static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) {
        const Rational want = parse_rational(tokens[i][k]);
        const Point3 p = c.compact ? m.compact.point(i) : m.vertices[i];
        ASSERT_EQ(p[k], want) << i << " " << tokens[i][k];
        if (c.compact) ASSERT_EQ(m.compact.approx(i, k).lo, bounds_of(want).lo) << i << " " << tokens[i][k];
      }
    ASSERT_EQ(m.faces[n - 1], (Face{n - 1, 0, 1}));
    const Polyhedron p = make_polyhedron(MeshData(m), "dec.off");
    EXPECT_EQ(p.vertex_store().compact(), c.compact);
    EXPECT_EQ(p.num_vertices(), static_cast<std::size_t>(n));
  }
  const std::string bad = decimal_off(n, 30001, "0.5.5", tokens);
  const std::string e = off_error(bad);
  EXPECT_NE(e.find("big.off:30034: vertex y: bad number '0.5.5'"), std::string::npos) << e;  // 2 header lines, 30 comments
}

// The loader's repairs on a compact store: a large file (a terrain of non-planar quads, and a
// box whose top has a zero-area triangle on its seam) renders exactly as the same file read as
// exact rationals (one coordinate written as a fraction): the same repairs, segments and pieces.
namespace {
std::string repair_off(bool fraction) {
  std::mt19937 rng(7);
  const int n = 130;  // quads a side: 17,161 vertices and 16,900 quads, with the box over 32,768 records
  std::string v, f;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const std::string z = "1.5" + std::to_string(rng() % 1000);
      v += std::to_string(i) + ".5 " + std::to_string(j) + " " + (i == 0 && j == 0 ? (fraction ? "3/2" : "1.5") : z) + "\n";
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i * (n + 1) + j;
      f += "4 " + std::to_string(a) + " " + std::to_string(a + n + 1) + " " + std::to_string(a + n + 2) + " " + std::to_string(a + 1) + "\n";
    }
  const int o = (n + 1) * (n + 1);  // the box [0, 4] x [0, 2] x [-6, -4.25], the seam's middle (2, 1, -4.25)
  for (const char* p : {"0 0 -6", "4 0 -6", "0 2 -6", "4 2 -6", "0 0 -4.25", "4 0 -4.25", "0 2 -4.25", "4 2 -4.25", "2 1 -4.25"})
    v += std::string(p) + "\n";
  for (const std::vector<int>& face :
       std::vector<std::vector<int>>{{0, 2, 3, 1}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}, {4, 5, 7}, {4, 7, 8}, {4, 8, 7, 6}}) {
    f += std::to_string(face.size());
    for (int k : face) f += " " + std::to_string(o + k);
    f += "\n";
  }
  return "OFF\n" + std::to_string(o + 9) + " " + std::to_string(n * n + 8) + " 0\n" + v + f;
}
}  // namespace

TEST(MeshIO, CompactVerticesTakeTheSameRepairs) {
  const std::string compact = temp_file("terrain.off", repair_off(false)), exact = temp_file("terrain_exact.off", repair_off(true));
  ASSERT_TRUE(read_mesh_file(compact).compact.compact());
  ASSERT_FALSE(read_mesh_file(exact).compact.compact());
  RenderOptions o;
  o.view.direction = Vector3(1, parse_rational("1.3"), parse_rational("1.7"));
  o.lines.edges = EdgeSelection::All;
  const RenderResult a = render_files({compact}, o), b = render_files({exact}, o);
  for (const RenderResult* r : {&a, &b}) {
    std::string notes;
    for (const std::string& n : r->notes) notes += n + "\n";
    EXPECT_NE(notes.find("16887 non-planar quads split along the shorter diagonal"), std::string::npos) << notes;
    EXPECT_NE(notes.find("has 1 zero-area triangle"), std::string::npos) << notes;
  }
  ASSERT_EQ(a.drawing.segments.size(), b.drawing.segments.size());
  for (std::size_t i = 0; i < a.drawing.segments.size(); ++i) {
    const Segment &s = a.drawing.segments[i], &t = b.drawing.segments[i];
    ASSERT_EQ(s.v0, t.v0);
    ASSERT_EQ(s.v1, t.v1);
    ASSERT_EQ(s.from(), t.from());
    ASSERT_EQ(s.pieces.size(), t.pieces.size());
    for (std::size_t k = 0; k < s.pieces.size(); ++k) {
      ASSERT_EQ(s.pieces[k].t1, t.pieces[k].t1);
      ASSERT_EQ(s.pieces[k].visible, t.pieces[k].visible);
    }
  }
}

// Binary STL corners are welded by exact float value (a hash table without allocation per
// vertex): the same vertices, numbered by first appearance, as a plain map of the values;
// -0 and +0 are one point, 0.1f and the double 0.1 are not the same value.
TEST(MeshIO, BinaryStlWeldsLikeAMapOfValues) {
  std::mt19937 rng(3);
  const float values[] = {0.0f, -0.0f, 0.1f, -0.1f, 1.0f, 1e-30f, 3.5f, 123456.78f};
  std::uniform_int_distribution<int> pick(0, 7);
  std::vector<std::array<float, 9>> tris(5000);
  for (auto& t : tris)
    for (float& c : t) c = values[pick(rng)];
  MeshData m = read_stl(binary_stl(tris), "w.stl");
  std::map<std::array<float, 3>, int> seen;
  std::vector<std::array<float, 3>> order;
  ASSERT_EQ(m.faces.size(), tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      std::array<float, 3> p = {tris[t][3 * c], tris[t][3 * c + 1], tris[t][3 * c + 2]};
      for (float& x : p) x = x == 0.0f ? 0.0f : x;
      auto [it, fresh] = seen.emplace(p, static_cast<int>(order.size()));
      if (fresh) order.push_back(p);
      ASSERT_EQ(m.faces[t][c], it->second) << t << " " << c;
    }
  ASSERT_EQ(m.vertices.size(), order.size());
  for (std::size_t v = 0; v < order.size(); ++v)
    EXPECT_EQ(m.vertices[v], Point3(Rational(order[v][0]), Rational(order[v][1]), Rational(order[v][2])));
}
