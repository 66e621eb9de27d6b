// Clipper specifications on the command line: `box:XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX`,
// `frustum:XL,XR,YB,YT,ZNEAR,ZFAR,ZCP` (the course notes' viewing pyramid), or a mesh file
// holding a convex body.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "algorithms/clip/cyrus_beck.hpp"
#include "algorithms/clip/midpoint_clip.hpp"

namespace hlr {

struct ClipperSpec {
  ConvexClipper clipper;
  std::optional<Window> window;  // for box and frustum: the midpoint method's window
  std::string text;              // as given
};

/// Parses a clipper; throws std::invalid_argument (bad text) or InputError (bad file).
ClipperSpec parse_clipper(const std::string& option, const std::string& text);

/// Cutting half-spaces for a section (section_cut.hpp: value <= 0 is kept): `z<1.2` or `z=1.2`
/// (keep below, the cap faces up: seen from above), `x>0` (keep above), `A,B,C,D` (keep
/// A·x + B·y + C·z + D <= 0), `box:XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX` (keep the box's inside: six
/// planes). Throws std::invalid_argument naming `option`.
std::vector<Plane> parse_section(const std::string& option, const std::string& text);

/// Exact numbers separated by commas (and/or spaces): exactly `count` of them.
std::vector<Rational> parse_numbers(const std::string& option, const std::string& text, std::size_t count);

}  // namespace hlr
