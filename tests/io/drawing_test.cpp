// SVG and JSON output of Roberts' results (io/writers/drawing.hpp) and atomic output files.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <unistd.h>

#include "io/writers/atomic_file.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/hlr/roberts.hpp"
#include "io/writers/drawing.hpp"
#include "io/writers/json_writer.hpp"
#include "io/readers/tile_file.hpp"
#include "io/readers/input_error.hpp"
#include "io/readers/scene.hpp"
#include "io/readers/text_reader.hpp"

using namespace hlr;

namespace {
const std::string kData = HLR_DATA_DIR;

struct Rendered {
  Scene scene;
  std::vector<DrawingBody> names;
  LineDrawing result;
  Camera camera;
};

Rendered render(const std::string& scene_file, const Camera& cam) {
  Rendered r{load_scene(scene_file), {}, {}, cam};
  std::vector<const Polyhedron*> ptrs;
  for (auto& b : r.scene.bodies) {
    ptrs.push_back(&b.body);
    r.names.push_back({b.name, b.source});
  }
  r.result = roberts(ptrs, cam);
  return r;
}

std::string temp_dir() {
  auto dir = std::filesystem::temp_directory_path() / ("hlr_out_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir.string();
}
}  // namespace

TEST(Json, SchemaAndExactCoordinates) {
  Rendered r = render(kData + "/two_boxes.yaml", make_orthographic(Vector3(1, parse_rational("1.3"), parse_rational("1.7"))));
  auto j = nlohmann::json::parse(to_json(r.names, r.result, r.camera));
  EXPECT_EQ(j["view"]["type"], "orthographic");
  EXPECT_EQ(j["view"]["direction"], nlohmann::json({"1", "13/10", "17/10"}));
  ASSERT_EQ(j["bodies"].size(), 2u);
  EXPECT_EQ(j["bodies"][1]["name"], "bar");
  EXPECT_EQ(j["bodies"][1]["source"], kData + "/two_boxes.yaml");
  bool saw_intersection = false, saw_fraction = false;
  for (const auto& s : j["segments"]) {
    ASSERT_TRUE(s.contains("kind") && s.contains("visible") && s.contains("from") && s.contains("to"));
    if (s["kind"] == "edge" || s["kind"] == "crease" || s["kind"] == "silhouette") {
      ASSERT_TRUE(s["body"].is_number_integer());
      ASSERT_EQ(s["edge"].size(), 2u);
    } else {
      EXPECT_EQ(s["kind"], "intersection");
      EXPECT_EQ(s["bodies"], nlohmann::json({0, 1}));
      saw_intersection = true;
    }
    for (const auto& c : s["from"]) {
      std::string v = c;
      EXPECT_TRUE(std::regex_match(v, std::regex("-?[0-9]+(/[0-9]+)?"))) << v;
      saw_fraction = saw_fraction || v.find('/') != std::string::npos;
    }
  }
  EXPECT_TRUE(saw_intersection);
  EXPECT_TRUE(saw_fraction);  // e.g. 1/2 and the exact split points
  // The pieces of one edge are listed in order and cover it: consecutive, from t 0 to 1.
  std::string prev_end;
  for (const auto& s : j["segments"]) {
    if (s["kind"] == "intersection" || s["body"] != 1 || s["edge"] != nlohmann::json({1 | 4, 1 | 2 | 4})) continue;
    if (prev_end.empty()) EXPECT_EQ(s["t"][0], "0");
    else EXPECT_EQ(s["t"][0], prev_end);
    prev_end = s["t"][1];
  }
  EXPECT_EQ(prev_end, "1");
}

TEST(Json, PerspectiveView) {
  Rendered r = render(kData + "/two_boxes.yaml", make_perspective(Point3(10, 12, 9), Point3(2, 1, 1)));
  auto j = nlohmann::json::parse(to_json(r.names, r.result, r.camera));
  EXPECT_EQ(j["view"]["type"], "perspective");
  EXPECT_EQ(j["view"]["eye"], nlohmann::json({"10", "12", "9"}));
}

// The segments' lines are written straight into the text (append_piece_json), not through a
// JSON value: every kind of segment and every flag must read exactly as piece_json's dump.
TEST(Json, PiecesWrittenDirectlyReadAsTheJsonValue) {
  Segment e;
  e.kind = Segment::Kind::Edge;
  e.body = 3, e.v0 = 17, e.v1 = 4;
  e.set_ends(Point3(parse_rational("-1/3"), 2, parse_rational("12345678901234567890/7")), Point3(0, parse_rational("-2.5"), 1));
  Segment x;
  x.kind = Segment::Kind::Intersection;
  x.body = 1, x.body2 = 2;
  x.set_ends(Point3(1, 1, 1), Point3(-1, 0, parse_rational("1/9")));
  int checked = 0;
  for (Segment* s : {&e, &x})
    for (LineKind k : {LineKind::Edge, LineKind::Boundary, LineKind::Crease, LineKind::Silhouette})
      for (int flags = 0; flags < 32; ++flags) {
        s->line = k;
        s->self_hidden = flags & 16;
        Piece p{parse_rational("1/7"), parse_rational("5/6"), (flags & 1) != 0, (flags & 2) != 0, (flags & 4) != 0, (flags & 8) != 0};
        if (flags == 0) p.t0 = 0, p.t1 = 1;
        std::string text = "[";
        append_piece_json(text, *s, p);
        EXPECT_EQ(text.substr(1), piece_json(*s, p).dump()) << "flags " << flags;
        ++checked;
      }
  EXPECT_EQ(checked, 2 * 4 * 32);
}

TEST(Svg, GroupsViewBoxAndDeterminism) {
  Rendered r = render(kData + "/demo.yaml", make_orthographic(Vector3(1, parse_rational("1.3"), parse_rational("1.7"))));
  SvgOptions o;
  o.hidden_dashed = true;
  o.width_mm = 120;
  std::string a = to_svg(r.names, r.result, r.camera, o);
  EXPECT_EQ(a, to_svg(r.names, r.result, r.camera, o));  // deterministic
  EXPECT_NE(a.find("width=\"120.000mm\""), std::string::npos);
  EXPECT_NE(a.find("viewBox=\"0 0 120.000 "), std::string::npos);
  EXPECT_NE(a.find("<g id=\"visible\""), std::string::npos);
  EXPECT_NE(a.find("<g id=\"hidden\""), std::string::npos);
  EXPECT_NE(a.find("stroke-dasharray"), std::string::npos);
  // One group per line kind inside visible and hidden, one per body (or pair) inside those.
  EXPECT_NE(a.find("<g id=\"visible-crease\">"), std::string::npos);
  EXPECT_NE(a.find("<g id=\"visible-silhouette\">"), std::string::npos);
  EXPECT_NE(a.find("<g id=\"visible-silhouette-body-0\" data-name=\"base\">"), std::string::npos);
  EXPECT_NE(a.find("<g id=\"hidden-intersection-0-2\">"), std::string::npos);
  o.hidden_dashed = false;
  std::string b = to_svg(r.names, r.result, r.camera, o);
  EXPECT_EQ(b.find("<g id=\"hidden\""), std::string::npos);
  // Every coordinate lies inside the viewBox.
  std::smatch m;
  std::regex vb("viewBox=\"0 0 ([0-9.]+) ([0-9.]+)\"");
  ASSERT_TRUE(std::regex_search(a, m, vb));
  double w = std::stod(m[1]), h = std::stod(m[2]);
  std::regex num("[xy][12]=\"(-?[0-9.]+)\"");
  for (auto it = std::sregex_iterator(a.begin(), a.end(), num); it != std::sregex_iterator(); ++it) {
    double v = std::stod((*it)[1]);
    EXPECT_GE(v, 0);
    EXPECT_LE(v, std::max(w, h));
  }
}

TEST(AtomicFile, WritesAndReplaces) {
  std::string path = temp_dir() + "/out.svg";
  write_file_atomically(path, "one");
  write_file_atomically(path, "two");
  std::ifstream in(path);
  std::string s((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(s, "two");
  for (const auto& e : std::filesystem::directory_iterator(temp_dir()))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << "stray temporary file";
}

TEST(AtomicFile, LargeContentWrittenInPiecesComesBackByteForByte) {
  // Over two 4 MiB pieces and a partial third: every byte at its offset.
  std::string content(9u << 20, '\0');
  for (std::size_t i = 0; i < content.size(); ++i) content[i] = static_cast<char>('a' + (i * 7919 + i / 4096) % 26);
  std::string path = temp_dir() + "/large.svg";
  write_file_atomically(path, content);
  std::ifstream in(path, std::ios::binary);
  std::string s((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(s.size(), content.size());
  EXPECT_TRUE(s == content);
  // And read back through the parallel reader (16 MiB and more): a file of 17 MiB.
  content.append(8u << 20, 'z');
  write_file_atomically(path, content);
  EXPECT_TRUE(read_file_bytes(path) == content);
}

TEST(AtomicFile, PartsComeBackInOrderByteForByte) {
  // Empty parts, parts over the 1 MiB write pieces, many small ones: the file is their join.
  std::vector<std::string> parts;
  std::string joined;
  std::mt19937 rng(5);
  for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(5u << 19), std::size_t(0), std::size_t(1u << 20), std::size_t(77)}) {
    std::string part(n, '\0');
    for (char& c : part) c = static_cast<char>('a' + rng() % 26);
    parts.push_back(part);
    joined += part;
  }
  for (int i = 0; i < 500; ++i) parts.push_back(std::to_string(i) + ","), joined += parts.back();
  const std::string path = temp_dir() + "/parts.json";
  write_file_atomically(path, parts);
  EXPECT_TRUE(read_file_bytes(path) == joined);
  write_file_atomically(path, std::vector<std::string>{});
  EXPECT_EQ(read_file_bytes(path), "");
}

// Text made as it is written (the JSON's segments): runs of pieces made on all cores a batch at
// a time into reused buffers, in order, the same bytes on 1, 2 and 8 threads, empty pieces
// and empty runs included; a piece that cannot be made leaves no file (not the old one
// overwritten, no temporary file).
TEST(AtomicFile, RunsMadeAsTheyAreWrittenComeBackInOrder) {
  auto piece = [](std::size_t k, std::string& out) {
    if (k % 7 == 3) return;  // empty
    out.append(k % 5 == 0 ? 300000 : k % 11 + 1, static_cast<char>('a' + k % 26));
    out += std::to_string(k) + "\n";
  };
  std::string want = "head\n";
  for (std::size_t k = 0; k < 1000; ++k) piece(k, want);
  want += "tail\n";
  const std::string path = temp_dir() + "/runs.json";
  for (unsigned threads : {1u, 2u, 8u}) {
    ThreadLimit limit(threads);
    PartText text;
    text.add("head\n");
    text.add_run(0, piece);
    text.add_run(1000, piece);
    text.add_view("tail\n");
    EXPECT_TRUE(text.str() == want) << threads;
    write_file_atomically(path, text);
    EXPECT_TRUE(read_file_bytes(path) == want) << threads;
  }
  PartText failing;
  failing.add("head\n");
  failing.add_run(100, [](std::size_t k, std::string& out) {
    if (k == 60) throw std::runtime_error("piece 60");
    out += "x";
  });
  EXPECT_THROW(write_file_atomically(path, failing), std::runtime_error);
  EXPECT_TRUE(read_file_bytes(path) == want);  // the old file stands
  std::size_t temporaries = 0;
  for (const auto& e : std::filesystem::directory_iterator(temp_dir()))
    temporaries += e.path().filename().string().rfind(".runs.json.tmp", 0) == 0;
  EXPECT_EQ(temporaries, 0u);
}

// A tile file whose 'tile', 'segments' or 'counters' record comes twice is refused (the fuzzer
// found a second 'segments' that lowered the count after pieces had been checked against it).
TEST(TileFile, RepeatedRecordsAreRefused) {
  const std::string head = "hlr-tile 1\ntile 2 4\nsegments 68 5b94\ncounters 1 2 3 4 5 6\npiece 41 0 1 v\n";
  EXPECT_NO_THROW(read_tile_text(head + "end\n", "t.tile"));
  for (const char* again : {"segments 2 4\n", "tile 1 4\n", "counters 1 2 3 4 5 6\n"}) {
    try {
      read_tile_text(head + again + "end\n", "t.tile");
      ADD_FAILURE() << again;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("a second"), std::string::npos) << e.what();
    }
  }
}

// The family of the fuzzer's second find: a number that does not fit its field ('tile 2
// 4444444444444' was cut to an int and gave a tile index past the count) or is not a plain
// count (a sign, a space too many) is refused, in every numeric record.
TEST(TileFile, NumbersOutOfRangeOrMalformedAreRefused) {
  const std::string tile = "tile 2 4\n", segments = "segments 68 5b94\n", counters = "counters 1 2 3 4 5 6\n";
  auto text = [&](const std::string& t, const std::string& s, const std::string& c) {
    return "hlr-tile 1\n" + t + s + c + "piece 41 0 1 v\nend\n";
  };
  const TileFile ok = read_tile_text(text(tile, segments, counters), "t.tile");
  EXPECT_EQ(ok.index, 1);
  EXPECT_EQ(ok.count, 4);
  EXPECT_EQ(ok.segments, 68u);
  EXPECT_EQ(ok.fingerprint, 0x5b94u);
  EXPECT_EQ(ok.comparisons_exact, 6u);
  const TileFile most = read_tile_text(text("tile 1000000 1000000\n", "segments 18446744073709551615 ffffffffffffffff\n", counters), "t.tile");
  EXPECT_EQ(most.index, kMaxTiles - 1);
  EXPECT_EQ(most.fingerprint, ~std::uint64_t{0});
  const std::vector<std::string> bad_tiles = {"tile 2 4444444444444\n", "tile 4294967298 4294967299\n", "tile 1 1000001\n",
                                              "tile -1 4\n", "tile +2 4\n", "tile 2  4\n", "tile 2 4 \n", "tile 2\n", "tile 0 4\n", "tile 5 4\n"};
  const std::vector<std::string> bad_segments = {"segments -1 5b94\n", "segments 18446744073709551616 5b94\n", "segments 68 -5b94\n",
                                                 "segments 68 10000000000000000\n", "segments 68 0x5b94\n", "segments 68\n", "segments 68 5b94 1\n"};
  const std::vector<std::string> bad_counters = {"counters 1 2 3 4 5 -6\n", "counters 1 2 3 4 5 18446744073709551616\n",
                                                 "counters 1 2 3 4 5\n", "counters 1 2 3 4 5 6 7\n", "counters 1 2 3 4 5 6x\n"};
  auto refused = [&](const std::string& file, const std::string& what) {
    try {
      const TileFile t = read_tile_text(file, "t.tile");
      ADD_FAILURE() << what << " was read as tile " << t.index << " of " << t.count;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("t.tile:"), std::string::npos) << e.what();
    }
  };
  for (const std::string& b : bad_tiles) refused(text(b, segments, counters), b);
  for (const std::string& b : bad_segments) refused(text(tile, b, counters), b);
  for (const std::string& b : bad_counters) refused(text(tile, segments, b), b);
}

TEST(AtomicFile, DirectoryAndUnwritablePathsFailCleanly) {
  EXPECT_THROW(write_file_atomically(temp_dir(), "x"), OutputError);
  EXPECT_THROW(write_file_atomically(temp_dir() + "/no/such/folder/out.svg", "x"), OutputError);
  try {
    write_file_atomically("/proc/hlr-cannot-write-here.svg", "x");
    FAIL();
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write /proc/hlr-cannot-write-here.svg"), std::string::npos);
  }
}
