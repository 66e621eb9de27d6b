// The render command as a library call (docs/design.md, "The render request"): every option of
// `hlr render` as text or flags with the command line's defaults, turned into the renders of one
// view or a sheet of views and then into the file's text. The CLI and the Python package only
// fill a RenderRequest and call these, so both draw the same thing from the same options.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/models/model_input.hpp"
#include "io/output/output.hpp"
#include "io/pipeline/render.hpp"
#include "io/writers/atomic_file.hpp"

namespace hlr {

/// The options of `hlr render` (its help names each), with its defaults; the output options
/// are the OutputOptions base.
struct RenderRequest : OutputOptions {
  std::string view, eye, target, up, edges = "feature", clip, near = "1/1000";
  std::string method = "faces", crease = "30";
  bool surfaces = false, shadows = false, no_through = false;
  std::string views, up_axis;
  std::vector<std::string> section, cutaway;
  std::string plan;  ///< a height: a floor plan
  std::string plan_depth;
  bool no_overhead = false;
  std::vector<std::string> section_views;        ///< "A=PLANE"
  std::string input_format;                      ///< the inputs' format whatever their names
  double deflection = 0, deflection_angle = 15;  ///< a STEP or IGES model's tessellation
  std::string tangent_edges = "thin", units;
  std::string fov, fov_v, aspect, frame, focal, sensor;  ///< a perspective picture's frame
};

/// What a call adds to the request's options: a tile of the picture, the caller's own 3D
/// polylines, and whether only the segments are needed (a merge of tiles).
struct RenderExtras {
  std::optional<RenderOptions::Tile> tile;
  std::vector<Polyline3> polylines;
  bool segments_only = false;
  /// The work shared by every drawing of the same input (a batch); a sheet's views share
  /// theirs in any case.
  std::shared_ptr<ViewShare> share;
};

/// The renders of a request: one, or one per view of the sheet (`names` then label them).
struct RenderedViews {
  std::vector<RenderResult> results;
  std::vector<std::string> names;
};

/// How a STEP, IGES or mesh file of the request is read.
ModelOptions model_options(const RenderRequest& r);

/// Checks the request before any long work: a view and an eye, a sheet and one view, a tile of
/// a sheet, the output options. Throws std::invalid_argument.
void check_request(const RenderRequest& r, bool tile);

/// Loads an input of the request (a mesh, model or scene file; "-" standard input).
Scene load_request_input(const RenderRequest& r, const std::string& path);

/// The RenderOptions of one view of the request (its view and up axis as given).
RenderOptions render_options(const RenderRequest& r);

/// Renders the scenes as the request says: one view, or every view of `views` (a sheet);
/// `format` (svg, pdf, png, dxf, json) says what the text will need. Throws std::invalid_argument, InputError, RenderBodyError.
RenderedViews render_request(std::vector<Scene> scenes, const RenderRequest& r, const std::string& format, const RenderExtras& extras = {});

/// The file's text of the renders (drawing_text() with the request's output options).
PartText request_text(const RenderedViews& views, const RenderRequest& r, const std::string& format, const std::string& command);

}  // namespace hlr
