// A polyhedron's exact vertices, as points or as numerators over one denominator (see
// point_store.hpp).
#include "kernel/point_store.hpp"

#include <cmath>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <utility>

namespace hlr {

PointStore::PointStore(std::vector<Point3> points) : points_(std::move(points)) {}

PointStore::PointStore(std::vector<Numerators> nums, std::int64_t den) : compact_(true), nums_(std::move(nums)), den_(den) {
  if (den <= 0 || den > kLimit) throw std::invalid_argument("a compact point store needs a denominator in [1, 2^53 - 1]");
  for (const Numerators& n : nums_)
    for (std::int64_t c : n)
      if (c > kLimit || c < -kLimit) throw std::invalid_argument("a compact point store needs numerators below 2^53");
  made_.store(nums_.empty(), std::memory_order_release);
}

PointStore::PointStore(const PointStore& o) : compact_(o.compact_), nums_(o.nums_), den_(o.den_) {
  if (o.points_made()) points_ = o.points_;
  made_.store(o.points_made(), std::memory_order_release);
}

PointStore& PointStore::operator=(const PointStore& o) {
  if (this != &o) *this = PointStore(o);
  return *this;
}

PointStore::PointStore(PointStore&& o) noexcept { take(o); }

PointStore& PointStore::operator=(PointStore&& o) noexcept {
  if (this != &o) take(o);
  return *this;
}

// o's contents moved here; o left an empty store of exact points.
void PointStore::take(PointStore& o) noexcept {
  compact_ = std::exchange(o.compact_, false);
  nums_ = std::move(o.nums_);
  den_ = std::exchange(o.den_, 1);
  points_ = std::move(o.points_);
  made_.store(o.points_made(), std::memory_order_release);
  o.nums_.clear();
  o.points_.clear();
  o.made_.store(true, std::memory_order_release);
}

Point3 PointStore::point(std::size_t i) const {
  if (!compact_ || points_made()) return points_[i];
  Point3 p;
  p.fill([&](Rational& x, Rational& y, Rational& z) {
    Rational* c[3] = {&x, &y, &z};
    for (int k = 0; k < 3; ++k) {
      mpz_set_si(c[k]->get_num_mpz_t(), static_cast<long>(nums_[i][k]));
      mpz_set_si(c[k]->get_den_mpz_t(), static_cast<long>(den_));
      c[k]->canonicalize();
    }
  });
  return p;
}

namespace {
std::mutex& points_mutex() {  // one for all stores: the points are made once each
  static std::mutex m;
  return m;
}
}  // namespace

const std::vector<Point3>& PointStore::points() const {
  if (points_made()) return points_;
  std::lock_guard<std::mutex> lock(points_mutex());
  if (points_made()) return points_;
  std::vector<Point3> out(nums_.size());
  for (std::size_t i = 0; i < nums_.size(); ++i) out[i] = point(i);
  points_ = std::move(out);
  made_.store(true, std::memory_order_release);
  return points_;
}

}  // namespace hlr
