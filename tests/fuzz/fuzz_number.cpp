// libFuzzer target: exact number parsing. Any bytes: either a NumberError or a rational whose
// lowest-terms text parses back to the same value.
#include <cstdint>
#include <string_view>

#include "kernel/number.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  hlr::Rational q;
  if (!hlr::try_parse_rational(text, q)) return 0;
  if (hlr::parse_rational(hlr::to_string(q)) != q) __builtin_trap();
  return 0;
}
