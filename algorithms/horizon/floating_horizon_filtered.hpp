// The exact floating horizon on certified doubles (course notes section 24): the same
// sweep as floating_horizon_exact() (floating_horizon.hpp), decision for decision, so the same
// result, but every decision (the order of two abscissas, which of two lines is higher at an
// abscissa, the turn of three points, whether two lines are one) is the sign of an exact
// number found in three steps: (1) the symbols: a line through the sample it is evaluated at,
// the crossing of the two lines compared, two samples of one column or one cut; (2) a double
// filter with a proven error bound (docs/design.md, "The floating horizon on certified
// doubles"); (3) rationals, computed from the grid when the first two cannot tell. The
// crossings are kept as pairs of lines, so rationals are built only for the parameters of the
// visible runs that end inside a segment.
#pragma once

#include <cstdint>

#include "algorithms/horizon/floating_horizon.hpp"

namespace hlr {

/// How the decisions were taken (for the tests and the benchmark).
struct HorizonCounters {
  std::uint64_t exact = 0;  // decided by rationals (the symbols and the filter could not tell)
};

/// floating_horizon_exact()'s result, computed on certified doubles (see above); `threads`: 0 =
/// all cores; `flat` = false leaves the visible pieces in HorizonResult::visible_chunks.
/// Throws std::invalid_argument as floating_horizon_exact() does.
HorizonResult floating_horizon_filtered(const HeightGrid& grid, const Camera& camera, unsigned threads = 0,
                                        HorizonCounters* counters = nullptr, bool flat = true);

}  // namespace hlr
