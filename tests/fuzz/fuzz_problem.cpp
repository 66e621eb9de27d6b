// libFuzzer target: problem files of `hlr explain` (YAML and JSON). Any text gives an
// InputError or a problem; a problem is then solved (small bodies only, to keep runs fast).
// Every error message is also put into Russian (the catalogue's matcher on any text).
#include <cstdint>
#include <string>

#include "algorithms/hlr/roberts.hpp"
#include "io/explain/explain.hpp"
#include "io/explain/messages_ru.hpp"
#include "io/explain/problem.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  try {
    hlr::Problem p = hlr::load_problem_text(text, "/nonexistent-fuzz-dir/problem.yaml");
    std::size_t faces = 0;
    for (const auto& b : p.scene.bodies) faces += b.body.num_faces();
    if (faces <= 64 && p.segments.size() <= 16) {
      try {
        (void)hlr::explain_markdown(hlr::explain(p), hlr::Lang::Ru);
      } catch (const hlr::BodyError& e) {
        (void)hlr::message_ru(e.what());
      } catch (const std::invalid_argument& e) {
        (void)hlr::message_ru(e.what());
      }
    }
  } catch (const hlr::InputError& e) {
    (void)hlr::message_ru(e.message());
  }
  return 0;
}
