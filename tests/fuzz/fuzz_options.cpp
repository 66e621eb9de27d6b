// libFuzzer target: the command line's exact vectors, number lists and clipper specs.
#include <cstdint>
#include <stdexcept>
#include <string>

#include "cli/arguments.hpp"
#include "io/readers/clipper_spec.hpp"
#include "io/readers/input_error.hpp"
#include "io/views/view_choice.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)hlr::parse_vector3("--view", text);
  } catch (const std::invalid_argument&) {
  }
  try {
    (void)hlr::parse_numbers("--segment", text, 6);
  } catch (const std::invalid_argument&) {
  }
  if (text.rfind("box:", 0) == 0 || text.rfind("frustum:", 0) == 0) {
    try {
      (void)hlr::parse_clipper("--clipper", text);
    } catch (const std::invalid_argument&) {
    } catch (const hlr::InputError&) {
    }
  }
  return 0;
}
