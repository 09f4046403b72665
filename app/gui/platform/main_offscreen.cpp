// sandbox-offscreen: the sandbox rendered through OSMesa to PNG files, with no display and no GPU.
// `sandbox` runs it for --screenshot, --record and --benchmark-frames, and when no display is
// available; it takes the same arguments.
#include "offscreen_run.h"
#include "options.h"

int main(int argc, char** argv) {
    const ParsedOptions parsed = parseOptions(argc, argv);
    if (parsed.exit) return parsed.exitCode;
    return runOffscreen(parsed.options);
}
