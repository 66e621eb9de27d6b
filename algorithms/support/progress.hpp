// Progress of long stages (long runs must not be silent): the library says what it
// is doing through progress(); the command line installs a sink that prints it on a terminal.
// Without a sink nothing is printed, and the calls cost a test of one flag.
#pragma once

#include <functional>
#include <string>

namespace hlr {

using ProgressSink = std::function<void(const std::string& message)>;

/// Installs (or, with an empty function, removes) the process-wide sink.
void set_progress_sink(ProgressSink sink);

/// Reports a stage ("decomposing body 2: 14 convex pieces so far"); call from one thread.
void progress(const std::string& message);

/// Whether a sink is installed (to skip building messages).
bool progress_enabled();

}  // namespace hlr
