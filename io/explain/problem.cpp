// Problem files (see problem.hpp).
#include "io/explain/problem.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>

#include "io/readers/mesh_reader.hpp"
#include "io/readers/text_reader.hpp"
#include "io/readers/yaml_context.hpp"

namespace hlr {
namespace {

using P = YamlContext;

std::vector<Rational> numbers(const P& c, const YAML::Node& n, std::size_t count, const std::string& what) {
  if (!n.IsSequence() || n.size() != count) c.fail(n, what + " must be a list of " + std::to_string(count) + " numbers");
  std::vector<Rational> out;
  for (std::size_t i = 0; i < count; ++i) out.push_back(c.number(n[i], what));
  return out;
}

Problem::Type parse_type(const P& c, const YAML::Node& n) {
  if (!n || !n.IsScalar())
    c.fail(n,
           "a problem file needs 'problem: TYPE' (roberts, cyrus-beck, midpoint, convexity, decompose, transform, horizon, weiler-atherton, "
           "priority, raster, ray-tree, section)");
  const std::string t = n.Scalar();
  if (t == "roberts") return Problem::Type::Roberts;
  if (t == "cyrus-beck") return Problem::Type::CyrusBeck;
  if (t == "midpoint") return Problem::Type::Midpoint;
  if (t == "convexity") return Problem::Type::Convexity;
  if (t == "decompose") return Problem::Type::Decompose;
  if (t == "transform") return Problem::Type::Transform;
  if (t == "horizon") return Problem::Type::Horizon;
  if (t == "weiler-atherton") return Problem::Type::WeilerAtherton;
  if (t == "priority") return Problem::Type::Priority;
  if (t == "raster") return Problem::Type::Raster;
  if (t == "ray-tree") return Problem::Type::RayTree;
  if (t == "section") return Problem::Type::Section;
  c.fail(
      n,
      "unknown problem type '" + t +
          "' (known: roberts, cyrus-beck, midpoint, convexity, decompose, transform, horizon, weiler-atherton, priority, raster, ray-tree, section)");
}

std::string list_text(const std::vector<Rational>& v) {
  std::string s;
  for (const Rational& q : v) s += (s.empty() ? "" : ", ") + to_string(q);
  return "[" + s + "]";
}

void parse_clipper(const P& c, const YAML::Node& n, Problem& pr) {
  if (!n.IsMap() || n.size() != 1) c.fail(n, "clipper must be one of {box: [6 numbers]}, {frustum: [7 numbers]}, {mesh: PATH}");
  const std::string kind = n.begin()->first.Scalar();
  const YAML::Node v = n.begin()->second;
  try {
    if (kind == "box") {
      auto x = numbers(c, v, 6, "box [xmin, xmax, ymin, ymax, zmin, zmax]");
      pr.clipper = box_clipper(x[0], x[1], x[2], x[3], x[4], x[5]);
      pr.window = Window(BoxWindow{x[0], x[1], x[2], x[3], x[4], x[5]});
      pr.clipper_text = "box " + list_text(x);
    } else if (kind == "frustum") {
      auto x = numbers(c, v, 7, "frustum [xl, xr, yb, yt, znear, zfar, zcp]");
      pr.clipper = frustum_clipper(x[0], x[1], x[2], x[3], x[4], x[5], x[6]);
      pr.window = Window(FrustumWindow{x[0], x[1], x[2], x[3], x[4], x[5], x[6]});
      pr.clipper_text = "frustum " + list_text(x);
    } else if (kind == "mesh") {
      if (!v.IsScalar()) c.fail(v, "mesh must be a path");
      std::filesystem::path mp = v.Scalar();
      if (mp.is_relative()) mp = std::filesystem::path(pr.file).parent_path() / mp;
      pr.clipper = make_clipper(load_mesh(mp.string()), v.Scalar());
      pr.clipper_text = "mesh " + v.Scalar();
    } else {
      c.fail(n.begin()->first, "unknown clipper '" + kind + "' (known: box, frustum, mesh)");
    }
  } catch (const std::invalid_argument& e) {
    c.fail(n, std::string("clipper: ") + e.what());
  } catch (const InputError& e) {
    c.fail(n, std::string("clipper: ") + e.what());
  }
}

}  // namespace

const char* to_string(Problem::Type t) {
  switch (t) {
    case Problem::Type::Roberts: return "roberts";
    case Problem::Type::CyrusBeck: return "cyrus-beck";
    case Problem::Type::Midpoint: return "midpoint";
    case Problem::Type::Convexity: return "convexity";
    case Problem::Type::Decompose: return "decompose";
    case Problem::Type::Transform: return "transform";
    case Problem::Type::Horizon: return "horizon";
    case Problem::Type::WeilerAtherton: return "weiler-atherton";
    case Problem::Type::Priority: return "priority";
    case Problem::Type::Raster: return "raster";
    case Problem::Type::RayTree:
      return "ray-tree";
    case Problem::Type::Section:
      break;
  }
  return "section";
}

Problem load_problem(const std::string& path) { return load_problem_text(read_file_bytes(path), path); }

Problem load_problem_text(const std::string& text, const std::string& path) {
  P c{path};
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(path, e.mark.is_null() ? 0 : e.mark.line + 1, "not valid YAML/JSON: " + e.msg);
  }
  if (!root || !root.IsMap()) throw InputError(path, 0, "a problem file must be a mapping with 'problem: TYPE'");
  Problem pr;
  pr.file = path;
  pr.type = parse_type(c, root["problem"]);
  const bool clipping = pr.type == Problem::Type::CyrusBeck || pr.type == Problem::Type::Midpoint;
  const bool horizon = pr.type == Problem::Type::Horizon;
  std::vector<std::string> extra = {"problem", "title"};
  if (pr.type == Problem::Type::Roberts) extra.push_back("edges");
  if (clipping) extra.insert(extra.end(), {"clipper", "segments"});
  if (pr.type == Problem::Type::Midpoint) extra.push_back("eps");
  if (horizon) extra.insert(extra.end(), {"heights", "x", "z"});
  const bool raster = pr.type == Problem::Type::Raster;
  if (raster) extra.insert(extra.end(), {"size", "window", "trace"});
  const bool ray_tree = pr.type == Problem::Type::RayTree;
  if (ray_tree) extra.insert(extra.end(), {"ray", "depth"});
  pr.scene = load_scene_text(text, path, extra, !clipping && !horizon);
  if (root["title"]) {
    if (!root["title"].IsScalar()) c.fail(root["title"], "title must be text");
    pr.title = root["title"].Scalar();
  }
  const bool one_body = pr.type == Problem::Type::Convexity || pr.type == Problem::Type::Decompose || pr.type == Problem::Type::Transform ||
                        pr.type == Problem::Type::Section;
  if (one_body && pr.scene.bodies.size() != 1) c.fail(root["bodies"], std::string(to_string(pr.type)) + " problems take exactly one body");
  if (pr.type == Problem::Type::Section && pr.scene.section.size() != 1)
    c.fail(root["section"] ? root["section"] : root, "a section problem needs one cutting plane: 'section: PLANE' (e.g. z<1 or A,B,C,D)");
  if (clipping && root["bodies"]) c.fail(root["bodies"], "clipping problems take a clipper and segments, not bodies");
  if (root["edges"]) {
    const YAML::Node e = root["edges"];
    if (!e.IsSequence()) c.fail(e, "edges must be a list of [body, vertex, vertex]");
    for (const YAML::Node& x : e) {
      if (!x.IsSequence() || x.size() != 3) c.fail(x, "an edge is [body, vertex, vertex]");
      std::array<int, 3> t{static_cast<int>(c.integer(x[0], "body")), static_cast<int>(c.integer(x[1], "vertex")),
                           static_cast<int>(c.integer(x[2], "vertex"))};
      if (t[0] < 0 || t[0] >= static_cast<int>(pr.scene.bodies.size())) c.fail(x, "no body " + std::to_string(t[0]));
      const auto& edges = pr.scene.bodies[t[0]].body.edges();
      std::pair<int, int> key{std::min(t[1], t[2]), std::max(t[1], t[2])};
      if (!std::binary_search(edges.begin(), edges.end(), key))
        c.fail(x, "body " + std::to_string(t[0]) + " has no edge " + std::to_string(t[1]) + "-" + std::to_string(t[2]));
      pr.edges.push_back({t[0], key.first, key.second});
    }
  }
  if (clipping) {
    if (!root["clipper"]) c.fail(root, "a clipping problem needs a 'clipper'");
    parse_clipper(c, root["clipper"], pr);
    if (pr.type == Problem::Type::Midpoint && !pr.window) c.fail(root["clipper"], "midpoint subdivision needs a box or a frustum");
    const YAML::Node s = root["segments"];
    if (!s || !s.IsSequence() || s.size() == 0) c.fail(s ? s : root, "a clipping problem needs 'segments': [[x1, y1, z1, x2, y2, z2], ...]");
    for (const YAML::Node& x : s) {
      auto v = numbers(c, x, 6, "a segment [x1, y1, z1, x2, y2, z2]");
      pr.segments.push_back({Point3(v[0], v[1], v[2]), Point3(v[3], v[4], v[5])});
    }
  }
  if (horizon) {
    if (root["bodies"]) c.fail(root["bodies"], "a horizon problem takes heights, not bodies");
    const YAML::Node h = root["heights"];
    if (!h || !h.IsSequence() || h.size() == 0) c.fail(h ? h : root, "a horizon problem needs 'heights': one list of heights per cut z = const");
    std::size_t nx = 0;
    for (const YAML::Node& row : h) {
      if (!row.IsSequence() || row.size() < 2) c.fail(row, "each row of heights needs at least 2 numbers");
      if (nx == 0) nx = row.size();
      if (row.size() != nx) c.fail(row, "every row of heights must have " + std::to_string(nx) + " numbers, as the first");
      for (const YAML::Node& v : row) pr.grid.ys.push_back(c.number(v, "height"));
    }
    const std::size_t nz = h.size();
    auto axis = [&](const char* key, std::size_t n, std::vector<Rational>& out) {
      Rational from = 0, to = static_cast<long>(n) - 1;
      if (root[key]) {
        auto v = numbers(c, root[key], 2, std::string(key) + " [from, to]");
        from = v[0], to = v[1];
        if (!(from < to)) c.fail(root[key], std::string(key) + ": from must be below to");
      }
      for (std::size_t k = 0; k < n; ++k) {
        Rational t(static_cast<long>(k), static_cast<long>(std::max<std::size_t>(n - 1, 1)));
        t.canonicalize();
        out.push_back(from + (to - from) * t);
      }
    };
    axis("x", nx, pr.grid.xs);
    axis("z", nz, pr.grid.zs);
  }
  if (raster) {
    if (pr.scene.view.type == View::Type::Perspective) c.fail(root["view"], "a raster problem takes an orthographic view (the notes' depth is linear across the picture)");
    if (root["size"]) {
      const YAML::Node n = root["size"];
      if (!n.IsSequence() || n.size() != 2) c.fail(n, "size must be [width, height] in pixels");
      pr.raster_width = static_cast<int>(c.integer(n[0], "width"));
      pr.raster_height = static_cast<int>(c.integer(n[1], "height"));
      if (pr.raster_width < 1 || pr.raster_width > 32 || pr.raster_height < 1 || pr.raster_height > 32)
        c.fail(n, "size: a problem's grid is 1 to 32 pixels each way");
      pr.raster_window = {Rational(0), Rational(pr.raster_width), Rational(0), Rational(pr.raster_height)};
    }
    if (root["window"]) {
      auto w = numbers(c, root["window"], 4, "window [x0, x1, y0, y1]");
      if (!(w[0] < w[1] && w[2] < w[3])) c.fail(root["window"], "window: x0 < x1 and y0 < y1");
      pr.raster_window = {w[0], w[1], w[2], w[3]};
    }
    // Every centre must be an exact double (the grid of raster_scene.hpp): binary fractions.
    const Rational xs = (pr.raster_window[1] - pr.raster_window[0]) / pr.raster_width;
    const Rational ys = (pr.raster_window[3] - pr.raster_window[2]) / pr.raster_height;
    for (int i = 0; i < pr.raster_width; ++i)
      for (int j = 0; j < pr.raster_height; ++j)
        for (const Rational& v : {Rational(pr.raster_window[0] + rational(2 * i + 1, 2) * xs), Rational(pr.raster_window[3] - rational(2 * j + 1, 2) * ys)})
          if (Rational(to_double(v)) != v)
            c.fail(root["window"] ? root["window"] : root["size"], "window: every pixel centre must be a binary fraction (halves, quarters, ...)");
    if (root["trace"]) {
      const YAML::Node t = root["trace"];
      if (!t.IsSequence()) c.fail(t, "trace must be a list of pixels [column, row]");
      for (const YAML::Node& x : t) {
        if (!x.IsSequence() || x.size() != 2) c.fail(x, "a traced pixel is [column, row]");
        std::array<int, 2> ij{static_cast<int>(c.integer(x[0], "column")), static_cast<int>(c.integer(x[1], "row"))};
        if (ij[0] < 0 || ij[0] >= pr.raster_width || ij[1] < 0 || ij[1] >= pr.raster_height) c.fail(x, "the pixel is outside the grid");
        pr.raster_trace.push_back(ij);
      }
    }
  }
  if (ray_tree) {
    const YAML::Node r = root["ray"];
    if (!r || !r.IsMap() || !r["from"] || !r["direction"]) c.fail(r ? r : root, "a ray-tree problem needs 'ray: {from: [x, y, z], direction: [dx, dy, dz]}'");
    c.check_keys(r, "ray", {"from", "direction"});
    pr.ray_from = c.point(r["from"], "ray from");
    pr.ray_direction = c.vector(r["direction"], "ray direction");
    if (pr.ray_direction.is_zero()) c.fail(r["direction"], "the ray's direction has zero length");
    if (root["depth"]) {
      pr.ray_depth = static_cast<int>(c.integer(root["depth"], "depth"));
      if (pr.ray_depth < 0 || pr.ray_depth > 8) c.fail(root["depth"], "depth must be 0 to 8");
    }
  }
  if (root["eps"]) {
    pr.eps = c.number(root["eps"], "eps");
    if (!(pr.eps > 0)) c.fail(root["eps"], "eps must be positive");
  }
  return pr;
}

}  // namespace hlr
