// Warnock's algorithm (course notes sections 29-30), exact: a window is filled at once when it
// is simple, else split into four. Each polygon is, against the window (the rectangle of the
// window's pixel centres), disjoint, surrounding, or contained/intersecting; every type is
// decided exactly (the rectangle's corners against the polygon's sides, interval doubles
// first). A window is simple when no polygon meets it (background), when one polygon
// contained or intersecting is the only one (it is scan-converted centre by centre), or when a
// surrounding polygon is nearer than every other polygon at all four corners with the sign of
// the depth difference fixed over the window (it is linear in the picture point, and in
// perspective the denominators keep their signs); a window of one pixel takes the face seen
// at its centre. The same face at every pixel as the z-buffer.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "algorithms/raster/raster_scene.hpp"

namespace hlr {

/// One window of the subdivision, as the exam page shows it.
struct WarnockWindow {
  int i0, j0, i1, j1;                           // pixels [i0, i1) x [j0, j1)
  int level = 0;                                // 0: a tile of the frame
  std::vector<std::pair<int, bool>> polygons;   // the polygons not disjoint from it; true: surrounding
  enum class Decision { Empty, Surrounded, Single, Pixel, Split } decision = Decision::Split;
  int polygon = -1;                             // Surrounded, Single, Pixel: the polygon (Pixel: -1 background)
};

struct WarnockOptions {
  unsigned threads = 0;  // 0: all cores (tiles of 64 x 64 pixels, each subdivided on its own)
  /// When set: every window in the order visited (the run is then sequential).
  std::vector<WarnockWindow>* trace = nullptr;
};

/// The subdivision's counters (docs: the notes' window types).
struct WarnockStats {
  std::size_t windows = 0;          // windows looked at
  std::size_t empty = 0;            // no polygon: background
  std::size_t surrounded = 0;       // filled by a surrounding polygon in front of all others
  std::size_t single = 0;           // one contained or intersecting polygon, scan-converted
  std::size_t pixels = 0;           // one-pixel windows decided at the centre
};

/// The face seen at every pixel centre of `scene`'s grid.
FaceIdBuffer warnock(const RasterScene& scene, const WarnockOptions& options = {}, WarnockStats* stats = nullptr);

}  // namespace hlr
