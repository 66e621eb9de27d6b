// Reading YAML (and JSON) input files with exact numbers and errors that name the file and
// line: shared by the scene reader (scene.cpp) and the problem reader (problem.cpp). Include
// only in .cpp files that use yaml-cpp.
#pragma once

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <vector>

#include "io/readers/input_error.hpp"
#include "kernel/geometry.hpp"

namespace hlr {

struct YamlContext {
  std::string file;
  [[noreturn]] void fail(const YAML::Node& n, const std::string& msg) const {
    throw InputError(file, n.Mark().is_null() ? 0 : n.Mark().line + 1, msg);
  }
  void expect_map(const YAML::Node& n, const std::string& what) const {
    if (!n.IsMap()) fail(n, what + " must be a mapping");
  }
  void check_keys(const YAML::Node& n, const std::string& what, std::initializer_list<const char*> known) const {
    check_keys(n, what, std::vector<std::string>(known.begin(), known.end()));
  }
  // Checks keys: all known, none repeated.
  void check_keys(const YAML::Node& n, const std::string& what, const std::vector<std::string>& known) const {
    expect_map(n, what);
    std::set<std::string> seen;
    for (auto it = n.begin(); it != n.end(); ++it) {
      if (!it->first.IsScalar()) fail(it->first, "keys of " + what + " must be names");
      std::string k = it->first.Scalar();
      if (std::find(known.begin(), known.end(), k) == known.end()) {
        std::string list;
        for (const std::string& s : known) list += std::string(list.empty() ? "" : ", ") + s;
        fail(it->first, "unknown key '" + k + "' in " + what + " (known: " + list + ")");
      }
      if (!seen.insert(k).second) fail(it->first, "key '" + k + "' appears twice in " + what);
    }
  }
  Rational number(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) fail(n, what + " must be a number");
    try {
      return parse_rational(n.Scalar());
    } catch (const NumberError& e) {
      fail(n, what + ": " + e.what());
    }
  }
  std::string text(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) fail(n, what + " must be text");
    return n.Scalar();
  }
  std::array<Rational, 3> triple(const YAML::Node& n, const std::string& what) const {
    if (!n.IsSequence() || n.size() != 3) fail(n, what + " must be a list of 3 numbers [x, y, z]");
    return {number(n[0], what), number(n[1], what), number(n[2], what)};
  }
  Point3 point(const YAML::Node& n, const std::string& what) const {
    auto t = triple(n, what);
    return Point3(t[0], t[1], t[2]);
  }
  Vector3 vector(const YAML::Node& n, const std::string& what) const {
    auto t = triple(n, what);
    return Vector3(t[0], t[1], t[2]);
  }
  long integer(const YAML::Node& n, const std::string& what) const {
    Rational q = number(n, what);
    if (q.get_den() != 1 || !q.get_num().fits_sint_p()) fail(n, what + " must be an integer");
    return q.get_num().get_si();
  }
};

}  // namespace hlr
