// libFuzzer target: tile files of hlr render --tile (io/readers/tile_file.hpp). Any text gives an
// InputError or a tile whose pieces are valid: 0 <= t0 < t1 <= 1 on listed segments.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "io/readers/input_error.hpp"
#include "io/readers/tile_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  try {
    hlr::TileFile t = hlr::read_tile_text(text, "fuzz.tile");
    for (const auto& [seg, p] : t.pieces)
      if (seg >= t.segments || !(p.t0 >= 0 && p.t0 < p.t1 && p.t1 <= 1) || t.index < 0 || t.index >= t.count) std::abort();
  } catch (const hlr::InputError&) {
  }
  return 0;
}
