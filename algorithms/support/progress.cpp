// Progress of long stages (see progress.hpp).
#include "algorithms/support/progress.hpp"

#include <atomic>

namespace hlr {
namespace {

ProgressSink& sink() {
  static ProgressSink s;
  return s;
}
std::atomic<bool> g_enabled{false};

}  // namespace

void set_progress_sink(ProgressSink s) {
  sink() = std::move(s);
  g_enabled = static_cast<bool>(sink());
}

void progress(const std::string& message) {
  if (g_enabled) sink()(message);
}

bool progress_enabled() { return g_enabled; }

}  // namespace hlr
