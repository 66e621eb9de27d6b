// The method table (see render_methods.hpp and method_table.hpp).
#include "io/pipeline/render_methods.hpp"

#include <stdexcept>

namespace hlr {

void no_lines(LineStep&) { throw std::logic_error("this method draws no lines of its own"); }
void no_polygons(PolygonStep&) { throw std::logic_error("this method makes no polygons"); }

const std::vector<RenderMethodEntry>& render_methods() {
#define HLR_METHOD_ROW(e, name, lines, polygons, flags, help) RenderMethodEntry{RenderMethod::e, name, &lines, &polygons, flags, help},
  static const std::vector<RenderMethodEntry> table = {HLR_RENDER_METHODS(HLR_METHOD_ROW)};
#undef HLR_METHOD_ROW
  return table;
}

const RenderMethodEntry& method_entry(RenderMethod m) {
  for (const RenderMethodEntry& e : render_methods())
    if (e.method == m) return e;
  throw std::logic_error("a render method without a row in method_table.hpp");
}

std::vector<std::string> render_method_names() {
  std::vector<std::string> names;
  for (const RenderMethodEntry& e : render_methods()) names.push_back(e.name);
  return names;
}

std::string method_list(bool (*pick)(const RenderMethodEntry&)) {
  std::vector<std::string> names;
  for (const RenderMethodEntry& e : render_methods())
    if (pick(e)) names.push_back(e.name);
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k) out += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + names[k];
  return out;
}

RenderMethod parse_render_method(const std::string& name) {
  for (const RenderMethodEntry& e : render_methods())
    if (name == e.name) return e.method;
  throw std::invalid_argument("method must be " + method_list([](const RenderMethodEntry&) { return true; }) + " (got '" + name + "')");
}

}  // namespace hlr
