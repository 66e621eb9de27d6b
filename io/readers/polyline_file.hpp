// The user's own 3D lines (docs/usage.md, "Your own lines"): a text file with one polyline per
// line, its points' coordinates as exact decimals or fractions, x y z after x y z, separated by
// spaces or commas; '#' starts a comment, blank lines are skipped. hlr render --lines draws them
// hidden by the bodies (io/pipeline/polylines.hpp).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "kernel/geometry.hpp"

namespace hlr {

using Polyline3 = std::vector<Point3>;

/// Parses polylines from `text` (`file` names it in errors). Throws InputError with the line:
/// a bad number, a count of numbers that is not a multiple of three, a polyline of one point.
std::vector<Polyline3> parse_polylines(std::string_view text, const std::string& file);

/// Reads a polyline file ("-": standard input). Throws InputError; an empty file is an error.
std::vector<Polyline3> read_polylines(const std::string& path);

}  // namespace hlr
