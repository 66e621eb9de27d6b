// Exam mode (io/explain/problem.hpp, io/explain/explain.hpp, issue 6): golden Markdown and JSON for every
// problem in data/problems/ (deterministic output), exact values worked by hand on several
// problems, the explain result equal to render's on every Roberts problem, and bad problem
// files. Regenerate the golden files with HLR_UPDATE_GOLDEN=1 after a deliberate change.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/hlr/roberts.hpp"
#include "algorithms/surfaces/visible_surfaces.hpp"
#include "io/writers/drawing.hpp"
#include "io/explain/explain.hpp"

using namespace hlr;
namespace fs = std::filesystem;

namespace {
const std::string kData = HLR_DATA_DIR;
const std::string kGolden = HLR_GOLDEN_DIR;

std::vector<std::string> problems() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(kData + "/problems"))
    if (e.path().extension() == ".yaml") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

// The rows of the first table with this caption in the section with this title.
const SolutionJson& table(const SolutionJson& s, const std::string& section, const std::string& caption, int nth = 0) {
  for (const auto& sec : s["sections"])
    if (sec["title"] == section)
      for (const auto& t : sec["tables"])
        if (t["caption"] == caption && nth-- == 0) return t["rows"];
  throw std::runtime_error("no table " + caption);
}
const SolutionJson& values(const SolutionJson& s, const std::string& section, int nth = 0) {
  for (const auto& sec : s["sections"])
    if (sec["title"] == section && nth-- == 0) return sec["values"];
  throw std::runtime_error("no section " + section);
}
}  // namespace

TEST(Explain, AtLeastEightProblemsCoveringAllElevenTypes) {
  std::set<std::string> types;
  for (const auto& p : problems()) types.insert(to_string(load_problem(p).type));
  EXPECT_GE(problems().size(), 8u);
  EXPECT_EQ(types.size(), 11u);
}

TEST(Explain, GoldenMarkdownAndJson) {
  const bool update = std::getenv("HLR_UPDATE_GOLDEN") != nullptr;
  for (const auto& p : problems()) {
    SolutionJson s = explain(load_problem(p));
    std::string stem = fs::path(p).stem().string();
    std::map<std::string, std::string> outputs = {{stem + ".md", explain_markdown(s, Lang::En)},
                                                  {stem + ".ru.md", explain_markdown(s, Lang::Ru)},
                                                  {stem + ".json", s.dump(1) + "\n"}};
    EXPECT_EQ(explain_markdown(explain(load_problem(p)), Lang::En), outputs[stem + ".md"]) << "not deterministic: " << p;
    for (const auto& [name, text] : outputs) {
      std::string path = kGolden + "/" + name;
      if (update) {
        std::ofstream(path) << text;
        continue;
      }
      ASSERT_TRUE(fs::exists(path)) << path << " (HLR_UPDATE_GOLDEN=1 writes it)";
      EXPECT_EQ(slurp(path), text) << name << " differs from its golden file";
    }
  }
}

// The notes' cube (seed 003, section 27), worked by hand: the corrected body matrix has the
// columns [1 0 0 1], [-1 0 0 1], [0 1 0 1], [0 -1 0 1], [0 0 1 1], [0 0 -1 1]; from +z
// (E = [0 0 -1 0]) faces 0-3 are edge-on, the back face 4 gives -1 (non-facing), the front +1.
TEST(Explain, NotesCubeBodyMatrixAndFacing) {
  SolutionJson s = explain(load_problem(kData + "/problems/roberts_cube.yaml"));
  const auto& planes = table(s, "body_matrix", "planes");
  std::vector<std::string> want = {"[1 0 0 1]", "[-1 0 0 1]", "[0 1 0 1]", "[0 -1 0 1]", "[0 0 1 1]", "[0 0 -1 1]"};
  ASSERT_EQ(planes.size(), 6u);
  for (std::size_t f = 0; f < 6; ++f) {
    EXPECT_EQ(planes[f][4], want[f]);
    EXPECT_EQ(planes[f][2], "-1");   // [S]·[V] at the centre before the correction
    EXPECT_EQ(planes[f][3], "yes");  // so every column was negated
  }
  EXPECT_EQ(values(s, "body_matrix")["interior_point"], "(0, 0, 0)");
  const auto& facing = table(s, "facing", "facing_table");
  std::vector<std::string> ev = {"0", "0", "0", "0", "-1", "1"}, cls = {"edge-on", "edge-on", "edge-on", "edge-on", "non-facing", "facing"};
  for (std::size_t f = 0; f < 6; ++f) {
    EXPECT_EQ(facing[f][1], ev[f]);
    EXPECT_EQ(facing[f][2], cls[f]);
  }
  EXPECT_TRUE(table(s, "facing", "self_hidden").empty());  // one non-facing face: no edge has two
}

// The pyramid with a light from [1, 2, 3] seen from [1, -2, 2], by hand: the columns of [V]
// are inward planes, E = -[v 0], so E·[VT] = n·v for the outward normal n (positive: facing);
// likewise L·[VT] = n·L (negative: self-shadowed).
TEST(Explain, PyramidLightSelfShadowedFaces) {
  SolutionJson s = explain(load_problem(kData + "/problems/roberts_pyramid_light.yaml"));
  const auto& facing = table(s, "facing", "facing_table");
  const auto& light = table(s, "facing", "light_table");
  Polyhedron pyr = load_problem(kData + "/problems/roberts_pyramid_light.yaml").scene.bodies[0].body;
  Vector3 v(1, -2, 2), L(1, 2, 3);
  for (std::size_t f = 0; f < pyr.num_faces(); ++f) {
    Vector3 n = pyr.planes()[f].normal();  // outward
    Rational nv = dot(n, v), nl = dot(n, L);
    // E·[VT] has the sign of n·v (inward column, E = -v); L·[VT] likewise with -L.
    EXPECT_EQ(sgn(parse_rational(facing[f][1].get<std::string>())), sgn(nv)) << f;
    EXPECT_EQ(light[f][2], nl < 0 ? "yes" : "no") << f;                       // self-shadowed
    EXPECT_EQ(light[f][3], nl < 0 && nv > 0 ? "yes" : "no") << f;             // visible shadow
  }
  // Face 1 (0 1 4, the y = 0 side, normal (0, -2, 1)): n·v = 6 > 0 facing, n·L = -1 < 0 shadowed.
  EXPECT_EQ(facing[1][1], "6");
  EXPECT_EQ(light[1][1], "-1");
  EXPECT_EQ(light[1][3], "yes");
}

// Cyrus-Beck, segment (-1,1,1) -> (3,1,1) against [0,2]^3 by hand: D = (4, 0, 0); the left face
// (inner normal (1,0,0)) gives W·n = -1, D·n = 4, t = 1/4 (lower); the right face W·n = 3,
// D·n = -4, t = 3/4 (upper); visible (0,1,1) - (2,1,1).
TEST(Explain, CyrusBeckTableByHand) {
  SolutionJson s = explain(load_problem(kData + "/problems/cyrus_beck_box.yaml"));
  const auto& rows = table(s, "cyrus_beck", "cb_table");
  bool left = false, right = false;
  for (const auto& r : rows) {
    if (r[4] == "4") {
      EXPECT_EQ(r[1], "left");
      EXPECT_EQ(r[3], "-1");
      EXPECT_EQ(r[5], "1/4");
      EXPECT_EQ(r[6], "lower");
      left = true;
    }
    if (r[4] == "-4") {
      EXPECT_EQ(r[1], "right");
      EXPECT_EQ(r[3], "3");
      EXPECT_EQ(r[5], "3/4");
      EXPECT_EQ(r[6], "upper");
      right = true;
    }
    if (r[4] == "0") {
      EXPECT_EQ(r[6], "parallel-inside");
    }
  }
  EXPECT_TRUE(left && right);
  EXPECT_EQ(values(s, "cyrus_beck")["visible_part"], "(0, 1, 1) - (2, 1, 1)");
  EXPECT_EQ(s["result"]["segments"][2]["visible"], false);  // (-1,3,1)-(3,3,1) passes above
}

// Convexity of the L-prism by hand: face 4 (y = 1, x in [1, 2]) has vertex 4 (1, 2, 0) on one
// side and vertex 0 on the other; the outer faces have every vertex on one side.
TEST(Explain, ConvexityAndDecompositionByHand) {
  SolutionJson c = explain(load_problem(kData + "/problems/convexity_l_prism.yaml"));
  const auto& signs = table(c, "convexity", "signs");
  EXPECT_EQ(signs[4][1], "[0 1 0 -1]");
  EXPECT_EQ(signs[4][2 + 0], "-");
  EXPECT_EQ(signs[4][2 + 4], "+");
  EXPECT_EQ(signs[4].back(), "no");
  EXPECT_EQ(signs[0].back(), "yes");
  EXPECT_EQ(c["result"]["convex"], false);
  SolutionJson d = explain(load_problem(kData + "/problems/decompose_l_prism.yaml"));
  EXPECT_EQ(table(d, "decompose", "cuts")[0][1], "[0 1 0 -1]");
  EXPECT_EQ(d["result"]["pieces"].size(), 2u);
  EXPECT_EQ(values(d, "decompose")["total_volume"], "3");
  EXPECT_EQ(values(d, "decompose")["body_volume"], "3");
}

// The transform problem by hand, row-vector convention: vertex 0 (-1,-1,-1) scaled by 2 about
// (1,1,1) -> (-3,-3,-3); rotated 90 degrees about z -> (3,-3,-3); moved by (1,2,3) -> (4,-1,0).
TEST(Explain, TransformByHand) {
  SolutionJson s = explain(load_problem(kData + "/problems/transform_cube.yaml"));
  const auto& v = table(s, "transform", "vertices_moved");
  EXPECT_EQ(v[0][1], "(-1, -1, -1)");
  EXPECT_EQ(v[0][2], "(4, -1, 0)");
  EXPECT_EQ(s["result"]["vertices"][7], "(0, 3, 4)");  // (1,1,1) -> (1,1,1) -> (-1,1,1) -> (0,3,4)
}

// The explanation reads the same results as `hlr render --method roberts --edges all`.
TEST(Explain, RobertsSegmentsEqualRendersOnEveryProblem) {
  int compared = 0;
  for (const auto& p : problems()) {
    Problem pr = load_problem(p);
    if (pr.type != Problem::Type::Roberts) continue;
    SolutionJson s = explain(pr);
    Scene scene = load_scene(p);  // the problem file read as a scene, as render reads it
    if (scene.ground) scene.bodies.pop_back();  // render's ground body: an open surface, not for Roberts
    std::vector<const Polyhedron*> polys;
    std::vector<DrawingBody> names;
    for (const auto& b : scene.bodies) {
      polys.push_back(&b.body);
      names.push_back({b.name, b.source});
    }
    Camera cam = scene.view.type == View::Type::Perspective ? make_perspective(scene.view.eye, *scene.view.target)
                                                           : make_orthographic(scene.view.direction);
    LineOptions ro;
    ro.edges = EdgeSelection::All;
    auto j = nlohmann::ordered_json::parse(to_json(names, roberts(polys, cam, ro), cam));
    EXPECT_EQ(s["result"]["segments"], j["segments"]) << p;
    ++compared;
  }
  EXPECT_GE(compared, 4);
}

TEST(Explain, BadProblemFilesNameTheLine) {
  auto err = [](const std::string& text) {
    try {
      load_problem_text(text, "p.yaml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(err("problem: hidden-surface\n").find("p.yaml:1: unknown problem type 'hidden-surface'"), std::string::npos);
  EXPECT_NE(err("bodies: []\n").find("needs 'problem: TYPE'"), std::string::npos);
  EXPECT_NE(err("problem: cyrus-beck\nclipper: {box: [0, 1, 0, 1, 0]}\nsegments: [[0,0,0,1,1,1]]\n").find("p.yaml:2:"), std::string::npos);
  EXPECT_NE(err("problem: midpoint\nclipper: {box: [0, 2, 0, 2, 0, 2]}\nsegments: [[0,0,0,1,1,1]]\neps: 0\n").find("eps must be positive"),
            std::string::npos);
  EXPECT_NE(err("problem: convexity\nbodies:\n  - box: {min: [0,0,0], max: [1,1,1]}\n  - box: {min: [0,0,0], max: [1,1,1]}\n")
                .find("exactly one body"),
            std::string::npos);
  EXPECT_NE(err("problem: roberts\nbodies:\n  - box: {min: [0,0,0], max: [1,1,1]}\nedges: [[0, 0, 7]]\n").find("has no edge 0-7"),
            std::string::npos);
  EXPECT_NE(err("problem: roberts\ncolour: red\nbodies:\n  - box: {min: [0,0,0], max: [1,1,1]}\n").find("unknown key 'colour'"),
            std::string::npos);
}

namespace {

// "[a b c d]" or "(x, y, z)" as exact numbers.
std::vector<Rational> numbers(std::string s) {
  for (char& c : s)
    if (c == '[' || c == ']' || c == '(' || c == ')' || c == ',') c = ' ';
  std::vector<Rational> out;
  std::istringstream in(s);
  std::string tok;
  while (in >> tok) out.push_back(parse_rational(tok));
  return out;
}

Rational dot4(const std::vector<Rational>& a, const std::vector<Rational>& b) {
  Rational s = 0;
  for (int k = 0; k < 4; ++k) s += a[k] * b[k];
  return s;
}

}  // namespace

// Every value of the exam page can be recomputed from values printed before it (issue 12): the
// matrix a body's later values use is its [VT] when it is transformed, else its [V]; E·[VT],
// L·[VT], and p = [P1 1]·[VT], q = [P2 - P1 0]·[VT], w = g·[VT] of every edge table follow.
TEST(Explain, EveryValueRecomputedFromThePrintedMatrices) {
  int checked = 0;
  for (const std::string& file : problems()) {
    Problem pr = load_problem(file);
    if (pr.type != Problem::Type::Roberts) continue;
    SolutionJson s = explain(pr);
    std::map<std::string, std::vector<std::vector<Rational>>> columns;  // body -> columns
    for (const auto& sec : s["sections"]) {
      if (sec["title"] != "body_matrix") continue;
      std::vector<std::vector<Rational>> cols;
      for (const auto& t : sec["tables"]) {
        if (t["caption"] == "planes" && cols.empty())
          for (const auto& row : t["rows"]) cols.push_back(numbers(row[4]));
        if (t["caption"] == "VT") {
          cols.clear();
          for (const auto& row : t["rows"]) cols.push_back(numbers(row[2]));
        }
      }
      columns[sec["subject"]] = cols;
    }
    for (const auto& sec : s["sections"]) {
      if (sec["title"] == "facing") {
        const auto& cols = columns[sec["subject"]];
        std::vector<Rational> E = numbers(sec["values"]["E"]);
        for (const auto& t : sec["tables"]) {
          if (t["caption"] == "facing_table") {
            for (std::size_t f = 0; f < t["rows"].size(); ++f, ++checked)
              EXPECT_EQ(to_string(dot4(E, cols[f])), t["rows"][f][1].get<std::string>()) << file << " face " << f;
          }
          if (t["caption"] == "light_table") {
            std::vector<Rational> L = numbers(sec["values"]["L"]);
            for (std::size_t f = 0; f < t["rows"].size(); ++f, ++checked)
              EXPECT_EQ(to_string(dot4(L, cols[f])), t["rows"][f][1].get<std::string>()) << file << " L face " << f;
          }
        }
      }
      if (sec["title"] == "edge_vs_body") {
        std::string subject = sec["subject"];
        const auto& cols = columns[subject.substr(subject.find(" / ") + 3)];
        std::vector<Rational> P1 = numbers(sec["values"]["P1"]), P2 = numbers(sec["values"]["P2"]), g = numbers(sec["values"]["g"]);
        std::vector<Rational> P = {P1[0], P1[1], P1[2], 1}, D = {P2[0] - P1[0], P2[1] - P1[1], P2[2] - P1[2], 0};
        for (const auto& t : sec["tables"]) {
          if (t["caption"] != "inequalities") continue;
          for (std::size_t j = 0; j < t["rows"].size(); ++j, ++checked) {
            EXPECT_EQ(to_string(dot4(P, cols[j])), t["rows"][j][1].get<std::string>()) << file << " " << subject << " p" << j;
            EXPECT_EQ(to_string(dot4(D, cols[j])), t["rows"][j][2].get<std::string>()) << file << " " << subject << " q" << j;
            EXPECT_EQ(to_string(dot4(g, cols[j])), t["rows"][j][3].get<std::string>()) << file << " " << subject << " w" << j;
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 60);
}

// Inequalities are written as a student writes them (issue 12: not "2 + -4·t + -1·a > 0").
TEST(Explain, InequalitiesReadLikeTheNotes) {
  SolutionJson s = explain(load_problem(kData + "/problems/roberts_rotated_cube.yaml"));
  const auto& rows = table(s, "edge_vs_body", "inequalities");
  EXPECT_EQ(rows[2][4], "3/2 > 0");
  EXPECT_EQ(rows[5][4], "6 − 18/5·t − 4/5·a > 0");
  for (const auto& sec : s["sections"])
    for (const auto& t : sec["tables"])
      if (t["caption"] == "inequalities")
        for (const auto& r : t["rows"]) {
          EXPECT_EQ(r[4].get<std::string>().find("+ -"), std::string::npos);
          EXPECT_EQ(r[4].get<std::string>().find("0·"), std::string::npos);
        }
}

// The Russian page is Russian (issue 12): apart from the problem's own title and body names
// (the author's text) and formula symbols, no Latin word; and it uses the course's words.
TEST(Explain, RussianPageHasNoEnglishOutsideFormulas) {
  const std::set<std::string> formulas = {"VT", "eps", "h_j", "light", "t_max", "t_min", "f_", "z_", "z_min", "z_max",
                                          "X_L", "X_R", "Z_L", "Z_x", "Z_y", "k_r", "k_t", "ior", "cos"};  // f_п, z_б, z_min: the notes' symbols
  bool saw_nonfacing = false, saw_hidden_edges = false, saw_piercing = false;
  for (const std::string& file : problems()) {
    Problem pr = load_problem(file);
    std::string page = explain_markdown(explain(pr), Lang::Ru);
    for (std::size_t a; (a = page.find("<svg")) != std::string::npos;) page.erase(a, page.find("</svg>", a) + 6 - a);
    auto erase_all = [&](const std::string& text) {
      if (text.empty()) return;
      for (std::size_t a; (a = page.find(text)) != std::string::npos;) page.erase(a, text.size());
    };
    erase_all(pr.title);
    for (const SceneBody& b : pr.scene.bodies) erase_all(b.name);
    std::regex latin("[A-Za-z_]{2,}");
    for (auto it = std::sregex_iterator(page.begin(), page.end(), latin); it != std::sregex_iterator(); ++it)
      EXPECT_TRUE(formulas.count(it->str())) << file << ": English word '" << it->str() << "' on the Russian page";
    saw_nonfacing = saw_nonfacing || page.find("Нелицевые грани") != std::string::npos;
    saw_hidden_edges = saw_hidden_edges || page.find("невидимые рёбра") != std::string::npos;
    saw_piercing = saw_piercing || page.find("протыкания") != std::string::npos;
    EXPECT_EQ(page.find("самоскрыт"), std::string::npos) << file;
    EXPECT_EQ(page.find("проникновени"), std::string::npos) << file;
  }
  EXPECT_TRUE(saw_nonfacing);
  EXPECT_TRUE(saw_hidden_edges);
  EXPECT_TRUE(saw_piercing);
}

// An edge lying in a face of another body (issue 12): the closed region gives t_min < t_max,
// the strict test hides nothing, and the page says why instead of contradicting itself.
TEST(Explain, EdgeInAFaceSaysWhyItIsNotHidden) {
  SolutionJson s = explain(load_problem(kData + "/problems/roberts_edge_in_face.yaml"));
  const auto& v = values(s, "edge_vs_body");
  EXPECT_EQ(v["t_min"], "0");
  EXPECT_EQ(v["t_max"], "1");
  EXPECT_EQ(v["hidden_interval"], "none");
  const std::string en = v["strict_test"]["en"], ru = v["strict_test"]["ru"];
  EXPECT_NE(en.find("the edge lies in the plane of face 5"), std::string::npos) << en;
  EXPECT_NE(ru.find("ребро лежит в плоскости грани 5"), std::string::npos) << ru;
}

// The exam drawing numbers its vertices (issue 12: every table refers to vertices by number):
// the cube's eight vertices, each once.
TEST(Explain, DrawingLabelsVertices) {
  SolutionJson s = explain(load_problem(kData + "/problems/roberts_cube.yaml"));
  const std::string svg = s["drawing_svg"];
  ASSERT_NE(svg.find("<g id=\"vertex-labels\""), std::string::npos);
  for (int v = 0; v < 8; ++v) EXPECT_NE(svg.find(">" + std::to_string(v) + "</text>"), std::string::npos) << v;
  EXPECT_EQ(svg.find(">8</text>"), std::string::npos);
}

// Faces typed in both orientations (issue 12): shown as typed, planes from the typed order, only
// the columns whose [S]·[V] is negative negated, the same corrected [V], and a note naming the
// faces the tool turned.
TEST(Explain, FacesShownAsTyped) {
  SolutionJson s = explain(load_problem(kData + "/problems/roberts_typed_faces.yaml"));
  const auto& faces = table(s, "input", "faces");
  EXPECT_EQ(faces[1][1], "0 3 1");
  EXPECT_EQ(faces[3][1], "1 3 2");
  const auto& planes = table(s, "body_matrix", "planes");
  EXPECT_EQ(planes[0][3], "yes");
  EXPECT_EQ(planes[1][1], "[0 1 0 0]");
  EXPECT_EQ(planes[1][2], "1/2");
  EXPECT_EQ(planes[1][3], "no");
  EXPECT_EQ(planes[1][4], "[0 1 0 0]");
  EXPECT_EQ(planes[3][4], "[-1 -1 -1 2]");
  const std::string note = values(s, "input")["reoriented"]["en"];
  EXPECT_EQ(note.rfind("faces 1, 3 run clockwise", 0), 0u) << note;
}

// Midpoint subdivision against the viewing pyramid shows the notes' coefficients and test
// functions (issue 12): α1 = x_R/(z_far - z_cp) = 3/(-10 - 5) = -1/5, α2 = -α1·z_cp = 1; at
// P1 = (-5, 0, -5): f_right = x - zα1 - α2 = -7, f_left = x - zβ1 - β2 = -3 (left of the left
// plane: outside).
TEST(Explain, PyramidTestFunctionsByHand) {
  SolutionJson s = explain(load_problem(kData + "/problems/midpoint_frustum.yaml"));
  const auto& c = table(s, "midpoint", "coefficients");
  EXPECT_EQ(c[0][1], "α1 = -1/5");
  EXPECT_EQ(c[0][2], "α2 = 1");
  EXPECT_EQ(c[1][1], "β1 = 1/5");
  const auto& f = table(s, "midpoint", "test_functions");
  EXPECT_EQ(f[0][1], "-7");
  EXPECT_EQ(f[0][2], "-3");
  EXPECT_EQ(values(s, "midpoint")["codes_and"], "000000 = 0");
}

// The notes number faces and vertices from 1 (issue 12: offer it): with index_base 1 every
// index on the page is one more, the verdict too, and the drawing's labels run 1..8; the
// problem file's own indices and the JSON result stay 0-based.
TEST(Explain, NumberingFromOne) {
  Problem pr = load_problem(kData + "/problems/convexity_l_prism.yaml");
  pr.index_base = 1;
  SolutionJson c = explain(pr);
  EXPECT_EQ(table(c, "input", "faces")[0][0], "1");
  EXPECT_EQ(table(c, "input", "faces")[0][1], "6 5 4 3 2 1");
  EXPECT_EQ(values(c, "convexity")["verdict"]["en"], "not convex: face 5 has vertex 5 on one side of its plane and vertex 1 on the other");
  EXPECT_EQ(c["result"]["verdict"], "not convex: face 4 has vertex 4 on one side of its plane and vertex 0 on the other");
  Problem cube = load_problem(kData + "/problems/roberts_rotated_cube.yaml");
  cube.index_base = 1;
  SolutionJson s = explain(cube);
  EXPECT_EQ(table(s, "body_matrix", "planes")[0][0], "1");
  bool subject = false;
  for (const auto& sec : s["sections"]) subject = subject || sec.value("subject", "") == "slab 3-4 / cube";
  EXPECT_TRUE(subject);
  const std::string svg = s["drawing_svg"];
  EXPECT_NE(svg.find(">8</text>"), std::string::npos);
  EXPECT_EQ(svg.find(">0</text>"), std::string::npos);
  // Back to 0 for the next page.
  EXPECT_EQ(table(explain(load_problem(kData + "/problems/roberts_cube.yaml")), "input", "faces")[0][0], "0");
}

namespace hlr {
namespace {

// The horizon page (issue 18): every crossing printed is the meeting of the two lines printed
// beside it, each point's picture coordinates follow from the axes printed, and the visible
// runs are the notes' method's (each cut against the cuts in front).
TEST(Explain, HorizonPageValuesFollowFromEachOther) {
  Problem pr = load_problem(std::string(HLR_DATA_DIR) + "/problems/horizon_small.yaml");
  SolutionJson s = explain(pr);
  auto line = [](const std::string& text, Rational& slope, Rational& c) {  // "Y = a·X − b"
    std::string t = text.substr(4);
    auto take = [](std::string v) {
      std::string out;
      for (std::size_t i = 0; i < v.size();) {
        if (v.compare(i, 3, "−") == 0) out += '-', i += 3;
        else if (v[i] != ' ') out += v[i++];
        else ++i;
      }
      return out;
    };
    t = take(t);
    auto x = t.find("·X");
    if (x == std::string::npos && (x = t.find('X')) == std::string::npos) {
      slope = 0;
      c = parse_rational(t);
      return;
    }
    std::string a = t.substr(0, x);
    slope = a.empty() ? Rational(1) : a == "-" ? Rational(-1) : parse_rational(a);
    std::string rest = t.substr(x + (t.compare(x, 3, "·X") == 0 ? 3 : 1));
    c = rest.empty() ? Rational(0) : parse_rational(rest[0] == '+' ? rest.substr(1) : rest);
  };
  int crossings = 0, points = 0;
  for (const auto& sec : s["sections"]) {
    if (sec["title"] != "horizon_cut") continue;
    for (const auto& t : sec["tables"]) {
      if (t["caption"] == "crossings")
        for (const auto& r : t["rows"]) {
          Rational s1, c1, s2, c2;
          line(r[2], s1, c1);
          line(r[3], s2, c2);
          std::string xs = r[4];
          Rational x = parse_rational(xs.substr(xs.rfind("= ") + 2)), y = parse_rational(std::string(r[5]));
          EXPECT_EQ(x, (c2 - c1) / (s1 - s2)) << xs;
          EXPECT_EQ(y, s1 * x + c1);
          EXPECT_EQ(y, s2 * x + c2);
          ++crossings;
        }
      if (t["caption"] == "cut_points") {
        const int j = std::stoi(sec["subject"].get<std::string>());
        for (const auto& r : t["rows"]) {
          const int i = std::stoi(r[0].get<std::string>());
          Rational X = 4 * pr.grid.xs[i] - pr.grid.zs[j], Y = -2 * pr.grid.xs[i] + 17 * pr.grid.y(i, j) - 8 * pr.grid.zs[j];
          EXPECT_EQ(parse_rational(std::string(r[2])), X);
          EXPECT_EQ(parse_rational(std::string(r[3])), Y);
          ++points;
        }
      }
    }
  }
  EXPECT_EQ(points, 15);
  EXPECT_GE(crossings, 2);
  // The far cut is hidden behind the peak between its crossings: t in (1/6, 5/6) of segment 1-2.
  bool found = false;
  for (const auto& v : s["result"]["visible"])
    if (v["cut"] == 0 && v["segment"] == 1 && v["t"][1] == "1/6") found = true;
  EXPECT_TRUE(found);
}

// The page answers by the notes' method: two cuts seen along (0, 1, 2) with a ridge across the
// cell from the far cut's left end (height 1) to the near cut's right end (height 1). The notes
// test the far cut against the near one alone, Y = 4y − 2z: the far cut runs from Y = 4 down to
// 0, the near one from −2 up to 2, so the far cut is on one side of it everywhere: visible
// whole. The exact surface's strip (the triangles (0,0)-(1,0)-(1,1) and (0,0)-(1,1)-(0,1), split
// along the ridge) covers the band between Y = 4 − 2X and Y = −2 + 4X, which holds the far cut
// for X < 3/4: the drawing sees only [3/4, 1] of it, and the page says so beside the answer.
TEST(Explain, HorizonPageAnswersByTheNotesMethod) {
  SolutionJson s = explain(load_problem_text("problem: horizon\nheights:\n  - [1, 0]\n  - [0, 1]\nx: [0, 1]\nz: [0, 1]\n"
                                             "view:\n  direction: [0, 1, 2]\n",
                                             "ridge.yaml"));
  auto runs = [&](const char* key) {
    std::vector<std::string> out;
    for (const auto& v : s["result"][key])
      if (v["cut"] == 0) out.push_back(v["t"][0].get<std::string>() + "," + v["t"][1].get<std::string>());
    return out;
  };
  EXPECT_EQ(runs("visible"), std::vector<std::string>({"0,1"}));
  EXPECT_EQ(runs("visible_exact_surface"), std::vector<std::string>({"3/4,1"}));
  const auto& diff = table(s, "horizon_exact", "horizon_differences");
  ASSERT_EQ(diff.size(), 1u);
  EXPECT_EQ(diff[0][0], "0");
  EXPECT_EQ(diff[0][2], "[0, 1]");
  EXPECT_EQ(diff[0][3], "[3/4, 1]");
}

}  // namespace
}  // namespace hlr

// The Weiler–Atherton pages (issue 15): the displayed polygons add up to exactly the visible
// area the fast route finds, each clip's inside and outside lists cover the clipped polygons
// exactly (areas), and the cyclic and piercing examples show their steps.
TEST(Explain, WeilerAthertonPagesAddUp) {
  auto area = [](const std::string& corners) {
    std::vector<Exact2> p;
    std::regex pt(R"re(\(([^,()]+), ([^,()]+)\))re");
    for (auto it = std::sregex_iterator(corners.begin(), corners.end(), pt); it != std::sregex_iterator(); ++it)
      p.push_back({parse_rational((*it)[1].str()), parse_rational((*it)[2].str())});
    Rational s = 0;
    for (std::size_t i = 0; i < p.size(); ++i) s += p[i][0] * p[(i + 1) % p.size()][1] - p[i][1] * p[(i + 1) % p.size()][0];
    return s / 2;
  };
  int pages = 0;
  bool saw_split = false, saw_violation = false;
  for (const std::string& file : problems()) {
    Problem pr = load_problem(file);
    if (pr.type != Problem::Type::WeilerAtherton) continue;
    ++pages;
    SolutionJson s = explain(pr);
    std::vector<const Polyhedron*> polys;
    for (const SceneBody& b : pr.scene.bodies) polys.push_back(&b.body);
    Camera cam = make_orthographic(pr.scene.view.direction);
    LineOptions lo;
    lo.edges = EdgeSelection::All;
    VisibleSurfaces fast = visible_surfaces(polys, cam, face_occluders(polys, cam, lo));
    Rational fast_area = 0;
    for (const VisibleFace& f : fast.faces)
      for (const VisiblePolygon& p : f.polygons) fast_area += p.area2 / 2;
    EXPECT_EQ(values(s, "wa_result")["total_area"].get<std::string>(), to_string(fast_area)) << file;
    Rational shown = 0;
    for (const auto& row : table(s, "wa_result", "wa_visible")) shown += parse_rational(row[2].get<std::string>());
    EXPECT_EQ(shown, fast_area) << file;
    for (const auto& sec : s["sections"]) {
      saw_split = saw_split || sec["title"] == "wa_split";
      saw_violation = saw_violation || sec["title"] == "wa_in_front";
      if (sec["title"] != "wa_clip") continue;
      Rational in = 0, out = 0;
      for (const auto& t : sec["tables"])
        for (const auto& row : t["rows"]) (t["caption"] == "wa_inside" ? in : out) += area(row[1].get<std::string>());
      EXPECT_GT(in, 0) << file;  // the clipper is always inside itself
      EXPECT_GE(out, 0) << file;
    }
  }
  EXPECT_EQ(pages, 3);
  EXPECT_TRUE(saw_split);
  EXPECT_TRUE(saw_violation);
}

// The priority-list pages (issue 19): the swap example moves P to the head and paints it
// first; the notes' cyclic overlap of two polygons cuts Q by P's plane z = 1 at exactly
// (3, 1, 1) and (3, 2, 1) and paints the part behind, P, then the part in front; every page's
// order is the algorithm's, and each answer table stops at the first yes.
TEST(Explain, PriorityPagesShowTheTestsSwapsAndCuts) {
  auto order = [](const SolutionJson& s) {
    std::vector<std::string> out;
    for (const auto& o : s["result"]["order"]) out.push_back(o["polygon"].get<std::string>());
    return out;
  };
  SolutionJson sw = explain(load_problem(kData + "/problems/priority_swap.yaml"));
  EXPECT_EQ(order(sw), (std::vector<std::string>{"P/0", "Q/0"}));
  int swaps = 0;
  for (const auto& sec : sw["sections"])
    if (sec["title"] == "pl_swap") {
      ++swaps;
      EXPECT_EQ(sec["subject"], "P/0");
    }
  EXPECT_EQ(swaps, 1);

  SolutionJson pi = explain(load_problem(kData + "/problems/priority_pierce.yaml"));
  EXPECT_EQ(order(pi), (std::vector<std::string>{"Q/0.2", "P/0", "Q/0.1"}));
  int cuts = 0;
  for (const auto& sec : pi["sections"]) {
    if (sec["title"] == "pl_tests") {
      // Answers: "no" up to the first "yes", then "-".
      bool yes = false;
      for (const auto& row : sec["tables"][0]["rows"]) {
        std::string a = row[2].get<std::string>();
        if (row[0] == "3'" || row[0] == "4'") continue;
        EXPECT_EQ(a, yes ? "-" : a == "yes" ? "yes" : "no");
        yes = yes || a == "yes";
      }
    }
    if (sec["title"] != "pl_split") continue;
    ++cuts;
    EXPECT_EQ(sec["subject"], "Q/0");
    EXPECT_EQ(sec["values"]["cut_plane"], "f = z − 1");
    for (const auto& row : sec["tables"][0]["rows"]) EXPECT_EQ(row[2], "(3, 1, 1), (3, 2, 1)");
  }
  EXPECT_EQ(cuts, 1);

  SolutionJson cy = explain(load_problem(kData + "/problems/priority_cycle.yaml"));
  int cy_cuts = 0;
  for (const auto& sec : cy["sections"]) cy_cuts += sec["title"] == "pl_split";
  EXPECT_GE(cy_cuts, 1);
  EXPECT_GE(order(cy).size(), 4u);
}

// Shadows in exam mode (issue 16), against the hand solution written in the problem file: the
// self-shadowed faces (base and front), the visible shadow face (the front) with its plane,
// and the cast shadow on the ground: the apex moves s = 2/3 to (1/3, -1/3, 0), the outline's
// area is 13/3; the same on the Russian page.
TEST(Explain, ShadowOnTheGroundMatchesTheHandSolution) {
  Problem pr = load_problem(kData + "/problems/roberts_shadow_ground.yaml");
  ASSERT_TRUE(pr.scene.ground);
  EXPECT_EQ(pr.scene.bodies.size(), 1u);  // a problem keeps the ground as a plane, not a body
  SolutionJson s = explain(pr);
  std::vector<std::string> shadowed;
  for (const auto& row : table(s, "facing", "light_table"))
    if (row[2] == "yes") shadowed.push_back(row[0].get<std::string>());
  EXPECT_EQ(shadowed, (std::vector<std::string>{"0", "1"}));
  const auto& planes = table(s, "facing", "visible_shadow_planes");
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0][0], "1");
  EXPECT_EQ(planes[0][1], "2·y − z = 0");  // the front face, -2y + z = 0
  const auto& verts = table(s, "cast_shadow", "shadow_vertices");
  ASSERT_EQ(verts.size(), 5u);
  EXPECT_EQ(verts[4][2], "2/3");
  EXPECT_EQ(verts[4][3], "(1/3, -1/3, 0)");
  EXPECT_EQ(values(s, "cast_shadow")["shadow_area"], "13/3");
  EXPECT_EQ(values(s, "cast_shadow")["shadow_outline"], "(0, 0, 0), (1/3, -1/3, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0)");
  std::string ru = explain_markdown(s, Lang::Ru);
  EXPECT_NE(ru.find("Падающая тень на земле"), std::string::npos);
  EXPECT_NE(ru.find("| 4 | (1, 1, 2) | 2/3 | (1/3, -1/3, 0) |"), std::string::npos);
  EXPECT_NE(ru.find("| 1 | 2·y − z = 0 |"), std::string::npos);
}

// The raster page (issue 17), worked by hand: Q's depth s = 2/5·x − 6/5 meets P's s = 1 at
// x = 11/2, the centres of column 5: the z-buffer keeps P there by the tie rule; the scan-line
// spans of Q on row 2 (y = 7/2) run from X_L = 3 to X_R = 43/6 (the upper right side
// x = 8 − 5(y − 3)/3), ΔX_R = 5/3 per row down, ΔZ_x = 2/5; the frame as drawn by hand.
TEST(Explain, RasterPageByHand) {
  SolutionJson s = explain(load_problem(kData + "/problems/raster_pierce.yaml"));
  const auto& zt = table(s, "rs_zbuffer", "rs_trace");
  ASSERT_EQ(zt.size(), 6u);
  EXPECT_EQ(zt[3][4], "1");  // Q's s at (11/2, 7/2)
  EXPECT_EQ(zt[3][6]["en"], "no (a tie: the rule)");
  EXPECT_EQ(zt[5][4], "7/5");  // Q at (13/2, 7/2)
  EXPECT_EQ(zt[5][6], "yes");
  bool row2 = false;
  for (const auto& r : table(s, "rs_scanline", "rs_spans"))
    if (r[0] == "2" && r[1] == "B") {
      row2 = true;
      EXPECT_EQ(r[2], "3");
      EXPECT_EQ(r[3], "43/6");
      EXPECT_EQ(r[5], "5/3");
      EXPECT_EQ(r[6], "0");
      EXPECT_EQ(r[7], "2/5");
      EXPECT_EQ(r[9], "3 4 5 6");
    }
  EXPECT_TRUE(row2);
  const auto& frame = table(s, "rs_result", "rs_frame");
  const char* want[6] = {". . . B . . . .", ". A A A A A . .", ". A A A A A B .", ". A A A A A B .", ". A A A A A . .", ". . . B . . . ."};
  ASSERT_EQ(frame.size(), 6u);
  for (int j = 0; j < 6; ++j) EXPECT_EQ(frame[j][1], want[j]) << "row " << j;
  bool filled = false;
  for (const auto& r : table(s, "rs_warnock", "rs_windows"))
    filled = filled || r[3]["en"].get<std::string>().rfind("filled with A", 0) == 0;
  EXPECT_TRUE(filled) << "a window filled at once by the surrounding square";
}

// A row through a corner of a polygon (the notes: ΔX is "the change to the next row down"): on
// row 2 (y = 7/2) the quadrilateral A(4, 1/2) B(7, 3) C(4, 11/2) D(2, 7/2) has its left corner D;
// the side above it, C-D, changes by −1 per row, the side the row continues on, D-A, by 2/3.
// The rows above and below D take C-D and D-A as by hand.
TEST(Explain, ScanLineRowThroughACornerTakesTheSideBelow) {
  SolutionJson s = explain(load_problem_text("problem: raster\n"
                                             "bodies:\n  - name: P\n    vertices: [[4, 1/2, 0], [7, 3, 0], [4, 11/2, 0], [2, 7/2, 0]]\n"
                                             "    faces: [[0, 1, 2, 3]]\n"
                                             "view: {direction: [0, 0, 1], up: [0, 1, 0]}\nsize: [8, 6]\nwindow: [0, 8, 0, 6]\n",
                                             "corner.yaml"));
  std::map<std::string, std::pair<std::string, std::string>> left;  // row -> (X_L, ΔX_L)
  for (const auto& r : table(s, "rs_scanline", "rs_spans")) left[r[0]] = {r[2], r[4]};
  ASSERT_TRUE(left.count("2"));
  EXPECT_EQ(left["2"].first, "2");
  EXPECT_EQ(left["2"].second, "2/3");  // D-A, not C-D's −1
  EXPECT_EQ(left["1"].second, "-1");   // row 1 (y = 9/2) lies on C-D
  EXPECT_EQ(left["3"].second, "2/3");  // row 3 (y = 5/2) lies on D-A
  // X_L one row down is X_L + ΔX_L, on every row that has a next one on the same side.
  EXPECT_EQ(parse_rational(left["3"].first), parse_rational(left["2"].first) + parse_rational(left["2"].second));
}

TEST(Explain, RasterProblemErrors) {
  auto fails = [](const std::string& text, const std::string& what) {
    try {
      load_problem_text(text, "p.yaml");
      ADD_FAILURE() << "accepted: " << what;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  const std::string body = "bodies:\n  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n    faces: [[0, 1, 2]]\n";
  fails("problem: raster\n" + body + "size: [40, 3]\n", "1 to 32 pixels");
  fails("problem: raster\n" + body + "size: [3, 3]\nwindow: [0, 1, 0, 1]\n", "binary fraction");
  fails("problem: raster\n" + body + "view: {eye: [0, 0, 5]}\n", "orthographic");
  fails("problem: raster\n" + body + "trace: [[9, 0]]\n", "outside the grid");
}

// The ray tree (issue 17) worked by hand: the ray (3, 0, −4) from (−3, 0, 5) meets the glass
// top z = 1 at t = 1, (0, 0, 1); entering, η = 2/3, cos²θ = 16/25, k = 1 − (4/9)(9/25) = 21/25;
// the reflection (3, 0, 4) is exact and leaves; the refracted ray has sin θt = (2/3)(3/5) = 2/5,
// direction (2/5, 0, −√21/5), and leaves the slab's bottom parallel to the primary ray.
TEST(Explain, RayTreePageByHand) {
  SolutionJson s = explain(load_problem(kData + "/problems/ray_tree_slab.yaml"));
  const auto& t = table(s, "rt_tree", "rt_nodes");
  ASSERT_GE(t.size(), 5u);
  EXPECT_EQ(t[0][6], "1");
  EXPECT_EQ(t[0][7], "(0, 0, 1)");
  EXPECT_EQ(t[0][8], "2/3");
  EXPECT_EQ(t[0][9], "16/25");
  EXPECT_EQ(t[0][10], "21/25");
  EXPECT_EQ(t[0][11], "no");
  EXPECT_EQ(t[1][4], "(3, 0, 4)");
  EXPECT_EQ(t[1][5]["en"], "leaves the scene");
  EXPECT_EQ(t[2][4], "≈ (0.4, 0, -0.916515)");
  EXPECT_EQ(t[4][4], "≈ (0.6, 0, -0.8)");  // out of the slab: parallel to (3, 0, −4)
  EXPECT_EQ(t[4][5], "mirror/0");
}
