// Exam-mode solutions (see explain.hpp): one builder per problem type (explain_parts.hpp).
#include "io/explain/explain.hpp"

#include <filesystem>

#include "io/explain/explain_parts.hpp"
#include "io/writers/svg_writer.hpp"

namespace hlr {

using namespace explain_parts;

std::string explain_parts::problem_drawing_svg(const Problem& pr, const LineDrawing& lines, const Camera& camera) {
  std::vector<DrawingBody> names;
  for (const SceneBody& b : pr.scene.bodies) names.push_back({b.name, b.source});
  SvgOptions so;
  so.hidden_dashed = true;
  so.width_mm = 120;
  return to_svg(names, lines, camera, so);
}

SolutionJson explain(const Problem& pr) {
  struct Base {  // the page's numbering for this call only
    explicit Base(int b) { index_base = b; }
    ~Base() { index_base = 0; }
  } base(pr.index_base);
  J out;
  out["problem"] = to_string(pr.type);
  out["file"] = std::filesystem::path(pr.file).filename().string();
  if (!pr.title.empty()) out["title"] = pr.title;
  J body;
  switch (pr.type) {
    case Problem::Type::Roberts: body = roberts_solution(pr); break;
    case Problem::Type::CyrusBeck: body = cyrus_beck_solution(pr); break;
    case Problem::Type::Midpoint: body = midpoint_solution(pr); break;
    case Problem::Type::Convexity: body = convexity_solution(pr); break;
    case Problem::Type::Decompose: body = decompose_solution(pr); break;
    case Problem::Type::Transform: body = transform_solution(pr); break;
    case Problem::Type::Horizon: body = horizon_solution(pr); break;
    case Problem::Type::WeilerAtherton: body = weiler_atherton_solution(pr); break;
    case Problem::Type::Priority: body = priority_solution(pr); break;
    case Problem::Type::Raster: body = raster_solution(pr); break;
    case Problem::Type::RayTree: body = ray_tree_solution(pr); break;
    case Problem::Type::Section:
      body = section_solution(pr);
      break;
  }
  for (auto it = body.begin(); it != body.end(); ++it) out[it.key()] = it.value();
  return out;
}

}  // namespace hlr
