// The exact arrangement of segments in the picture plane (course notes section 31: the
// Weiler–Atherton method works with the polygons of the picture; section 25: object-space
// results drawn in image space). Segments with exact rational ends are split where they meet
// (crossings, an end on another segment, collinear overlaps), the pieces form a planar graph,
// and its faces are traced as cycles of half-edges with the face on the left. A caller labels
// each cycle (visible_surfaces.cpp: the face of the scene seen there); merge_regions() then
// removes every edge with the same label on both sides and returns the regions of equal label
// as polygons with holes. Every decision is exact: doubles only decide when their error bound
// (docs/design.md, "Visible surfaces") proves the sign.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "algorithms/picture/picture_plane.hpp"

namespace hlr {

struct ArrangementOptions {
  unsigned threads = 0;  // 0: all cores
};

/// The planar graph of the split segments. Edge e has half-edges 2e (from -> to) and 2e + 1
/// (to -> from); next[h] is the half-edge after h around the face on h's left.
struct PlanarArrangement {
  std::vector<Exact2> points;                  // input points first, then crossing points
  std::vector<std::array<double, 2>> approx;   // doubles of the points (filters, drawing)
  std::vector<std::uint32_t> origin;           // per half-edge: its start point
  std::vector<std::uint32_t> next;             // per half-edge
  std::vector<std::uint32_t> source;           // per edge: the input segment it is part of
  std::vector<std::uint32_t> cycle;            // per half-edge: its cycle
  std::vector<std::uint32_t> cycle_edge;       // per cycle: one of its half-edges
  std::size_t crossings = 0;                   // proper crossings of input segments
  std::size_t splits = 0;                      // points found inside segments (ends and crossings)
  std::size_t exact_tests = 0;                 // orientation signs the double filter left to rationals
  bool filters = true;                         // the doubles are trustworthy (design.md): filters may decide
  std::uint32_t head(std::uint32_t h) const { return origin[h ^ 1]; }
  std::size_t num_edges() const { return source.size(); }
};

/// Builds the arrangement of `segments` (pairs of indices into `points`; equal points are
/// joined, zero-length segments ignored).
PlanarArrangement build_arrangement(std::vector<Exact2> points, const std::vector<std::array<std::uint32_t, 2>>& segments,
                                    const ArrangementOptions& options = {});

/// A region of equal label: its outer boundary counter-clockwise and its holes clockwise, as
/// half-edges of the arrangement (the region on their left; their origins are the corners);
/// `area2` is twice its exact area (outer minus holes).
struct LabelledRegion {
  int label = -1;
  std::vector<std::uint32_t> outer;
  std::vector<std::vector<std::uint32_t>> holes;
  Rational area2;
};

/// Removes every edge whose two sides carry the same label (`cycle_label` per cycle of `a`),
/// traces the remaining boundaries and nests every hole in the smallest outer boundary of its
/// label that contains it. Regions labelled `background` are not returned. Regions come in
/// order of label, then of their first point. `exact_area` off: area2 is left 0.
std::vector<LabelledRegion> merge_regions(const PlanarArrangement& a, const std::vector<int>& cycle_label, int background,
                                          bool exact_area = true);

}  // namespace hlr
