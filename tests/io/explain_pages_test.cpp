// Exam mode's pages of the image-space, priority, shadow and horizon problems
// (io/explain/explain.hpp): every value printed follows from the values printed before it, and
// the hand solutions of the course notes' examples.
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

namespace hlr {
namespace {

// The horizon page: every crossing printed is the meeting of the two lines printed
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

// The Weiler–Atherton pages: the displayed polygons add up to exactly the visible
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

// The priority-list pages: the swap example moves P to the head and paints it
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

// Shadows in exam mode, against the hand solution written in the problem file: the
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

// The raster page, worked by hand: Q's depth s = 2/5·x − 6/5 meets P's s = 1 at
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

// The ray tree worked by hand: the ray (3, 0, −4) from (−3, 0, 5) meets the glass
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
