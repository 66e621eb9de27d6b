// The Python package's inputs (docs/design.md, "The Python package"): exact numbers from
// Python values, in-memory meshes (lists, numpy arrays, objects with .vertices and .faces) and
// scene texts turned into the library's scenes, and the keywords' options parsed by the render
// command's own option table (cli/render_arguments.hpp).
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

#include "cli/render_arguments.hpp"
#include "io/readers/scene.hpp"

namespace hlr::python {

/// An option's value was refused (a bad view, a bad page, an unknown method): the CLI's message.
class OptionError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// The exact value of a Python number: int, float (its exact binary value), Fraction, Decimal,
/// numpy scalars, or text ("1/3", "0.1", "1e-400"). `what` names it in errors.
Rational exact_number(const pybind11::handle& h, const std::string& what);

/// The render command's options from "--name=value" / "--flag" arguments (with one placeholder
/// input). Throws OptionError with the CLI's message.
std::shared_ptr<cli::RenderArgs> parse_render_args(const std::vector<std::string>& args);

/// The long names of the render command's options (without "--") and their kinds ("flag",
/// "value", "list": repeatable): all, or the output ones.
std::vector<std::pair<std::string, std::string>> render_option_names(bool output_only);

/// One input of render(): ("file", path), ("mesh", vertices, faces, name) or ("scene", text,
/// name), as the package's Python side sorts them. Reads it into a scene (the GIL held: the
/// mesh's numbers are Python objects).
Scene input_scene(const pybind11::tuple& item, const RenderRequest& request);

}  // namespace hlr::python
