// The render pipeline of the library (course notes sections 20-28): load -> camera -> hidden
// lines -> clipping -> the exact line drawing, ready for the 2D stage (drawing_2d.hpp) and the
// writers (svg_writer.hpp, json_writer.hpp). `hlr render` parses its arguments into
// RenderOptions and calls this; so can any program (examples/consumer) and the Python module.
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/clip/cyrus_beck.hpp"
#include "algorithms/clip/view_pyramid.hpp"
#include "algorithms/model/line_drawing.hpp"
#include "algorithms/plot/plot.hpp"
#include "algorithms/shading/face_shading.hpp"
#include "algorithms/shading/lighting.hpp"
#include "algorithms/surfaces/priority_list.hpp"
#include "algorithms/surfaces/shadows.hpp"
#include "algorithms/surfaces/transparency.hpp"
#include "algorithms/surfaces/visible_surfaces.hpp"
#include "io/pipeline/method_table.hpp"
#include "io/readers/polyline_file.hpp"
#include "io/readers/scene.hpp"
#include "io/views/view_choice.hpp"
#include "io/writers/svg_writer.hpp"

namespace hlr {

/// Which hidden-line route renders. Roberts: the course's algorithm on convex bodies, and
/// through convex pieces for non-convex solids (Method::RobertsPieces in the stats).
/// WeilerAtherton: the course's visible-surface algorithm (weiler_atherton.hpp) for the
/// surfaces, the per-face route for the lines; implies `surfaces`. Priority: the course's
/// priority-list (painter's) algorithm (priority_list.hpp): the faces and their cut parts
/// painted back to front under the per-face route's lines.
/// The methods are the rows of method_table.hpp (io/pipeline/render_methods.hpp: names, steps).
#define HLR_METHOD_ENUM(e, name, lines, polygons, flags, help) e,
enum class RenderMethod { HLR_RENDER_METHODS(HLR_METHOD_ENUM) };
#undef HLR_METHOD_ENUM

/// A named section of a sheet (ISO 128-40): the view "A–A" of what `plane` keeps (value <= 0),
/// seen from the removed side; `standard` names the standard view of the same direction
/// ("front", or "" for none), whose place on the sheet it takes when that place is free.
struct NamedSection {
  std::string name;
  Plane plane;
  std::string standard;
};

struct FaceRouteShare;  // algorithms/hlr/face_occluders.hpp

/// What one view of a set does for the next (the views of a sheet, a batch of drawings of one
/// input; docs/design.md, "Views that share their work"): the scenes repaired once, and the
/// per-face route's work that no orthographic view changes. Give one object to every render of
/// the same input scenes: a render that can use it ignores the scenes it is given after the
/// first; one that cuts the bodies (a section, a cut-away, the eye's near plane), fills faces
/// or draws tiles neither reads nor fills it.
struct ViewShare {
  std::shared_ptr<std::vector<Scene>> scenes;  // repaired (null until a render fills it)
  std::vector<DrawingBody> names;
  std::vector<std::string> repairs;
  std::shared_ptr<FaceRouteShare> faces;
};

/// How tangent edges (where two surfaces of a CAD model meet tangentially) are drawn: Thin, a
/// narrow line of their own (layer "tangent", ISO 128); None, left out; Visible, as sharp edges.
enum class TangentEdges { Thin, None, Visible };

struct RenderOptions {
  RenderMethod method = RenderMethod::Faces;
  LineOptions lines;
  TangentEdges tangent_edges = TangentEdges::Thin;
  ViewRequest view;
  /// Perspective near plane, as a fraction of the eye-target distance (positive). Filled
  /// products (and `cut_at_near`) with the eye among the bodies cut every body by it first.
  Rational near = Rational(1, 1000);
  /// Clip the drawing to a convex volume (Cyrus-Beck, exact).
  std::optional<ConvexClipper> clip;
  /// A section: the half-spaces plane.value(p) <= 0 are kept, the rest of every body that takes
  /// cuts is removed before any route runs, and each cut body gets its caps (io/pipeline/
  /// section.hpp). Empty: the first scene file's `section:`, if any.
  std::vector<Plane> section;
  /// A cut-away: the convex region where every plane's value is <= 0 is removed (two planes: a
  /// half section), each cut body closed by caps facing into it. Empty: the scene's `cutaway:`.
  std::vector<Plane> cutaway;
  /// A floor plan's overhead lines: with a section of one plane in an orthographic view, also
  /// the visible lines of what the section removed seen from the other side (from below, in a
  /// plan), as LineKind::Overhead segments (no body: -1), drawn dashed; the cut lines there are
  /// left out (they are the plan's own).
  bool overhead = false;
  /// A floor plan's depth: lines are drawn only where this plane's value is >= 0 (the plan's
  /// lower band; clipped after visibility, exact for views from above, where nothing below the
  /// plane hides anything above it). Line drawings only.
  std::optional<Plane> view_depth;
  /// A section view of a sheet: its plane cuts as `section`'s do, in addition to them.
  std::optional<NamedSection> section_view;
  /// The user's own 3D lines, drawn with their hidden parts removed by the bodies (LineKind::
  /// Polyline, no body: io/pipeline/polylines.hpp); any route, not with tiles.
  std::vector<Polyline3> polylines;
  /// Also the visible part of every face as exact polygons, shaded (visible_surfaces.hpp,
  /// lighting.hpp); the line drawing is then the selected lines of the same exact solution.
  bool surfaces = false;
  /// With surfaces: lift every visible polygon to exact 3D corners (the JSON needs them; the
  /// fills of SVG, PDF and PNG do not).
  bool surface_corners = true;
  /// The visible polygons per face (JSON, Python); off: per colour group only (SVG, PDF, PNG).
  bool surface_faces = true;
  /// The visible polygons merged per colour (the fills of SVG, PDF and PNG); off: none (a
  /// drawing hatched by tone, made from the per-face polygons).
  bool surface_groups = true;
  /// Shadows of the scene's lights on the visible surfaces, as exact polygons (shadows.hpp);
  /// implies `surfaces` (the per-face route).
  bool shadows = false;
  /// Lines behind transparent bodies (a material with transparency > 0) as their own class,
  /// seen through (see_through_lines.hpp; the per-face route). Off: they are hidden lines.
  bool through_lines = true;
  /// The edges a body's own faces hide wholly (its back), each a segment with one hidden piece:
  /// the JSON and hidden lines show them. Off (a drawing without hidden lines): the per-face
  /// route leaves them out of an orthographic view that nothing clips, which changes no drawn
  /// line and no number of the drawing's frame.
  bool back_edges = true;
  /// Only the part of the drawing in tile `index` (0-based) of a `count`-tile split of the
  /// picture (picture_tiles.hpp): segments outside it are not solved, every piece is
  /// cut to the tile. The per-face route's line drawings only.
  struct Tile {
    int index = 0, count = 1;
  };
  std::optional<Tile> tile;
  /// The segments without their visibility (each one placeholder piece): a merge of tiles
  /// puts the tiles' pieces in (io/readers/tile_file.hpp). The per-face route's line drawings only.
  bool segments_only = false;
  /// The prepare stage alone for the raster pipeline: bodies, camera and each face's facing
  /// (LineDrawing::facing, back_faces_unseen), no lines.
  bool facing_only = false;
  /// Cut every body by the near plane when some body reaches the eye's plane, as filled
  /// products do (the raster pipeline's prepare stage).
  bool cut_at_near = false;
  /// The work shared with the other views of the same input (null: none).
  std::shared_ptr<ViewShare> share;
};

struct RenderResult {
  std::shared_ptr<const std::vector<Scene>> scenes;  // owns the bodies the segments point into
  std::vector<const SceneBody*> bodies;               // all bodies, in drawing order
  std::vector<DrawingBody> names;                     // their names and sources
  Camera camera;
  LineDrawing drawing;
  /// With RenderOptions::surfaces: the visible polygons (merged per colour in `groups`), each
  /// face's flat colour (per body, per face) and the colour of each group.
  std::optional<VisibleSurfaces> surfaces;
  std::vector<std::vector<Rgb>> face_colours;
  std::vector<Rgb> group_colours;
  /// With RenderMethod::Priority: the painter's list (polygons painted back to front) and the
  /// seconds it took.
  std::optional<PriorityResult> priority;
  /// With RenderOptions::shadows: every visible face cut by the lights' shadows, and the colour
  /// of each region (per shadow face, per region).
  std::optional<Shadows> shadows;
  std::vector<std::vector<Rgb>> shadow_colours;
  /// With surfaces and a body whose material has a transparency: the regions of equal ordered
  /// face lists and the final colour of each (transparency.hpp).
  std::optional<TransparentPicture> transparent;
  std::vector<Rgb> transparent_colours;
  double priority_seconds = 0;
  /// Pieces of lines seen through transparent faces (RenderOptions::through_lines).
  std::size_t through_pieces = 0;
  /// With a section: its planes, the kept side's (RenderOptions::section) then the cut-away's;
  /// a cap face of plane k (SceneBody::section_cap) lies on section_planes[k].
  std::vector<Plane> section_planes;
  bool section_cut_away = false;  // some of them are a cut-away's
  /// With caps drawn by the per-face route in an orthographic view: that route's work on the
  /// cut bodies (scaled points, topology, triangles, normals), which the caps' hatching reads
  /// instead of doing it again (null otherwise).
  std::shared_ptr<FaceRouteShare> section_share;
  /// The clipping the drawing got (the perspective near plane, RenderOptions::clip), for lines
  /// made later on the page (a section's hatching).
  std::optional<Plane> near_plane;
  /// Set when the eye lay among the bodies and every body was cut by the near plane (its
  /// caps: SceneBody::section_cap kEyeCap): the plane, its kept side n·X + d <= 0.
  std::optional<Plane> eye_cut;
  /// With eye_cut and shadows: the bodies before that cut, which the lights see whole.
  struct WholeBodies {
    std::vector<Polyhedron> bodies;
    ShadowCasters casters;
  };
  std::shared_ptr<const WholeBodies> whole;
  std::optional<ConvexClipper> clip;
  /// With RenderOptions::section_view: the section this view shows.
  std::optional<NamedSection> section_view;
  /// Remarks for the user ("file: body 'name' is open ...: drawn as a surface", eye in a face plane).
  std::vector<std::string> notes;
  /// A perspective view's picture frame (--fov, --frame, --focal, or the scene's): the lines are
  /// clipped exactly to its pyramid and the page shows its rectangle.
  std::optional<ViewPyramid> pyramid;
};

/// A body a route cannot take, named: what() is "SOURCE: body 'NAME' REASON".
class RenderBodyError : public std::runtime_error {
 public:
  RenderBodyError(int body, std::string name, std::string source, std::string reason);
  int body() const { return body_; }
  const std::string& name() const { return name_; }
  const std::string& source() const { return source_; }
  const std::string& reason() const { return reason_; }

 private:
  int body_;
  std::string name_, source_, reason_;
};

/// Renders loaded scenes (the first scene file's view unless options.view overrides it).
/// Throws RenderBodyError, std::invalid_argument (bad view or options).
RenderResult render(std::vector<Scene> scenes, const RenderOptions& options = {});

/// Whether render(scenes, options) would draw options.share's scenes, repaired by a view
/// before, and not look at the scenes it is given (they need not be copied for it).
bool reads_shared_scenes(const RenderOptions& options);

/// The shaded regions of a surfaces render in the 2D stage's drawing coordinates (the same
/// projector as the lines), one fill per region of one colour (a priority render: one fill per
/// polygon of the list, in the order painted); also widens the plot's bounds.
void add_surface_fills(Plot& plot, const RenderResult& result);

/// The lights a render shades with: the scene's `lighting:`, else its `light:` as one
/// directional light, else the default lights for the camera.
Lighting render_lighting(const RenderResult& result);

/// Where those lights are, exactly, in their order (the shadow pass's lights: bit i of a
/// ShadowRegion's `lights` is light i here).
std::vector<LightPlace> render_light_places(const RenderResult& result);

/// The material of body b (its own, else the palette's default colour).
Material body_material(const RenderResult& result, std::size_t body);

/// Every face's flat colour (per body, per face) for the side the viewer sees (facing from
/// result.drawing; -1: the back side), with face_normal's normals; with `only`, just the faces
/// it marks (the others black).
std::vector<std::vector<Rgb>> flat_face_colours(const RenderResult& result, const std::vector<std::vector<char>>* only = nullptr);

/// Loads mesh files (.off .obj .stl .ply), models (.step .stp .iges .igs: default tessellation) and
/// scene files (.yaml .yml .json), then renders.
/// Also throws InputError (file and line) for bad input.
RenderResult render_files(const std::vector<std::string>& inputs, const RenderOptions& options = {});

}  // namespace hlr
