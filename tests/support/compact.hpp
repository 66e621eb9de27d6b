// A polyhedron's copy with its vertices in a compact store (kernel/point_store.hpp): the same
// exact points as numerators over their common denominator, when that and every numerator are
// below 2^53 (else nullopt: such vertices have no compact form).
#pragma once

#include <cstdint>
#include <optional>

#include "kernel/polyhedron.hpp"

namespace hlr::test {

inline std::optional<Polyhedron> compact_copy(const Polyhedron& p) {
  mpz_class L = 1;
  for (const Point3& v : p.vertices())
    for (int k = 0; k < 3; ++k) mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), v[k].get_den_mpz_t());
  const mpz_class limit = PointStore::kLimit;
  if (L > limit) return std::nullopt;
  std::vector<PointStore::Numerators> nums;
  for (const Point3& v : p.vertices()) {
    PointStore::Numerators n;
    for (int k = 0; k < 3; ++k) {
      const mpz_class x = v[k].get_num() * (L / v[k].get_den());
      if (abs(x) > limit) return std::nullopt;
      n[k] = static_cast<std::int64_t>(x.get_si());
    }
    nums.push_back(n);
  }
  return Polyhedron(PointStore(std::move(nums), static_cast<std::int64_t>(L.get_si())), p.faces(),
                    [](std::size_t n, const std::function<void(std::size_t)>& body) {
                      for (std::size_t i = 0; i < n; ++i) body(i);
                    });
}

}  // namespace hlr::test
