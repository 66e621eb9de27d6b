// Error messages of exam mode in Russian: every error a problem file can cause is
// translated, nested parts too, with no English word outside the file format's own keys; and
// every English message the sources throw on that path has a catalogue entry (so a reworded
// message cannot silently fall back to English).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "algorithms/model/line_drawing.hpp"
#include "io/explain/explain.hpp"
#include "io/readers/input_error.hpp"
#include "io/explain/messages_ru.hpp"
#include "io/explain/problem.hpp"
#include "kernel/number.hpp"

namespace hlr {
namespace {

const std::string kSource = std::string(HLR_DATA_DIR) + "/..";

// Words a Russian message may keep in Latin letters: keys and values of the file format (what
// the student types), formula symbols, and format names.
bool allowed_latin(const std::string& w) {
  static const std::set<std::string> keys = {
      "problem",  "roberts",     "cyrus",     "beck",    "midpoint", "convexity",  "decompose",    "transform", "horizon",   "heights",
      "bodies",   "vertices",    "faces",     "box",     "frustum",  "mesh",       "clipper",      "segments",  "edges",     "eps",
      "title",    "view",        "direction", "eye",     "target",   "up",         "light",        "name",      "translate", "scale",
      "rotate",   "reflect",     "matrix",    "factors", "axis",     "degrees",    "cos",          "sin",       "tan_half",  "centre",
      "center",   "min",         "max",       "xmin",    "xmax",     "ymin",       "ymax",         "zmin",      "zmax",      "xl",
      "xr",       "yb",          "yt",        "znear",   "zfar",     "zcp",        "XMIN",         "XMAX",      "YMIN",      "YMAX",
      "ZMIN",     "ZMAX",        "XL",        "XR",      "YB",       "YT",         "ZCP",          "ZNEAR",     "ZFAR",      "x1",
      "y1",       "z1",          "x2",        "y2",      "z2",       "YAML",       "JSON",         "NaN",       "hlr",       "off",
      "input",    "format",      "obj",       "stl",     "ply",      "GiB",        "yaml",         "material",  "lighting",  "lights",
      "ambient",  "specular",    "phong",     "blinn",   "colour",   "color",      "ka",           "kd",        "ks",        "shininess",
      "type",     "directional", "point",     "spot",    "position", "intensity",  "attenuation",  "cone",      "exponent",  "rrggbb",
      "a0",       "a1",          "a2",        "r",       "g",        "b",          "weiler",       "atherton",  "faces",     "method",
      "priority", "raster",      "size",      "window",  "trace",    "reflection", "transparency", "ior",       "x0",        "x1",
      "y0",       "y1",          "PNG",       "ray",     "tree",     "from",       "direction",    "dx",        "dy",        "dz",
      "depth",    "cut",         "hatch",     "section", "pattern",  "angle",      "spacing",      "single",    "cross",     "solid",
      "none",     "true",        "false",     "mm"};
  return keys.count(w) > 0;
}

// The Latin words of a message outside quotes ('...') and outside the file name prefix.
std::vector<std::string> english_words(std::string m) {
  m = std::regex_replace(m, std::regex("[^ ]*/[^ ]*"), "");  // file paths
  for (std::size_t a; (a = m.find('\'')) != std::string::npos;) {
    std::size_t b = m.find('\'', a + 1);
    if (b == std::string::npos) break;
    m.erase(a, b + 1 - a);
  }
  std::vector<std::string> out;
  std::regex latin("[A-Za-z_][A-Za-z_0-9]+");
  for (auto it = std::sregex_iterator(m.begin(), m.end(), latin); it != std::sregex_iterator(); ++it)
    if (!allowed_latin(it->str())) out.push_back(it->str());
  return out;
}

// The error a problem text causes, as the reader or the solver throws it (message part only).
std::string error_of(const std::string& yaml) {
  std::filesystem::path p = std::filesystem::temp_directory_path() / "hlr_messages_ru_test.yaml";
  {
    std::ofstream(p) << yaml;
  }
  try {
    Problem pr = load_problem(p.string());
    explain(pr);
  } catch (const InputError& e) {
    return e.message();
  } catch (const NumberError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

void expect_russian(const std::string& en, const std::string& context) {
  bool ok = false;
  std::string ru = message_ru(en, &ok);
  EXPECT_TRUE(ok) << context << ": no Russian for \"" << en << "\"";
  EXPECT_TRUE(english_words(ru).empty()) << context << ": English left in \"" << ru << "\" (first: '"
                                         << (english_words(ru).empty() ? "" : english_words(ru)[0]) << "')";
  EXPECT_NE(ru, en) << context;
}

const char* kCube = "  - vertices: [[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1],[0,1,1]]\n"
                    "    faces: [[0,3,2,1],[4,5,6,7],[0,1,5,4],[1,2,6,5],[2,3,7,6],[3,0,4,7]]\n";

// One bad problem per message the readers and the solver give; each must fail (a test of the
// corpus itself) and its message must be translated completely.
TEST(MessagesRu, EveryErrorOfABadProblemIsTranslated) {
  const std::string box = "clipper: {box: [0, 1, 0, 1, 0, 1]}\n";
  const std::vector<std::string> bad = {
      "title: x\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    material: {colour: red}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    material: {ka: 2}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    material: {colour: [1, 1, 1], color: [1, 1, 1]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {specular: gouraud}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {lights: 3}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {lights: [{direction: [1, 2, 3]}]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {lights: [{type: lamp}]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {lights: [{type: spot, position: [1, 2, 3]}]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {lights: [{type: point, position: [1, 2, 3], direction: [1, 0, 0]}]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {lights: [{type: point}]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {lights: [{type: directional, direction: [1, 0, 0], position: [0, 0, 0]}]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {lights: [{type: directional, direction: [0, 0, 0]}]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {lights: [{type: directional, direction: [1, 0, 0], attenuation: [1, 0, 0]}]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {lights: [{type: point, position: [0, 0, 9], attenuation: [1, -1, 0]}]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {lights: [{type: point, position: [0, 0, 9], cone: 20}]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {lights: [{type: spot, position: [0, 0, 9], direction: [0, 0, -1], cone: 100}]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {lights: [{type: point, position: [0, 0, 9], colour: '#12'}]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "lighting: {lights: [{type: point, position: [0, 0, 9], flux: 2}]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    material: {transparency: 0.6, reflection: 0.6}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    material: {ior: 20}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    material: {texture: no_such.png}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    material: {colour2: [1, 1, 1], color2: [1, 1, 1]}\n",
      "problem: raster\nbodies:\n" + std::string(kCube) + "view: {eye: [3, 4, 5]}\n",
      "problem: raster\nbodies:\n" + std::string(kCube) + "size: 8\n",
      "problem: raster\nbodies:\n" + std::string(kCube) + "size: [0, 8]\n",
      "problem: raster\nbodies:\n" + std::string(kCube) + "window: [1, 0, 0, 1]\n",
      "problem: raster\nbodies:\n" + std::string(kCube) + "size: [3, 3]\nwindow: [0, 1, 0, 1]\n",
      "problem: raster\nbodies:\n" + std::string(kCube) + "trace: 3\n",
      "problem: raster\nbodies:\n" + std::string(kCube) + "trace: [[1, 2, 3]]\n",
      "problem: raster\nbodies:\n" + std::string(kCube) + "trace: [[100, 0]]\n",
      "problem: ray-tree\nbodies:\n" + std::string(kCube) + "ray: {from: [0, 0, 5]}\n",
      "problem: ray-tree\nbodies:\n" + std::string(kCube) + "ray: {from: [0, 0, 5], direction: [0, 0, 0]}\n",
      "problem: ray-tree\nbodies:\n" + std::string(kCube) + "ray: {from: [0, 0, 5], direction: [0, 0, -1]}\ndepth: 9\n",
      "problem: [roberts]\n",
      "problem: robert\n",
      "- 1\n- 2\n",
      "problem: roberts\nbodies: [ {box: {min: [0,0,0], max: [1,1,1]}\n",
      "problem: roberts\nbodies: [[1, 2]\n",
      "problem: roberts\nbodies:\n  - box: {min: [0,0,0], max: [1,1,1]}\n    colour: red\n",
      "problem: roberts\nbodies:\n  - box: {min: [0,0,0], max: [1,1,1]}\n    box: {min: [0,0,0], max: [1,1,1]}\n",
      "problem: roberts\nbodies:\n  - box: {min: [0,0,0], max: [1,1,x]}\n",
      "problem: roberts\nbodies:\n  - box: {min: [0,0,0], max: [1,1,1/0]}\n",
      "problem: roberts\nbodies:\n  - box: {min: [0,0,0], max: [1,1,1e]}\n",
      "problem: roberts\nbodies:\n  - box: {min: [0,0,0], max: [1,1,nan]}\n",
      "problem: roberts\nbodies:\n  - box: {min: [0,0,0], max: [1,1,1e99999999]}\n",
      "problem: roberts\nbodies:\n  - box: {min: [0,0,0], max: [1,1]}\n",
      "problem: roberts\nbodies:\n  - box: {min: [0,0,0], max: [1,1,0]}\n",
      "problem: roberts\nbodies:\n  - box: {min: [0,0,0]}\n",
      "problem: roberts\nbodies:\n  - name: a\n",
      "problem: roberts\nbodies: []\n",
      "problem: roberts\n",
      "problem: roberts\nbodies:\n  - vertices: [[0,0,0]]\n",
      "problem: roberts\nbodies:\n  - vertices: []\n    faces: [[0,1,2]]\n",
      "problem: roberts\nbodies:\n  - vertices: [[0,0,0],[1,0,0],[0,1,0]]\n    faces: []\n",
      "problem: roberts\nbodies:\n  - vertices: [[0,0,0],[1,0,0],[0,1,0]]\n    faces: [7]\n",
      "problem: roberts\nbodies:\n  - vertices: [[0,0,0],[1,0,0],[0,1,0]]\n    faces: [[0,1,5]]\n",
      "problem: roberts\nbodies:\n  - vertices: [[0,0,0],[1,0,0],[0,1,0]]\n    faces: [[0,1]]\n",
      "problem: roberts\nbodies:\n  - vertices: [[0,0,0],[1,0,0],[0,1,0]]\n    faces: [[0,1,1/2]]\n",
      "problem: roberts\nbodies:\n  - vertices: [[0,0,0],[1,0,0],[0,1,0]]\n    faces: [[0,1,2]]\nview: {direction: [0,0,1]}\n",
      "problem: roberts\nbodies:\n  - mesh: no_such_file.off\n",
      "problem: roberts\nbodies:\n  - mesh: no_such_file.xyz\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "view: {direction: [0,0,0]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "view: {direction: [0,0,1], eye: [0,0,5]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "view: {direction: [0,0,1], target: [0,0,5]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "view: {eye: [0,0,5], target: [0,0,5]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "view: {up: [0,1,0]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "view: {direction: [0,0,1], up: [0,0,0]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "view: {eye: [1/2,1/2,1/2]}\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "light: [0,0,0]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "edges: 3\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "edges: [[0, 1]]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "edges: [[1, 0, 1]]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "edges: [[0, 0, 6]]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "title: [a]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: 3\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{shear: 2}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{scale: 0}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{scale: {centre: [0,0,0]}}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{rotate: {degrees: 30}}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{rotate: {axis: w, degrees: 30}}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{rotate: {axis: x}}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{rotate: {axis: x, cos: 1}}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{rotate: {axis: x, cos: 1, sin: 1}}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{rotate: {axis: x, degrees: 3, centre: [0,0,0], center: [0,0,0]}}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{reflect: {centre: [0,0,0]}}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{reflect: {axis: w}}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{matrix: [[1,0,0,0]]}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{matrix: [[1,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{matrix: [[1,0,0,0],[0,1,0,0],[0,0,0,0],[0,0,0,1]]}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{matrix: [[1,0,0,0],[0,1,0,0],[0,0,1,-1],[0,0,0,1]]}]\n",
      "problem: roberts\nbodies:\n" + std::string(kCube) + "    transform: [{translate: [1,2,3], scale: 2}]\n",
      "problem: roberts\nbodies:\n  - vertices: [[0,0,0],[2,0,0],[2,2,0],[1,1,0],[0,2,0],[0,0,1],[2,0,1],[2,2,1],[1,1,1],[0,2,1]]\n"
      "    faces: [[0,4,3,2,1],[5,6,7,8,9],[0,1,6,5],[1,2,7,6],[2,3,8,7],[3,4,9,8],[4,0,5,9]]\n",
      "problem: cyrus-beck\nbodies:\n" + std::string(kCube),
      "problem: cyrus-beck\n",
      "problem: cyrus-beck\n" + box,
      "problem: cyrus-beck\n" + box + "segments: [[0,0,0,1,1]]\n",
      "problem: cyrus-beck\nclipper: {box: [1, 0, 0, 1, 0, 1]}\nsegments: [[0,0,0,1,1,1]]\n",
      "problem: cyrus-beck\nclipper: {frustum: [1, 0, 0, 1, -1, -2, 5]}\nsegments: [[0,0,0,1,1,1]]\n",
      "problem: cyrus-beck\nclipper: {frustum: [0, 1, 0, 1, -1, -2, -5]}\nsegments: [[0,0,0,1,1,1]]\n",
      "problem: cyrus-beck\nclipper: {sphere: [0, 1]}\nsegments: [[0,0,0,1,1,1]]\n",
      "problem: cyrus-beck\nclipper: {box: [0, 1], frustum: [1]}\nsegments: [[0,0,0,1,1,1]]\n",
      "problem: cyrus-beck\nclipper: {mesh: [a]}\nsegments: [[0,0,0,1,1,1]]\n",
      "problem: cyrus-beck\nclipper: {mesh: l_prism_missing.off}\nsegments: [[0,0,0,1,1,1]]\n",
      "problem: midpoint\n" + box + "segments: [[0,0,0,1,1,1]]\neps: 0\n",
      "problem: convexity\nbodies:\n" + std::string(kCube) + std::string(kCube),
  };
  std::set<std::string> seen;
  for (const std::string& yaml : bad) {
    std::string en = error_of(yaml);
    EXPECT_FALSE(en.empty()) << "this problem must fail:\n" << yaml;
    if (en.empty()) continue;
    seen.insert(en);
    expect_russian(en, yaml);
  }
  EXPECT_GE(seen.size(), 60u);  // distinct messages, not one message many times
}

// Messages of the kernel and the algorithms that a problem file reaches only in rare ways.
TEST(MessagesRu, NestedMessagesAreTranslatedPartByPart) {
  EXPECT_EQ(message_ru("clipper: the clipper 'a' is not convex: face 4 has vertex 1 on one side of its plane and vertex 7 on "
                       "the other; Cyrus-Beck needs a convex clipper"),
            "отсекатель: отсекатель 'a' — тело невыпуклое: вершина 1 лежит по одну сторону плоскости грани 4, а вершина 7 — по "
            "другую; алгоритму Кируса–Бека нужен выпуклый отсекатель");
  EXPECT_EQ(message_ru("body 2 is not a valid closed solid: face 3 is degenerate (repeated vertex 5)"),
            "тело 2 не является правильным замкнутым телом: грань 3 вырождена (вершина 5 повторяется)");
  EXPECT_EQ(message_ru("unknown key 'colour' in a body (known: name, mesh)"), "тело: неизвестный ключ 'colour' (известны: name, mesh)");
  for (const char* en : {"body 1 has a non-planar face (face 2, vertex 3 is off its plane)", "body 0 is not manifold",
                         "body 0 has duplicate vertices (1 and 2)", "body 0 has a T-junction (vertex 4 inside edge 1-2)",
                         "body 0 has a self-intersecting face (face 3)", "body 0 is not consistently oriented (edge 1-2)",
                         "convex decomposition needs a valid solid: edge 1-2 is in three or more faces (not manifold)",
                         "convex decomposition needs a valid solid: vertex 3 joins separate fans of faces (not manifold)",
                         "convex decomposition needs a valid solid: vertices 1 and 2 are the same point",
                         "convex decomposition needs a valid solid: vertex 4 lies inside edge 1-2 (a T-junction)",
                         "convex decomposition needs an outward-oriented solid: the volume is not positive",
                         "the interior point (1/2, 1/2, 1/2) lies on the plane of face 3: the body is flat or not convex",
                         "midpoint clipping needs a tolerance eps > 0", "is a directory, not a file"})
    expect_russian(en, en);
  bool ok = true;
  EXPECT_EQ(message_ru("something new", &ok), "something new");
  EXPECT_FALSE(ok);
  EXPECT_EQ(message_ru("body 1 " + std::string(1000000, 'a'), &ok).size(), 1000007u);  // long text: quick, no crash
}

// The catalogue follows the sources: every piece of English text in a `throw`, `fail(...)` or
// returned reason on the exam path is part of some template.
TEST(MessagesRu, EveryMessageInTheSourcesHasAnEntry) {
  const std::vector<std::string> files = {"io/explain/problem.cpp",
                                          "io/readers/scene.cpp",
                                          "io/readers/yaml_context.hpp",
                                          "io/readers/mesh_reader.cpp",
                                          "kernel/body_matrix.cpp",
                                          "kernel/number.cpp",
                                          "kernel/rotation.cpp",
                                          "kernel/polyhedron.cpp",
                                          "kernel/transform.cpp",
                                          "kernel/mesh_checks.cpp",
                                          "algorithms/hlr/roberts.cpp",
                                          "algorithms/hlr/roberts_pieces.cpp",
                                          "algorithms/clip/cyrus_beck.cpp",
                                          "algorithms/clip/midpoint_clip.cpp",
                                          "algorithms/solids/convex_decomposition.cpp",
                                          "algorithms/solids/convexity.cpp",
                                          "io/views/view_choice.cpp",
                                          "io/readers/scene_lighting.cpp",
                                          "algorithms/clip/weiler_atherton.cpp",
                                          "algorithms/surfaces/priority_list.cpp"};
  std::string all;
  for (const std::string& t : message_ru_templates()) all += t + "\n";
  std::regex statement(R"re((throw |fail\(|return "|push_back\(\{face, ")[^;]*;)re");
  std::regex literal(R"re("((?:[^"\\]|\\.)*)")re");
  int checked = 0;
  for (const std::string& f : files) {
    std::ifstream in(kSource + "/" + f);
    ASSERT_TRUE(in) << f;
    std::stringstream ss;
    ss << in.rdbuf();
    std::string src = ss.str();
    for (auto s = std::sregex_iterator(src.begin(), src.end(), statement); s != std::sregex_iterator(); ++s) {
      std::string st = s->str();
      if (st.find("notes.push_back") != std::string::npos) continue;
      for (auto l = std::sregex_iterator(st.begin(), st.end(), literal); l != std::sregex_iterator(); ++l) {
        std::string text = (*l)[1].str();
        std::string letters;
        for (char c : text)
          if (std::isalpha(static_cast<unsigned char>(c))) letters += c;
        if (letters.size() < 4 || text.find(' ') == std::string::npos) continue;  // " (", ": ", keys and names
        if (text.find("%") != std::string::npos || text.find("\\n") != std::string::npos) continue;
        ++checked;
        EXPECT_NE(all.find(text), std::string::npos) << f << ": \"" << text << "\" is in no template of io/explain/messages_ru.cpp";
      }
    }
  }
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace hlr
