// Tone hatching in the render pipeline (docs/design.md, "Tone hatching"): the visible regions
// of a surfaces render (with shadows: each face's lit and shadowed regions) hatched by their
// shade on the page's scale, as lines of the kinds Tone1..Tone8 (algorithms/hatching/
// tone_hatch.hpp). The regions are the exact visible polygons, so no hatch line crosses a
// visible line or runs under an occluder; every line is exact.
#pragma once

#include <optional>

#include "algorithms/hatching/tone_hatch.hpp"
#include "algorithms/plot/plot.hpp"
#include "io/pipeline/render.hpp"

namespace hlr {

struct ToneHatchOptions {
  ToneOptions tone;
  /// The lines' angle on the page in degrees: the hatch planes are parallel to the view axis
  /// and at right angles to that page direction (in a perspective, at the view's centre: the
  /// lines are parallel in space, not on the page).
  double angle = 45;
  /// Contour hatching: the hatch planes are level (at right angles to the camera's up axis), so
  /// each face's lines are its contour lines, their direction chosen by its normal; level faces
  /// (within 6 degrees) take `angle`'s planes. Seen from above, the height interval is the
  /// spacing at the drawing's scale.
  bool contour = false;
  unsigned threads = 0;
};

/// One hatch piece: exact picture points (picture_plane.hpp) of its ends, which lie on the
/// border of a visible region of face `face` of body `body`; `kind` its tone level's line kind.
struct TonePiece {
  int body = -1, face = -1;
  LineKind kind = LineKind::Tone1;
  std::array<Exact2, 2> ends;
};

/// The hatching of every visible region of `r` (made with surfaces, per face:
/// RenderOptions::surface_faces) at `mm_per_unit` page mm per drawing unit. Refused
/// (std::invalid_argument) for a render without them.
std::vector<TonePiece> tone_hatching(const RenderResult& r, double mm_per_unit, const ToneHatchOptions& options);

/// The point of face `face` of body `body` that picture point `q` shows, exactly.
Point3 tone_point(const RenderResult& r, const TonePiece& piece, const Exact2& q);

/// The hatching's strokes in the drawing coordinates of `r`'s drawing (its frame): the pieces
/// joined where their ends are the same exact picture point (a line's pieces on the faces it
/// crosses), chained into strokes. No clean-up is needed: every piece lies inside one visible
/// region, regions do not overlap, and no piece runs along a region's border, so no two overlap.
Plot tone_plot(const std::vector<TonePiece>& hatch, const RenderResult& r, const PlotOptions& options);

/// Every hatched region's level (for tests and statistics): per region, in the order hatched.
struct ToneRegion {
  int body = -1, face = -1;
  const VisiblePolygon* polygon = nullptr;
  ToneLevel level;
};
std::vector<ToneRegion> tone_regions(const RenderResult& r, const ToneOptions& tone);

}  // namespace hlr
