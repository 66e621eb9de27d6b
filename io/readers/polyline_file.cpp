// The user's own 3D lines (see polyline_file.hpp).
#include "io/readers/polyline_file.hpp"

#include <iostream>
#include <iterator>

#include "io/readers/input_error.hpp"
#include "io/readers/text_reader.hpp"

namespace hlr {

std::vector<Polyline3> parse_polylines(std::string_view text, const std::string& file) {
  std::vector<Polyline3> out;
  int line_no = 0;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(at, end - at);
    at = end + 1;
    ++line_no;
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    std::vector<Rational> nums;
    std::size_t k = 0;
    while (k < line.size()) {
      while (k < line.size() && (line[k] == ' ' || line[k] == '\t' || line[k] == ',' || line[k] == '\r')) ++k;
      std::size_t e = k;
      while (e < line.size() && line[e] != ' ' && line[e] != '\t' && line[e] != ',' && line[e] != '\r') ++e;
      if (e == k) break;
      const std::string_view token = line.substr(k, e - k);
      Rational v;
      if (!try_parse_rational(token, v))
        throw InputError(file, line_no, "'" + std::string(token) + "' is not a number (a polyline is x y z x y z ...)");
      nums.push_back(std::move(v));
      k = e;
    }
    if (nums.empty()) continue;
    if (nums.size() % 3 != 0)
      throw InputError(file, line_no, std::to_string(nums.size()) + " numbers: a polyline's points are x y z, three numbers each");
    if (nums.size() < 6) throw InputError(file, line_no, "a polyline needs at least two points");
    Polyline3 pl;
    for (std::size_t i = 0; i < nums.size(); i += 3) pl.emplace_back(nums[i], nums[i + 1], nums[i + 2]);
    out.push_back(std::move(pl));
  }
  return out;
}

std::vector<Polyline3> read_polylines(const std::string& path) {
  std::string text;
  if (path == "-") text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
  else text = read_file_bytes(path);
  const std::string name = path == "-" ? "<stdin>" : path;
  std::vector<Polyline3> out = parse_polylines(text, name);
  if (out.empty()) throw InputError(name, 0, "no polyline in the file (one polyline per line: x y z x y z ...)");
  return out;
}

}  // namespace hlr
