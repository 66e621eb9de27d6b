// `hlr explain PROBLEM`: a step-by-step exact solution of a problem file, as
// Markdown, one self-contained HTML page, or JSON with every value; English or Russian.
#include <filesystem>
#include <iostream>

#include "cli/arguments.hpp"
#include "cli/commands.hpp"
#include "io/writers/atomic_file.hpp"
#include "io/explain/explain.hpp"
#include "io/readers/input_error.hpp"
#include "io/explain/messages_ru.hpp"
#include "kernel/number.hpp"

namespace hlr::cli {
namespace {

struct ExplainArgs {
  std::string input, output, format, lang = "en";
  int number_from = 0;
};

// Prints an error of the problem file in the page's language: "hlr explain: FILE[:LINE]: text".
int fail(const ExplainArgs& a, const std::string& file, int line, const std::string& message, const std::string& then = "") {
  const bool ru = a.lang == "ru";
  std::cerr << "hlr explain: " << file << (line > 0 ? ":" + std::to_string(line) : std::string()) << ": "
            << (ru ? message_ru(message) : message) << then << "\n";
  return 1;
}

int run_explain(const ExplainArgs& a) {
  const std::string format =
      output_format(a.format, a.output, {{".md", "md"}, {".markdown", "md"}, {".html", "html"}, {".htm", "html"}, {".json", "json"}}, "md");
  SolutionJson s;
  try {
    Problem pr = load_problem(a.input);
    pr.index_base = a.number_from;
    s = explain(pr);
  } catch (const InputError& e) {
    return fail(a, e.file(), e.line(), e.message());
  } catch (const NumberError& e) {
    return fail(a, a.input, 0, e.what());
  } catch (const BodyError& e) {
    std::string then;  // a non-convex body: the problem type that splits it
    if (e.reason().find("takes convex bodies") != std::string::npos)
      then = a.lang == "ru" ? " (это делает задача `decompose`)" : " (a `decompose` problem splits it first)";
    return fail(a, a.input, 0, e.what(), then);
  } catch (const std::invalid_argument& e) {
    return fail(a, a.input, 0, e.what());
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
