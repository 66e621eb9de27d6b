// Exam mode: step-by-step solutions of problem files the way the course notes solve
// them (section 23 convexity and decomposition, 21-22 clipping, 26-28 Roberts, 40
// self-shadowed faces), every intermediate value exact. The solution is built once as a JSON
// document (sections of tables, and the final result); Markdown and HTML are renderings of it,
// in English or in the course's Russian terms. The values come from the same algorithms
// `hlr render` and `hlr clip` run (roberts(), cyrus_beck(), midpoint_clip(), ...): no second
// implementation. Structure: docs/problem-format.md.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "io/explain/problem.hpp"

namespace hlr {

using SolutionJson = nlohmann::ordered_json;

/// Solves the problem. Throws BodyError (a body Roberts' algorithm cannot take) or
/// std::invalid_argument (a body that is not a valid solid for decomposition).
SolutionJson explain(const Problem& problem);

enum class Lang { En, Ru };

/// Markdown (tables) and one self-contained HTML page (with the drawing inline for Roberts).
std::string explain_markdown(const SolutionJson& solution, Lang lang);
std::string explain_html(const SolutionJson& solution, Lang lang);

}  // namespace hlr
