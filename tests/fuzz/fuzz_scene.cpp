// libFuzzer target: scene files (YAML and JSON). Any text gives an InputError or a scene.
#include <cstdint>
#include <string>

#include "io/readers/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  try {
    hlr::Scene s = hlr::load_scene_text(text, "/nonexistent-fuzz-dir/scene.yaml");
    for (const auto& b : s.bodies) (void)b.body.report();
  } catch (const hlr::InputError&) {
  }
  return 0;
}
