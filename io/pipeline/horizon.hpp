// `hlr horizon` as a library: a height grid from an expression of x and z (muparser)
// or from a CSV file, exactly; the exact floating horizon (algorithms/horizon/floating_horizon.hpp); its
// visible runs as a line drawing of the triangulated surface, so the 2D stage and every writer
// (SVG, PDF, PNG, DXF, JSON) apply unchanged.
#pragma once

#include <optional>
#include <string>

#include "algorithms/horizon/floating_horizon.hpp"
#include "algorithms/horizon/floating_horizon_classic.hpp"
#include "algorithms/plot/plot.hpp"
#include "io/pipeline/render.hpp"

namespace hlr {

/// How close the notes' view angles are realised (horizon_view_from_angles).
inline constexpr double kHorizonAngleErrorDegrees = 0.001;

/// The notes' view: the surface turned about x (elevation) and then y (azimuth), in degrees;
/// the direction toward the viewer is (cos e sin a, sin e, cos e cos a). Each angle is realised
/// exactly as the rational rotation with the smallest numbers within kHorizonAngleErrorDegrees
/// of it (rotation_from_degrees): small exact numbers, so the horizon stays fast.
Vector3 horizon_view_from_angles(const Rational& elevation_degrees, const Rational& azimuth_degrees);

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
HeightGrid grid_from_expression(const std::string& expression, const SampleRange& x, const SampleRange& z, unsigned threads = 0);

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
/// The horizon's runs and the drawn grid edges with their pieces, in render_horizon()'s order
/// (the z cuts nearest first, then the x cuts or the side edges). model(): render_horizon()'s
/// exact line drawing. plot(): the same drawing's Plot straight from the runs, for the picture
/// formats: the pieces projected as project_drawing() does, their ends keyed as the clean-up
/// keys them (a grid vertex, or a boundary between two pieces of one edge), cleaned by
/// dedup_by_keys() (exact points built only for the pairs its filters cannot separate) and
/// chained by plot_from_clean(): make_plot(model().drawing) piece for piece and point for
/// point, without the exact model; nullopt where the drawing frame would not be the identity
/// (coordinates beyond 2^100 or an extent below 2^-30 of them): then run make_plot() on model().
class HorizonDrawing {
 public:
  /// The sweeps (see render_horizon() for `classic_dx` and `cuts`); `grid` must outlive this.
  /// `threads`: 0 = all cores.
  HorizonDrawing(const HeightGrid& grid, const Camera& camera, double classic_dx = 0, const std::string& cuts = "z",
                 unsigned threads = 0);
  RenderResult model(const std::string& name) const;
  std::optional<Plot> plot(const PlotOptions& options) const;
  double seconds = 0;  // the floating horizon's own time

 private:
  struct EdgePiece {
    const Rational *t0, *t1;  // into the results (or 0 and 1)
    bool visible;
  };
  struct Edge {
    int v0, v1;                   // grid samples j * nx + i
    std::uint32_t first, count;   // its pieces in pieces_
  };
  const HeightGrid& g_;
  Camera camera_;
  double classic_dx_;
  std::string cuts_;
  unsigned threads_;
  HorizonResult h_, hx_;
  std::vector<Edge> edges_;
  std::vector<EdgePiece> pieces_;
};

/// `timings`, when given, gets the seconds of the floating horizon itself.
struct HorizonTimings {
  double horizon = 0;
};
RenderResult render_horizon(const HeightGrid& grid, const Camera& camera, const std::string& name, double classic_dx = 0,
                            const std::string& cuts = "z", HorizonTimings* timings = nullptr);

}  // namespace hlr
