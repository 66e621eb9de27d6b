// SVG writer: the 2D stage's polylines (drawing_2d.hpp) as SVG, visible lines solid, hidden
// lines optionally dashed, groups per visibility, line kind and body, viewBox fitted with a
// margin, size in millimetres, fixed number formatting (deterministic, diffable).
#pragma once

#include <string>
#include <vector>

#include "algorithms/drawing_2d.hpp"

namespace hlr {

/// A body's name and source file, as the writers label it.
struct DrawingBody {
  std::string name, source;
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
