// Ray casting for visible surfaces (course notes section 35), exact: one sight ray through
// every pixel centre; the polygons it may meet come from a bounding volume hierarchy over the
// polygons' picture boxes (a sight ray is a point of the picture, so its volumes are the boxes
// of the picture: orthographic rays are parallel and perspective ones pass through the eye),
// and the nearest hit is decided exactly (raster_scene.hpp: inside the closed polygon, exact
// depth of its plane on the ray, the tie rule). The same face at every pixel as the z-buffer.
#pragma once

#include <cstddef>

#include "algorithms/raster/raster_scene.hpp"

namespace hlr {

struct RayCastOptions {
  unsigned threads = 0;  // 0: all cores (rows)
};

struct RayCastStats {
  std::size_t nodes = 0;       // BVH nodes
  std::size_t candidates = 0;  // polygons offered to the exact test, over all rays
};

/// The face seen at every pixel centre of `scene`'s grid.
FaceIdBuffer ray_cast(const RasterScene& scene, const RayCastOptions& options = {}, RayCastStats* stats = nullptr);

}  // namespace hlr
