// `hlr clip`: clips segments against a box, the course notes' viewing pyramid or any convex
// mesh, exactly (Cyrus-Beck) or by midpoint subdivision, and prints each result with exact
// endpoints and t values (course notes sections 21-22).
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/arguments.hpp"
#include "io/readers/clipper_spec.hpp"
#include "cli/commands.hpp"
#include "io/readers/input_error.hpp"
#include "io/readers/text_reader.hpp"

namespace hlr::cli {
namespace {

struct ClipArgs {
  std::string clipper, segments_file, method = "cyrus-beck", eps = "1/1000", format = "text";
  std::vector<std::string> segments;
};

struct Seg {
  Point3 a, b;
};

std::vector<Seg> read_segments(const ClipArgs& args) {
  std::vector<Seg> out;
  for (const auto& s : args.segments) {
    auto v = parse_numbers("--segment", s, 6);
    out.push_back({Point3(v[0], v[1], v[2]), Point3(v[3], v[4], v[5])});
  }
  if (!args.segments_file.empty()) {
    std::string bytes = read_file_bytes(args.segments_file);
    std::istringstream in(bytes);
    std::string line;
    int n = 0;
    while (std::getline(in, line)) {
      ++n;
      if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      try {
        auto v = parse_numbers("segment", line, 6);
        out.push_back({Point3(v[0], v[1], v[2]), Point3(v[3], v[4], v[5])});
      } catch (const std::invalid_argument& e) {
        throw InputError(args.segments_file, n, e.what());
      }
    }
  }
  if (out.empty()) throw std::invalid_argument("no segments: give --segment X1,Y1,Z1,X2,Y2,Z2 or --segments FILE");
  return out;
}

nlohmann::ordered_json jp(const Point3& p) { return {to_string(p.x()), to_string(p.y()), to_string(p.z())}; }

int run_clip(const ClipArgs& a) {
  ClipperSpec spec = parse_clipper("--clipper", a.clipper);
  Rational eps;
  try {
    eps = parse_rational(a.eps);
  } catch (const NumberError& e) {
    throw std::invalid_argument(std::string("--eps: ") + e.what());
  }
  if (!(eps > 0)) throw std::invalid_argument("--eps must be positive");
  const bool midpoint = a.method == "midpoint";
  if (midpoint && !spec.window) throw std::invalid_argument("--method midpoint takes a box: or frustum: clipper");
  std::vector<Seg> segs = read_segments(a);
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  std::ostringstream text;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const Seg& s = segs[i];
    nlohmann::ordered_json j;
    j["from"] = jp(s.a);
    j["to"] = jp(s.b);
    text << "segment " << i + 1 << ": " << s.a << " -> " << s.b << "\n";
    if (!midpoint) {
      CyrusBeckResult r = cyrus_beck(spec.clipper, s.a, s.b);
      Point3 p = s.a + r.t_lower * (s.b - s.a), q = s.a + r.t_upper * (s.b - s.a);
      if (r.degenerate_point) {
        const char* where = r.point_class == CyrusBeckResult::PointClass::Inside ? "inside"
                            : r.point_class == CyrusBeckResult::PointClass::OnBoundary ? "on the boundary" : "outside";
        j["status"] = "point";
        j["point"] = where;
        text << "  a single point, " << where << "\n";
      } else if (r.status == CyrusBeckResult::Status::Visible) {
        j["status"] = "visible";
        j["t"] = {to_string(r.t_lower), to_string(r.t_upper)};
        j["clipped"] = {{"from", jp(p)}, {"to", jp(q)}};
        text << "  visible for t in [" << r.t_lower << ", " << r.t_upper << "]: " << p << " -> " << q << "\n";
      } else if (r.status == CyrusBeckResult::Status::Point) {
        j["status"] = "point";
        j["t"] = {to_string(r.t_lower), to_string(r.t_upper)};
        j["clipped"] = {{"from", jp(p)}, {"to", jp(p)}};
        text << "  touches the clipper at one point, t = " << r.t_lower << ": " << p << " (drawn as nothing)\n";
      } else {
        j["status"] = "outside";
        text << "  outside\n";
      }
    } else {
      MidpointResult r = midpoint_clip(*spec.window, s.a, s.b, eps);
      j["codes"] = {outcode_bits(r.code1), outcode_bits(r.code2)};
      unsigned n1 = notes_outcode(*spec.window, s.a), n2 = notes_outcode(*spec.window, s.b);
      text << "  codes " << outcode_bits(r.code1) << " " << outcode_bits(r.code2) << " (left right below above near far)";
      if (n1 != r.code1 || n2 != r.code2) {
        j["notes_codes"] = {outcode_bits(n1), outcode_bits(n2)};
        text << "; the notes' rule behind the centre of projection gives " << outcode_bits(n1) << " " << outcode_bits(n2);
      }
      text << "\n";
      j["subdivisions"] = r.subdivisions;
      j["eps"] = to_string(eps);
      if (r.visible) {
        j["status"] = "visible";
        j["clipped"] = {{"from", jp(r.from)}, {"to", jp(r.to)}};
        text << "  visible: " << r.from << " -> " << r.to << (r.trivially_accepted ? " (trivially accepted)" : "") << ", "
             << r.subdivisions << " subdivisions; each end within " << eps << " of the exact end\n";
      } else {
        j["status"] = "outside";
        text << "  outside" << (r.trivially_rejected ? " (trivially rejected)" : "") << ", " << r.subdivisions
             << " subdivisions (a visible part shorter than " << Rational(2 * eps) << " may be missed)\n";
      }
    }
    out.push_back(j);
  }
  if (a.format == "json") {
    // One segment per line, like `hlr render --format json`.
    std::cout << "{\n \"clipper\": " << nlohmann::ordered_json(a.clipper).dump() << ",\n \"method\": \"" << a.method
              << "\",\n \"segments\": [";
    for (std::size_t i = 0; i < out.size(); ++i) std::cout << (i ? "," : "") << "\n  " << out[i].dump();
    std::cout << "\n ]\n}\n";
  } else {
    std::cout << text.str();
  }
  return 0;
}

}  // namespace

void add_clip_command(CLI::App& app, int& exit_code) {
  auto a = std::make_shared<ClipArgs>();
  CLI::App* cmd = app.add_subcommand("clip", "Clip segments against a box, a viewing pyramid or a convex mesh");
  cmd->add_option("--clipper", a->clipper,
                  "box:XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX | frustum:XL,XR,YB,YT,ZNEAR,ZFAR,ZCP | a convex mesh file")
      ->required();
  cmd->add_option("--segment", a->segments, "X1,Y1,Z1,X2,Y2,Z2 (repeatable)");
  cmd->add_option("--segments", a->segments_file, "A file with one segment per line (six numbers)");
  cmd->add_option("--method", a->method, "cyrus-beck (exact, default) or midpoint")->check(CLI::IsMember({"cyrus-beck", "midpoint"}));
  cmd->add_option("--eps", a->eps, "Midpoint tolerance (default 1/1000)");
  cmd->add_option("--format", a->format, "text (default) or json")->check(CLI::IsMember({"text", "json"}));
  cmd->callback([a, &exit_code] { exit_code = run_clip(*a); });
}

}  // namespace hlr::cli
