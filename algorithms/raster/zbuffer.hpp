// The z-buffer (course notes section 32), exact: every polygon is scan-converted into the
// frame, and at each pixel centre it covers it replaces the polygon kept there when it is nearer
// there. The notes keep a rounded depth per pixel; here the buffer keeps the polygon, whose
// depth at the centre is an exact number, so the comparison is exact (interval doubles first,
// raster_scene.hpp) and the result is the same face at every pixel as every other algorithm.
#pragma once

#include "algorithms/raster/raster_scene.hpp"

namespace hlr {

struct ZBufferOptions {
  unsigned threads = 0;  // 0: all cores (horizontal bands of the frame)
};

/// The face seen at every pixel centre of `scene`'s grid.
FaceIdBuffer zbuffer(const RasterScene& scene, const ZBufferOptions& options = {});

/// Polygon indices (into scene.polygons) per pixel to global face numbers.
FaceIdBuffer face_ids(const RasterScene& scene, const std::vector<int>& polygon_at);

}  // namespace hlr
