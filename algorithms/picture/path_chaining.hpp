// Chaining the picture's edges into strokes (vpype's linemerge, decided on exact
// points): edges that meet end to end at the same point of the picture (line_dedup.hpp
// identifies the points exactly) become one polyline. The fewest strokes that draw a graph's
// edges once each are max(1, odd-degree vertices / 2) per connected component (Euler); this
// reaches that bound: the odd vertices are paired by extra edges, an Euler circuit is walked
// (Hierholzer) and cut at the extra edges.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hlr {

/// A stroke: point indices in drawing order (edges between consecutive ones); `closed` when
/// it returns to its first point (which is then not repeated).
struct Chain {
  std::vector<std::uint32_t> points;
  std::vector<std::uint32_t> edges;  // the input edge of each step, in order
  bool closed = false;
};

/// Chains `edges` (pairs of point indices below `points`; p != q) into the fewest strokes.
/// Deterministic: the same input gives the same strokes. `minimum`, when given, receives
/// minimum_chain_count() of the same graph (worked out from the same components).
std::vector<Chain> chain_edges(std::size_t points, const std::vector<std::array<std::uint32_t, 2>>& edges,
                               std::size_t* minimum = nullptr);

/// The lower bound the chaining reaches: the sum over connected components of
/// max(1, odd-degree vertices / 2).
std::size_t minimum_chain_count(std::size_t points, const std::vector<std::array<std::uint32_t, 2>>& edges);

}  // namespace hlr
