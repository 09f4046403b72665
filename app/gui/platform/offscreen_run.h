// The offscreen modes of `sandbox-offscreen` (and of `sandbox` with no display): a screenshot
// after N frames, a recording of N frames, or a benchmark. Each renders exactly what the window
// shows, through the same appFrame() and prepared frame (platform/frame/prepared_frame.h).
#pragma once

#include "options.h"

// Runs the mode the options ask for (a screenshot when none is asked); returns the process exit
// code.
int runOffscreen(const Options& options);
