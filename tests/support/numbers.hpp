// Exact numbers in tests: Q("1/3"), Q("0.1"), Q("1e-400") are exact rationals (the kernel's own
// parser, kernel/number.hpp).
#pragma once

#include "kernel/number.hpp"

namespace hlr::test {

inline Rational Q(const char* s) { return parse_rational(s); }

}  // namespace hlr::test
