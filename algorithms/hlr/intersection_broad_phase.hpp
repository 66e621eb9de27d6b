// Broad phase for intersection lines (course notes section 28, "penetration lines"): the pairs
// of triangles whose 3D bounding boxes overlap, each pair once, found by hashing the boxes
// into cubic cells (a pair is looked at only in the cell that holds the low corner of the two
// boxes' overlap). Boxes are conservative (certified bounds of exact coordinates); the caller
// decides each pair exactly. Runs on all cores through parallel.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "algorithms/support/parallel.hpp"

namespace hlr {

/// An axis-aligned box: lo x, y, z then hi x, y, z.
using Box3 = std::array<double, 6>;
/// The same in floats (half the memory), for boxes rounded outward from doubles.
using Box3f = std::array<float, 6>;

/// What the caller says of an overlapping pair.
enum class PairVerdict { Skip, Reject, Keep };  // Skip: not a pair to test at all (not counted)

struct BoxPairs {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> kept;  // (i < j), sorted
  std::size_t tested = 0;                                     // pairs judged Reject or Keep
};

/// The most (box, cell) entries the broad phase makes at once: a grid of more is swept a slab
/// of x layers at a time (8 bytes an entry, as much again for its sort).
inline constexpr std::size_t kSlabEntries = std::size_t{1} << 24;

/// Three corner ids of each box (a triangle's vertices, three ints), read in place from the
/// caller's records: box i's at first + i * stride bytes. Two boxes with a corner id in common
/// are a Skip without the judge (a mesh's neighbours: most overlapping pairs of a fine mesh).
struct BoxCorners {
  const std::byte* first = nullptr;  // none: every pair goes to the judge
  std::size_t stride = 3 * sizeof(int);
  std::array<int, 3> of(std::uint32_t i) const {
    std::array<int, 3> c;
    std::memcpy(c.data(), first + i * stride, sizeof c);
    return c;
  }
  static bool share(const std::array<int, 3>& a, const std::array<int, 3>& b) {
    return a[0] == b[0] || a[0] == b[1] || a[0] == b[2] || a[1] == b[0] || a[1] == b[1] || a[1] == b[2] || a[2] == b[0] || a[2] == b[1] ||
           a[2] == b[2];
  }
};

/// Every pair of overlapping boxes is passed to `judge` (from several threads at once) once,
/// but those `corners` skips. `slab_entries`: the most entries at once (the same pairs, in the
/// same order, for any).
BoxPairs overlapping_box_pairs(std::span<const Box3> boxes, const ParallelLoop& loop,
                               const std::function<PairVerdict(std::uint32_t, std::uint32_t)>& judge, std::size_t slab_entries = kSlabEntries,
                               BoxCorners corners = {});
BoxPairs overlapping_box_pairs(std::span<const Box3f> boxes, const ParallelLoop& loop,
                               const std::function<PairVerdict(std::uint32_t, std::uint32_t)>& judge, std::size_t slab_entries = kSlabEntries,
                               BoxCorners corners = {});

/// `b` rounded outward to floats; false when a bound lies beyond the floats' range (or is not
/// finite), where the doubles must be used.
bool outward_floats(const Box3& b, Box3f& out);

}  // namespace hlr
