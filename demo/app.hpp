// The demo's window and main loop: input, the fixed 60 Hz step, drawing, statistics.
#pragma once

#include "options.hpp"

namespace jostle::demo {

/// Runs the demo; returns the process's exit status.
int runApp(const Options& options);

/// Opens and closes a hidden window: 0 if a display is there to show the demo, else 1.
int probeDisplay();

} // namespace jostle::demo
