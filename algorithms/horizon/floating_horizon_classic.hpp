// The classic floating horizon of the course notes (section 24), for comparison with the
// exact one: the upper and lower horizons are arrays over picture columns dx apart;
// each cut is sampled at the columns (linear interpolation between its samples), a column is
// visible when the cut is above the upper or below the lower horizon there, and between two
// columns whose visibility differs the notes' crossing formula (intersection of the cut's and
// the horizon's chords) ends the run. Only the cuts update the horizons. Approximate by design,
// in doubles: a peak of a cut between two columns is not in the arrays, so a cut behind it can
// be shown where it is hidden (the notes' fault, kept here on purpose); its error is up to one
// column and the height the arrays miss between columns.
#pragma once

#include "algorithms/horizon/floating_horizon.hpp"

namespace hlr {

/// Visible runs as the classic method decides them, on the same cuts as floating_horizon()
/// (t ranges on the cut segments; the drawn lines are the cuts themselves). `dx`: the column
/// width in the picture's x, in units of the drawing (the x range of the picture / dx columns).
HorizonResult floating_horizon_classic(const HeightGrid& grid, const Camera& camera, double dx);

}  // namespace hlr
