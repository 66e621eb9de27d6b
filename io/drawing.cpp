// SVG and JSON writers for Roberts' results (see drawing.hpp, docs/output-format.md).
#include "io/drawing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

namespace hlr {
namespace {

using Json = nlohmann::ordered_json;

Json exact_point(const Point3& p) { return Json::array({to_string(p.x()), to_string(p.y()), to_string(p.z())}); }
Json exact_vector(const Vector3& v) { return Json::array({to_string(v.x()), to_string(v.y()), to_string(v.z())}); }

// Three decimals (micrometres in the drawing). Integer formatting of the value rounded to
// thousandths: several times faster than printf on million-line drawings, same text except
// for values exactly halfway between two thousandths (rounded away from zero here).
std::string fmt(double v) {
  if (!(std::fabs(v) < 1e12)) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    return buf;
  }
  long long m = std::llround(v * 1000.0);
  char buf[32];
  char* e = buf + sizeof buf;
  char* p = e;
  bool neg = m < 0;
  unsigned long long u = neg ? static_cast<unsigned long long>(-m) : static_cast<unsigned long long>(m);
  for (int i = 0; i < 3; ++i) *--p = static_cast<char>('0' + u % 10), u /= 10;
  *--p = '.';
  do *--p = static_cast<char>('0' + u % 10), u /= 10;
  while (u);
  if (neg) *--p = '-';
  return std::string(p, e);
}

struct Line2 {
  double x0, y0, x1, y1;
};

// Drawing coordinates of a piece; false when nothing of it is in front of the eye. For
// perspective, ends closer than `near` to the eye plane are pulled to it (drawing only: the
// visibility of the piece is already decided exactly).
bool piece_line(const Segment& s, const Piece& p, const Projector& proj, bool perspective, double near, Line2& out) {
  // Drawing only: the ends in doubles from the certified bounds and t rounded.
  auto mid = [](const Point3& q, int k) { return q.approx(k).lo + (q.approx(k).hi - q.approx(k).lo) / 2; };
  std::array<double, 3> F, T, A, B;
  for (int k = 0; k < 3; ++k) F[k] = mid(s.from(), k), T[k] = mid(s.to(), k);
  auto at = [&](const Rational& t, std::array<double, 3>& out) {
    if (t == 0) out = F;
    else if (t == 1) out = T;
    else {
      double u = to_double(t);
      for (int k = 0; k < 3; ++k) out[k] = F[k] + u * (T[k] - F[k]);
    }
  };
  at(p.t0, A);
  at(p.t1, B);
  auto pa = proj.project(A[0], A[1], A[2]), pb = proj.project(B[0], B[1], B[2]);
  if (perspective) {
    if (pa[2] < near && pb[2] < near) return false;
    if (pa[2] < near || pb[2] < near) {
      double u = (near - pa[2]) / (pb[2] - pa[2]);
      std::array<double, 3> C;
      for (int k = 0; k < 3; ++k) C[k] = A[k] + u * (B[k] - A[k]);
      auto pc = proj.project(C[0], C[1], C[2]);
      (pa[2] < near ? pa : pb) = pc;
    }
  }
  out = {pa[0], pa[1], pb[0], pb[1]};
  return true;
}

}  // namespace

std::string to_svg(const std::vector<DrawingBody>& bodies, const RobertsResult& r, const Camera& camera,
                   const SvgOptions& opt) {
  Projector proj(camera);
  double near = 0;
  if (camera.perspective) {
    double far = 0;
    for (const Segment& s : r.segments)
      for (const Point3* p : {&s.from(), &s.to()}) far = std::max(far, proj.project(*p)[2]);
    near = 1e-4 * std::max(far, 1e-300);
  }
  // Group key: (visible, line kind, body or -1 - body for intersections, second body).
  std::map<std::tuple<int, int, int, int>, std::vector<Line2>> groups;
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const Segment& s : r.segments)
    for (const Piece& p : s.pieces) {
      if (p.behind_eye || p.clipped || (!p.visible && !opt.hidden_dashed)) continue;
      Line2 l;
      if (!piece_line(s, p, proj, camera.perspective, near, l)) continue;
      bool junction = s.kind == Segment::Kind::Intersection;
      groups[{p.visible ? 0 : 1, static_cast<int>(s.line), junction ? -1 - s.body : s.body, junction ? s.body2 : -1}].push_back(l);
      x0 = std::min({x0, l.x0, l.x1});
      x1 = std::max({x1, l.x0, l.x1});
      y0 = std::min({y0, l.y0, l.y1});
      y1 = std::max({y1, l.y0, l.y1});
    }
  if (!(x1 >= x0)) x0 = y0 = 0, x1 = y1 = 1;
  double w = x1 - x0, h = y1 - y0, m = 0.04 * std::max({w, h, 1e-300});
  if (w == 0 && h == 0) m = 1;
  double k = opt.width_mm / (w + 2 * m);
  double height_mm = (h + 2 * m) * k;
  std::string out;
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + fmt(opt.width_mm) + "mm\" height=\"" + fmt(height_mm) +
         "mm\" viewBox=\"0 0 " + fmt(opt.width_mm) + " " + fmt(height_mm) + "\">\n";
  out += "<title>exact-hlr drawing</title>\n";
  auto X = [&](double x) { return fmt((x - x0 + m) * k); };
  auto Y = [&](double y) { return fmt((y1 - y + m) * k); };
  auto escape = [](const std::string& s) {
    std::string e;
    for (char c : s) {
      if (c == '&') e += "&amp;";
      else if (c == '<') e += "&lt;";
      else if (c == '>') e += "&gt;";
      else if (c == '"') e += "&quot;";
      else e += c;
    }
    return e;
  };
  for (int vis = 0; vis < 2; ++vis) {
    if (vis == 1 && !opt.hidden_dashed) break;
    const char* id = vis == 0 ? "visible" : "hidden";
    out += std::string("<g id=\"") + id + "\" fill=\"none\" stroke=\"#000\" stroke-width=\"" +
           fmt(vis == 0 ? opt.stroke_mm : opt.stroke_mm / 2) + "\" stroke-linecap=\"round\"" +
           (vis == 1 ? " stroke-dasharray=\"" + fmt(opt.stroke_mm * 4) + " " + fmt(opt.stroke_mm * 3) + "\"" : std::string()) +
           ">\n";
    int open_kind = -1;
    for (const auto& [key, lines] : groups) {
      auto [v, kind, b, b2] = key;
      if (v != vis) continue;
      std::string kid = std::string(id) + "-" + to_string(static_cast<LineKind>(kind));
      if (kind != open_kind) {
        if (open_kind >= 0) out += "  </g>\n";
        out += "  <g id=\"" + kid + "\">\n";
        open_kind = kind;
      }
      std::string gid = b >= 0 ? kid + "-body-" + std::to_string(b)
                               : kid + "-" + std::to_string(-1 - b) + "-" + std::to_string(b2);
      std::string name = b >= 0 && b < static_cast<int>(bodies.size()) ? " data-name=\"" + escape(bodies[b].name) + "\"" : "";
      out += "    <g id=\"" + gid + "\"" + name + ">\n";
      for (const Line2& l : lines)
        out += "      <line x1=\"" + X(l.x0) + "\" y1=\"" + Y(l.y0) + "\" x2=\"" + X(l.x1) + "\" y2=\"" + Y(l.y1) + "\"/>\n";
      out += "    </g>\n";
    }
    if (open_kind >= 0) out += "  </g>\n";
    out += "</g>\n";
  }
  out += "</svg>\n";
  return out;
}

nlohmann::ordered_json piece_json(const Segment& s, const Piece& p) {
  Json o;
  if (s.kind == Segment::Kind::Edge) {
    o["body"] = s.body;
    o["edge"] = Json::array({s.v0, s.v1});
    o["kind"] = to_string(s.line);
  } else {
    o["bodies"] = Json::array({s.body, s.body2});
    o["kind"] = "intersection";
  }
  o["visible"] = p.visible;
  o["from"] = exact_point(s.at(p.t0));
  o["to"] = exact_point(s.at(p.t1));
  o["t"] = Json::array({to_string(p.t0), to_string(p.t1)});
  if (s.self_hidden) o["self_hidden"] = true;
  if (p.behind_eye) o["behind_eye"] = true;
  if (p.clipped) o["clipped"] = true;
  return o;
}

std::string to_json(const std::vector<DrawingBody>& bodies, const RobertsResult& r, const Camera& camera) {
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
  j["view"] = view;
  Json jb = Json::array();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    Json b;
    b["name"] = bodies[i].name;
    b["source"] = bodies[i].source;
    Json nf = Json::array();
    if (i < r.facing.size())
      for (signed char e : r.facing[i]) nf.push_back(e < 0 ? "non-facing" : e == 0 ? "edge-on" : "facing");
    b["faces"] = nf;
    jb.push_back(b);
  }
  j["bodies"] = jb;
  Json segs = Json::array();
  for (const Segment& s : r.segments)
    for (const Piece& p : s.pieces) segs.push_back(piece_json(s, p));
  j["segments"] = segs;
  Json st;
  st["edges"] = r.stats.edges;
  st["self_hidden_edges"] = r.stats.self_hidden;
  st["intersection_segments"] = r.stats.junction_segments;
  st["pairs_tested"] = r.stats.pairs_tested;
  st["pairs_skipped_by_prefilter"] = r.stats.pairs_skipped;
  st["pairs_on_rational_path"] = r.stats.pairs_rational;
  st["method"] = r.stats.method;
  if (r.stats.method == "faces") {
    st["occluders"] = r.stats.occluders;
    st["parameter_comparisons"] = r.stats.comparisons;
    st["parameter_comparisons_identical"] = r.stats.comparisons_identical;
    st["parameter_comparisons_exact"] = r.stats.comparisons_exact;
    st["integer_path"] = r.stats.integer_path;
    st["intersection_pairs_tested"] = r.stats.intersection_pairs;
  }
  j["stats"] = st;
  // One body and one segment per line: readable, diffable and deterministic.
  std::string out = "{\n \"view\": " + j["view"].dump() + ",\n \"bodies\": [";
  for (std::size_t i = 0; i < j["bodies"].size(); ++i) out += std::string(i ? "," : "") + "\n  " + j["bodies"][i].dump();
  out += "\n ],\n \"segments\": [";
  for (std::size_t i = 0; i < j["segments"].size(); ++i) out += std::string(i ? "," : "") + "\n  " + j["segments"][i].dump();
  out += "\n ],\n \"stats\": " + j["stats"].dump() + "\n}\n";
  return out;
}

}  // namespace hlr
