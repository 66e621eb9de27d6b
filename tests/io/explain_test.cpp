// Exam mode (io/explain/problem.hpp, io/explain/explain.hpp): golden Markdown and JSON for every
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
#include "support/explain_tables.hpp"

using namespace hlr;
namespace fs = std::filesystem;

using namespace hlr::test;

TEST(Explain, AtLeastEightProblemsCoveringAllTwelveTypes) {
  std::set<std::string> types;
  for (const auto& p : problems()) types.insert(to_string(load_problem(p).type));
  EXPECT_GE(problems().size(), 8u);
  EXPECT_EQ(types.size(), 12u);
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

// The notes' cube (section 27), worked by hand: the corrected body matrix has the
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

// Every value of the exam page can be recomputed from values printed before it: the
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

// Inequalities are written as a student writes them (not "2 + -4·t + -1·a > 0").
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

// The Russian page is Russian: apart from the problem's own title and body names
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

// An edge lying in a face of another body: the closed region gives t_min < t_max,
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

// The exam drawing numbers its vertices (every table refers to vertices by number):
// the cube's eight vertices, each once.
TEST(Explain, DrawingLabelsVertices) {
  SolutionJson s = explain(load_problem(kData + "/problems/roberts_cube.yaml"));
  const std::string svg = s["drawing_svg"];
  ASSERT_NE(svg.find("<g id=\"vertex-labels\""), std::string::npos);
  for (int v = 0; v < 8; ++v) EXPECT_NE(svg.find(">" + std::to_string(v) + "</text>"), std::string::npos) << v;
  EXPECT_EQ(svg.find(">8</text>"), std::string::npos);
}

// Faces typed in both orientations: shown as typed, planes from the typed order, only
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
// functions: α1 = x_R/(z_far - z_cp) = 3/(-10 - 5) = -1/5, α2 = -α1·z_cp = 1; at
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

// The notes number faces and vertices from 1 (offer it): with index_base 1 every
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

// A section problem checked from its printed values: every crossing point lies on the plane and
// on its edge at the printed t; the cap's corners are exactly the crossings and the vertices on
// the plane, in counter-clockwise order seen from the removed side (Newell's normal along the
// plane's); a plane through three vertices of the cube names them.
TEST(Explain, SectionPageByHand) {
  for (const char* plane : {"2,2,2,-1", "1,1,1,-1", "z<1/3"}) {
    SCOPED_TRACE(plane);
    const std::string text =
        std::string("problem: section\nbodies:\n  - {name: cube, box: {min: [-1, -1, -1], max: [1, 1, 1]}}\nsection: \"") + plane + "\"\n";
    const Problem pr = load_problem_text(text, "p.yaml");
    const SolutionJson s = explain(pr);
    const Plane& h = pr.scene.section[0];
    const Polyhedron& cube = pr.scene.bodies[0].body;
    std::set<std::vector<Rational>> expected;  // crossings and vertices on the plane
    for (const auto& row : table(s, "crossed_edges", "edge_crossings")) {
      const std::string e = row[0];
      const int u = std::stoi(e.substr(0, e.find('-'))), v = std::stoi(e.substr(e.find('-') + 1));
      const Rational t = parse_rational(row[3].get<std::string>());
      const std::vector<Rational> p = numbers(row[4]);
      const Point3 at = cube.vertices()[u] + t * (cube.vertices()[v] - cube.vertices()[u]);
      EXPECT_EQ(p, (std::vector<Rational>{at.x(), at.y(), at.z()}));
      EXPECT_EQ(h.value(at), 0);
      EXPECT_TRUE(t > 0 && t < 1);
      expected.insert(p);
    }
    std::set<std::string> on_plane;
    for (std::size_t v = 0; v < cube.num_vertices(); ++v)
      if (h.value(cube.vertices()[v]) == 0) {
        const Point3& p = cube.vertices()[v];
        expected.insert({p.x(), p.y(), p.z()});
        on_plane.insert(std::to_string(v));
      }
    const auto& corners = table(s, "cap", "cap_polygon");
    std::vector<std::vector<Rational>> loop;
    for (const auto& row : corners) {
      loop.push_back(numbers(row[1]));
      if (on_plane.count(row[2])) on_plane.erase(row[2].get<std::string>());
    }
    EXPECT_TRUE(on_plane.empty());
    EXPECT_EQ(std::set<std::vector<Rational>>(loop.begin(), loop.end()), expected);
    Rational nx = 0, ny = 0, nz = 0;  // Newell's normal of the loop
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const auto &a = loop[i], &b = loop[(i + 1) % loop.size()];
      nx += (a[1] - b[1]) * (a[2] + b[2]), ny += (a[2] - b[2]) * (a[0] + b[0]), nz += (a[0] - b[0]) * (a[1] + b[1]);
    }
    EXPECT_GT(nx * h.a() + ny * h.b() + nz * h.c(), 0);
  }
  const SolutionJson tri = explain(
      load_problem_text("problem: section\nbodies:\n  - {name: c, box: {min: [-1, -1, -1], max: [1, 1, 1]}}\nsection: \"1,1,1,-1\"\n", "p.yaml"));
  EXPECT_EQ(table(tri, "cap", "cap_polygon").size(), 3u);
  EXPECT_EQ(table(tri, "crossed_edges", "edge_crossings").size(), 0u);
  EXPECT_THROW(load_problem_text("problem: section\nbodies:\n  - {name: c, box: {min: [0, 0, 0], max: [1, 1, 1]}}\n", "p.yaml"), InputError);
}
