// The Python package's drawing (docs/design.md, "The Python package"): the renders of one call
// (one view or a sheet), its options, and what Python reads of it: pieces as numpy arrays made
// in C++ (one array per column, no Python object per piece), exact Fractions per piece on
// request (made once), the visible surfaces and the painter's list, strokes, and the CLI's
// file text in every format.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "io/request/render_request.hpp"

namespace hlr::python {

/// What one render() call made; a Drawing and the Drawings of its views share it.
struct Rendered {
  RenderedViews views;
  std::vector<std::string> args;  ///< the options as "--name=value" arguments
};

class Drawing {
 public:
  Drawing(std::shared_ptr<Rendered> all, int view) : all_(std::move(all)), view_(view) {}

  /// The render of this drawing; a sheet of several views has none (its views have).
  const RenderResult& result() const;
  bool is_sheet() const { return view_ < 0 && all_->views.results.size() > 1; }
  std::vector<std::string> view_names() const { return all_->views.names; }
  Drawing view(const std::string& name) const;
  const std::vector<std::string>& args() const { return all_->args; }

  std::size_t piece_count() const;
  pybind11::dict piece(long i);
  pybind11::list segments();
  pybind11::dict arrays();
  pybind11::object surfaces() const;
  pybind11::object priority() const;
  pybind11::dict strokes(const std::vector<std::string>& output_args) const;
  /// The file's text as `hlr render` writes it with these output options.
  pybind11::bytes text(const std::string& format, const std::vector<std::string>& output_args) const;
  void save(const std::string& path, const std::string& format, const std::vector<std::string>& output_args) const;

 private:
  PartText part_text(const std::string& format, const std::vector<std::string>& output_args) const;
  std::shared_ptr<Rendered> all_;
  int view_;                                // -1: the call's drawing (a sheet or its one view)
  std::vector<std::pair<int, int>> index_;  // piece -> (segment, piece in it), made on first use
  std::vector<pybind11::object> pieces_;    // exact pieces made so far
  pybind11::object segments_, arrays_;
  std::unordered_map<const Point3*, pybind11::tuple> points_;  // ends' Fractions by the exact point
  void make_index();
  pybind11::tuple end_point(const Segment& s, const Rational& t);
};

/// The names of LineKind in order of their numbers (the arrays' "kind" column).
std::vector<std::string> line_kind_names();

}  // namespace hlr::python
