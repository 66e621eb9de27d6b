// SVG writer: the 2D stage's polylines (drawing_2d.hpp) as SVG, visible lines solid, hidden
// lines optionally dashed, groups per visibility, line kind and body, viewBox fitted with a
// margin, size in millimetres, fixed number formatting (deterministic, diffable).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "algorithms/picture/drawing_2d.hpp"

namespace hlr {

/// A body's name and source file, as the writers label it.
struct DrawingBody {
  DrawingBody() = default;
  DrawingBody(std::string n, std::string s) : name(std::move(n)), source(std::move(s)) {}
  std::string name, source;
  /// After a repair (mesh_repair.hpp): per face drawn, its number in the input; the input's
  /// numbers of the faces removed and of those changed. Empty: the faces are the input's.
  std::vector<int> input_face, removed_faces, repaired_faces;
  /// After a section: how many numbers input_face uses (the input's faces, then one per cap:
  /// the cap on plane k is number input faces + k). 0: no section.
  std::size_t numbered = 0;
  /// The input's number of drawn face f: what every output calls it.
  int output_face(int f) const { return input_face.empty() ? f : input_face[static_cast<std::size_t>(f)]; }
  /// How many faces the input body had (with a section: and its caps).
  std::size_t input_faces(std::size_t drawn) const { return numbered ? numbered : drawn + removed_faces.size(); }
};

/// A number as the SVG writers print it: three decimals, fixed (deterministic, diffable).
std::string svg_number(double v);
/// Text for SVG/XML: & < > " escaped.
std::string svg_escape(const std::string& s);

struct SvgOptions {
  bool hidden_dashed = false;
  double width_mm = 150;
  double stroke_mm = 0.35;
  bool vertex_labels = false;  // number every vertex (the exam page's drawing)
  int label_base = 0;          // 1: number from 1 as the notes do
};

std::string to_svg(const std::vector<DrawingBody>& bodies, const Drawing2D& drawing, const SvgOptions& options);

/// Projects (project_drawing, hidden pieces only when dashed) and formats.
std::string to_svg(const std::vector<DrawingBody>& bodies, const LineDrawing& drawing, const Camera& camera,
                   const SvgOptions& options);

}  // namespace hlr
