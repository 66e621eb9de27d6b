// Pen order for plotters (vpype's linesort): the order and direction in which the
// strokes are drawn, to cut the pen-up travel between them. Greedy nearest neighbour from the
// pen's home (each stroke may be drawn either way; a closed stroke starts at its nearest
// point), then 2-opt moves (reverse a run of strokes) over near neighbours until none helps
// (each stroke end's nearest ends found once; a queue of places whose pen-up edges changed,
// then whole passes until one finds nothing).
// Drawing coordinates only: the order never changes what is drawn.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hlr {

using Point2 = std::array<double, 2>;

/// A stroke as the ordering sees it: its points (closed: back to the first).
struct Stroke {
  std::vector<Point2> points;
  bool closed = false;
};

struct PenOrderOptions {
  bool two_opt = true;
  std::size_t neighbours = 8;  // 2-opt candidates per stroke end
  int max_passes = 50;         // bound on the 2-opt's work: about this many looks at every place
  unsigned threads = 0;        // neighbour lists on this many cores (0: all); the order does not depend on it
};

struct PenOrder {
  std::vector<std::uint32_t> order;  // stroke indices in drawing order
  std::vector<char> reversed;        // per position in `order`: drawn from its last point
  std::vector<std::uint32_t> start;  // per position: closed strokes start at this point index
  double pen_up = 0;                 // travel from home through all strokes (not back home)
  double pen_up_greedy = 0;          // the same after the greedy pass alone
};

/// Orders `strokes` starting from `home`.
PenOrder order_strokes(const std::vector<Stroke>& strokes, Point2 home, const PenOrderOptions& options = {});

/// Pen-up travel of strokes drawn in their given order and direction, from `home`.
double pen_up_length(const std::vector<Stroke>& strokes, Point2 home);

}  // namespace hlr
