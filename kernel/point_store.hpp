// A polyhedron's exact vertices in one of two forms: exact points (Point3, three GMP rationals
// and their bounds, about 190 bytes a vertex), or, for the short decimals most large files
// hold, integer numerators over one common denominator (24 bytes a vertex), from which the
// points are made only when something asks for them. The certified bounds of either form are
// the same doubles, so a filter reads them without making the points. Design:
// docs/design.md ("Compact vertices").
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

#include "kernel/geometry.hpp"
#include "kernel/int128.hpp"

namespace hlr {

class PointStore {
 public:
  using Numerators = std::array<std::int64_t, 3>;
  /// Largest numerator magnitude and denominator of the compact form: below 2^53, so that both
  /// are exact doubles of at most 53 bits, as are the lowest terms bounds_of divides.
  static constexpr std::int64_t kLimit = (std::int64_t{1} << 53) - 1;

  PointStore() = default;
  /// Exact points as given (not brought to lowest terms here).
  explicit PointStore(std::vector<Point3> points);
  /// Point i is nums[i] / den. Throws std::invalid_argument unless 0 < den <= kLimit and every
  /// |numerator| <= kLimit.
  PointStore(std::vector<Numerators> nums, std::int64_t den);

  PointStore(const PointStore& o);
  PointStore& operator=(const PointStore& o);
  PointStore(PointStore&& o) noexcept;
  PointStore& operator=(PointStore&& o) noexcept;

  std::size_t size() const { return compact_ ? nums_.size() : points_.size(); }
  bool empty() const { return size() == 0; }
  /// The compact form: numerators() over denominator().
  bool compact() const { return compact_; }
  const std::vector<Numerators>& numerators() const { return nums_; }
  std::int64_t denominator() const { return den_; }

  /// Every point, exact and in lowest terms when compact. Made on the first call from the
  /// numerators (once, also when that call comes on several threads at a time); the compact
  /// form's callers that only need bounds read approx() instead.
  const std::vector<Point3>& points() const;
  /// Whether points() has been made (always, for exact points).
  bool points_made() const { return made_.load(std::memory_order_acquire); }
  /// Point i's certified bounds of coordinate k: the same doubles as points()[i].approx(k).
  Bounds approx(std::size_t i, int k) const {
    if (!compact_) return points_[i].approx(k);
    return compact_bounds(nums_[i][k]);
  }
  /// Point i alone (a copy, or made from its numerators).
  Point3 point(std::size_t i) const;

 private:
  // bounds_of(num / den) without the rational: both are exact doubles, so the correctly rounded
  // quotient is the one bounds_of divides to (its lowest terms are the same number), and
  // bounds_of gives one double exactly when den divides num. Then the quotient is that integer
  // (below 2^53, so exact): tested only on an integral quotient, without a 64-bit division.
  void take(PointStore& o) noexcept;
  Bounds compact_bounds(std::int64_t num) const {
    const double v = static_cast<double>(num) / static_cast<double>(den_);
    if (v == static_cast<double>(static_cast<std::int64_t>(v)) && static_cast<Int128>(static_cast<std::int64_t>(v)) * den_ == num) return {v, v};
    return {next_down(v), next_up(v)};
  }

  bool compact_ = false;
  std::vector<Numerators> nums_;
  std::int64_t den_ = 1;
  mutable std::vector<Point3> points_;
  mutable std::atomic<bool> made_{true};
};

}  // namespace hlr
