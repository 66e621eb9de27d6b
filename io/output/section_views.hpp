// Section views on a sheet (ISO 128-40; docs/design.md, "Sections"): a named cutting plane's
// view "A–A" is seen from the side the plane removes and takes the place of the standard view
// that looks the same way; every other orthographic view that sees the plane edge-on gets the
// section line: a narrow chain line, wide at its ends, with arrows in the viewing direction and
// the section's letter at each end. These are marks made on the page, in the drawing's
// doubles: they decide nothing about the scene.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "algorithms/plot/plot.hpp"
#include "io/pipeline/render.hpp"
#include "io/writers/plot_output.hpp"

namespace hlr {

/// The section `name` through `plane` (kept: value <= 0) on a sheet whose named views have
/// `z_up`; `standard` is the standard view that looks the same way, if one does. Throws
/// std::invalid_argument for an empty name or a degenerate plane.
NamedSection named_section(std::string name, Plane plane, bool z_up);

/// The section view's view: from the removed side (along the plane's normal), up as the
/// standard view's of the same direction, else the up axis.
ViewRequest section_view_request(const NamedSection& section, bool z_up);

/// "A–A".
std::string section_view_label(const NamedSection& section);

/// The name of a sheet view that shows section `name` ("section:A"), and back ("" for others).
std::string section_view_name(const std::string& name);
std::string section_of_view_name(const std::string& view_name);

/// Adds to each orthographic view's plot the section lines of the sheet's section views that
/// it sees edge-on (layers visible-section-line and visible-section-mark, and the letters as
/// Plot::texts), sized on the page of `sheet` (its views are the plots').
void add_section_lines(std::vector<Plot>& plots, const std::vector<const RenderResult*>& results, const Sheet& sheet);

}  // namespace hlr
