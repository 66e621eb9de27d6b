// The render request (see render_request.hpp): the options of `hlr render` turned into the
// renders of one view or a sheet, and into the file's text.
#include "io/request/render_request.hpp"

#include <stdexcept>

#include "algorithms/support/progress.hpp"
#include "io/output/section_views.hpp"
#include "io/pipeline/render_methods.hpp"
#include "io/readers/clipper_spec.hpp"
#include "io/views/standard_views.hpp"
#include "io/views/view_choice.hpp"

namespace hlr {
namespace {

// The plane of section view `name` (--section-view NAME=PLANE), if given.
std::optional<Plane> section_plane(const RenderRequest& r, const std::string& name) {
  for (const std::string& d : r.section_views) {
    const std::size_t eq = d.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::invalid_argument("--section-view: '" + d + "' is not NAME=PLANE (e.g. A=x<0: keep x <= 0, seen from +x)");
    if (d.substr(0, eq) != name) continue;
    std::vector<Plane> h = parse_section("--section-view " + name, d.substr(eq + 1));
    if (h.size() != 1) throw std::invalid_argument("--section-view " + name + ": a section view takes one plane");
    return h[0];
  }
  return std::nullopt;
}

// The views of a sheet (`--views front,top,section:A`), each checked; empty: one view.
std::vector<std::string> sheet_views(const RenderRequest& r) {
  std::vector<std::string> names;
  if (r.views.empty()) return names;
  for (std::size_t at = 0; at <= r.views.size();) {
    const std::size_t comma = r.views.find(',', at);
    const std::string v = r.views.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    at = comma == std::string::npos ? r.views.size() + 1 : comma + 1;
    const std::string name = section_of_view_name(v);
    if (!name.empty()) {
      if (!section_plane(r, name)) throw std::invalid_argument("--views: section " + name + " is not given (--section-view " + name + "=PLANE)");
    } else if (!standard_view(v, false)) {
      throw std::invalid_argument("--views: '" + v + "' is not a standard view (" + standard_view_names() + ") or section:NAME");
    }
    names.push_back(v);
  }
  return names;
}

// A floor plan (--plan HEIGHT): the section below the height along the up axis, its overhead
// lines and its view depth.
void add_plan(const RenderRequest& r, RenderOptions& o) {
  const std::string axis = r.up_axis == "z" ? "z" : "y";
  for (Plane& h : parse_section("--plan", axis + "<" + r.plan)) o.section.push_back(std::move(h));
  o.overhead = !r.no_overhead;
  if (r.plan_depth.empty()) return;
  const std::vector<Rational> d = parse_numbers("--plan-depth", r.plan_depth, 1);
  if (d[0] <= 0) throw std::invalid_argument("--plan-depth must be a positive length below the cut");
  const int k = r.up_axis == "z" ? 2 : 1;
  const Plane& cut = o.section.back();  // cut[k]·axis + cut[3] <= 0 kept: HEIGHT = -cut[3] / cut[k]
  const Rational bottom = -cut[3] / cut[k] - d[0];
  o.view_depth = k == 2 ? Plane(0, 0, 1, -bottom) : Plane(0, 1, 0, -bottom);
}

Rational option_number(const std::string& option, const std::string& text) {
  try {
    return parse_rational(text);
  } catch (const NumberError& e) {
    throw std::invalid_argument(option + ": " + e.what());
  }
}

double option_real(const std::string& option, const std::string& text) { return to_double(option_number(option, text)); }

// "W,H" as two positive numbers.
std::array<Rational, 2> option_pair(const std::string& option, const std::string& text) {
  const std::vector<Rational> v = parse_numbers(option, text, 2);
  return {v[0], v[1]};
}

// The picture frame of --fov, --fov-v, --aspect, --frame, --focal and --sensor (none: unset).
std::optional<FrameRequest> frame_request(const RenderRequest& r) {
  if (r.fov.empty() && r.fov_v.empty() && r.frame.empty() && r.focal.empty()) {
    if (!r.aspect.empty() || !r.sensor.empty()) throw std::invalid_argument("--aspect and --sensor shape a frame: give --fov, --fov-v or --focal");
    return std::nullopt;
  }
  FrameRequest f;
  if (!r.fov.empty()) f.fov = option_real("--fov", r.fov);
  if (!r.fov_v.empty()) f.fov_v = option_real("--fov-v", r.fov_v);
  if (!r.frame.empty()) f.frame = option_pair("--frame", r.frame);
  if (!r.focal.empty()) f.focal = option_real("--focal", r.focal);
  if (!r.sensor.empty()) {
    const auto s = option_pair("--sensor", r.sensor);
    f.sensor = {to_double(s[0]), to_double(s[1])};
  }
  if (!r.aspect.empty()) {
    const std::size_t colon = r.aspect.find(':');
    f.aspect = colon == std::string::npos ? option_real("--aspect", r.aspect)
                                          : option_real("--aspect", r.aspect.substr(0, colon)) / option_real("--aspect", r.aspect.substr(colon + 1));
  }
  check_frame_request(f);
  return f;
}

}  // namespace

ModelOptions model_options(const RenderRequest& r) {
  ModelOptions m;
  m.tessellation.deflection = r.deflection;
  m.tessellation.angle_degrees = r.deflection_angle;
  m.units = r.units;
  return m;
}

void check_request(const RenderRequest& r, bool tile) {
  if (!r.view.empty() && !r.eye.empty()) throw std::invalid_argument("give --view (orthographic) or --eye (perspective), not both");
  if (!r.views.empty() && (!r.view.empty() || !r.eye.empty())) throw std::invalid_argument("give --views (a sheet) or one --view/--eye, not both");
  if (tile && !r.views.empty()) throw std::invalid_argument("--tile takes one view, not --views");
  if (r.plan_depth.size() && r.plan.empty()) throw std::invalid_argument("--plan-depth needs --plan");
  check_output_options(r);
  (void)sheet_views(r);
}

Scene load_request_input(const RenderRequest& r, const std::string& path) { return load_any_input(path, r.input_format, model_options(r)); }

RenderOptions render_options(const RenderRequest& r) {
  RenderOptions o;
  o.method = parse_render_method(r.method);
  o.lines.edges = r.edges == "all" ? EdgeSelection::All : EdgeSelection::Feature;
  o.tangent_edges = r.tangent_edges == "none" ? TangentEdges::None : r.tangent_edges == "visible" ? TangentEdges::Visible : TangentEdges::Thin;
  o.lines.threads = r.threads;
  o.lines.crease_degrees = option_number("--crease", r.crease);
  if (o.lines.crease_degrees < 0 || o.lines.crease_degrees > 180) throw std::invalid_argument("--crease must be an angle in degrees from 0 to 180");
  o.view = parse_view_request(r.view, r.eye, r.target, r.up, r.up_axis);
  o.view.frame = frame_request(r);
  o.near = option_number("--near", r.near);
  if (!r.clip.empty()) o.clip = parse_clipper("--clip", r.clip).clipper;
  for (const std::string& s : r.section)
    for (Plane& h : parse_section("--section", s)) o.section.push_back(std::move(h));
  for (const std::string& s : r.cutaway)
    for (Plane& h : parse_section("--cutaway", s)) o.cutaway.push_back(std::move(h));
  if (!r.plan.empty()) add_plan(r, o);
  else if (!r.plan_depth.empty()) throw std::invalid_argument("--plan-depth needs --plan");
  o.surfaces = r.surfaces || r.hatch;
  o.shadows = r.shadows;
  o.through_lines = !r.no_through;
  return o;
}

RenderedViews render_request(std::vector<Scene> scenes, const RenderRequest& r, const std::string& format, const RenderExtras& extras) {
  // Named views follow the scene's up axis: z when its view says up 0,0,1 (CAD, architecture).
  bool z_up = false;
  if (!scenes.empty() && scenes[0].view.up_given) {
    const Vector3& u = scenes[0].view.up;
    z_up = u.x() == 0 && u.y() == 0 && u.z() > 0;
  }
  RenderedViews out;
  out.names = sheet_views(r);
  const std::size_t n_views = std::max<std::size_t>(1, out.names.size());
  out.results.resize(n_views);
  std::shared_ptr<ViewShare> share = extras.share;
  if (!share && n_views > 1) share = std::make_shared<ViewShare>();
  for (std::size_t i = 0; i < n_views; ++i) {
    RenderRequest one = r;
    if (!out.names.empty()) one.view = out.names[i];
    if (one.up_axis.empty()) one.up_axis = z_up ? "z" : "y";
    if (!r.plan.empty() && one.view.empty() && one.eye.empty()) one.view = "top";  // a plan is seen from above
    const std::string section_name = out.names.empty() ? "" : section_of_view_name(out.names[i]);
    if (!section_name.empty()) one.view = "front";  // replaced by the section's own view below
    RenderOptions options = render_options(one);
    if (!section_name.empty()) {
      options.section_view = named_section(section_name, *section_plane(r, section_name), one.up_axis == "z");
      options.view = section_view_request(*options.section_view, one.up_axis == "z");
    }
    options.surface_corners = format == "json";  // hatching lifts what it needs itself
    options.surface_faces = format == "json" || r.hatch;
    options.surface_groups = !r.hatch;  // a hatched drawing has no fills
    options.back_edges = format == "json" || r.hidden != "none";
    options.tile = extras.tile;
    options.polylines = extras.polylines;
    options.segments_only = extras.segments_only;
    options.share = share;
    progress(out.names.empty() ? "hidden lines" : "hidden lines, view " + out.names[i]);
    // A view that draws the share's scenes needs no copy of them.
    if (reads_shared_scenes(options)) out.results[i] = render({}, options);
    else out.results[i] = render(i + 1 < n_views ? scenes : std::move(scenes), options);
  }
  return out;
}

PartText request_text(const RenderedViews& views, const RenderRequest& r, const std::string& format, const std::string& command) {
  return drawing_text(views.results, views.names, r, format, command);
}

}  // namespace hlr
