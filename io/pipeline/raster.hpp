// The raster pipeline (course notes sections 29-38): load -> camera ->
// the exact face seen at every pixel centre by the course's image-space algorithm of choice
// (z-buffer, scan-line, Warnock, ray casting: the same faces, raster_scene.hpp) -> shading in
// doubles after every decision (flat, Gouraud, Phong; sections 36-39) -> antialiasing by
// supersampling (box or tent filter) -> PNG. The face-id buffer and the exact pixel
// grid can be written too, so anyone can check a pixel by exact ray casting.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/raster/raster_scene.hpp"
#include "io/pipeline/render.hpp"

namespace hlr {

enum class RasterAlgorithm { ZBuffer, Scanline, Warnock, RayCast };
enum class RasterShading { Flat, Gouraud, Phong };
enum class RasterFilter { Box, Tent };

/// "zbuffer", "scanline", "warnock", "raytrace".
const char* to_string(RasterAlgorithm a);

struct RasterOptions {
  RasterAlgorithm algorithm = RasterAlgorithm::ZBuffer;
  int width = 512, height = 512;  // height 0: the camera frame's aspect (square without a frame)
  ViewRequest view;
  unsigned threads = 0;  // 0: all cores
  RasterShading shading = RasterShading::Flat;
  /// Gouraud and Phong: a vertex normal of a face averages the normals of the faces around the
  /// vertex within this angle of the face's own (sharp edges stay sharp).
  double smooth_degrees = 40;
  /// Antialiasing: samples x samples exact sample centres per pixel, combined by the filter.
  int samples = 1;
  RasterFilter filter = RasterFilter::Box;
  Rgb background{1, 1, 1};
  /// Whitted ray tracing (notes 43-45, ray_tracing.hpp) from the exact first hit: levels of
  /// reflected and refracted rays, with shadow rays (0: the local shading alone).
  int bounces = 0;
};

struct RasterTimes {
  double load = 0;  // reading the files (raster_files only)
  double setup = 0, scene = 0, visibility = 0, shading = 0;
};

struct RasterResult {
  RenderResult render;   // bodies, names, camera, facing (render.hpp)
  RasterScene scene;     // the exact sample grid and polygons
  FaceIdBuffer ids;      // the face at every sample centre (samples x the image size)
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // the image, 8-bit RGB, rows from the top
  RasterTimes seconds;
};

/// Renders loaded scenes to an image. Throws RenderBodyError, std::invalid_argument.
RasterResult raster(std::vector<Scene> scenes, const RasterOptions& options = {});

/// Loads mesh and scene files, then rasters.
RasterResult raster_files(const std::vector<std::string>& inputs, const RasterOptions& options = {});

/// The image as PNG bytes (8-bit RGB).
std::string png_rgb(int width, int height, const std::vector<std::uint8_t>& rgb);

/// The face-id buffer as a 16-bit grey PNG (value = global face number + 1, 0 = background);
/// throws std::invalid_argument over 65,534 faces (use JSON).
std::string ids_png(const FaceIdBuffer& ids);

/// The legend of the face numbers: per global face number its body (index and name) and face.
std::string ids_legend_json(const RasterResult& r);

/// The face-id buffer as JSON: width, height, the legend and the ids row by row (-1: background).
std::string ids_json(const RasterResult& r);

/// The exact sample grid as JSON: the picture axes, the world point of the grid's top-left
/// corner and the exact steps of one sample to the right and down, so that the centre of sample
/// (i, j) is origin + (i + 1/2)·right + (j + 1/2)·down; the eye (perspective) or the direction
/// toward the viewer (orthographic).
std::string raster_camera_json(const RasterResult& r);

}  // namespace hlr
