// Python bindings: `import exact_hlr`. The render pipeline of the library
// (io/pipeline/render.hpp) with the exact drawing returned as Python objects whose coordinates and
// parameters are fractions.Fraction; explain (exam mode) and Cyrus-Beck clipping too.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdio>

#include "algorithms/clip/cyrus_beck.hpp"
#include "io/explain/explain.hpp"
#include "io/explain/problem.hpp"
#include "io/output/output.hpp"
#include "io/pipeline/raster.hpp"
#include "io/pipeline/render.hpp"
#include "io/pipeline/render_methods.hpp"
#include "io/readers/clipper_spec.hpp"
#include "io/writers/json_writer.hpp"
#include "io/writers/plot_output.hpp"
#include "io/writers/svg_writer.hpp"

namespace py = pybind11;

namespace {

py::object fraction(const hlr::Rational& q) {
  static py::object F = py::module_::import("fractions").attr("Fraction");
  return F(hlr::to_string(q));
}

py::tuple point(const hlr::Point3& p) { return py::make_tuple(fraction(p.x()), fraction(p.y()), fraction(p.z())); }

// An exact number from Python: int, Fraction, or text ("1/3", "0.1", "1e-400").
hlr::Rational number(const py::handle& h) { return hlr::parse_rational(py::str(h).cast<std::string>()); }

std::optional<hlr::Vector3> vector3(const std::optional<py::sequence>& s) {
  if (!s) return std::nullopt;
  if (py::len(*s) != 3) throw std::invalid_argument("a vector needs 3 numbers");
  return hlr::Vector3(number((*s)[0]), number((*s)[1]), number((*s)[2]));
}

std::optional<hlr::Point3> point3(const std::optional<py::sequence>& s) {
  auto v = vector3(s);
  if (!v) return std::nullopt;
  return hlr::Point3(v->x(), v->y(), v->z());
}

// The drawing as Python values; keeps the render result (and so the scenes) alive.
struct Drawing {
  std::shared_ptr<hlr::RenderResult> r;

  py::list segments() const {
    py::list out;
    for (const hlr::Segment& s : r->drawing.segments)
      for (const hlr::Piece& p : s.pieces) {
        py::dict d;
        d["kind"] = s.kind == hlr::Segment::Kind::Intersection && s.line == hlr::LineKind::Intersection ? "intersection" : hlr::to_string(s.line);
        if (s.kind == hlr::Segment::Kind::Edge) {
          d["body"] = s.body;
          d["edge"] = py::make_tuple(s.v0, s.v1);
        } else {
          d["bodies"] = py::make_tuple(s.body, s.body2);
        }
        d["visible"] = p.visible;
        d["from"] = point(s.at(p.t0));
        d["to"] = point(s.at(p.t1));
        d["t"] = py::make_tuple(fraction(p.t0), fraction(p.t1));
        d["self_hidden"] = s.self_hidden;
        d["behind_eye"] = p.behind_eye;
        d["clipped"] = p.clipped;
        out.append(d);
      }
    return out;
  }
  // The CLI's output stage (io/output/output.hpp): the same bytes as `hlr render -o x.svg`.
  std::string svg(bool hidden_dashed, double width_mm, double stroke_mm) const {
    hlr::OutputOptions o;
    o.hidden = hidden_dashed ? "dashed" : "none";
    o.width = width_mm;
    o.stroke = stroke_mm;
    hlr::check_output_options(o);
    return hlr::drawing_text(*r, o, "svg", "python").str();
  }
  std::string json() const {
    std::string j = hlr::to_json(r->names, r->drawing, r->camera, nullptr, hlr::surfaces_json(*r));
    const std::string section = hlr::section_text(*r, hlr::OutputOptions{});
    if (!section.empty()) j.insert(j.rfind('}'), section + "\n");  // the "section" member last, as the CLI writes it
    return j;
  }
  // The painter's list (render(..., method='priority')): one dict per polygon, back to front.
  py::object priority() const {
    if (!r->priority) return py::none();
    py::list out;
    for (int i : r->priority->order) {
      const hlr::PriorityPolygon& p = r->priority->polygons[i];
      py::dict d;
      d["body"] = p.body;
      d["face"] = r->names[p.body].output_face(p.face);
      d["piece"] = p.piece;
      d["cut"] = i >= static_cast<int>(r->priority->initial);
      auto c = hlr::rgb8(r->face_colours[p.body][p.face]);
      char hex[8];
      std::snprintf(hex, sizeof hex, "#%02x%02x%02x", c[0], c[1], c[2]);
      d["shade"] = std::string(hex);
      py::list corners;
      for (const hlr::Point3& q : p.corners) corners.append(point(q));
      d["corners"] = corners;
      out.append(d);
    }
    return out;
  }
  // The visible surfaces (render(..., surfaces=True)): one dict per face seen.
  py::object surfaces() const {
    if (!r->surfaces) return py::none();
    py::list out;
    for (const hlr::VisibleFace& f : r->surfaces->faces) {
      py::dict d;
      d["body"] = f.body;
      d["face"] = r->names[f.body].output_face(f.face);
      d["side"] = f.front ? "front" : "back";
      auto c = hlr::rgb8(r->face_colours[f.body][f.face]);
      char hex[8];
      std::snprintf(hex, sizeof hex, "#%02x%02x%02x", c[0], c[1], c[2]);
      d["shade"] = std::string(hex);
      py::list polys;
      hlr::Rational total = 0;
      for (const hlr::VisiblePolygon& p : f.polygons) {
        py::dict pd;
        py::list outer;
        for (const hlr::Point3& q : p.outer) outer.append(point(q));
        py::list holes;
        for (const auto& h : p.holes) {
          py::list ring;
          for (const hlr::Point3& q : h) ring.append(point(q));
          holes.append(ring);
        }
        pd["outer"] = outer;
        pd["holes"] = holes;
        pd["area"] = fraction(p.area2 / 2);
        total += p.area2 / 2;
        polys.append(pd);
      }
      d["area"] = fraction(total);
      d["polygons"] = polys;
      out.append(d);
    }
    return out;
  }
  // The plotting 2D stage: strokes per layer in pen order (drawing coordinates).
  hlr::Plot make(bool hidden) const {
    hlr::PlotOptions po;
    po.hidden = hidden;
    hlr::Plot p = hlr::make_plot(r->drawing, r->camera, po);
    hlr::add_surface_fills(p, *r);
    if (p.fills.empty()) hlr::order_plot(p, {p.bounds[0], p.bounds[3]});
    return p;
  }
  py::dict strokes(bool hidden) const {
    hlr::Plot p = make(hidden);
    py::dict out;
    for (const hlr::PlotLayer& l : p.layers) {
      py::list ls;
      for (const hlr::Stroke& st : l.strokes) {
        py::list pts;
        for (const auto& q : st.points) pts.append(py::make_tuple(q[0], q[1]));
        if (st.closed && !st.points.empty()) pts.append(py::make_tuple(st.points[0][0], st.points[0][1]));
        ls.append(pts);
      }
      out[py::str(l.name())] = ls;
    }
    return out;
  }
  py::bytes plot(const std::string& format, bool hidden, py::object page, bool landscape, py::object scale,
                 const std::string& dashes) const {
    if (format != "svg" && format != "pdf" && format != "png" && format != "dxf")
      throw std::invalid_argument("format must be svg, pdf, png or dxf");
    hlr::OutputOptions o;
    o.hidden = hidden ? "dashed" : "none";
    if (!page.is_none()) o.page = page.cast<std::string>();
    o.landscape = landscape;
    if (!scale.is_none()) o.scale = py::str(scale).cast<std::string>();
    o.dashes = dashes;
    hlr::check_output_options(o);
    return py::bytes(hlr::drawing_text(*r, o, format, "python").str());
  }
  std::vector<std::string> bodies() const {
    std::vector<std::string> n;
    for (const auto& b : r->names) n.push_back(b.name);
    return n;
  }
};

Drawing render(const py::object& input, std::optional<py::sequence> view, std::optional<py::sequence> eye, std::optional<py::sequence> target,
               std::optional<py::sequence> up, const std::string& method, const std::string& edges, const py::object& crease, unsigned threads,
               bool surfaces, bool shadows, bool through, const std::vector<std::string>& section, const std::vector<std::string>& cutaway,
               const py::object& lines) {
  std::vector<std::string> inputs;
  if (py::isinstance<py::str>(input)) inputs.push_back(input.cast<std::string>());
  else inputs = input.cast<std::vector<std::string>>();
  hlr::RenderOptions o;
  if (edges != "feature" && edges != "all") throw std::invalid_argument("edges must be 'feature' or 'all'");
  o.method = hlr::parse_render_method(method);
  o.surfaces = surfaces;
  o.shadows = shadows;
  o.through_lines = through;
  o.lines.edges = edges == "all" ? hlr::EdgeSelection::All : hlr::EdgeSelection::Feature;
  o.lines.crease_degrees = number(crease);
  o.lines.threads = threads;
  o.view.direction = vector3(view);
  o.view.eye = point3(eye);
  o.view.target = point3(target);
  o.view.up = vector3(up);
  for (const std::string& s : section)
    for (hlr::Plane& h : hlr::parse_section("section", s)) o.section.push_back(std::move(h));
  for (const std::string& s : cutaway)
    for (hlr::Plane& h : hlr::parse_section("cutaway", s)) o.cutaway.push_back(std::move(h));
  if (!lines.is_none())
    for (const py::handle& line : lines) {
      hlr::Polyline3 l;
      for (const py::handle& p : line) l.push_back(*point3(p.cast<py::sequence>()));
      if (l.size() < 2) throw std::invalid_argument("lines: a polyline needs at least two points");
      o.polylines.push_back(std::move(l));
    }
  py::gil_scoped_release release;
  return Drawing{std::make_shared<hlr::RenderResult>(hlr::render_files(inputs, o))};
}

// `raster(...)`: the image-space algorithms (io/pipeline/raster.hpp).
struct Image {
  std::shared_ptr<hlr::RasterResult> r;
  py::bytes png() const { return py::bytes(hlr::png_rgb(r->width, r->height, r->rgb)); }
  // The face seen at every sample, row by row from the top: (body, face) or None.
  py::list faces() const {
    py::list rows;
    for (int j = 0; j < r->ids.height; ++j) {
      py::list row;
      for (int i = 0; i < r->ids.width; ++i) {
        int id = r->ids.at(i, j);
        if (id < 0) row.append(py::none());
        else row.append(py::make_tuple(r->scene.faces[id][0], r->render.names[r->scene.faces[id][0]].output_face(r->scene.faces[id][1])));
      }
      rows.append(row);
    }
    return rows;
  }
  // The exact centre of sample (i, j) in world coordinates (Fractions).
  py::tuple centre(int i, int j) const {
    if (i < 0 || j < 0 || i >= r->ids.width || j >= r->ids.height) throw std::invalid_argument("sample outside the grid");
    const hlr::PicturePlane pp(r->render.camera);
    const hlr::Exact2 q = r->scene.grid.centre(i, j);
    const hlr::Rational rr = hlr::dot(pp.r(), pp.r()), uu = hlr::dot(pp.u(), pp.u()), dd = hlr::dot(pp.d(), pp.d());
    std::array<hlr::Rational, 3> c;
    for (int k = 0; k < 3; ++k)
      c[k] = r->render.camera.perspective
                 ? hlr::Rational(r->render.camera.eye[k] + pp.d()[k] + q[0] * dd / rr * pp.r()[k] + q[1] * dd / uu * pp.u()[k])
                 : hlr::Rational(q[0] / rr * pp.r()[k] + q[1] / uu * pp.u()[k]);
    return py::make_tuple(fraction(c[0]), fraction(c[1]), fraction(c[2]));
  }
  std::string camera() const { return hlr::raster_camera_json(*r); }
};

Image raster(const py::object& input, std::optional<py::sequence> view, std::optional<py::sequence> eye,
             std::optional<py::sequence> target, std::optional<py::sequence> up, const std::string& algorithm, int width,
             int height, const std::string& shading, int samples, int bounces, unsigned threads) {
  std::vector<std::string> inputs;
  if (py::isinstance<py::str>(input)) inputs.push_back(input.cast<std::string>());
  else inputs = input.cast<std::vector<std::string>>();
  hlr::RasterOptions o;
  if (algorithm != "zbuffer" && algorithm != "scanline" && algorithm != "warnock" && algorithm != "raytrace")
    throw std::invalid_argument("algorithm must be 'zbuffer', 'scanline', 'warnock' or 'raytrace'");
  if (shading != "flat" && shading != "gouraud" && shading != "phong") throw std::invalid_argument("shading must be 'flat', 'gouraud' or 'phong'");
  o.algorithm = algorithm == "scanline" ? hlr::RasterAlgorithm::Scanline
                : algorithm == "warnock" ? hlr::RasterAlgorithm::Warnock
                : algorithm == "raytrace" ? hlr::RasterAlgorithm::RayCast
                                          : hlr::RasterAlgorithm::ZBuffer;
  o.shading = shading == "gouraud" ? hlr::RasterShading::Gouraud : shading == "phong" ? hlr::RasterShading::Phong : hlr::RasterShading::Flat;
  o.width = width, o.height = height, o.samples = samples, o.bounces = bounces, o.threads = threads;
  o.view.direction = vector3(view);
  o.view.eye = point3(eye);
  o.view.target = point3(target);
  o.view.up = vector3(up);
  py::gil_scoped_release release;
  return Image{std::make_shared<hlr::RasterResult>(hlr::raster_files(inputs, o))};
}

std::string explain(const std::string& problem, const std::string& lang, const std::string& format) {
  hlr::SolutionJson s = hlr::explain(hlr::load_problem(problem));
  hlr::Lang l = lang == "ru" ? hlr::Lang::Ru : hlr::Lang::En;
  if (format == "json") return s.dump(1) + "\n";
  if (format == "html") return hlr::explain_html(s, l);
  if (format == "md") return hlr::explain_markdown(s, l);
  throw std::invalid_argument("format must be 'md', 'html' or 'json'");
}

py::dict clip(const std::string& clipper, const py::sequence& segment) {
  if (py::len(segment) != 6) throw std::invalid_argument("a segment needs 6 numbers: x1, y1, z1, x2, y2, z2");
  hlr::Point3 p1(number(segment[0]), number(segment[1]), number(segment[2]));
  hlr::Point3 p2(number(segment[3]), number(segment[4]), number(segment[5]));
  hlr::ClipperSpec spec = hlr::parse_clipper("clipper", clipper);
  hlr::CyrusBeckResult r = hlr::cyrus_beck(spec.clipper, p1, p2);
  py::dict d;
  d["status"] = r.status == hlr::CyrusBeckResult::Status::Visible ? "visible"
                : r.status == hlr::CyrusBeckResult::Status::Point ? "point"
                                                                   : "outside";
  if (r.status != hlr::CyrusBeckResult::Status::Outside) {
    d["t"] = py::make_tuple(fraction(r.t_lower), fraction(r.t_upper));
    d["from"] = point(p1 + r.t_lower * (p2 - p1));
    d["to"] = point(p1 + r.t_upper * (p2 - p1));
  }
  return d;
}

}  // namespace

PYBIND11_MODULE(exact_hlr, m) {
  m.doc() = "exact-hlr: hidden lines of polyhedra, computed exactly (coordinates as fractions.Fraction)";
  py::register_exception<hlr::RenderBodyError>(m, "BodyError", PyExc_ValueError);
  py::register_exception<hlr::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<hlr::NumberError>(m, "NumberError", PyExc_ValueError);
  py::class_<Drawing>(m, "Drawing", "An exact hidden-line drawing")
      .def_property_readonly("segments", &Drawing::segments, "Pieces of the drawn lines: kind, body/edge or bodies, visible, from/to (Fractions), t")
      .def_property_readonly("bodies", &Drawing::bodies, "Body names, in drawing order")
      .def_property_readonly("notes", [](const Drawing& d) { return d.r->notes; })
      .def_property_readonly("method", [](const Drawing& d) { return std::string(hlr::to_string(d.r->drawing.stats.method)); })
      .def("svg", &Drawing::svg, py::arg("hidden_dashed") = false, py::arg("width_mm") = 150.0, py::arg("stroke_mm") = 0.0)
      .def("json", &Drawing::json, "The exact JSON of `hlr render` (docs/output-format.md)")
      .def_property_readonly("surfaces", &Drawing::surfaces,
                             "With surfaces=True: per face seen, its side, shade, exact area and visible polygons (outer, holes: "
                             "3D points as Fractions in the face's plane); None otherwise")
      .def_property_readonly("priority", &Drawing::priority,
                             "With method='priority': the painter's list back to front, one dict per polygon (body, face, piece, "
                             "cut, shade, corners: 3D points as Fractions); None otherwise")
      .def("strokes", &Drawing::strokes, py::arg("hidden") = false,
           "Strokes per layer ('visible-silhouette', ...) in pen order: lists of (x, y) drawing points")
      .def("plot", &Drawing::plot, py::arg("format") = "svg", py::kw_only(), py::arg("hidden") = false, py::arg("page") = py::none(),
           py::arg("landscape") = false, py::arg("scale") = py::none(), py::arg("dashes") = "pattern",
           "The drawing to plot or print (svg, pdf, png or dxf bytes), as `hlr render` writes it");
  m.def("render", &render, py::arg("inputs"), py::kw_only(), py::arg("view") = py::none(), py::arg("eye") = py::none(),
        py::arg("target") = py::none(), py::arg("up") = py::none(), py::arg("method") = "faces", py::arg("edges") = "feature",
        py::arg("crease") = py::int_(30), py::arg("threads") = 0u, py::arg("surfaces") = false, py::arg("shadows") = false, py::arg("through") = true,
        py::arg("section") = std::vector<std::string>{}, py::arg("cutaway") = std::vector<std::string>{}, py::arg("lines") = py::none(),
        "Renders mesh files and scene files: exact hidden lines (view: orthographic direction; eye: perspective); "
        "surfaces=True also gives the visible part of every face as exact polygons, shaded; shadows=True cuts them by "
        "the lights' shadows (json()['shadows']); through=False counts lines behind transparent bodies as hidden (by "
        "default they are their own class: 'through-*' layers, pieces with 'through': true); section=['z<1.2', ...] cuts "
        "the bodies and keeps the planes' common side (caps, cut lines, hatching: json()['section']), cutaway=[...] "
        "removes their common region (hlr render --section / --cutaway); lines=[[(x, y, z), ...], ...] are your own 3D "
        "polylines, drawn with their hidden parts removed by the bodies (segments of kind 'polyline')");
  py::class_<Image>(m, "Image", "A raster image with the exact face seen at every sample centre")
      .def_property_readonly("width", [](const Image& i) { return i.r->width; })
      .def_property_readonly("height", [](const Image& i) { return i.r->height; })
      .def("png", &Image::png, "The image as PNG bytes")
      .def("faces", &Image::faces, "The face seen at every sample, rows from the top: (body, face) or None")
      .def("centre", &Image::centre, py::arg("i"), py::arg("j"), "The exact world point of sample (i, j)'s centre (Fractions)")
      .def("camera", &Image::camera, "The exact sample grid as JSON text");
  m.def("raster", &raster, py::arg("inputs"), py::kw_only(), py::arg("view") = py::none(), py::arg("eye") = py::none(),
        py::arg("target") = py::none(), py::arg("up") = py::none(), py::arg("algorithm") = "zbuffer", py::arg("width") = 256,
        py::arg("height") = 256, py::arg("shading") = "flat", py::arg("samples") = 1, py::arg("bounces") = 0, py::arg("threads") = 0u,
        "The course's image-space algorithms (zbuffer, scanline, warnock, raytrace): the same exact face at every pixel "
        "centre; flat, Gouraud or Phong shading; samples x samples antialiasing; Whitted ray tracing with bounces > 0");
  m.def("explain", &explain, py::arg("problem"), py::kw_only(), py::arg("lang") = "en", py::arg("format") = "md",
        "Solves a problem file step by step (exam mode): Markdown, HTML or JSON text");
  m.def("clip", &clip, py::arg("clipper"), py::arg("segment"),
        "Cyrus-Beck clip of a segment (6 numbers) to box:..., frustum:... or a convex mesh file, exactly");
}
