// Exam mode, Markdown and HTML renderings of a solution (see explain.hpp).
#include <string>

#include "io/explain/explain_parts.hpp"

namespace hlr {

using namespace explain_parts;

namespace {
// "2: rotate" with the transform step's name in the reader's language.
std::string step_text(const J& t, Lang lang) {
  std::string st = t["step"].get<std::string>();
  auto colon = st.find(": ");
  if (colon == std::string::npos) return st;
  return st.substr(0, colon + 2) + word("step:" + st.substr(colon + 2), lang);
}
}  // namespace

std::string explain_markdown(const SolutionJson& s, Lang lang) {
  std::string o = "# " + word("problem", lang) + ": " + word("type:" + s["problem"].get<std::string>(), lang);
  if (s.contains("title")) o += " — " + s["title"].get<std::string>();
  o += "\n\n";
  for (const J& sec : s["sections"]) {
    o += "## " + word(sec["title"], lang);
    if (sec.contains("subject")) o += ": " + sec["subject"].get<std::string>();
    o += "\n\n";
    for (auto it = sec["values"].begin(); it != sec["values"].end(); ++it)
      o += "- " + word(it.key(), lang) + ": " + cell(it.value(), lang) + "\n";
    if (!sec["values"].empty()) o += "\n";
    for (const J& t : sec["tables"]) {
      o += "**" + word(t["caption"], lang) + (t.contains("step") ? " " + step_text(t, lang) : "") + "**\n\n";
      if (t["rows"].empty()) {
        o += "(" + word("none", lang) + ")\n\n";
        continue;
      }
      o += "|";
      for (const J& c : t["columns"]) {
        o += ' ';
        o += word(c, lang);
        o += " |";
      }
      o += "\n|";
      for (std::size_t i = 0; i < t["columns"].size(); ++i) o += "---|";
      o += "\n";
      for (const J& r : t["rows"]) {
        o += "|";
        for (const J& c : r) {
          o += ' ';
          o += cell(c, lang);
          o += " |";
        }
        o += "\n";
      }
      o += "\n";
    }
  }
  return o;
}

std::string explain_html(const SolutionJson& s, Lang lang) {
  auto esc = [](const std::string& x) {
    std::string e;
    for (char c : x) {
      if (c == '&') e += "&amp;";
      else if (c == '<') e += "&lt;";
      else if (c == '>') e += "&gt;";
      else e += c;
    }
    return e;
  };
  std::string title = word("problem", lang) + ": " + word("type:" + s["problem"].get<std::string>(), lang);
  if (s.contains("title")) title += " — " + s["title"].get<std::string>();
  std::string o = "<!DOCTYPE html>\n<html lang=\"" + std::string(lang == Lang::Ru ? "ru" : "en") +
                  "\">\n<head><meta charset=\"utf-8\"><title>" + esc(title) +
                  "</title>\n<style>body{font-family:sans-serif;max-width:60em;margin:2em auto}table{border-collapse:collapse;margin:.5em 0}"
                  "td,th{border:1px solid #999;padding:.2em .5em;font-family:monospace}</style></head>\n<body>\n<h1>" +
                  esc(title) + "</h1>\n";
  if (s.contains("drawing_svg")) {
    std::string svg = s["drawing_svg"];
    auto at = svg.find("<svg");
    o += "<h2>" + esc(word("drawing", lang)) + "</h2>\n" + (at == std::string::npos ? "" : svg.substr(at)) + "\n";
  }
  for (const J& sec : s["sections"]) {
    o += "<h2>" + esc(word(sec["title"], lang)) + (sec.contains("subject") ? ": " + esc(sec["subject"]) : "") + "</h2>\n";
    if (!sec["values"].empty()) {
      o += "<ul>\n";
      for (auto it = sec["values"].begin(); it != sec["values"].end(); ++it)
        o += "<li>" + esc(word(it.key(), lang)) + ": " + esc(cell(it.value(), lang)) + "</li>\n";
      o += "</ul>\n";
    }
    if (sec.contains("svg")) o += "<p>" + esc(word("region", lang)) + "</p>\n" + sec["svg"].get<std::string>() + "\n";
    for (const J& t : sec["tables"]) {
      o += "<p><b>" + esc(word(t["caption"], lang)) + (t.contains("step") ? " " + esc(step_text(t, lang)) : "") + "</b></p>\n<table><tr>";
      for (const J& c : t["columns"]) o += "<th>" + esc(word(c, lang)) + "</th>";
      o += "</tr>\n";
      for (const J& r : t["rows"]) {
        o += "<tr>";
        for (const J& c : r) o += "<td>" + esc(cell(c, lang)) + "</td>";
        o += "</tr>\n";
      }
      o += "</table>\n";
    }
  }
  o += "</body>\n</html>\n";
  return o;
}

}  // namespace hlr
