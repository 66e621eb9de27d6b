// Exam mode, the parts (internal to io/explain/explain*.cpp; see explain.hpp): the solution's building
// blocks (sections of values and tables), one builder per problem type, the word tables of
// both languages and the renderers.
//   explain_roberts.cpp   Roberts (sections 26-28, 40): body matrices, facing, light, edges
//   explain_clipping.cpp  Cyrus-Beck (21) and midpoint subdivision (22)
//   explain_bodies.cpp    convexity and decomposition (23), transforms (20)
//   explain_horizon.cpp   the floating horizon (24)
//   explain_weiler_atherton.cpp  the Weiler–Atherton algorithm (31)
//   explain_priority.cpp  the priority-list (painter's) algorithm (32-34, part 3.3)
//   explain_raster.cpp    z-buffer (32), the scan-line z-buffer (34), Warnock (29-30)
//   explain_ray_tree.cpp  the ray tree of Whitted ray tracing (43-45)
//   explain_section.cpp   a body cut by a plane (21-22 applied to a solid): test function, crossings, cap
//   explain_words.cpp     English and Russian words of the course
//   explain_render.cpp    Markdown and HTML
#pragma once

#include <string>
#include <vector>

#include "algorithms/model/camera.hpp"
#include "algorithms/model/line_drawing.hpp"
#include "io/explain/explain.hpp"
#include "io/readers/scene.hpp"

namespace hlr::explain_parts {

using J = SolutionJson;

inline std::string q(const Rational& x) { return to_string(x); }
/// The first number of faces, vertices and columns on the page (0, or 1 as the notes count);
/// set by explain() for the problem being solved (thread-local: pages build in parallel).
inline thread_local int index_base = 0;
/// An index as the page prints it.
inline std::string ix(long i) { return std::to_string(i + index_base); }
inline std::string pt(const Point3& p) { return "(" + q(p.x()) + ", " + q(p.y()) + ", " + q(p.z()) + ")"; }
inline std::string vec(const Vector3& p) { return "(" + q(p.x()) + ", " + q(p.y()) + ", " + q(p.z()) + ")"; }
inline std::string row4(const Rational& a, const Rational& b, const Rational& c, const Rational& d) {
  return "[" + q(a) + " " + q(b) + " " + q(c) + " " + q(d) + "]";
}

/// "−2·y + z − 4": a linear form with zero terms left out and signs between the terms.
inline std::string linear_text(const Rational& a, const Rational& b, const Rational& c, const Rational& d) {
  std::string out;
  const Rational* k[4] = {&a, &b, &c, &d};
  const char* var[4] = {"x", "y", "z", ""};
  for (int i = 0; i < 4; ++i) {
    if (*k[i] == 0) continue;
    Rational m = abs(*k[i]);
    std::string term = i < 3 && m == 1 ? var[i] : q(m) + (i < 3 ? std::string("·") + var[i] : "");
    out += out.empty() ? (*k[i] < 0 ? "−" + term : term) : (*k[i] < 0 ? " − " : " + ") + term;
  }
  return out.empty() ? "0" : out;
}

// A section: a title id, optional notes (id -> value), tables (caption id, column ids, rows).
struct Section {
  J j;
  explicit Section(const std::string& title, const std::string& subject = "") {
    j["title"] = title;
    if (!subject.empty()) j["subject"] = subject;
    j["values"] = J::object();
    j["tables"] = J::array();
  }
  void value(const std::string& id, const std::string& v) { j["values"][id] = v; }
  /// A value written in words: {"en": ..., "ru": ...}; the page shows the reader's language.
  void value(const std::string& id, const std::string& en, const std::string& ru) { j["values"][id] = J{{"en", en}, {"ru", ru}}; }
  J& table(const std::string& caption, std::vector<std::string> columns) {
    J t;
    t["caption"] = caption;
    t["columns"] = columns;
    t["rows"] = J::array();
    j["tables"].push_back(t);
    return j["tables"].back()["rows"];
  }
};

inline void input_section(const Scene& s, J& out) {
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const SceneBody& b = s.bodies[i];
    Section sec("input", b.name);
    J& vr = sec.table("vertices", {"vertex", "x", "y", "z"});
    for (std::size_t v = 0; v < b.body.num_vertices(); ++v) {
      const Point3& p = b.body.vertices()[v];
      vr.push_back({ix(static_cast<long>(v)), q(p.x()), q(p.y()), q(p.z())});
    }
    // The faces as typed (inline bodies), and which of them the tool turned outward.
    const bool typed = b.typed_faces.size() == b.body.num_faces();
    J& fr = sec.table("faces", {"face", "vertices"});
    std::string turned;
    for (std::size_t f = 0; f < b.body.num_faces(); ++f) {
      const Face& face = typed ? b.typed_faces[f] : b.body.faces()[f];
      std::string l;
      for (int v : face) {
        if (!l.empty()) l += ' ';
        l += ix(v);
      }
      fr.push_back({ix(static_cast<long>(f)), l});
      if (typed && face != b.body.faces()[f]) turned += (turned.empty() ? "" : ", ") + ix(static_cast<long>(f));
    }
    if (!turned.empty())
      sec.value("reoriented", "faces " + turned + " run clockwise seen from outside as typed; the tool turns them for drawing. The planes below follow the order as typed, and the interior point decides each column's sign either way.",
                "грани " + turned + " заданы по часовой стрелке (если смотреть снаружи); для рисунка программа их переворачивает. Плоскости ниже вычислены по порядку вершин, как он задан, а знак каждого столбца определяет внутренняя точка.");
    out["sections"].push_back(sec.j);
  }
}


/// The page's line drawing of the problem's bodies (hidden lines dashed, 120 mm wide).
std::string problem_drawing_svg(const Problem& pr, const LineDrawing& lines, const Camera& camera);

J roberts_solution(const Problem& pr);
J cyrus_beck_solution(const Problem& pr);
J midpoint_solution(const Problem& pr);
J convexity_solution(const Problem& pr);
J decompose_solution(const Problem& pr);
J transform_solution(const Problem& pr);
J horizon_solution(const Problem& pr);
J weiler_atherton_solution(const Problem& pr);
J priority_solution(const Problem& pr);
J raster_solution(const Problem& pr);
J ray_tree_solution(const Problem& pr);
J section_solution(const Problem& pr);

/// The word for `id` in `lang` (the id itself when there is none).
std::string word(const std::string& id, Lang lang);
/// Cell text: classes and yes/no are words too (ids "v:...").
std::string cell(const J& c, Lang lang);

}  // namespace hlr::explain_parts
