// `hlr horizon` as a library (issue 18): a height grid from an expression of x and z (muparser)
// or from a CSV file, exactly; the exact floating horizon (algorithms/floating_horizon.hpp); its
// visible runs as a line drawing of the triangulated surface, so the 2D stage and every writer
// (SVG, PDF, PNG, DXF, JSON) apply unchanged.
#pragma once

#include <string>

#include "algorithms/floating_horizon.hpp"
#include "algorithms/floating_horizon_classic.hpp"
#include "io/render.hpp"

namespace hlr {

/// `count` samples from `from` to `to` (both included), evenly spaced, exact.
struct SampleRange {
  Rational from = -1, to = 1;
  std::size_t count = 41;
};

/// "A:B" or "A:B:N" (N samples, at least 2); A and B exact numbers (1/3, 2.5, -1e-3).
/// Throws std::invalid_argument naming `option`.
SampleRange parse_sample_range(const std::string& option, const std::string& text, std::size_t default_count);

/// y = expression(x, z) at every sample; the double value of the expression is taken exactly as
/// its binary rational. Throws std::invalid_argument for a bad expression or a value that is
/// not finite (naming x and z).
HeightGrid grid_from_expression(const std::string& expression, const SampleRange& x, const SampleRange& z);

/// A CSV of heights, one row per z sample (the first row at z = z.from), one column per x
/// sample, decimals read exactly; the ranges give the coordinates (their counts are taken from
/// the file). Throws InputError (file and line) for bad input.
HeightGrid grid_from_csv(const std::string& path, const SampleRange& x, const SampleRange& z);

/// A heightmap image: PGM (P2 or P5, maxval up to 65535) or PNG (8- or 16-bit grey; colour is
/// refused), one row per z cut (the image's top row at z = z.from), one column per x sample;
/// y = value / maxval * height, exactly. Throws InputError for bad input.
HeightGrid grid_from_image(const std::string& path, const SampleRange& x, const SampleRange& z, const Rational& height);

/// By extension: .csv (grid_from_csv), .pgm or .png (grid_from_image).
HeightGrid grid_from_file(const std::string& path, const SampleRange& x, const SampleRange& z, const Rational& height);

/// The drawing of the surface's cuts with their exact visibility: one body (the triangulated
/// surface, cell (i, j) split along (i, j)-(i+1, j+1)), one segment per cut edge, pieces
/// visible as the floating horizon decides and hidden elsewhere.
/// `classic_dx` > 0: the notes' classic per-column method with that column width instead
/// (floating_horizon_classic.hpp), to show its faults next to the exact one.
/// `cuts`: "z" (the notes' cuts and their side edges), "x" (the other family only) or "both"
/// (a grid). The classic method draws the z cuts only.
/// `timings`, when given, gets the seconds of the floating horizon itself.
struct HorizonTimings {
  double horizon = 0;
};
RenderResult render_horizon(const HeightGrid& grid, const Camera& camera, const std::string& name, double classic_dx = 0,
                            const std::string& cuts = "z", HorizonTimings* timings = nullptr);

}  // namespace hlr
