// Helpers shared by the exam-mode tests: the problem files, whole files, and the tables and
// values of a solution's JSON (io/explain/explain.hpp).
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/explain/explain.hpp"

namespace hlr::test {
namespace fs = std::filesystem;

inline const std::string kData = HLR_DATA_DIR;
inline const std::string kGolden = HLR_GOLDEN_DIR;

inline std::vector<std::string> problems() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(kData + "/problems"))
    if (e.path().extension() == ".yaml") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

// The rows of the first table with this caption in the section with this title.
inline const SolutionJson& table(const SolutionJson& s, const std::string& section, const std::string& caption, int nth = 0) {
  for (const auto& sec : s["sections"])
    if (sec["title"] == section)
      for (const auto& t : sec["tables"])
        if (t["caption"] == caption && nth-- == 0) return t["rows"];
  throw std::runtime_error("no table " + caption);
}
inline const SolutionJson& values(const SolutionJson& s, const std::string& section, int nth = 0) {
  for (const auto& sec : s["sections"])
    if (sec["title"] == section && nth-- == 0) return sec["values"];
  throw std::runtime_error("no section " + section);
}

}  // namespace hlr::test
