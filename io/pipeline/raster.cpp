// The raster pipeline (course notes 29-38). See raster.hpp.
#include "io/pipeline/raster.hpp"

#include <png.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csetjmp>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "algorithms/raster/ray_casting.hpp"
#include "algorithms/raster/ray_tracing.hpp"
#include "algorithms/raster/scanline.hpp"
#include "algorithms/raster/warnock.hpp"
#include "algorithms/raster/zbuffer.hpp"
#include "algorithms/shading/face_shading.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/support/progress.hpp"
#include "io/models/model_input.hpp"

namespace hlr {

const char* to_string(RasterAlgorithm a) {
  switch (a) {
    case RasterAlgorithm::ZBuffer: return "zbuffer";
    case RasterAlgorithm::Scanline: return "scanline";
    case RasterAlgorithm::Warnock: return "warnock";
    case RasterAlgorithm::RayCast: return "raytrace";
  }
  return "?";
}

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

class Shader {
 public:
  Shader(const RasterResult& r, const RasterOptions& o) : r_(r), o_(o), lift_(r.render.camera), light_(render_lighting(r.render)) {
    std::vector<std::vector<char>> seen_face(r.render.bodies.size());  // the faces some sample sees
    for (std::size_t b = 0; b < seen_face.size(); ++b) seen_face[b].assign(r.render.bodies[b]->body.num_faces(), 0);
    for (int p : r.ids.polygons)
      if (p >= 0) seen_face[r.scene.polygons[p].body][r.scene.polygons[p].face] = 1;
    flat_ = flat_face_colours(r.render, &seen_face);
    for (std::size_t b = 0; b < r.render.bodies.size(); ++b) materials_.push_back(body_material(r.render, b));
    // Ray tracing reads the exact face planes (total internal reflection is decided exactly):
    // computed once here, on all cores. Shading needs none (face_normal).
    if (o.bounces > 0)
      for (const SceneBody* b : r.render.bodies) plane_all_faces(b->body, o.threads);
    // Textured polygons seen: their corners with the texture coordinates of the mesh.
    std::vector<char> seen_poly(r.scene.polygons.size(), 0);
    for (int p : r.ids.polygons)
      if (p >= 0) seen_poly[p] = 1;
    for (std::size_t p = 0; p < r.scene.polygons.size(); ++p) {
      const RasterPolygon& sp = r.scene.polygons[p];
      const SceneBody& body = *r.render.bodies[sp.body];
      if (!seen_poly[p] || !materials_[sp.body].texture || body.face_texcoords.size() <= static_cast<std::size_t>(sp.face) ||
          body.face_texcoords[sp.face].empty())
        continue;
      const Face& face = body.body.faces()[sp.face];
      Mapped mp;
      for (int k = 0; k < sp.count; ++k) {
        mp.at.push_back(d3(r.scene.corner(sp, k)));
        const std::size_t q = std::find(face.begin(), face.end(), r.scene.vert(sp, k)) - face.begin();
        mp.uv.push_back(body.texcoords[body.face_texcoords[sp.face][q]]);
      }
      mapped_.emplace(static_cast<int>(p), std::move(mp));
    }
    if (o.bounces > 0) {
      std::vector<const Polyhedron*> polys;
      std::vector<Material> materials;
      for (std::size_t b = 0; b < r.render.bodies.size(); ++b) {
        polys.push_back(&r.render.bodies[b]->body);
        materials.push_back(body_material(r.render, b));
      }
      WhittedOptions wo;
      wo.depth = o.bounces;
      wo.background = o.background;
      whitted_ = std::make_unique<WhittedScene>(polys, std::move(materials), light_, wo);
      return;
    }
    if (o.shading == RasterShading::Flat) return;
    const double cs = std::cos(o.smooth_degrees * M_PI / 180);
    for (std::size_t b = 0; b < r.render.bodies.size(); ++b) normals_.push_back(body_normals(r.render.bodies[b]->body));
    // Per polygon seen: corners in doubles, their normals toward the viewer, their colours.
    const auto& polys = r.scene.polygons;
    corners_.resize(polys.size());
    std::vector<char> seen(polys.size(), 0);
    for (int p : r.ids.polygons)
      if (p >= 0) seen[p] = 1;
    ParallelLoop(o.threads).for_each(polys.size(), 64, [&](std::size_t p) {
      if (!seen[p]) return;
      const RasterPolygon& sp = polys[p];
      const BodyNormals& n = normals_[sp.body];
      const bool back = r.render.drawing.facing[sp.body][sp.face] < 0;
      Material m = body_material(r.render, sp.body);
      if (m.checker > 0 || m.texture) m.colour = {1, 1, 1};  // Gouraud: the texture modulates the interpolated light
      Corners& c = corners_[p];
      c.n = plane_d(sp.body, sp.face, c.offset);
      c.material = m;
      for (int k = 0; k < sp.count; ++k) {
        Vec3d x = d3(r.scene.corner(sp, k)), vn = vertex_normal(n, sp.face, r.scene.vert(sp, k), cs);
        if (back) vn = {-vn[0], -vn[1], -vn[2]};
        c.at.push_back(x);
        c.normal.push_back(vn);
        c.colour.push_back(shade(m, light_, x, vn, lift_.to_viewer(x)));
      }
    });
  }

  Rgb colour(std::size_t sample, double x, double y) const {
    const int p = r_.ids.polygons[sample];
    if (p < 0) return o_.background;
    const RasterPolygon& sp = r_.scene.polygons[p];
    if (whitted_) return traced(sp, x, y);
    const Material& mat = materials_[sp.body];
    const bool textured = mat.checker > 0 || mat.bump > 0 || mapped_.count(p);
    if (o_.shading == RasterShading::Flat && !textured) return flat_[sp.body][sp.face];
    if (o_.shading == RasterShading::Flat) {  // a textured face: its colour and bumped normal at the point
      double offset = 0;
      const Vec3d n = plane_d(sp.body, sp.face, offset);
      const Vec3d at = lift_.at(x, y, n, offset);
      Material m = mat;
      m.colour = colour_at(p, mat, at, n);
      Vec3d un = unit(n);
      if (r_.render.drawing.facing[sp.body][sp.face] < 0) un = {-un[0], -un[1], -un[2]};
      return shade(m, light_, at, bumped_normal(mat, at, un), lift_.to_viewer(at));
    }
    const Corners& c = corners_[p];
    Vec3d at = lift_.at(x, y, c.n, c.offset);
    double w[3];
    int k = fan_weights(c.at, c.n, at, w);
    const int idx[3] = {0, k, k + 1};
    if (o_.shading == RasterShading::Gouraud) {
      Rgb out{0, 0, 0};
      for (int t = 0; t < 3; ++t)
        for (int ch = 0; ch < 3; ++ch) out[ch] += w[t] * c.colour[idx[t]][ch];
      if (mat.checker > 0) {
        const Rgb t = colour_at(p, mat, at, c.n);
        for (int ch = 0; ch < 3; ++ch) out[ch] *= t[ch];
      }
      for (double& ch : out) ch = std::clamp(ch, 0.0, 1.0);
      return out;
    }
    Vec3d nn{0, 0, 0};
    for (int t = 0; t < 3; ++t)
      for (int ch = 0; ch < 3; ++ch) nn[ch] += w[t] * c.normal[idx[t]][ch];
    Material m = c.material;
    m.colour = colour_at(p, mat, at, c.n);
    return shade(m, light_, at, bumped_normal(mat, at, unit(nn)), lift_.to_viewer(at));
  }

 private:
  // The colour of the material at a point of polygon p: its image texture through the corners'
  // texture coordinates (interpolated over the fan triangles, notes 42's linear map), else its
  // checker or plain colour.
  Rgb colour_at(int p, const Material& mat, const Vec3d& at, const Vec3d& n) const {
    auto it = mapped_.find(p);
    if (it == mapped_.end() || !mat.texture) return surface_colour(mat, at, n);
    const Mapped& mp = it->second;
    double w[3];
    const int k = fan_weights(mp.at, n, at, w);
    const int idx[3] = {0, k, k + 1};
    double u = 0, v = 0;
    for (int t = 0; t < 3; ++t) u += w[t] * mp.uv[idx[t]][0], v += w[t] * mp.uv[idx[t]][1];
    return mat.texture->at(u, v);
  }

  // The face's plane in doubles for shading: its unit normal n (face_normal) and n·X + offset = 0.
  Vec3d plane_d(int b, int f, double& offset) const {
    const Polyhedron& p = r_.render.bodies[b]->body;
    const Vec3d n = face_normal(p, f), x = d3(p.vertices()[p.faces()[f][0]]);
    offset = -dot3(n, x);
    return n;
  }

  // Whitted: the exact first hit in doubles, the ray's direction, and total internal reflection
  // there decided exactly when the material could reflect totally on entering (ior < 1).
  Rgb traced(const RasterPolygon& sp, double x, double y) const {
    const Plane& h = r_.render.bodies[sp.body]->body.planes()[sp.face];
    const Vec3d n{mid(h.approx(0)), mid(h.approx(1)), mid(h.approx(2))};
    const Vec3d at = lift_.at(x, y, n, mid(h.approx(3)));
    const Vec3d dir = lift_.persp ? unit(minus(at, lift_.e)) : Vec3d{-lift_.v[0], -lift_.v[1], -lift_.v[2]};
    const Material m = body_material(r_.render, sp.body);
    bool tir = false;
    if (m.transparency > 0 && m.ior_exact < 1) {
      const Camera& cam = r_.render.camera;
      const Point3 X = PicturePlane(cam).lift(Exact2{Rational(x), Rational(y)}, h);
      std::array<Rational, 3> d;
      for (int k = 0; k < 3; ++k) d[k] = cam.perspective ? X[k] - cam.eye[k] : Rational(-cam.direction[k]);
      tir = exact_total_internal_reflection(d, {h.normal().x(), h.normal().y(), h.normal().z()}, 1 / m.ior_exact);
    }
    return whitted_->shade_first(sp.body, sp.face, at, unit(dir), tir);
  }

  struct Corners {
    std::vector<Vec3d> at, normal;
    std::vector<Rgb> colour;
    Vec3d n{0, 0, 0};  // the face's plane n·X + offset = 0, doubles
    double offset = 0;
    Material material;
  };
  const RasterResult& r_;
  const RasterOptions& o_;
  Lift lift_;
  Lighting light_;
  std::vector<std::vector<Rgb>> flat_;
  std::vector<BodyNormals> normals_;
  std::vector<Corners> corners_;
  std::unique_ptr<WhittedScene> whitted_;
  std::vector<Material> materials_;
  struct Mapped {  // a textured polygon's corners and their texture coordinates
    std::vector<Vec3d> at;
    std::vector<std::array<double, 2>> uv;
  };
  std::map<int, Mapped> mapped_;
};

// The image from the samples: each pixel the filter's weighted mean of its samples (box: its
// own n x n; tent: the 2n x 2n around its centre, weights falling linearly to the edge).
void resolve(const RasterResult& r, const RasterOptions& o, const std::vector<Rgb>& samples, std::vector<std::uint8_t>& rgb) {
  const int n = o.samples, W = r.ids.width, H = r.ids.height;
  rgb.resize(static_cast<std::size_t>(r.width) * r.height * 3);
  auto byte = [](double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  if (n == 1 && o.filter == RasterFilter::Box) {  // one sample per pixel: its colour (the mean of one, exactly)
    ParallelLoop(o.threads).for_each(samples.size(), 16384, [&](std::size_t k) {
      for (int ch = 0; ch < 3; ++ch) rgb[k * 3 + ch] = byte(samples[k][ch]);
    });
    return;
  }
  ParallelLoop(o.threads).for_each(r.height, 1, [&](std::size_t j) {
    for (int i = 0; i < r.width; ++i) {
      Rgb acc{0, 0, 0};
      double wsum = 0;
      const int reach = o.filter == RasterFilter::Tent ? n : 0;
      for (int sj = static_cast<int>(j) * n - reach / 2; sj < (static_cast<int>(j) + 1) * n + (reach + 1) / 2; ++sj)
        for (int si = i * n - reach / 2; si < (i + 1) * n + (reach + 1) / 2; ++si) {
          if (si < 0 || sj < 0 || si >= W || sj >= H) continue;
          double w = 1;
          if (o.filter == RasterFilter::Tent) {  // distance from the pixel's centre in pixels
            double dx = (si + 0.5) / n - (i + 0.5), dy = (sj + 0.5) / n - (static_cast<double>(j) + 0.5);
            w = std::max(0.0, 1 - std::fabs(dx)) * std::max(0.0, 1 - std::fabs(dy));
          }
          const Rgb& c = samples[static_cast<std::size_t>(sj) * W + si];
          for (int ch = 0; ch < 3; ++ch) acc[ch] += w * c[ch];
          wsum += w;
        }
      for (int ch = 0; ch < 3; ++ch)
        rgb[(j * r.width + i) * 3 + ch] = static_cast<std::uint8_t>(std::lround(std::clamp(acc[ch] / wsum, 0.0, 1.0) * 255));
    }
  });
}

}  // namespace

namespace {

// The image height that gives `width` pixels the frame's aspect (at least one pixel).
int frame_height(const Camera& cam, const ViewPyramid& f, int width) {
  const PicturePlane pp(cam);
  // A picture unit is |d|/|r| long along x and |d|/|u| along y (raster_scene.cpp).
  const double rr = to_double(dot(pp.r(), pp.r())), uu = to_double(dot(pp.u(), pp.u()));
  const double aspect = to_double(f.half_y) / to_double(f.half_x) * std::sqrt(rr / uu);
  return std::clamp(static_cast<int>(std::lround(width * aspect)), 1, 65536);
}

}  // namespace

RasterResult raster(std::vector<Scene> scenes, const RasterOptions& o) {
  if (o.samples < 1 || o.samples > 16) throw std::invalid_argument("--samples must be 1 to 16");
  if (static_cast<long long>(o.width) * o.samples > 65536 || static_cast<long long>(o.height) * o.samples > 65536)
    throw std::invalid_argument("--size times --samples must stay within 65536 pixels each way");
  RasterResult r;
  auto t0 = Clock::now();
  progress("facing");
  RenderOptions ro;
  ro.view = o.view;
  ro.lines.edges = EdgeSelection::Feature;
  ro.lines.intersections = false;
  ro.facing_only = true;  // no lines: the facing of every face is all the raster needs
  ro.lines.threads = o.threads;
  ro.through_lines = false;
  ro.cut_at_near = true;  // the eye among the bodies: what lies behind the near plane is cut away
  r.render = render(std::move(scenes), ro);
  if (r.render.eye_cut && o.bounces > 0)
    throw std::invalid_argument("--bounces needs every body in front of the eye (rays would miss what the near plane cuts away)");
  const Camera& cam = r.render.camera;
  std::vector<const Polyhedron*> polys;
  for (const SceneBody* b : r.render.bodies) polys.push_back(&b->body);
  if (cam.perspective)
    for (std::size_t b = 0; b < polys.size(); ++b)
      for (const Point3& v : polys[b]->vertices())
        if (cam.in_front(v) != Sign::Positive)
          throw std::invalid_argument(r.render.names[b].source + ": body '" + r.render.names[b].name +
                                      "' reaches the eye's plane or behind it: hlr raster needs every body in front of the eye");
  r.seconds.setup = since(t0);
  t0 = Clock::now();
  r.width = o.width, r.height = o.height;
  std::optional<RasterGrid> framed;  // a camera's frame is the picture
  if (r.render.pyramid) {
    const ViewPyramid& f = *r.render.pyramid;
    if (r.height == 0) r.height = frame_height(cam, f, r.width);
    framed = frame_grid(cam, f.half_x, f.half_y, r.width * o.samples, r.height * o.samples);
  } else if (r.height == 0) {
    r.height = r.width;
  }
  progress("exact scene: " + std::to_string(polys.size()) + " bodies");
  r.scene = raster_scene(polys, cam, r.render.drawing, r.width * o.samples, r.height * o.samples, o.threads, framed ? &*framed : nullptr);
  r.seconds.scene = since(t0);
  t0 = Clock::now();
  progress(std::string(to_string(o.algorithm)) + ", " + std::to_string(r.width * o.samples) + " x " + std::to_string(r.height * o.samples) +
           " samples");
  switch (o.algorithm) {
    case RasterAlgorithm::ZBuffer: r.ids = zbuffer(r.scene, {o.threads}); break;
    case RasterAlgorithm::Scanline: r.ids = scanline(r.scene, {o.threads}); break;
    case RasterAlgorithm::Warnock: r.ids = warnock(r.scene, {o.threads}); break;
    case RasterAlgorithm::RayCast: r.ids = ray_cast(r.scene, {o.threads}); break;
  }
  r.seconds.visibility = since(t0);
  t0 = Clock::now();
  progress(o.bounces > 0 ? "Whitted ray tracing" : "shading");
  Shader shader(r, o);
  std::vector<Rgb> samples(r.ids.ids.size());
  const RasterGrid& g = r.scene.grid;
  ParallelLoop(o.threads).for_each(g.height, 4, [&](std::size_t j) {
    for (int i = 0; i < g.width; ++i) {
      const std::size_t k = j * g.width + i;
      samples[k] = shader.colour(k, g.cx(i), g.cy(static_cast<int>(j)));
    }
  });
  resolve(r, o, samples, r.rgb);
  r.seconds.shading = since(t0);
  return r;
}

RasterResult raster_files(const std::vector<std::string>& inputs, const RasterOptions& o) {
  const auto t0 = Clock::now();
  std::vector<Scene> scenes;
  for (const auto& in : inputs) scenes.push_back(load_any_input(in, "", ModelOptions{}));  // as hlr render reads them
  const double load = since(t0);
  RasterResult r = raster(std::move(scenes), o);
  r.seconds.load = load;
  return r;
}

namespace {

std::string png_bytes(png_image& image, const void* data, std::ptrdiff_t stride) {
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&image, nullptr, &size, 0, data, stride, nullptr))
    throw std::runtime_error(std::string("PNG: ") + image.message);
  std::string out(size, '\0');
  if (!png_image_write_to_memory(&image, out.data(), &size, 0, data, stride, nullptr))
    throw std::runtime_error(std::string("PNG: ") + image.message);
  out.resize(size);
  return out;
}

// 8-bit RGB through libpng's full API, to choose fast compression (an image of flat regions
// compresses well at level 1; the simplified API always uses the default level).
void append_bytes(png_structp png, png_bytep data, png_size_t n) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), n);
}

std::string png_rgb_fast(int width, int height, const std::vector<std::uint8_t>& rgb) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) throw std::runtime_error("PNG: out of memory");
  png_infop info = png_create_info_struct(png);
  std::string out;
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("PNG: could not encode the image");
  }
  png_set_write_fn(png, &out, append_bytes, nullptr);
  png_set_compression_level(png, 1);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int j = 0; j < height; ++j) png_write_row(png, const_cast<png_bytep>(&rgb[static_cast<std::size_t>(j) * width * 3]));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

}  // namespace

std::string png_rgb(int width, int height, const std::vector<std::uint8_t>& rgb) { return png_rgb_fast(width, height, rgb); }

std::string ids_png(const FaceIdBuffer& ids) {
  std::vector<std::uint16_t> v(ids.ids.size());
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (ids.ids[k] >= 65535) throw std::invalid_argument("--ids: over 65,534 faces do not fit a 16-bit PNG: write JSON (--ids FILE.json)");
    v[k] = static_cast<std::uint16_t>(ids.ids[k] + 1);
  }
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(ids.width);
  image.height = static_cast<png_uint_32>(ids.height);
  image.format = PNG_FORMAT_LINEAR_Y;  // 16-bit grey, stored as it is
  return png_bytes(image, v.data(), 0);
}

namespace {

nlohmann::ordered_json legend(const RasterResult& r) {
  nlohmann::ordered_json faces = nlohmann::ordered_json::array();
  for (const auto& [b, f] : r.scene.faces) faces.push_back({{"body", b}, {"name", r.render.names[b].name}, {"face", r.render.names[b].output_face(f)}});
  return faces;
}

nlohmann::ordered_json exact3(const Rational& x, const Rational& y, const Rational& z) {
  return nlohmann::ordered_json::array({to_string(x), to_string(y), to_string(z)});
}

}  // namespace

std::string ids_legend_json(const RasterResult& r) {
  nlohmann::ordered_json j;
  j["png"] = "value = face + 1 (0: background)";
  j["faces"] = legend(r);
  return j.dump() + "\n";
}

std::string ids_json(const RasterResult& r) {
  nlohmann::ordered_json j;
  j["width"] = r.ids.width;
  j["height"] = r.ids.height;
  j["algorithm_note"] = "face seen at each sample centre, rows from the top; -1: background";
  j["faces"] = legend(r);
  j["ids"] = r.ids.ids;
  return j.dump() + "\n";
}

std::string raster_camera_json(const RasterResult& r) {
  const Camera& cam = r.render.camera;
  PicturePlane pp(cam);
  const Vector3 &ax = pp.r(), &au = pp.u(), &ad = pp.d();
  const Rational rr = dot(ax, ax), uu = dot(au, au), dd = dot(ad, ad);
  const RasterGrid& g = r.scene.grid;
  // A picture point (x, y) is the world point base + x·kr·r + y·ku·u on the picture plane.
  const Rational kr = cam.perspective ? Rational(dd / rr) : Rational(1 / rr);
  const Rational ku = cam.perspective ? Rational(dd / uu) : Rational(1 / uu);
  std::array<Rational, 3> origin, right, down;
  for (int k = 0; k < 3; ++k) {
    const Rational base = cam.perspective ? cam.eye[k] + ad[k] : Rational(0);
    origin[k] = base + g.x0 * kr * ax[k] + g.y1 * ku * au[k];
    right[k] = g.xstep * kr * ax[k];
    down[k] = -g.ystep * ku * au[k];
  }
  nlohmann::ordered_json j;
  j["type"] = cam.perspective ? "perspective" : "orthographic";
  if (cam.perspective) j["eye"] = exact3(cam.eye.x(), cam.eye.y(), cam.eye.z());
  else j["toward_viewer"] = exact3(cam.direction.x(), cam.direction.y(), cam.direction.z());
  j["width"] = g.width;
  j["height"] = g.height;
  j["origin"] = exact3(origin[0], origin[1], origin[2]);
  j["right"] = exact3(right[0], right[1], right[2]);
  j["down"] = exact3(down[0], down[1], down[2]);
  j["centre"] = "the centre of sample (i, j), column i from the left and row j from the top, is origin + (i + 1/2)·right + (j + 1/2)·down; "
                "its sight ray runs along -toward_viewer (orthographic) or from the eye through it (perspective)";
  j["picture"] = {{"right_axis", exact3(ax.x(), ax.y(), ax.z())},
                  {"up_axis", exact3(au.x(), au.y(), au.z())},
                  {"x0", to_string(g.x0)},
                  {"y1", to_string(g.y1)},
                  {"xstep", to_string(g.xstep)},
                  {"ystep", to_string(g.ystep)}};
  j["samples_per_pixel"] = g.width / std::max(1, r.width);
  return j.dump(1) + "\n";
}

}  // namespace hlr
