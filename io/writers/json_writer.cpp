// JSON writer (see json_writer.hpp): formats the exact drawing, nothing else.
#include "io/writers/json_writer.hpp"

#include "algorithms/support/parallel.hpp"

#include <cmath>
#include <cstdio>

#include "algorithms/picture/picture_plane.hpp"
#include "io/writers/parallel_text.hpp"

namespace hlr {
namespace {

using Json = nlohmann::ordered_json;

Json exact_point(const Point3& p) { return Json::array({to_string(p.x()), to_string(p.y()), to_string(p.z())}); }
Json exact_vector(const Vector3& v) { return Json::array({to_string(v.x()), to_string(v.y()), to_string(v.z())}); }

constexpr signed char kRemoved = 2;  // a face the repair removed (mesh_repair.hpp)

// A repaired body's facing in its input's numbering, its removed faces kRemoved.
std::vector<signed char> input_facing(const DrawingBody& body, const std::vector<signed char>& facing) {
  std::vector<signed char> out(body.input_faces(facing.size()), kRemoved);
  for (std::size_t f = 0; f < facing.size() && f < body.input_face.size(); ++f) out[static_cast<std::size_t>(body.input_face[f])] = facing[f];
  return out;
}

// A body's faces as JSON strings ("facing", "non-facing", "edge-on"), comma-separated, as
// nlohmann's dump writes an array of them; made on all cores in runs of faces.
void append_facing(std::string& out, const std::vector<signed char>& facing) {
  constexpr std::size_t kRun = 65536;
  std::vector<std::string> parts((facing.size() + kRun - 1) / kRun);
  ParallelLoop().for_each(parts.size(), 1, [&](std::size_t c) {
    std::string& t = parts[c];
    for (std::size_t k = c * kRun, end = std::min(facing.size(), k + kRun); k < end; ++k) {
      if (k) t += ',';
      const signed char e = facing[k];
      t += e == kRemoved ? "\"removed\"" : e < 0 ? "\"non-facing\"" : e == 0 ? "\"edge-on\"" : "\"facing\"";
    }
  });
  append_parts(out, parts);
}

}  // namespace

nlohmann::ordered_json piece_json(const Segment& s, const Piece& p) {
  Json o;
  if (s.kind == Segment::Kind::Edge) {
    o["body"] = s.body;
    o["edge"] = Json::array({s.v0, s.v1});
    o["kind"] = to_string(s.line);
  } else {
    o["bodies"] = Json::array({s.body, s.body2});
    o["kind"] = to_string(s.line);  // intersection (or a plan's overhead line: bodies -1)
  }
  o["visible"] = p.visible;
  o["from"] = exact_point(s.at(p.t0));
  o["to"] = exact_point(s.at(p.t1));
  o["t"] = Json::array({to_string(p.t0), to_string(p.t1)});
  if (s.self_hidden) o["self_hidden"] = true;
  if (p.through) o["through"] = true;
  if (p.behind_eye) o["behind_eye"] = true;
  if (p.clipped) o["clipped"] = true;
  return o;
}

namespace {

void append_all(std::string&) {}
template <class First, class... Rest>
void append_all(std::string& out, const First& first, const Rest&... rest) {
  out += first;
  append_all(out, rest...);
}

void append_exact_point(std::string& out, const Point3& p) {
  append_all(out, "[\"", to_string(p.x()), "\",\"", to_string(p.y()), "\",\"", to_string(p.z()), "\"]");
}

}  // namespace

void append_piece_json(std::string& out, const Segment& s, const Piece& p) {
  if (s.kind == Segment::Kind::Edge)
    append_all(out, "{\"body\":", std::to_string(s.body), ",\"edge\":[", std::to_string(s.v0), ",", std::to_string(s.v1),
               "],\"kind\":\"", to_string(s.line), "\"");
  else append_all(out, "{\"bodies\":[", std::to_string(s.body), ",", std::to_string(s.body2), "],\"kind\":\"", to_string(s.line), "\"");
  out += p.visible ? ",\"visible\":true,\"from\":" : ",\"visible\":false,\"from\":";
  append_exact_point(out, s.at(p.t0));
  out += ",\"to\":";
  append_exact_point(out, s.at(p.t1));
  append_all(out, ",\"t\":[\"", to_string(p.t0), "\",\"", to_string(p.t1), "\"]");
  if (s.self_hidden) out += ",\"self_hidden\":true";
  if (p.through) out += ",\"through\":true";
  if (p.behind_eye) out += ",\"behind_eye\":true";
  if (p.clipped) out += ",\"clipped\":true";
  out += '}';
}

std::string to_json(const std::vector<DrawingBody>& bodies, const LineDrawing& r, const Camera& camera, const PlotStats* plot) {
  return to_json(bodies, r, camera, plot, SurfacesJson{});
}

namespace {

// The input's number of face f of body b (a repaired body's faces keep their input numbers).
using Bodies = std::vector<DrawingBody>;
int face_number(const Bodies& bodies, int b, int f) {
  return b >= 0 && static_cast<std::size_t>(b) < bodies.size() ? bodies[static_cast<std::size_t>(b)].output_face(f) : f;
}

std::string hex_colour(const Rgb& colour) {
  auto c = rgb8(colour);
  char hex[8];
  std::snprintf(hex, sizeof hex, "#%02x%02x%02x", c[0], c[1], c[2]);
  return hex;
}

std::string priority_text(const Bodies& bodies, const SurfacesJson& sj, const Camera& camera) {
  const PriorityResult& pr = *sj.priority;
  PicturePlane pp(camera);
  Json axes;
  axes["right"] = exact_vector(pp.r());
  axes["up"] = exact_vector(pp.u());
  axes["depth"] = exact_vector(pp.d());
  std::string out = ",\n \"priority\": {\n  \"picture_axes\": " + axes.dump() + ",\n  \"order\": [";
  for (std::size_t k = 0; k < pr.order.size(); ++k) {
    const PriorityPolygon& p = pr.polygons[pr.order[k]];
    Json jp;
    jp["body"] = p.body;
    jp["face"] = face_number(bodies, p.body, p.face);
    jp["piece"] = p.piece;
    jp["cut"] = pr.order[k] >= static_cast<int>(pr.initial);
    if (sj.colours) jp["shade"] = hex_colour((*sj.colours)[p.body][p.face]);
    Json corners = Json::array();
    for (const Point3& q : p.corners) corners.push_back(exact_point(q));
    jp["corners"] = corners;
    jp["area"] = to_string(picture_area2(p.pts) / 2);
    out += std::string(k ? "," : "") + "\n   " + jp.dump();
  }
  Json st;
  st["polygons"] = pr.initial;
  st["painted"] = pr.order.size();
  st["pairs_tested"] = pr.pairs;
  Json passed = Json::object();
  for (int t = 1; t <= 5; ++t) passed[std::to_string(t)] = pr.passed[t];
  st["first_yes_by_test"] = passed;
  st["swaps"] = pr.swaps;
  st["cycles"] = pr.cycles;
  st["cuts"] = pr.splits;
  st["outline_cuts"] = pr.outline_splits;
  out += "\n  ],\n  \"stats\": " + st.dump() + "\n }";
  return out;
}

Json polygon_json(const VisiblePolygon& p) {
  Json jp;
  Json outer = Json::array();
  for (const Point3& q : p.outer) outer.push_back(exact_point(q));
  jp["outer"] = outer;
  Json holes = Json::array();
  for (const auto& h : p.holes) {
    Json ring = Json::array();
    for (const Point3& q : h) ring.push_back(exact_point(q));
    holes.push_back(ring);
  }
  jp["holes"] = holes;
  jp["area"] = to_string(p.area2 / 2);
  return jp;
}

std::string shadows_text(const Bodies& bodies, const SurfacesJson& sj) {
  const Shadows& sh = *sj.shadows;
  std::string out = ",\n \"shadows\": {\n  \"lights\": " + std::to_string(sh.from_light.size()) + ",\n  \"faces\": [";
  Rational total = 0, dark = 0;
  for (std::size_t k = 0; k < sh.faces.size(); ++k) {
    const ShadowFace& f = sh.faces[k];
    Json jf;
    jf["body"] = f.body;
    jf["face"] = face_number(bodies, f.body, f.face);
    jf["side"] = f.front ? "front" : "back";
    jf["area"] = to_string(f.area2 / 2);
    jf["shadow_area"] = to_string(f.shadow_area2 / 2);
    jf["shadow_fraction"] = f.area2 == 0 ? "0" : to_string(f.shadow_area2 / f.area2);
    Json regions = Json::array();
    for (std::size_t j = 0; j < f.regions.size(); ++j) {
      Json jr = polygon_json(f.regions[j].polygon);
      Json lights = Json::array();
      for (std::size_t i = 0; i < sh.from_light.size(); ++i)
        if ((f.regions[j].lights >> i) & 1u) lights.push_back(i);
      jr["lights"] = lights;
      if (sj.shadow_colours) jr["shade"] = hex_colour((*sj.shadow_colours)[k][j]);
      regions.push_back(jr);
    }
    jf["regions"] = regions;
    Json by = Json::array();
    for (std::size_t i = 0; i < f.by_light.size(); ++i) {
      Json jl;
      jl["light"] = i;
      Rational lit = 0;
      Json a = Json::array(), b = Json::array();
      for (const VisiblePolygon& p : f.by_light[i][0]) a.push_back(polygon_json(p)), lit += p.area2 / 2;
      for (const VisiblePolygon& p : f.by_light[i][1]) b.push_back(polygon_json(p));
      jl["lit_area"] = to_string(lit);
      jl["lit"] = a;
      jl["shadow"] = b;
      by.push_back(jl);
    }
    jf["by_light"] = by;
    total += f.area2 / 2, dark += f.shadow_area2 / 2;
    out += std::string(k ? "," : "") + "\n   " + jf.dump();
  }
  Json st;
  st["faces"] = sh.faces.size();
  st["area"] = to_string(total);
  st["shadow_area"] = to_string(dark);
  out += "\n  ],\n  \"stats\": " + st.dump() + "\n }";
  return out;
}

std::string transparency_text(const Bodies& bodies, const SurfacesJson& sj) {
  const TransparentPicture& tp = *sj.transparent;
  std::string out = ",\n \"transparency\": {\n  \"regions\": [";
  for (std::size_t k = 0; k < tp.regions.size(); ++k) {
    const TransparentRegion& r = tp.regions[k];
    Json jr;
    Json faces = Json::array();
    for (auto [b, f] : r.faces) faces.push_back(Json::array({b, face_number(bodies, b, f)}));
    jr["faces"] = faces;
    if (sj.transparent_colours) jr["colour"] = hex_colour((*sj.transparent_colours)[k]);
    auto ring = [](const std::vector<Exact2>& pts) {
      Json a = Json::array();
      for (const Exact2& q : pts) a.push_back(Json::array({to_string(q[0]), to_string(q[1])}));
      return a;
    };
    jr["outer"] = ring(r.polygon.outer_2d);
    Json holes = Json::array();
    for (const auto& h : r.polygon.holes_2d) holes.push_back(ring(h));
    jr["holes"] = holes;
    jr["area"] = to_string(r.polygon.area2 / 2);
    out += std::string(k ? "," : "") + "\n   " + jr.dump();
  }
  Json st;
  st["regions"] = tp.regions.size();
  st["painted"] = tp.painted;
  st["cuts"] = tp.cuts;
  out += "\n  ],\n  \"stats\": " + st.dump() + "\n }";
  return out;
}

std::string surfaces_text(const Bodies& bodies, const SurfacesJson& sj, const Camera& camera) {
  const VisibleSurfaces& vs = *sj.surfaces;
  PicturePlane pp(camera);
  Json axes;
  axes["right"] = exact_vector(pp.r());
  axes["up"] = exact_vector(pp.u());
  axes["depth"] = exact_vector(pp.d());
  std::string out = ",\n \"surfaces\": {\n  \"picture_axes\": " + axes.dump() + ",\n  \"faces\": [";
  Rational total = 0;
  std::size_t polygons = 0;
  for (std::size_t i = 0; i < vs.faces.size(); ++i) {
    const VisibleFace& f = vs.faces[i];
    Json jf;
    jf["body"] = f.body;
    jf["face"] = face_number(bodies, f.body, f.face);
    jf["side"] = f.front ? "front" : "back";
    if (sj.colours) jf["shade"] = hex_colour((*sj.colours)[f.body][f.face]);
    Rational area = 0;
    Json polys = Json::array();
    for (const VisiblePolygon& p : f.polygons) {
      polys.push_back(polygon_json(p));
      area += p.area2 / 2;
      ++polygons;
    }
    jf["area"] = to_string(area);
    jf["visible"] = polys;
    total += area;
    out += std::string(i ? "," : "") + "\n   " + jf.dump();
  }
  Json st;
  st["method"] = vs.stats.weiler_atherton ? "weiler-atherton" : "arrangement";
  st["faces_seen"] = vs.faces.size();
  st["polygons"] = polygons;
  st["area"] = to_string(total);
  st["segments"] = vs.stats.segments;
  st["arrangement_edges"] = vs.stats.edges;
  st["cells"] = vs.stats.cycles;
  st["crossings"] = vs.stats.crossings;
  st["exact_sign_tests"] = vs.stats.exact_tests;
  st["triangles"] = vs.stats.triangles;
  if (vs.stats.weiler_atherton) {
    st["clips"] = vs.stats.wa_clips;
    st["splits"] = vs.stats.wa_splits;
    st["recursions"] = vs.stats.wa_recursions;
    st["cycles"] = vs.stats.wa_cycles;
  }
  out += "\n  ],\n  \"stats\": " + st.dump() + "\n }";
  return out;
}

}  // namespace

std::string to_json(const std::vector<DrawingBody>& bodies, const LineDrawing& r, const Camera& camera, const PlotStats* plot,
                    const SurfacesJson& surfaces) {
  return to_json_text(bodies, r, camera, plot, surfaces).str();
}

PartText to_json_text(const std::vector<DrawingBody>& bodies, const LineDrawing& r, const Camera& camera, const PlotStats* plot,
                      const SurfacesJson& surfaces) {
  Json j;
  Json view;
  if (camera.perspective) {
    view["type"] = "perspective";
    view["eye"] = exact_point(camera.eye);
    view["target"] = exact_point(camera.target);
  } else {
    view["type"] = "orthographic";
    view["direction"] = exact_vector(camera.direction);
  }
  view["up"] = exact_vector(camera.up);
  if (surfaces.frame) {
    Json planes = Json::array();
    for (const Plane& h : surfaces.frame->sides)
      planes.push_back(Json::array({to_string(h.a()), to_string(h.b()), to_string(h.c()), to_string(h.d())}));
    Json frame;
    frame["planes"] = planes;
    frame["rect"] = surfaces.frame->rect;
    view["frame"] = frame;
  }
  j["view"] = view;
  Json st;
  st["edges"] = r.stats.edges;
  st["self_hidden_edges"] = r.stats.self_hidden;
  st["intersection_segments"] = r.stats.intersection_segments;
  st["pairs_tested"] = r.stats.pairs_tested;
  st["pairs_skipped_by_prefilter"] = r.stats.pairs_skipped;
  st["pairs_on_rational_path"] = r.stats.pairs_rational;
  st["method"] = to_string(r.stats.method);
  if (const auto& f = r.stats.faces) {
    st["occluders"] = f->occluders;
    st["parameter_comparisons"] = f->comparisons;
    st["parameter_comparisons_identical"] = f->comparisons_identical;
    st["parameter_comparisons_exact"] = f->comparisons_exact;
    st["integer_path"] = f->integer_path;
    st["intersection_pairs_tested"] = f->intersection_pairs;
  }
  j["stats"] = st;
  // One body and one segment per line: readable, diffable and deterministic.
  std::string out = "{\n \"view\": " + j["view"].dump() + ",\n \"bodies\": [";
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    out += std::string(i ? "," : "") + "\n  {\"name\":" + Json(bodies[i].name).dump() + ",\"source\":" + Json(bodies[i].source).dump() +
           ",\"faces\":[";
    if (i < r.facing.size()) {
      if (bodies[i].input_face.empty()) append_facing(out, r.facing[i]);
      else append_facing(out, input_facing(bodies[i], r.facing[i]));
    }
    out += "]";
    auto list = [&](const char* key, const std::vector<int>& faces) {
      if (faces.empty()) return;
      out += std::string(",\"") + key + "\":[";
      for (std::size_t k = 0; k < faces.size(); ++k) out += (k ? "," : "") + std::to_string(faces[k]);
      out += "]";
    };
    list("removed_faces", bodies[i].removed_faces);
    list("repaired_faces", bodies[i].repaired_faces);
    out += "}";
  }
  out += "\n ],\n \"segments\": [";
  // One line per piece, made on every core in runs of segments as the text is written (the
  // pieces' text is never all in memory). The first piece has no comma before it.
  constexpr std::size_t kRun = 2048;
  std::size_t first = r.segments.size();
  for (std::size_t k = 0; k < r.segments.size() && first == r.segments.size(); ++k)
    if (!r.segments[k].pieces.empty()) first = k;
  PartText text;
  text.add(std::move(out));
  text.add_run((r.segments.size() + kRun - 1) / kRun, [&r, first](std::size_t c, std::string& part) {
    for (std::size_t k = c * kRun, end = std::min(r.segments.size(), k + kRun); k < end; ++k) {
      bool lead = k == first;
      for (const Piece& p : r.segments[k].pieces) {
        part += lead ? "\n  " : ",\n  ";
        lead = false;
        append_piece_json(part, r.segments[k], p);
      }
    }
  });
  out = std::string();
  out += "\n ],\n \"stats\": " + j["stats"].dump();
  if (plot) {
    Json pj;
    pj["pieces"] = plot->pieces;
    pj["end_on"] = plot->zero_length;
    pj["overlap_groups"] = plot->overlap_groups;
    pj["overlapped_pieces"] = plot->overlapped_pieces;
    auto mm = [](double v) { return std::round(v * 1000) / 1000; };  // three decimals, as the SVG
    pj["duplicate_length"] = mm(plot->duplicate_length);
    pj["edges"] = plot->edges;
    pj["path_count"] = plot->path_count;
    pj["min_path_count"] = plot->min_path_count;
    pj["pen_down_length"] = mm(plot->pen_down_length);
    pj["pen_up_length"] = mm(plot->pen_up_length);
    pj["pen_up_length_greedy"] = mm(plot->pen_up_greedy);
    pj["pen_up_length_unordered"] = mm(plot->pen_up_unordered);
    out += ",\n \"plot\": " + pj.dump();
  }
  if (surfaces.surfaces) out += surfaces_text(bodies, surfaces, camera);
  if (surfaces.priority) out += priority_text(bodies, surfaces, camera);
  if (surfaces.shadows) out += shadows_text(bodies, surfaces);
  if (surfaces.transparent) out += transparency_text(bodies, surfaces);
  out += surfaces.section;
  out += "\n}\n";
  text.add(std::move(out));
  return text;
}

}  // namespace hlr
