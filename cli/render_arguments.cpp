// The options of `hlr render` (see render_arguments.hpp).
#include "cli/render_arguments.hpp"

#include "io/pipeline/render_methods.hpp"

namespace hlr::cli {

void add_render_options(CLI::App* cmd, const std::shared_ptr<RenderArgs>& a) {
  cmd->add_option("inputs", a->inputs,
                  "Mesh files (.off .obj .stl .ply), models (.step .stp .iges .igs) and scene files (.yaml .yml .json); - is "
                  "standard input (with --input-format)")
      ->required();
  cmd->add_option("--deflection", a->deflection,
                  "A STEP or IGES model's tessellation: the largest distance in mm from a triangle to the surface (default: a "
                  "thousandth of the model's size)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--deflection-angle", a->deflection_angle,
                  "A STEP or IGES model's tessellation: the largest angle in degrees between neighbouring triangles of one "
                  "surface (default 15)")
      ->check(CLI::Range(0.01, 90.0));
  cmd->add_option("--tangent-edges", a->tangent_edges,
                  "Edges where two faces of a model meet tangentially: thin (default, a narrow line of their own, layer "
                  "'tangent'), none, or visible (as sharp edges)")
      ->check(CLI::IsMember({"thin", "none", "visible"}));
  cmd->add_option("--units", a->units,
                  "The length unit of mesh files (mm default, cm, m, in, ft, um): coordinates are brought to millimetres, so that "
                  "--scale 1:100 means a hundredth of the real size (models say their own unit)")
      ->check(CLI::IsMember({"mm", "cm", "m", "in", "ft", "um"}));
  cmd->add_option("--input-format", a->input_format,
                  "Read the inputs as off, obj, stl, ply, yaml or json whatever their names (needed for - , standard input)")
      ->check(CLI::IsMember({"off", "obj", "stl", "ply", "yaml", "json"}));
  add_output_options(cmd, *a, *a, true);
  cmd->add_option("--view", a->view,
                  "Orthographic view: front, back, top, bottom, left, right, iso, dimetric, or a direction X,Y,Z from the scene "
                  "toward the viewer (default 0,0,1 = front); repeated with one -o each, a batch of drawings from one load")
      ->each([a](const std::string& v) { a->each_view.push_back(v); })
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  cmd->add_option("--views", a->views,
                  "A sheet of standard views at one scale, e.g. front,top,right,iso, and section views section:NAME "
                  "(--section-view)");
  cmd->add_option("--up-axis", a->up_axis, "Which axis is up for the named views: y or z (default: z when the scene's view has up 0,0,1, else y)")
      ->check(CLI::IsMember({"y", "z"}));
  cmd->add_option("--eye", a->eye, "Perspective: the eye point X,Y,Z");
  cmd->add_option("--target", a->target, "Perspective: the point looked at (default: centre of the scene's bounding box)");
  cmd->add_option("--up", a->up, "Up direction X,Y,Z (default 0,1,0, or 0,0,1 when looking along y)");
  cmd->add_option("--edges", a->edges,
                  "feature (default: boundaries, silhouettes, creases over --crease, intersection lines) or all (every mesh edge)")
      ->check(CLI::IsMember({"all", "feature"}));
  cmd->add_option("--crease", a->crease,
                  "Crease threshold in degrees between face normals (default 30; 0 keeps every edge between non-coplanar faces)");
  std::string methods;
  for (const RenderMethodEntry& m : render_methods()) methods += std::string(methods.empty() ? "" : "; ") + m.name + " (" + m.help + ")";
  cmd->add_option("--method", a->method, methods)->check(CLI::IsMember(render_method_names()));
  cmd->add_flag("--surfaces", a->surfaces,
                "Also the visible part of every face as exact polygons, flat-shaded by the scene's lights and materials "
                "(SVG/PDF/PNG fills under the lines; JSON 'surfaces')");
  cmd->add_flag("--shadows", a->shadows,
                "Shadows of the scene's lights on the visible surfaces, as exact polygons (implies --surfaces; "
                "each region shaded by the lights that reach it; JSON 'shadows')");
  cmd->add_flag("--hatch", a->hatch,
                "Tone hatching for pen plotters: every visible region (with --shadows, lit and shadowed apart) hatched by its "
                "shade instead of filled, exact lines clipped to the exact visible polygons (implies --surfaces; layers "
                "'visible-tone-1' .. lightest to darkest)");
  cmd->add_option("--hatch-levels", a->hatch_levels, "Tone levels, 2 to 8 (default 5: white, then coverage 1/5 .. 4/5; over 1/2 cross-hatched)");
  cmd->add_option("--hatch-angle", a->hatch_angle,
                  "The hatch lines' angle on the page in degrees (default 45), or 'contour': each face's level lines");
  cmd->add_option("--hatch-pen", a->hatch_pen, "The hatching pen's width in mm (default 0.25, the 'tone' weight); spacing = pen / coverage");
  cmd->add_flag("--no-through", a->no_through,
                "Lines behind transparent bodies (material transparency > 0) count as hidden; by default they are their own "
                "class, seen through (thin grey layers 'through-*', JSON pieces with \"through\": true)");
  cmd->add_flag("--timings", a->timings, "Print the time of each stage to standard error");
  cmd->add_option("--clip", a->clip,
                  "Clip the drawing to box:XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX, frustum:XL,XR,YB,YT,ZNEAR,ZFAR,ZCP or a convex mesh file");
  cmd->add_option("--section", a->section,
                  "Cut the bodies and keep z<1.2 (or x>0, A,B,C,D for A*x+B*y+C*z+D <= 0, box:XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX); "
                  "repeat to keep the intersection. What is removed hides nothing; each cut body gets exact caps, cut lines "
                  "(layer 'visible-cut') and hatching ('visible-hatch')");
  cmd->add_option("--cutaway", a->cutaway,
                  "Remove the region where every --cutaway half-space holds (same forms as --section; 'x>0' and 'y>0': a half "
                  "section's quarter) and close the cut bodies with caps");
  cmd->add_option("--plan", a->plan,
                  "A floor plan: a section at this height along the up axis, the part below kept, seen from above (--view top "
                  "unless a view is given)");
  cmd->add_option("--plan-depth", a->plan_depth, "A plan's view depth: lines are drawn down to this far below the cut (default: all the way down)");
  cmd->add_option("--section-view", a->section_views,
                  "A named section for --views section:NAME, as NAME=PLANE (e.g. A=x<0: keep x <= 0, seen from +x, labelled "
                  "A-A); the other views that see the plane edge-on show its section line, arrows and letters");
  cmd->add_flag("--no-overhead", a->no_overhead,
                "A plan without its overhead lines (what lies above the cut, seen from below, dashed: layer 'visible-overhead')");
  cmd->add_option("--lines", a->lines,
                  "Your own 3D polylines, drawn with their hidden parts removed by the bodies (layers 'visible-polyline', "
                  "'hidden-polyline'): a text file, one polyline per line as x y z x y z ... ('-': standard input)");
  cmd->add_option("--fov", a->fov,
                  "Perspective: the horizontal field of view in degrees; the picture is clipped exactly to its frame and the page "
                  "shows the frame (the vertical from --aspect, default 3:2)");
  cmd->add_option("--fov-v", a->fov_v, "Perspective: the vertical field of view in degrees (with --fov: both sides of the frame)");
  cmd->add_option("--aspect", a->aspect, "The frame's width to height, W:H or a number, when one angle is given (default 3:2)");
  cmd->add_option("--frame", a->frame, "Perspective: the frame's width and height W,H at the target's distance (scene units)");
  cmd->add_option("--focal", a->focal, "Perspective: a lens's focal length in mm on --sensor (the photographer's and Blender's frame)");
  cmd->add_option("--sensor", a->sensor, "The sensor's width and height in mm for --focal, and the default aspect (default 36,24: full frame)");
  cmd->add_option("--near", a->near, "Perspective near plane at this fraction of the eye-target distance from the eye (default 1/1000)");
  cmd->add_option("--tile", a->tile,
                  "Only tile I of an N-tile split of the picture, as a tile file for hlr merge (I/N, e.g. 3/9; the per-face route's "
                  "line drawings)");
}

}  // namespace hlr::cli
