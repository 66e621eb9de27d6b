// Renders the unit cube through the library API (render pipeline, 2D stage, SVG writer, the
// output stage of `hlr render`) and
// checks the exact drawing: seen along (1, 2, 3), three faces face the viewer, so 9 edges are
// visible whole and the 3 edges between the back faces are self-hidden. Exits 1 on any
// mismatch; prints the drawing's segments with exact coordinates.
#include <iostream>

#include "algorithms/picture/drawing_2d.hpp"
#include "io/output/output.hpp"
#include "io/pipeline/render.hpp"
#include "io/writers/svg_writer.hpp"

int main() {
  using hlr::Rational;
  hlr::Scene scene;
  scene.bodies.push_back(hlr::SceneBody{"cube", "(api)", hlr::make_box(hlr::Point3(0, 0, 0), hlr::Point3(1, 1, 1)),
                                        hlr::identity_transform(), {}, {}});
  hlr::RenderOptions options;
  options.lines.edges = hlr::EdgeSelection::All;
  options.view.direction = hlr::Vector3(1, 2, 3);
  std::vector<hlr::Scene> scenes;
  scenes.push_back(std::move(scene));
  hlr::RenderResult r = hlr::render(std::move(scenes), options);
  int visible = 0, hidden = 0;
  for (const hlr::Segment& s : r.drawing.segments) {
    bool all_visible = s.pieces.size() == 1 && s.pieces[0].visible;
    bool all_hidden = s.pieces.size() == 1 && !s.pieces[0].visible;
    visible += all_visible;
    hidden += all_hidden && s.self_hidden;
    std::cout << "edge " << s.v0 << "-" << s.v1 << " " << hlr::to_string(s.from()) << " -> " << hlr::to_string(s.to())
              << (all_visible ? " visible" : all_hidden ? " hidden" : " split") << "\n";
  }
  hlr::Drawing2D d = hlr::project_drawing(r.drawing, r.camera);
  std::string svg = hlr::to_svg(r.names, d, hlr::SvgOptions{});
  // The output stage of `hlr render` (io/output/output.hpp): the page hlr writes, with layers.
  const std::string page = hlr::drawing_text(r, hlr::OutputOptions{}, "svg", "consumer").str();
  bool ok = r.drawing.segments.size() == 12 && visible == 9 && hidden == 3 && d.lines.size() == 12 &&
            svg.find("<line") != std::string::npos && page.find("inkscape:label=\"1 visible-") != std::string::npos;
  std::cout << (ok ? "consumer: OK" : "consumer: WRONG DRAWING") << " (" << visible << " visible, " << hidden << " hidden)\n";
  return ok ? 0 : 1;
}
