// The Python package's drawing (see core_drawing.hpp).
#include "core_drawing.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdio>

#include "algorithms/picture/drawing_2d.hpp"
#include "algorithms/support/parallel.hpp"
#include "core_inputs.hpp"
#include "io/writers/json_writer.hpp"

namespace py = pybind11;

namespace hlr::python {
namespace {

py::object py_int(const mpz_class& z) {
  if (mpz_fits_slong_p(z.get_mpz_t())) return py::reinterpret_steal<py::object>(PyLong_FromLong(mpz_get_si(z.get_mpz_t())));
  const std::string hex = z.get_str(16);
  return py::reinterpret_steal<py::object>(PyLong_FromString(hex.c_str(), nullptr, 16));
}

// A Fraction made from the exact value in lowest terms (GMP keeps it so), without parsing text.
py::object fraction(const Rational& q) {
  static const py::object F = py::module_::import("fractions").attr("Fraction");
  if (q.get_den() == 1) return F(py_int(q.get_num()));
  return F(py_int(q.get_num()), py_int(q.get_den()));
}

py::tuple point(const Point3& p) { return py::make_tuple(fraction(p.x()), fraction(p.y()), fraction(p.z())); }

std::string shade(const RenderResult& r, int body, int face) {
  auto c = rgb8(r.face_colours[body][face]);
  char hex[8];
  std::snprintf(hex, sizeof hex, "#%02x%02x%02x", c[0], c[1], c[2]);
  return hex;
}

// The output options of `args` (the render's own, then the caller's).
std::shared_ptr<cli::RenderArgs> output_request(const std::vector<std::string>& args) {
  auto a = parse_render_args(args);
  check_output_options(*a);
  return a;
}

}  // namespace

std::vector<std::string> line_kind_names() {
  std::vector<std::string> out;
  for (int k = 0; k <= static_cast<int>(LineKind::Tangent); ++k) out.emplace_back(to_string(static_cast<LineKind>(k)));
  return out;
}

const RenderResult& Drawing::result() const {
  if (is_sheet())
    throw OptionError("a sheet of several views (" + std::to_string(all_->views.results.size()) +
                      ") has no one drawing: take one of its views, drawing.views['" + all_->views.names[0] + "']");
  return all_->views.results[view_ < 0 ? 0 : static_cast<std::size_t>(view_)];
}

Drawing Drawing::view(const std::string& name) const {
  const auto& names = all_->views.names;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return Drawing(all_, static_cast<int>(i));
  throw py::key_error("no view '" + name + "' in this drawing");
}

void Drawing::make_index() {
  if (!index_.empty() || pieces_.size()) return;
  const auto& segs = result().drawing.segments;
  for (std::size_t s = 0; s < segs.size(); ++s)
    for (std::size_t p = 0; p < segs[s].pieces.size(); ++p) index_.emplace_back(static_cast<int>(s), static_cast<int>(p));
  pieces_.resize(index_.size());
}

std::size_t Drawing::piece_count() const {
  std::size_t n = 0;
  for (const Segment& s : result().drawing.segments) n += s.pieces.size();
  return n;
}

py::dict Drawing::piece(long i) {
  make_index();
  const long n = static_cast<long>(index_.size());
  if (i < 0) i += n;
  if (i < 0 || i >= n) throw py::index_error("piece " + std::to_string(i) + " of " + std::to_string(n));
  py::object& cached = pieces_[static_cast<std::size_t>(i)];
  if (cached) return cached;
  const Segment& s = result().drawing.segments[static_cast<std::size_t>(index_[i].first)];
  const Piece& p = s.pieces[static_cast<std::size_t>(index_[i].second)];
  py::dict d;
  d["kind"] = to_string(s.line);
  if (s.kind == Segment::Kind::Edge) {
    d["body"] = s.body;
    d["edge"] = py::make_tuple(s.v0, s.v1);
  } else {
    d["bodies"] = py::make_tuple(s.body, s.body2);
  }
  d["visible"] = p.visible;
  d["from"] = end_point(s, p.t0);
  d["to"] = end_point(s, p.t1);
  d["t"] = py::make_tuple(fraction(p.t0), fraction(p.t1));
  d["self_hidden"] = s.self_hidden;
  d["through"] = p.through;
  d["behind_eye"] = p.behind_eye;
  d["clipped"] = p.clipped;
  cached = d;
  return d;
}

// A piece's end: a segment's own end (a mesh vertex, shared by the pieces of every edge at it)
// made into Fractions once.
py::tuple Drawing::end_point(const Segment& s, const Rational& t) {
  if (t != 0 && t != 1) return point(s.at(t));
  const Point3& p = t == 0 ? s.from() : s.to();
  auto [it, added] = points_.try_emplace(&p);
  if (added) it->second = point(p);
  return it->second;
}

py::list Drawing::segments() {
  if (segments_) return segments_;
  make_index();
  py::list out(index_.size());
  for (std::size_t i = 0; i < index_.size(); ++i) out[i] = piece(static_cast<long>(i));
  segments_ = out;
  return out;
}

py::dict Drawing::arrays() {
  if (arrays_) return arrays_;
  const RenderResult& r = result();
  const auto& segs = r.drawing.segments;
  std::vector<std::size_t> first(segs.size() + 1, 0);
  for (std::size_t s = 0; s < segs.size(); ++s) first[s + 1] = first[s] + segs[s].pieces.size();
  const auto n = static_cast<py::ssize_t>(first.back());
  py::array_t<double> start({n, py::ssize_t(2)}), end({n, py::ssize_t(2)}), start3({n, py::ssize_t(3)}), end3({n, py::ssize_t(3)});
  py::array_t<double> t({n, py::ssize_t(2)});
  py::array_t<std::int32_t> body(n), body2(n);
  py::array_t<std::int64_t> edge({n, py::ssize_t(2)}), segment(n);
  py::array_t<std::uint8_t> kind(n);
  py::array_t<bool> visible(n), self_hidden(n), through(n), behind_eye(n), clipped(n);
  double *ps = start.mutable_data(), *pe = end.mutable_data(), *ps3 = start3.mutable_data(), *pe3 = end3.mutable_data(), *pt = t.mutable_data();
  std::int32_t *pb = body.mutable_data(), *pb2 = body2.mutable_data();
  std::int64_t *pedge = edge.mutable_data(), *pseg = segment.mutable_data();
  std::uint8_t* pk = kind.mutable_data();
  bool *pv = visible.mutable_data(), *psh = self_hidden.mutable_data(), *pth = through.mutable_data(), *pbe = behind_eye.mutable_data(),
       *pc = clipped.mutable_data();
  {
    py::gil_scoped_release release;
    const Projector proj = drawing_projector(r.drawing, r.camera);
    // Drawing doubles: the ends' doubles (in the drawing's frame for the picture) interpolated
    // at each piece's t; the exact values are the Fractions.
    ParallelLoop().for_each(segs.size(), 1024, [&](std::size_t s) {
      const Segment& g = segs[s];
      const auto a = proj.frame().to_frame(g.from()), b = proj.frame().to_frame(g.to());
      std::array<double, 3> wa, wb;
      for (int k = 0; k < 3; ++k) wa[k] = to_double(g.from()[k]), wb[k] = to_double(g.to()[k]);
      for (std::size_t j = 0; j < g.pieces.size(); ++j) {
        const std::size_t i = first[s] + j;
        const Piece& p = g.pieces[j];
        const double t0 = to_double(p.t0), t1 = to_double(p.t1);
        auto at = [](const std::array<double, 3>& u, const std::array<double, 3>& v, double x) {
          return std::array<double, 3>{u[0] + x * (v[0] - u[0]), u[1] + x * (v[1] - u[1]), u[2] + x * (v[2] - u[2])};
        };
        const auto q0 = proj.project(at(a, b, t0)[0], at(a, b, t0)[1], at(a, b, t0)[2]);
        const auto q1 = proj.project(at(a, b, t1)[0], at(a, b, t1)[1], at(a, b, t1)[2]);
        ps[2 * i] = q0[0], ps[2 * i + 1] = q0[1], pe[2 * i] = q1[0], pe[2 * i + 1] = q1[1];
        const auto w0 = at(wa, wb, t0), w1 = at(wa, wb, t1);
        for (int k = 0; k < 3; ++k) ps3[3 * i + k] = w0[k], pe3[3 * i + k] = w1[k];
        pt[2 * i] = t0, pt[2 * i + 1] = t1;
        const bool is_edge = g.kind == Segment::Kind::Edge;
        pb[i] = g.body, pb2[i] = is_edge ? -1 : g.body2;
        pedge[2 * i] = is_edge ? g.v0 : -1, pedge[2 * i + 1] = is_edge ? g.v1 : -1;
        pseg[i] = static_cast<std::int64_t>(s);
        pk[i] = static_cast<std::uint8_t>(g.line);
        pv[i] = p.visible, psh[i] = g.self_hidden, pth[i] = p.through, pbe[i] = p.behind_eye, pc[i] = p.clipped;
      }
    });
  }
  py::dict d;
  d["start"] = start, d["end"] = end, d["start3"] = start3, d["end3"] = end3, d["t"] = t;
  d["body"] = body, d["body2"] = body2, d["edge"] = edge, d["segment"] = segment, d["kind"] = kind;
  d["visible"] = visible, d["self_hidden"] = self_hidden, d["through"] = through, d["behind_eye"] = behind_eye, d["clipped"] = clipped;
  arrays_ = d;
  return d;
}

py::object Drawing::surfaces() const {
  const RenderResult& r = result();
  if (!r.surfaces) return py::none();
  py::list out;
  for (const VisibleFace& f : r.surfaces->faces) {
    py::dict d;
    d["body"] = f.body;
    d["face"] = r.names[f.body].output_face(f.face);
    d["side"] = f.front ? "front" : "back";
    d["shade"] = shade(r, f.body, f.face);
    py::list polys;
    Rational total = 0;
    for (const VisiblePolygon& p : f.polygons) {
      py::dict pd;
      py::list outer, holes;
      for (const Point3& q : p.outer) outer.append(point(q));
      for (const auto& h : p.holes) {
        py::list ring;
        for (const Point3& q : h) ring.append(point(q));
        holes.append(ring);
      }
      pd["outer"] = outer, pd["holes"] = holes, pd["area"] = fraction(p.area2 / 2);
      total += p.area2 / 2;
      polys.append(pd);
    }
    d["area"] = fraction(total);
    d["polygons"] = polys;
    out.append(d);
  }
  return out;
}

py::object Drawing::priority() const {
  const RenderResult& r = result();
  if (!r.priority) return py::none();
  py::list out;
  for (int i : r.priority->order) {
    const PriorityPolygon& p = r.priority->polygons[i];
    py::dict d;
    d["body"] = p.body;
    d["face"] = r.names[p.body].output_face(p.face);
    d["piece"] = p.piece;
    d["cut"] = i >= static_cast<int>(r.priority->initial);
    d["shade"] = shade(r, p.body, p.face);
    py::list corners;
    for (const Point3& q : p.corners) corners.append(point(q));
    d["corners"] = corners;
    out.append(d);
  }
  return out;
}

py::dict Drawing::strokes(const std::vector<std::string>& output_args) const {
  const auto a = output_request(output_args);
  const RenderResult& r = result();
  PlotOptions po;
  po.hidden = a->hidden != "none";
  Plot p = make_plot(r.drawing, r.camera, po);
  add_surface_fills(p, r);
  if (p.fills.empty()) order_plot(p, {p.bounds[0], p.bounds[3]});
  py::dict out;
  for (const PlotLayer& l : p.layers) {
    py::list ls;
    for (const Stroke& st : l.strokes) {
      const std::size_t m = st.points.size() + (st.closed && !st.points.empty() ? 1 : 0);
      py::array_t<double> pts({static_cast<py::ssize_t>(m), py::ssize_t(2)});
      double* q = pts.mutable_data();
      for (std::size_t k = 0; k < m; ++k) q[2 * k] = st.points[k % st.points.size()][0], q[2 * k + 1] = st.points[k % st.points.size()][1];
      ls.append(pts);
    }
    out[py::str(l.name())] = ls;
  }
  return out;
}

PartText Drawing::part_text(const std::string& format, const std::vector<std::string>& output_args) const {
  if (format != "svg" && format != "pdf" && format != "png" && format != "dxf" && format != "json")
    throw OptionError("format must be svg, pdf, png, dxf or json, not '" + format + "'");
  const auto a = output_request(output_args);
  if (is_sheet() && format == "json")
    throw OptionError("a sheet of views is written as svg, pdf, png or dxf (JSON is one view: drawing.views['" + all_->views.names[0] + "'].json())");
  if (view_ < 0) return request_text(all_->views, *a, format, "python");  // the CLI's text of the call
  return drawing_text(result(), *a, format, "python");
}

py::bytes Drawing::text(const std::string& format, const std::vector<std::string>& output_args) const {
  const PartText t = part_text(format, output_args);
  std::string s;
  {
    py::gil_scoped_release release;
    s = t.str();
  }
  return py::bytes(s);
}

void Drawing::save(const std::string& path, const std::string& format, const std::vector<std::string>& output_args) const {
  const PartText t = part_text(format, output_args);
  py::gil_scoped_release release;
  write_file_atomically(path, t);
}

}  // namespace hlr::python
