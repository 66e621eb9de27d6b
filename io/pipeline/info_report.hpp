// The text report of `hlr info`: per body its counts, the checks with the indices involved,
// convexity, and optionally the body matrix.
#pragma once

#include <string>
#include <vector>

#include "io/readers/scene.hpp"

namespace hlr {

struct InfoOptions {
  bool matrix = false;          // print the body matrix [V]
  std::size_t max_matrix_faces = 64;
  std::size_t max_listed = 10;  // indices listed per failed check
};

/// Report of one body.
std::string info_report(const SceneBody& body, int index, const InfoOptions& opt);

/// Names of checks that `--require` accepts.
const std::vector<std::string>& requirement_names();

/// Empty when `body` meets requirement `name`, else why not (one line).
std::string requirement_failure(const SceneBody& body, const std::string& name);

}  // namespace hlr
