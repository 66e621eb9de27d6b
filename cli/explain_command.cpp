// `hlr explain PROBLEM`: a step-by-step exact solution of a problem file (issue 6), as
// Markdown, one self-contained HTML page, or JSON with every value; English or Russian.
#include <filesystem>
#include <iostream>

#include "cli/arguments.hpp"
#include "cli/commands.hpp"
#include "io/atomic_file.hpp"
#include "io/explain.hpp"

namespace hlr::cli {
namespace {

struct ExplainArgs {
  std::string input, output, format, lang = "en";
  int number_from = 0;
};

int run_explain(const ExplainArgs& a) {
  const std::string format =
      output_format(a.format, a.output, {{".md", "md"}, {".markdown", "md"}, {".html", "html"}, {".htm", "html"}, {".json", "json"}}, "md");
  Problem pr = load_problem(a.input);
  pr.index_base = a.number_from;
  SolutionJson s;
  try {
    s = explain(pr);
  } catch (const BodyError& e) {
    std::cerr << "hlr explain: " << a.input << ": " << e.what() << " (a `decompose` problem splits it first)\n";
    return 1;
  } catch (const std::invalid_argument& e) {
    std::cerr << "hlr explain: " << a.input << ": " << e.what() << "\n";
    return 1;
  }
  Lang lang = a.lang == "ru" ? Lang::Ru : Lang::En;
  std::string text = format == "json" ? s.dump(1) + "\n" : format == "html" ? explain_html(s, lang) : explain_markdown(s, lang);
  write_output(a.output, text);
  return 0;
}

}  // namespace

void add_explain_command(CLI::App& app, int& exit_code) {
  auto a = std::make_shared<ExplainArgs>();
  CLI::App* cmd = app.add_subcommand("explain", "Solve a problem file step by step, exactly (exam mode)");
  cmd->add_option("problem", a->input, "Problem file (.yaml, .yml, .json; docs/problem-format.md)")->required();
  cmd->add_option("-o", a->output, "Output file (default: standard output); .json or .html select the format");
  cmd->add_option("--format", a->format, "md, html or json (default: from the output file's extension, else md)")
      ->check(CLI::IsMember({"md", "html", "json"}));
  cmd->add_option("--lang", a->lang, "en or ru (the course's own terms)")->check(CLI::IsMember({"en", "ru"}));
  cmd->add_option("--number-from", a->number_from,
                  "0 or 1: number faces, vertices and columns on the page from 1 as the notes do (the problem file keeps "
                  "0-based indices)")
      ->check(CLI::IsMember({0, 1}));
  cmd->callback([a, &exit_code] { exit_code = run_explain(*a); });
}

}  // namespace hlr::cli
