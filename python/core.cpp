// The compiled part of the Python package `exact_hlr` (the module exact_hlr._core; the package's
// Python side is exact_hlr/__init__.py): render() through the library's render request
// (io/request/render_request.hpp) with the keywords parsed by the render command's own option
// table, in-memory meshes, the drawing with numpy arrays and exact Fractions, raster(), explain
// (exam mode) and Cyrus-Beck clipping; every library error as a typed Python exception.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "algorithms/clip/cyrus_beck.hpp"
#include "algorithms/support/parallel.hpp"
#include "core_drawing.hpp"
#include "core_inputs.hpp"
#include "io/explain/explain.hpp"
#include "io/explain/problem.hpp"
#include "io/pipeline/raster.hpp"
#include "io/readers/clipper_spec.hpp"
#include "io/views/view_choice.hpp"
#include "io/writers/atomic_file.hpp"

namespace py = pybind11;
using hlr::python::Drawing;

namespace {

py::object fraction(const hlr::Rational& q) {
  static const py::object F = py::module_::import("fractions").attr("Fraction");
  return F(hlr::to_string(q));
}

py::tuple point(const hlr::Point3& p) { return py::make_tuple(fraction(p.x()), fraction(p.y()), fraction(p.z())); }

hlr::Point3 exact_point(const py::handle& h, const std::string& what) {
  const py::sequence s = py::reinterpret_borrow<py::sequence>(h);
  if (py::len(s) != 3) throw hlr::python::OptionError(what + " needs 3 numbers");
  return hlr::Point3(hlr::python::exact_number(s[0], what), hlr::python::exact_number(s[1], what), hlr::python::exact_number(s[2], what));
}

std::vector<hlr::Scene> scenes_of(const py::list& items, const hlr::RenderRequest& request) {
  std::vector<hlr::Scene> scenes;
  for (const py::handle& item : items) scenes.push_back(hlr::python::input_scene(py::reinterpret_borrow<py::tuple>(item), request));
  return scenes;
}

Drawing render(const py::list& items, const std::vector<std::string>& args, const py::object& lines) {
  const auto a = hlr::python::parse_render_args(args);
  hlr::check_request(*a, false);
  std::vector<hlr::Scene> scenes = scenes_of(items, *a);
  hlr::RenderExtras extras;
  if (!lines.is_none())
    for (const py::handle& line : lines) {
      hlr::Polyline3 l;
      for (const py::handle& p : line) l.push_back(exact_point(p, "lines: a point"));
      if (l.size() < 2) throw hlr::python::OptionError("lines: a polyline needs at least two points");
      extras.polylines.push_back(std::move(l));
    }
  auto all = std::make_shared<hlr::python::Rendered>();
  all->args = args;
  {
    py::gil_scoped_release release;
    const hlr::ThreadLimit limit(a->threads);
    // "json": the render keeps what every format needs (the surfaces' corners and faces).
    all->views = hlr::render_request(std::move(scenes), *a, "json", extras);
  }
  return Drawing(all, -1);
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
        const int id = r->ids.at(i, j);
        if (id < 0) row.append(py::none());
        else row.append(py::make_tuple(r->scene.faces[id][0], r->render.names[r->scene.faces[id][0]].output_face(r->scene.faces[id][1])));
      }
      rows.append(row);
    }
    return rows;
  }
  // The exact centre of sample (i, j) in world coordinates (Fractions).
  py::tuple centre(int i, int j) const {
    if (i < 0 || j < 0 || i >= r->ids.width || j >= r->ids.height) throw py::index_error("sample outside the grid");
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

Image raster(const py::list& items, const std::vector<std::string>& view, const std::string& algorithm, int width, int height,
             const std::string& shading, int samples, int bounces, unsigned threads) {
  using hlr::python::OptionError;
  hlr::RasterOptions o;
  if (algorithm != "zbuffer" && algorithm != "scanline" && algorithm != "warnock" && algorithm != "raytrace")
    throw OptionError("algorithm must be 'zbuffer', 'scanline', 'warnock' or 'raytrace'");
  if (shading != "flat" && shading != "gouraud" && shading != "phong") throw OptionError("shading must be 'flat', 'gouraud' or 'phong'");
  if (width < 1 || height < 1 || width > 16384 || height > 16384) throw OptionError("width and height must be 1 to 16384 pixels");
  o.algorithm = algorithm == "scanline"   ? hlr::RasterAlgorithm::Scanline
                : algorithm == "warnock"  ? hlr::RasterAlgorithm::Warnock
                : algorithm == "raytrace" ? hlr::RasterAlgorithm::RayCast
                                          : hlr::RasterAlgorithm::ZBuffer;
  o.shading = shading == "gouraud" ? hlr::RasterShading::Gouraud : shading == "phong" ? hlr::RasterShading::Phong : hlr::RasterShading::Flat;
  o.width = width, o.height = height, o.samples = samples, o.bounces = bounces, o.threads = threads;
  if (view.size() != 5) throw OptionError("raster: view, eye, target, up and up_axis");
  o.view = hlr::parse_view_request(view[0], view[1], view[2], view[3], view[4]);
  std::vector<hlr::Scene> scenes = scenes_of(items, hlr::RenderRequest{});
  py::gil_scoped_release release;
  return Image{std::make_shared<hlr::RasterResult>(hlr::raster(std::move(scenes), o))};
}

std::string explain(const std::string& problem, const std::string& lang, const std::string& format) {
  if (lang != "en" && lang != "ru") throw hlr::python::OptionError("lang must be 'en' or 'ru'");
  if (format != "json" && format != "html" && format != "md") throw hlr::python::OptionError("format must be 'md', 'html' or 'json'");
  hlr::SolutionJson s = hlr::explain(hlr::load_problem(problem));
  const hlr::Lang l = lang == "ru" ? hlr::Lang::Ru : hlr::Lang::En;
  if (format == "json") return s.dump(1) + "\n";
  return format == "html" ? hlr::explain_html(s, l) : hlr::explain_markdown(s, l);
}

py::dict clip(const std::string& clipper, const py::sequence& segment) {
  if (py::len(segment) != 6) throw hlr::python::OptionError("a segment needs 6 numbers: x1, y1, z1, x2, y2, z2");
  auto n = [&](int i) { return hlr::python::exact_number(segment[i], "segment"); };
  const hlr::Point3 p1(n(0), n(1), n(2)), p2(n(3), n(4), n(5));
  const hlr::ClipperSpec spec = hlr::parse_clipper("clipper", clipper);
  const hlr::CyrusBeckResult r = hlr::cyrus_beck(spec.clipper, p1, p2);
  py::dict d;
  d["status"] = r.status == hlr::CyrusBeckResult::Status::Visible ? "visible" : r.status == hlr::CyrusBeckResult::Status::Point ? "point" : "outside";
  if (r.status != hlr::CyrusBeckResult::Status::Outside) {
    d["t"] = py::make_tuple(fraction(r.t_lower), fraction(r.t_upper));
    d["from"] = point(p1 + r.t_lower * (p2 - p1));
    d["to"] = point(p1 + r.t_upper * (p2 - p1));
  }
  return d;
}

// The package's exceptions: Error (a ValueError) and one class per kind of error.
struct Errors {
  py::handle base, input, number, body, option, output;
};

Errors make_errors(py::module_& m) {
  Errors e;
  auto make = [&](const char* name, py::handle parent, const char* doc) {
    const std::string full = std::string("exact_hlr.") + name;
    py::handle t(PyErr_NewExceptionWithDoc(full.c_str(), doc, parent.ptr(), nullptr));
    m.add_object(name, py::reinterpret_borrow<py::object>(t));
    return t;
  };
  e.base = make("Error", PyExc_ValueError, "Every error of exact_hlr (a ValueError): its message says what is wrong and where.");
  e.input = make("InputError", e.base, "A bad input file or mesh: .file and .line (0: none) say where.");
  e.number = make("NumberError", e.base, "Text that is not an exact finite number: .token is the text.");
  e.body = make("BodyError", e.base, "A body that the render cannot draw as asked (e.g. it contains the eye).");
  e.option = make("OptionError", e.base, "An option's value or a keyword that is refused (the CLI's message for its option).");
  e.output = make("OutputError", e.base, "A file that could not be written.");
  return e;
}

void raise(py::handle type, const std::string& message, const std::vector<std::pair<const char*, py::object>>& attrs = {}) {
  py::object exc = py::reinterpret_borrow<py::object>(type)(message);
  for (const auto& [k, v] : attrs) exc.attr(k) = v;
  PyErr_SetObject(type.ptr(), exc.ptr());
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "exact-hlr's compiled core; use the package exact_hlr";
  m.attr("__version__") = HLR_VERSION;
  static const Errors errors = make_errors(m);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const py::builtin_exception&) {
      throw;
    } catch (const hlr::InputError& e) {
      raise(errors.input, e.what(), {{"file", py::str(e.file())}, {"line", py::int_(e.line())}});
    } catch (const hlr::NumberError& e) {
      raise(errors.number, e.what(), {{"token", py::str(e.token())}});
    } catch (const hlr::RenderBodyError& e) {
      raise(errors.body, e.what());
    } catch (const hlr::OutputError& e) {
      raise(errors.output, e.what());
    } catch (const std::invalid_argument& e) {
      raise(errors.option, e.what());
    } catch (const std::runtime_error& e) {
      raise(errors.base, e.what());
    }
  });
  py::class_<Drawing>(m, "Drawing")
      .def_property_readonly("views", &Drawing::view_names)
      .def("view", &Drawing::view, py::arg("name"))
      .def_property_readonly("is_sheet", &Drawing::is_sheet)
      .def_property_readonly("args", &Drawing::args)
      .def_property_readonly("bodies",
                             [](const Drawing& d) {
                               std::vector<std::string> n;
                               for (const auto& b : d.result().names) n.push_back(b.name);
                               return n;
                             })
      .def_property_readonly("notes", [](const Drawing& d) { return d.result().notes; })
      .def_property_readonly("method", [](const Drawing& d) { return std::string(hlr::to_string(d.result().drawing.stats.method)); })
      .def("piece_count", &Drawing::piece_count)
      .def("piece", &Drawing::piece, py::arg("i"))
      .def_property_readonly("segments", &Drawing::segments)
      .def("arrays", &Drawing::arrays)
      .def_property_readonly("surfaces", &Drawing::surfaces)
      .def_property_readonly("priority", &Drawing::priority)
      .def("strokes", &Drawing::strokes, py::arg("output_args"))
      .def("text", &Drawing::text, py::arg("format"), py::arg("output_args"))
      .def("save", &Drawing::save, py::arg("path"), py::arg("format"), py::arg("output_args"));
  m.def("render", &render, py::arg("items"), py::arg("args"), py::arg("lines"));
  m.def("option_names", &hlr::python::render_option_names, py::arg("output_only"));
  m.def("line_kinds", &hlr::python::line_kind_names);
  py::class_<Image>(m, "Image")
      .def_property_readonly("width", [](const Image& i) { return i.r->width; })
      .def_property_readonly("height", [](const Image& i) { return i.r->height; })
      .def("png", &Image::png)
      .def("faces", &Image::faces)
      .def("centre", &Image::centre, py::arg("i"), py::arg("j"))
      .def("camera", &Image::camera);
  m.def("raster", &raster, py::arg("items"), py::arg("view"), py::arg("algorithm"), py::arg("width"), py::arg("height"), py::arg("shading"),
        py::arg("samples"), py::arg("bounces"), py::arg("threads"));
  m.def("explain", &explain, py::arg("problem"), py::arg("lang"), py::arg("format"));
  m.def("clip", &clip, py::arg("clipper"), py::arg("segment"));
}
