// The Python package's inputs (see core_inputs.hpp).
#include "core_inputs.hpp"

#include <pybind11/stl.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstring>

namespace py = pybind11;

namespace hlr::python {
namespace {

Rational exact_int(const py::handle& h) {
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(h.ptr(), &overflow);
  if (!overflow) {
    if (v == -1 && PyErr_Occurred()) throw py::error_already_set();
    mpz_class z;
    mpz_set_si(z.get_mpz_t(), static_cast<long>(v));
    return Rational(z);
  }
  return Rational(mpz_class(py::str(h).cast<std::string>(), 10));
}

// A numpy array (or any buffer) of numbers, row by row: its values as exact rationals.
// Returns false when `h` is not a 2D buffer of a plain number type.
template <class Out>
bool read_buffer(const py::handle& h, std::size_t columns, const std::string& what, std::vector<Out>& out,
                 Out (*convert)(double, long long, bool, std::size_t)) {
  if (!PyObject_CheckBuffer(h.ptr())) return false;
  py::buffer_info info = py::reinterpret_borrow<py::buffer>(h).request();
  if (info.ndim != 2) return false;
  const std::string f = info.format;
  const char c = f.empty() ? '?' : f.back();
  const bool is_float = c == 'd' || c == 'f', is_int = std::strchr("bBhHiIlLqQ", c) != nullptr && c != '\0';
  if (!is_float && !is_int) return false;
  if (columns && static_cast<std::size_t>(info.shape[1]) != columns)
    throw OptionError(what + ": each row needs " + std::to_string(columns) + " numbers, the array has " + std::to_string(info.shape[1]));
  const auto rows = static_cast<std::size_t>(info.shape[0]), cols = static_cast<std::size_t>(info.shape[1]);
  out.reserve(rows * cols);
  const auto* base = static_cast<const char*>(info.ptr);
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < cols; ++j) {
      const char* p = base + i * info.strides[0] + j * info.strides[1];
      double d = 0;
      long long n = 0;
      switch (c) {
        case 'd':
          std::memcpy(&d, p, sizeof d);
          break;
        case 'f': {
          float x;
          std::memcpy(&x, p, sizeof x);
          d = x;
          break;
        }
        case 'b':
          n = *reinterpret_cast<const std::int8_t*>(p);
          break;
        case 'B':
          n = *reinterpret_cast<const std::uint8_t*>(p);
          break;
        case 'h': {
          std::int16_t x;
          std::memcpy(&x, p, sizeof x);
          n = x;
          break;
        }
        case 'H': {
          std::uint16_t x;
          std::memcpy(&x, p, sizeof x);
          n = x;
          break;
        }
        case 'i': {
          std::int32_t x;
          std::memcpy(&x, p, sizeof x);
          n = x;
          break;
        }
        case 'I': {
          std::uint32_t x;
          std::memcpy(&x, p, sizeof x);
          n = x;
          break;
        }
        default: {
          if (info.itemsize != 8) return false;
          std::int64_t x;
          std::memcpy(&x, p, sizeof x);
          if ((c == 'L' || c == 'Q') && x < 0) throw OptionError(what + ": a number beyond 2^63");
          n = x;
        }
      }
      out.push_back(convert(d, n, is_float, i));
    }
  return true;
}

Rational buffer_number(double d, long long n, bool is_float, std::size_t) {
  if (!is_float) {
    mpz_class z;
    mpz_set_si(z.get_mpz_t(), static_cast<long>(n));
    return Rational(z);
  }
  return rational_from_double(d);
}

int buffer_index(double, long long n, bool is_float, std::size_t) {
  if (is_float) throw OptionError("faces: vertex numbers must be integers (the array holds floats)");
  if (n < 0 || n > INT_MAX) throw OptionError("faces: vertex number " + std::to_string(n) + " is not a vertex");
  return static_cast<int>(n);
}

std::vector<Point3> mesh_vertices(const py::handle& v) {
  std::vector<Rational> c;
  if (!read_buffer<Rational>(v, 3, "vertices", c, buffer_number)) {
    for (const py::handle& row : py::reinterpret_borrow<py::iterable>(v)) {
      const std::size_t k = c.size() / 3;
      const py::sequence s = py::reinterpret_borrow<py::sequence>(row);
      if (py::len(s) != 3) throw OptionError("vertices: vertex " + std::to_string(k) + " needs 3 numbers, it has " + std::to_string(py::len(s)));
      for (int j = 0; j < 3; ++j) c.push_back(exact_number(s[j], "vertex " + std::to_string(k)));
    }
  }
  std::vector<Point3> out(c.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = Point3(c[3 * i], c[3 * i + 1], c[3 * i + 2]);
  return out;
}

std::vector<Face> mesh_faces(const py::handle& f) {
  std::vector<Face> out;
  std::vector<int> flat;
  if (PyObject_CheckBuffer(f.ptr())) {
    py::buffer_info info = py::reinterpret_borrow<py::buffer>(f).request();
    if (info.ndim == 2 && read_buffer<int>(f, 0, "faces", flat, buffer_index)) {
      const auto cols = static_cast<std::size_t>(info.shape[1]);
      for (std::size_t i = 0; cols && i < flat.size(); i += cols) out.emplace_back(flat.begin() + i, flat.begin() + i + cols);
      return out;
    }
  }
  for (const py::handle& row : py::reinterpret_borrow<py::iterable>(f)) {
    Face face;
    for (const py::handle& x : py::reinterpret_borrow<py::iterable>(row)) {
      if (!PyIndex_Check(x.ptr()) || PyBool_Check(x.ptr()))
        throw OptionError("faces: face " + std::to_string(out.size()) + " holds '" + py::str(x).cast<std::string>() + "', not a vertex number");
      const long long n = py::reinterpret_steal<py::object>(PyNumber_Index(x.ptr())).cast<long long>();
      if (n < 0 || n > INT_MAX) throw OptionError("faces: face " + std::to_string(out.size()) + " names vertex " + std::to_string(n));
      face.push_back(static_cast<int>(n));
    }
    out.push_back(std::move(face));
  }
  return out;
}

}  // namespace

Rational exact_number(const py::handle& h, const std::string& what) {
  PyObject* o = h.ptr();
  try {
    if (PyBool_Check(o)) throw OptionError(what + ": True/False is not a coordinate");
    if (PyFloat_Check(o)) return rational_from_double(PyFloat_AS_DOUBLE(o));
    if (PyLong_Check(o)) return exact_int(h);
    if (PyUnicode_Check(o)) return parse_rational(h.cast<std::string>());
    if (py::hasattr(h, "numerator") && py::hasattr(h, "denominator"))  // Fraction, numpy integers
      return exact_int(h.attr("numerator")) / exact_int(h.attr("denominator"));
    if (py::hasattr(h, "as_integer_ratio")) {  // Decimal, numpy floats
      const py::tuple r = h.attr("as_integer_ratio")();
      return exact_int(r[0]) / exact_int(r[1]);
    }
    if (PyIndex_Check(o)) return exact_int(py::reinterpret_steal<py::object>(PyNumber_Index(o)));
  } catch (const NumberError& e) {
    throw NumberError(e.token(), what + ": " + e.what());
  }
  throw OptionError(what + ": '" + py::str(h).cast<std::string>() + "' is not a number");
}

std::shared_ptr<cli::RenderArgs> parse_render_args(const std::vector<std::string>& args) {
  CLI::App app{"exact_hlr.render"};
  auto a = std::make_shared<cli::RenderArgs>();
  cli::add_render_options(&app, a);
  std::vector<std::string> argv(args.rbegin(), args.rend());
  argv.push_back("<python>");  // the inputs are the Python call's own
  try {
    app.parse(argv);
  } catch (const CLI::ParseError& e) {
    throw OptionError(e.what());
  }
  a->inputs.clear();
  return a;
}

std::vector<std::pair<std::string, std::string>> render_option_names(bool output_only) {
  CLI::App app{"exact_hlr.render"};
  auto a = std::make_shared<cli::RenderArgs>();
  CLI::App o{"output"};
  OutputOptions opts;
  cli::OutputFlags flags;
  if (output_only) cli::add_output_options(&o, opts, flags, true);  // the options add_output_options adds
  else cli::add_render_options(&app, a);
  std::vector<std::pair<std::string, std::string>> out;
  for (const CLI::Option* opt : (output_only ? o : app).get_options()) {
    const std::string kind = opt->get_expected_max() == 0 ? "flag" : opt->get_expected_max() > 1 ? "list" : "value";
    for (const std::string& n : opt->get_lnames()) out.emplace_back(n, kind);
  }
  return out;
}

Scene input_scene(const py::tuple& item, const RenderRequest& request) {
  const std::string kind = item[0].cast<std::string>();
  if (kind == "file") {
    const std::string path = item[1].cast<std::string>();
    py::gil_scoped_release release;
    return load_request_input(request, path);
  }
  if (kind == "scene") {
    const std::string text = item[1].cast<std::string>(), name = item[2].cast<std::string>();
    py::gil_scoped_release release;
    return load_scene_text(text, name);
  }
  if (kind != "mesh") throw OptionError("unknown input kind '" + kind + "'");
  const std::string name = item[3].cast<std::string>();
  MeshData data;
  data.vertices = mesh_vertices(item[1]);
  data.faces = mesh_faces(item[2]);
  if (data.vertices.empty()) throw InputError("mesh '" + name + "'", 0, "no vertices");
  if (data.faces.empty()) throw InputError("mesh '" + name + "'", 0, "no faces");
  py::gil_scoped_release release;
  return scene_from_mesh_data(std::move(data), name, "mesh '" + name + "'");
}

}  // namespace hlr::python
