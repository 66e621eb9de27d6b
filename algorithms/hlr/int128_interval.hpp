// A fast exact path for Roberts' hidden interval (algorithms/hlr/roberts.hpp) in 128-bit integers.
// Face planes are primitive integer vectors (kernel: primitive_plane) and decimal input
// coordinates share small denominators, so after scaling the segment by the common
// denominator of its ends every quantity p_j, q_j, w_j is an integer below 2^62 in practice,
// the eliminated inequalities alpha + beta·t > 0 fit in 128 bits, and interval ends compare
// exactly by 256-bit cross products. When a bound would be exceeded the caller falls back to
// the rational path, so the answer is exact either way.
#pragma once

#include <optional>
#include <vector>

#include "algorithms/hlr/roberts.hpp"
#include "kernel/int128.hpp"

namespace hlr {

/// A body matrix (and the viewpoint's values) prepared for the fast path.
struct FastBody {
  bool usable = false;
  std::vector<std::array<Int128, 4>> planes;  // integer (a, b, c, d) per face
  std::vector<Int128> w;                       // G·V_j for the integer-scaled viewpoint G
};

FastBody prepare_fast_body(const BodyMatrixData& V, const RowVector4& g);

/// The hidden interval of P1P2 (as hidden_interval), or nullopt when the numbers do not fit
/// the 128-bit bounds (then use hidden_interval).
std::optional<OpenInterval> fast_hidden_interval(const Point3& p1, const Point3& p2, const FastBody& body);

}  // namespace hlr
