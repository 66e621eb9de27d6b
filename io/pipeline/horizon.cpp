// `hlr horizon` as a library (see horizon.hpp).
#include "io/pipeline/horizon.hpp"

#include "kernel/rotation.hpp"

#include <muParser.h>

#include <png.h>

#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>

#include "algorithms/horizon/floating_horizon_filtered.hpp"
#include "algorithms/support/parallel.hpp"
#include "io/readers/input_error.hpp"
#include "io/readers/text_reader.hpp"

namespace hlr {

Vector3 horizon_view_from_angles(const Rational& elevation, const Rational& azimuth) {
  const Rotation e = rotation_from_degrees(elevation, kHorizonAngleErrorDegrees);
  const Rotation a = rotation_from_degrees(azimuth, kHorizonAngleErrorDegrees);
  return Vector3(e.cos * a.sin, e.sin, e.cos * a.cos);
}

namespace {

std::vector<Rational> samples(const SampleRange& r) {
  std::vector<Rational> out;
  for (std::size_t k = 0; k < r.count; ++k) {
    Rational t(static_cast<long>(k), static_cast<long>(r.count - 1));
    t.canonicalize();
    out.push_back(r.from + (r.to - r.from) * t);
  }
  return out;
}

}  // namespace

SampleRange parse_sample_range(const std::string& option, const std::string& text, std::size_t default_count) {
  SampleRange r;
  r.count = default_count;
  std::vector<std::string> parts;
  std::size_t at = 0;
  while (true) {
    std::size_t c = text.find(':', at);
    parts.push_back(text.substr(at, c == std::string::npos ? std::string::npos : c - at));
    if (c == std::string::npos) break;
    at = c + 1;
  }
  if (parts.size() < 2 || parts.size() > 3) throw std::invalid_argument(option + ": '" + text + "' is not FROM:TO or FROM:TO:SAMPLES");
  try {
    r.from = parse_rational(parts[0]);
    r.to = parse_rational(parts[1]);
  } catch (const NumberError& e) {
    throw std::invalid_argument(option + ": " + e.what());
  }
  if (!(r.from < r.to)) throw std::invalid_argument(option + ": FROM must be below TO");
  if (parts.size() == 3) {
    std::size_t used = 0;
    unsigned long n = 0;
    try {
      n = std::stoul(parts[2], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != parts[2].size() || n < 2 || n > 100000) throw std::invalid_argument(option + ": SAMPLES must be a whole number from 2 to 100000");
    r.count = n;
  }
  return r;
}

HeightGrid grid_from_expression(const std::string& expression, const SampleRange& x, const SampleRange& z, unsigned threads) {
  HeightGrid g;
  g.xs = samples(x);
  g.zs = samples(z);
  const std::size_t nx = g.xs.size(), nz = g.zs.size();
  std::vector<double> xd(nx), zd(nz);
  for (std::size_t i = 0; i < nx; ++i) xd[i] = to_double(g.xs[i]);
  for (std::size_t j = 0; j < nz; ++j) zd[j] = to_double(g.zs[j]);
  // One parser per range of rows (muparser binds its variables by address); the expression is
  // checked here first, so that its errors come before any work.
  auto parser = [&](double& xv, double& zv) {
    auto p = std::make_unique<mu::Parser>();
    p->DefineVar("x", &xv);
    p->DefineVar("z", &zv);
    p->SetExpr(expression);
    return p;
  };
  try {
    double xv = xd[0], zv = zd[0];
    parser(xv, zv)->Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw std::invalid_argument("expression '" + expression + "': " + e.GetMsg());
  }
  g.yd.resize(nx * nz);
  std::vector<std::size_t> bad(nz, nx);  // per row, the first sample that is not finite
  ParallelLoop(threads).run(nz, 8, [&](unsigned, std::size_t begin, std::size_t end) {
    double xv = 0, zv = 0;
    auto p = parser(xv, zv);
    for (std::size_t j = begin; j < end; ++j) {
      zv = zd[j];
      for (std::size_t i = 0; i < nx; ++i) {
        xv = xd[i];
        const double y = p->Eval();
        if (!std::isfinite(y)) {
          bad[j] = i;
          break;
        }
        g.yd[j * nx + i] = y;  // taken exactly (HeightGrid::yd)
      }
    }
  });
  for (std::size_t j = 0; j < nz; ++j)
    if (bad[j] < nx)
      throw std::invalid_argument("the expression is not finite at x = " + to_string(g.xs[bad[j]]) + ", z = " + to_string(g.zs[j]));
  return g;
}

HeightGrid grid_from_csv(const std::string& path, const SampleRange& x, const SampleRange& z) {
  std::string text = read_file_bytes(path);
  HeightGrid g;
  std::size_t nx = 0, line = 0, at = 0;
  while (at <= text.size()) {
    std::size_t end = text.find('\n', at);
    std::string row = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
    at = end == std::string::npos ? text.size() + 1 : end + 1;
    ++line;
    if (!row.empty() && row.back() == '\r') row.pop_back();
    if (row.empty() || row[0] == '#') continue;
    std::size_t n = 0, c = 0;
    while (true) {
      std::size_t comma = row.find(',', c);
      std::string cell = row.substr(c, comma == std::string::npos ? std::string::npos : comma - c);
      while (!cell.empty() && (cell.front() == ' ' || cell.front() == '\t')) cell.erase(0, 1);
      while (!cell.empty() && (cell.back() == ' ' || cell.back() == '\t')) cell.pop_back();
      try {
        g.ys.push_back(parse_rational(cell));
      } catch (const NumberError& e) {
        throw InputError(path, static_cast<int>(line), "column " + std::to_string(n + 1) + ": " + e.what());
      }
      ++n;
      if (comma == std::string::npos) break;
      c = comma + 1;
    }
    if (nx == 0) nx = n;
    if (n != nx)
      throw InputError(path, static_cast<int>(line), "row has " + std::to_string(n) + " heights, the first row " + std::to_string(nx));
  }
  if (nx < 2 || g.ys.size() / nx < 1) throw InputError(path, 0, "a height grid needs at least 2 columns and 1 row");
  SampleRange xr = x, zr = z;
  xr.count = nx;
  zr.count = g.ys.size() / nx;
  g.xs = samples(xr);
  g.zs = zr.count == 1 ? std::vector<Rational>{zr.from} : samples(zr);
  return g;
}

namespace {

// A grey image: width, height, maxval, values row by row.
struct GreyImage {
  std::size_t w = 0, h = 0;
  unsigned maxval = 255;
  std::vector<unsigned> v;
};

GreyImage read_pgm(const std::string& path) {
  std::string data = read_file_bytes(path);
  std::size_t at = 0;
  auto fail = [&](const std::string& why) -> void { throw InputError(path, 0, why); };
  auto token = [&]() {
    while (at < data.size()) {
      if (data[at] == '#') {
        while (at < data.size() && data[at] != '\n') ++at;
      } else if (std::isspace(static_cast<unsigned char>(data[at]))) {
        ++at;
      } else {
        break;
      }
    }
    std::size_t b = at;
    while (at < data.size() && !std::isspace(static_cast<unsigned char>(data[at])) && data[at] != '#') ++at;
    return data.substr(b, at - b);
  };
  auto number = [&](const char* what) {
    std::string t = token();
    if (t.empty() || t.size() > 9 || t.find_first_not_of("0123456789") != std::string::npos) fail(std::string("bad ") + what + " '" + t.substr(0, 20) + "'");
    return static_cast<unsigned>(std::stoul(t));
  };
  std::string magic = token();
  if (magic != "P2" && magic != "P5") fail("not a PGM file (expected P2 or P5, found '" + magic.substr(0, 8) + "')");
  GreyImage img;
  img.w = number("width");
  img.h = number("height");
  img.maxval = number("maxval");
  if (img.w < 2 || img.h < 1 || img.w * img.h > 50'000'000) fail("image size " + std::to_string(img.w) + "x" + std::to_string(img.h) + " out of range");
  if (img.maxval < 1 || img.maxval > 65535) fail("maxval must be 1 to 65535");
  img.v.reserve(img.w * img.h);
  if (magic == "P2") {
    for (std::size_t k = 0; k < img.w * img.h; ++k) {
      unsigned x = number("value");
      if (x > img.maxval) fail("value " + std::to_string(x) + " above maxval");
      img.v.push_back(x);
    }
  } else {
    ++at;  // one whitespace after maxval
    const std::size_t bytes = img.maxval > 255 ? 2 : 1;
    if (data.size() < at + img.w * img.h * bytes) fail("the file ends before its " + std::to_string(img.w * img.h) + " values");
    for (std::size_t k = 0; k < img.w * img.h; ++k) {
      unsigned x = bytes == 2 ? (static_cast<unsigned char>(data[at + 2 * k]) << 8) | static_cast<unsigned char>(data[at + 2 * k + 1])
                              : static_cast<unsigned char>(data[at + k]);
      if (x > img.maxval) fail("value " + std::to_string(x) + " above maxval");
      img.v.push_back(x);
    }
  }
  return img;
}

GreyImage read_png(const std::string& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  std::string data = read_file_bytes(path);
  if (!png_image_begin_read_from_memory(&image, data.data(), data.size()))
    throw InputError(path, 0, std::string("not a PNG image: ") + image.message);
  if (image.format & PNG_FORMAT_FLAG_COLOR) {
    png_image_free(&image);
    throw InputError(path, 0, "a heightmap must be a grey image, this PNG has colour");
  }
  GreyImage img;
  img.w = image.width, img.h = image.height;
  if (img.w < 2 || img.h < 1 || img.w * img.h > 50'000'000) {
    png_image_free(&image);
    throw InputError(path, 0, "image size out of range");
  }
  // The stored values as they are: 16-bit files as 16-bit linear grey (no conversion), 8-bit
  // files as 8-bit grey (libpng would convert 8-bit values through the sRGB curve if read as
  // linear).
  const bool sixteen = (image.format & PNG_FORMAT_FLAG_LINEAR) != 0;
  if (sixteen) {
    image.format = PNG_FORMAT_LINEAR_Y;
    std::vector<png_uint_16> buf(img.w * img.h);
    if (!png_image_finish_read(&image, nullptr, buf.data(), 0, nullptr)) throw InputError(path, 0, std::string("PNG: ") + image.message);
    img.maxval = 65535;
    img.v.assign(buf.begin(), buf.end());
  } else {
    image.format = PNG_FORMAT_GRAY;
    std::vector<png_byte> buf(img.w * img.h);
    if (!png_image_finish_read(&image, nullptr, buf.data(), 0, nullptr)) throw InputError(path, 0, std::string("PNG: ") + image.message);
    img.maxval = 255;
    img.v.assign(buf.begin(), buf.end());
  }
  return img;
}

}  // namespace

HeightGrid grid_from_image(const std::string& path, const SampleRange& x, const SampleRange& z, const Rational& height) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  GreyImage img = ext == ".png" ? read_png(path) : read_pgm(path);
  HeightGrid g;
  SampleRange xr = x, zr = z;
  xr.count = img.w;
  zr.count = img.h;
  g.xs = samples(xr);
  g.zs = img.h == 1 ? std::vector<Rational>{zr.from} : samples(zr);
  g.ys.reserve(img.v.size());
  for (unsigned val : img.v) {
    Rational y(static_cast<long>(val), static_cast<long>(img.maxval));
    y.canonicalize();
    g.ys.push_back(y * height);
  }
  return g;
}

HeightGrid grid_from_file(const std::string& path, const SampleRange& x, const SampleRange& z, const Rational& height) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".csv") return grid_from_csv(path, x, z);
  if (ext == ".pgm" || ext == ".png") return grid_from_image(path, x, z, height);
  throw InputError(path, 0, "unknown height grid format '" + ext + "' (expected .csv, .pgm or .png)");
}

HorizonDrawing::HorizonDrawing(const HeightGrid& g, const Camera& camera, double classic_dx, const std::string& cuts,
                               unsigned threads)
    : g_(g), camera_(camera), classic_dx_(classic_dx), cuts_(cuts), threads_(threads) {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t nx = g.xs.size(), nz = g.zs.size();
  const bool z_family = cuts != "x", x_family = cuts != "z" || classic_dx <= 0;  // "z": its side edges
  if (z_family) h_ = classic_dx > 0 ? floating_horizon_classic(g, camera, classic_dx) : floating_horizon_filtered(g, camera, threads, nullptr, false);
  const bool edge_on = x_cuts_edge_on(camera);
  if (edge_on && cuts != "z")
    throw std::invalid_argument("the view has no x component: the x cuts are seen edge-on; give the view an x component (or draw the z cuts)");
  if (x_family && cuts != "z" && classic_dx <= 0 && !edge_on && nz >= 2) hx_ = floating_horizon_x(g, camera, threads, false);
  if (cuts == "z") hx_.visible = h_.side;  // the side edges, from the z sweep's final horizons
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Visible runs by (curve, segment): each pair's runs are consecutive in the sorted lists (in
  // one chunk where the sweep left them in chunks), so a table of spans finds them; each cut
  // edge gets them and hidden pieces between.
  using Range = std::pair<const HorizonPiece*, const HorizonPiece*>;
  auto ranges = [](const HorizonResult& h, std::size_t curves, std::size_t segments) {
    std::vector<Range> out(curves * segments, Range{nullptr, nullptr});
    auto add = [&](const std::vector<HorizonPiece>& pieces) {
      for (const HorizonPiece& p : pieces) {
        Range& r = out[static_cast<std::size_t>(p.curve) * segments + static_cast<std::size_t>(p.segment)];
        if (r.first == r.second) r.first = &p;
        r.second = &p + 1;
      }
    };
    add(h.visible);
    for (const std::vector<HorizonPiece>& chunk : h.visible_chunks) add(chunk);
    return out;
  };
  static const Rational zero(0), one(1);
  // One edge per drawn grid edge, visible where the runs say, hidden between.
  auto add_edge = [&](int v0, int v1, Range range) {
    Edge e{v0, v1, static_cast<std::uint32_t>(pieces_.size()), 0};
    const Rational* at = &zero;
    auto add = [&](const Rational* t0, const Rational* t1, bool visible) {
      if (!(*t0 < *t1)) return;
      if (e.count > 0 && pieces_.back().visible == visible) {
        pieces_.back().t1 = t1;
        return;
      }
      pieces_.push_back(EdgePiece{t0, t1, visible});
      ++e.count;
    };
    for (const HorizonPiece* p = range.first; p != range.second; ++p) {
      add(at, &p->t0, false);
      add(&p->t0, &p->t1, true);
      at = &p->t1;
    }
    add(at, &one, false);
    edges_.push_back(e);
  };
  if (z_family) {
    const std::vector<Range> runs = ranges(h_, nz, nx > 0 ? nx - 1 : 0);
    for (int j : h_.order)
      for (std::size_t i = 0; i + 1 < nx; ++i) {
        int v0 = static_cast<int>(static_cast<std::size_t>(j) * nx + i);
        add_edge(v0, v0 + 1, runs[static_cast<std::size_t>(j) * (nx - 1) + i]);
      }
  }
  // The x cuts (all of them, or the side edges i = 0 and i = nx - 1 with the z cuts).
  if (x_family && classic_dx <= 0 && nz >= 2) {
    // hx.visible by (x cut i, segment j); the side edges (cuts == "z") come sorted by curve,
    // segment and t too.
    const std::vector<Range> xruns = ranges(hx_, nx, nz - 1);
    static const std::vector<HorizonPiece> whole{{0, 0, Rational(0), Rational(1)}};
    for (std::size_t i = 0; i < nx; ++i) {
      if (cuts == "z" && i != 0 && i + 1 != nx) continue;
      for (std::size_t j = 0; j + 1 < nz; ++j) {
        int v0 = static_cast<int>(j * nx + i), v1 = static_cast<int>((j + 1) * nx + i);
        if (edge_on && cuts != "z") {  // the side edges, seen edge-on: visible whole (see x_cuts_edge_on)
          add_edge(v0, v1, Range{whole.data(), whole.data() + 1});
          continue;
        }
        add_edge(v0, v1, xruns[i * (nz - 1) + j]);
      }
    }
  }
}

RenderResult HorizonDrawing::model(const std::string& name) const {
  const HeightGrid& g = g_;
  const std::size_t nx = g.xs.size(), nz = g.zs.size();
  // The surface's points, row by row on every core (each point's certified bounds cost).
  std::vector<std::vector<Point3>> rows(nz);
  ParallelLoop(threads_).for_each(nz, 1, [&](std::size_t j) {
    rows[j].reserve(nx);
    for (std::size_t i = 0; i < nx; ++i) rows[j].push_back(g.point(i, j));
  });
  std::vector<Point3> vs;
  vs.reserve(nx * nz);
  for (std::vector<Point3>& row : rows) {
    for (Point3& p : row) vs.push_back(std::move(p));
    std::vector<Point3>().swap(row);
  }
  std::vector<Face> fs;
  for (std::size_t j = 0; j + 1 < nz; ++j)
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      int a = static_cast<int>(j * nx + i), b = a + 1, c = a + static_cast<int>(nx) + 1, d = a + static_cast<int>(nx);
      fs.push_back({a, b, c});
      fs.push_back({a, c, d});
    }
  RenderResult r;
  auto scenes = std::make_shared<std::vector<Scene>>(1);
  (*scenes)[0].bodies.push_back(SceneBody{name, name, Polyhedron(std::move(vs), std::move(fs)), identity_transform(), {}, {}, {}});
  r.scenes = scenes;
  const SceneBody& body = (*scenes)[0].bodies[0];
  r.bodies = {&body};
  r.names = {DrawingBody{name, name}};
  r.camera = camera_;
  r.drawing.stats.method = Method::Horizon;
  r.drawing.facing.push_back({});  // the faces' classes are not part of the horizon (their planes cost time)
  r.drawing.segments.resize(edges_.size());
  ParallelLoop(threads_).for_each(edges_.size(), 1024, [&](std::size_t k) {
    const Edge& e = edges_[k];
    Segment& s = r.drawing.segments[k];
    s.kind = Segment::Kind::Edge;
    s.line = LineKind::Edge;
    s.body = 0;
    s.v0 = e.v0;
    s.v1 = e.v1;
    s.borrow_ends(body.body.vertices());
    std::vector<Piece> pieces(e.count);
    for (std::uint32_t n = 0; n < e.count; ++n) {
      const EdgePiece& q = pieces_[e.first + n];
      Piece& p = pieces[n];
      p.t0 = *q.t0, p.t1 = *q.t1, p.visible = q.visible;
    }
    s.pieces = std::move(pieces);
  });
  r.drawing.stats.edges = r.drawing.segments.size();
  return r;
}

std::optional<Plot> HorizonDrawing::plot(const PlotOptions& opt) const {
  const auto start = std::chrono::steady_clock::now();
  const HeightGrid& g = g_;
  const std::size_t nx = g.xs.size(), nz = g.zs.size();
  // The points' doubles as the drawing frame takes them (DrawingFrame::to_frame: the middle of
  // each coordinate's certified bounds), and the frame's own test on their bounds.
  auto mid = [](const Bounds& b) { return b.lo + (b.hi - b.lo) / 2; };
  std::vector<Bounds> bx(nx), bz(nz), by(nx * nz);
  for (std::size_t i = 0; i < nx; ++i) bx[i] = bounds_of(g.xs[i]);
  for (std::size_t j = 0; j < nz; ++j) bz[j] = bounds_of(g.zs[j]);
  ParallelLoop loop(opt.threads);
  loop.for_each(nz, 4, [&](std::size_t j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t k = j * nx + i;  // a double height's bounds are itself (bounds_of gives that)
      by[k] = g.yd.empty() ? bounds_of(g.ys[k]) : Bounds{g.yd[k], g.yd[k]};
    }
  });
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, big = 0;
  auto box = [&](int k, const Bounds& b) {
    lo[k] = std::min(lo[k], b.lo), hi[k] = std::max(hi[k], b.hi);
    big = std::max({big, std::fabs(b.lo), std::fabs(b.hi)});
  };
  for (const Bounds& b : bx) box(0, b);
  for (const Bounds& b : by) box(1, b);
  for (const Bounds& b : bz) box(2, b);
  const double ext = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  // drawing_frame()'s test for the identity frame over every segment end (every sample is one).
  if (!(std::isfinite(big) && big < 0x1p100 && ext > 0x1p-100 && ext >= big * 0x1p-30)) return std::nullopt;
  const Projector proj(camera_, DrawingFrame{});
  auto frame_point = [&](int v) {
    const std::size_t k = static_cast<std::size_t>(v);
    return std::array<double, 3>{mid(bx[k % nx]), mid(by[k]), mid(bz[k / nx])};
  };
  // project_drawing()'s pieces and sources, and join_same_keys()'s keys for their ends.
  std::vector<std::uint32_t> first(edges_.size() + 1, 0);  // drawn pieces before edge k
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    std::uint32_t n = 0;
    for (std::uint32_t m = 0; m < edges_[k].count; ++m) n += pieces_[edges_[k].first + m].visible || opt.hidden;
    first[k + 1] = first[k] + n;
  }
  Drawing2D d;
  const std::size_t drawn = first.back();
  d.lines.resize(drawn);
  d.points.resize(2 * drawn);
  d.sources.resize(drawn);
  std::vector<std::uint64_t> keys(2 * drawn);
  loop.for_each(edges_.size(), 1024, [&](std::size_t k) {
    const Edge& e = edges_[k];
    const std::array<double, 3> F = frame_point(e.v0), T = frame_point(e.v1);
    auto at = [&](const Rational& t) {
      if (t == 0) return F;
      if (t == 1) return T;
      const double u = to_double(t);
      return std::array<double, 3>{F[0] + u * (T[0] - F[0]), F[1] + u * (T[1] - F[1]), F[2] + u * (T[2] - F[2])};
    };
    auto key = [&](const Rational& t, std::uint32_t piece, int end) -> std::uint64_t {
      const int v = t == 0 ? e.v0 : t == 1 ? e.v1 : -1;
      std::uint32_t boundary = 2 * piece;  // (join_same_keys(): an end meets the next piece's start, or a gap follows)
      if (end) boundary += piece + 1 < e.count && *pieces_[e.first + piece + 1].t0 == t ? 2 : 3;
      return v >= 0 ? (std::uint64_t{1} << 63) | static_cast<std::uint32_t>(v) : (static_cast<std::uint64_t>(k) << 32) | boundary;
    };
    std::uint32_t out = first[k];
    for (std::uint32_t m = 0; m < e.count; ++m) {
      const EdgePiece& q = pieces_[e.first + m];
      if (!q.visible && !opt.hidden) continue;
      const std::array<double, 3> A = at(*q.t0), B = at(*q.t1);
      const auto pa = proj.project(A[0], A[1], A[2]), pb = proj.project(B[0], B[1], B[2]);
      Polyline2D& l = d.lines[out];
      l.first = 2 * out, l.count = 2, l.first_edge = out;
      l.kind = LineKind::Edge, l.visible = q.visible, l.body = 0;
      d.points[2 * out] = {pa[0], pa[1]};
      d.points[2 * out + 1] = {pb[0], pb[1]};
      d.sources[out] = PieceRef{static_cast<int>(k), static_cast<int>(m)};
      keys[2 * out] = key(*q.t0, m, 0);
      keys[2 * out + 1] = key(*q.t1, m, 1);
      ++out;
    }
  });
  DedupOptions dopt;
  dopt.overlaps = opt.dedup;
  dopt.threads = opt.threads;
  // The exact point of an end, for the pairs the clean-up's filters cannot separate: the
  // segment's exact point at the piece's parameter, as Segment::at() gives it.
  const std::function<Point3(std::uint32_t)> end_point = [&](std::uint32_t end) {
    const PieceRef& ref = d.sources[end / 2];
    const Edge& e = edges_[static_cast<std::size_t>(ref.segment)];
    const EdgePiece& q = pieces_[e.first + static_cast<std::uint32_t>(ref.piece)];
    const Rational& t = end & 1 ? *q.t1 : *q.t0;
    const std::size_t a = static_cast<std::size_t>(e.v0), b = static_cast<std::size_t>(e.v1);
    const Point3 A = g.point(a % nx, a / nx), B = g.point(b % nx, b / nx);
    if (t == 0) return A;
    if (t == 1) return B;
    return Point3(A.x() + t * (B.x() - A.x()), A.y() + t * (B.y() - A.y()), A.z() + t * (B.z() - A.z()));
  };
  const CleanDrawing clean = dedup_by_keys(d, keys, end_point, camera_, dopt);
  return plot_from_clean(clean, opt, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

RenderResult render_horizon(const HeightGrid& g, const Camera& camera, const std::string& name, double classic_dx,
                            const std::string& cuts, HorizonTimings* timings) {
  HorizonDrawing hd(g, camera, classic_dx, cuts);
  if (timings) timings->horizon = hd.seconds;
  return hd.model(name);
}

}  // namespace hlr
