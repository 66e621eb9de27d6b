// Text report of `hlr info` (see info_report.hpp).
#include "io/pipeline/info_report.hpp"

#include <sstream>

#include "algorithms/solids/convexity.hpp"
#include "kernel/body_matrix.hpp"

namespace hlr {
namespace {

template <class T, class F>
std::string list(const std::vector<T>& items, std::size_t max, F fmt) {
  std::string s;
  for (std::size_t i = 0; i < items.size() && i < max; ++i) s += (i ? ", " : "") + fmt(items[i]);
  if (items.size() > max) s += ", ... (" + std::to_string(items.size()) + " in all)";
  return s;
}

std::string edges_text(const std::vector<Edge>& e, std::size_t max) {
  return list(e, max, [](const Edge& x) { return to_string(x); });
}
std::string ints_text(const std::vector<int>& e, std::size_t max) {
  return list(e, max, [](int x) { return std::to_string(x); });
}

std::string check_line(const char* name, bool ok, const std::string& detail) {
  return std::string("  ") + name + ": " + (ok ? "yes" : "no (" + detail + ")") + "\n";
}

std::string matrix_text(const BodyMatrix& bm) {
  std::vector<std::vector<std::string>> cells(4);
  std::size_t w = 1;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < bm.V.cols(); ++j) {
      cells[i].push_back(to_string(bm.V(i, j)));
      w = std::max(w, cells[i].back().size());
    }
  std::string out;
  for (int i = 0; i < 4; ++i) {
    out += "    [";
    for (std::size_t j = 0; j < cells[i].size(); ++j)
      out += std::string(w - cells[i][j].size() + (j ? 1 : 0), ' ') + cells[i][j];
    out += "]\n";
  }
  return out;
}

}  // namespace

std::string info_report(const SceneBody& b, int index, const InfoOptions& opt) {
  const Polyhedron& p = b.body;
  const MeshReport& r = p.report();
  std::ostringstream o;
  o << "body " << index << ": " << b.name << " (" << b.source << ")\n";
  o << "  vertices " << p.num_vertices() << ", edges " << p.edges().size() << ", faces " << p.num_faces() << "\n";
  const std::size_t m = opt.max_listed;
  o << check_line("closed", r.closed(),
                  r.boundary_edges.empty() ? "non-manifold edges" : std::to_string(r.boundary_edges.size()) +
                                                                        " boundary edges: " + edges_text(r.boundary_edges, m));
  std::string nm;
  if (!r.non_manifold_edges.empty()) nm += "edges in 3+ faces: " + edges_text(r.non_manifold_edges, m);
  if (!r.non_manifold_vertices.empty())
    nm += std::string(nm.empty() ? "" : "; ") + "vertices with several fans: " + ints_text(r.non_manifold_vertices, m);
  o << check_line("manifold", r.manifold(), nm);
  o << check_line("oriented", r.oriented(), "edges traversed twice in one direction: " + edges_text(r.misoriented_edges, m));
  o << check_line("planar faces", r.planar(), list(r.non_planar_faces, m, [](const NonPlanarFace& f) {
                    return "face " + std::to_string(f.face) + " (vertex " + std::to_string(f.vertex) + " off its plane)";
                  }));
  o << check_line("non-degenerate faces", r.degenerate_faces.empty(), list(r.degenerate_faces, m, [](const DegenerateFace& f) {
                    return "face " + std::to_string(f.face) + ": " + f.why;
                  }));
  o << check_line("distinct vertices", r.duplicate_vertices.empty(), list(r.duplicate_vertices, m, [](const std::pair<int, int>& d) {
                    return std::to_string(d.first) + " = " + std::to_string(d.second);
                  }));
  if (!r.t_junctions.empty())
    o << "  T-junctions: " << list(r.t_junctions, m, [](const MeshReport::TJunction& t) {
      return "vertex " + std::to_string(t.vertex) + " inside edge " + to_string(t.edge);
    }) << "\n";
  o << check_line("simple faces", r.self_intersecting_faces.empty(),
                  "self-intersecting: " + list(r.self_intersecting_faces, m, [](int f) { return "face " + std::to_string(f); }));
  if (!r.negative_components.empty())
    o << "  negative-volume components: " << list(r.negative_components, m, [](int f) {
      return "the one with face " + std::to_string(f);
    }) << " (inside out, or a cavity's shell; render turns one that lies outside the others)\n";
  if (!r.isolated_vertices.empty()) o << "  unused vertices: " << ints_text(r.isolated_vertices, m) << "\n";
  if (!r.refused_faces.empty())
    o << "  faces OpenMesh refused: " << ints_text(r.refused_faces, m) << "\n";
  ConvexityResult cv = convexity(p);
  o << "  convex: " << (cv.convex() ? "yes" : "no (" + describe(cv) + ")") << "\n";
  for (const auto& n : b.notes) o << "  note: " << n << "\n";
  if (opt.matrix) {
    if (p.num_faces() > opt.max_matrix_faces) {
      o << "  body matrix: not printed (" << p.num_faces() << " faces; at most " << opt.max_matrix_faces << ")\n";
    } else if (!cv.convex()) {
      o << "  body matrix: none (the body matrix is defined for convex bodies)\n";
    } else {
      BodyMatrix bm = body_matrix(p);
      std::string neg;
      for (std::size_t j = 0; j < bm.negated.size(); ++j)
        if (bm.negated[j]) neg += (neg.empty() ? "" : ", ") + std::to_string(j);
      o << "  interior point [S] = " << to_string(bm.interior) << ", [S][V] before correction = [";
      for (std::size_t j = 0; j < bm.s_v.size(); ++j) o << (j ? " " : "") << to_string(bm.s_v[j]);
      o << "]\n  columns negated: " << (neg.empty() ? "none" : neg) << "\n";
      o << "  body matrix [V] (rows a, b, c, d; one column per face):\n" << matrix_text(bm);
    }
  }
  return o.str();
}

const std::vector<std::string>& requirement_names() {
  static const std::vector<std::string> names = {"closed", "manifold", "oriented", "planar",
                                                 "nondegenerate", "distinct", "convex", "solid"};
  return names;
}

std::string requirement_failure(const SceneBody& b, const std::string& name) {
  const MeshReport& r = b.body.report();
  auto first_edge = [](const std::vector<Edge>& e) { return e.empty() ? std::string() : " (edge " + to_string(e[0]) + ")"; };
  if (name == "closed" && !r.closed())
    return "is not closed" + first_edge(r.boundary_edges.empty() ? r.non_manifold_edges : r.boundary_edges);
  if (name == "manifold" && !r.manifold())
    return "is not manifold" + (r.non_manifold_edges.empty() ? " (vertex " + std::to_string(r.non_manifold_vertices[0]) + ")"
                                                              : first_edge(r.non_manifold_edges));
  if (name == "oriented" && !r.oriented()) return "is not consistently oriented" + first_edge(r.misoriented_edges);
  if (name == "planar" && !r.planar())
    return "has a non-planar face (face " + std::to_string(r.non_planar_faces[0].face) + ")";
  if (name == "nondegenerate" && !r.degenerate_faces.empty())
    return "has a degenerate face (face " + std::to_string(r.degenerate_faces[0].face) + ": " + r.degenerate_faces[0].why + ")";
  if (name == "distinct" && !r.duplicate_vertices.empty())
    return "has duplicate vertices (" + std::to_string(r.duplicate_vertices[0].first) + " and " +
           std::to_string(r.duplicate_vertices[0].second) + ")";
  if (name == "solid" && !r.valid_solid()) return "is not a valid solid: " + solid_problem(r);
  if (name == "convex") {
    ConvexityResult cv = convexity(b.body);
    if (!cv.convex()) return "is " + describe(cv);
  }
  return {};
}

}  // namespace hlr
