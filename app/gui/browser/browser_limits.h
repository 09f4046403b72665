// What the browser build takes on, and how it says no (issue 41: the browser never hangs
// silently). The page has one thread: while a file is read and checked, or a trace compared,
// nothing else runs, not even a key. So the browser opens a file only up to a size whose work
// stays short, refuses a larger one at once with a message that names the limit and where it can
// be opened (the window, sandbox-cli), and says "Opening ..." on the page for the frame before the
// work. Pure logic: the web main asks it; tested in tests/app.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

// The largest scene file and the largest trace (a student's engine's CSV) the browser opens,
// measured with tests/web/big_inputs_test.py on headless Chromium (SwiftShader) on 2 cores shared
// at load 16 to 18, several times what a CI run puts on them. A scene's whole open (read, parse,
// build the world, the first frame) is one task of the page's thread: for the densest scene at
// the limit (4,124 blocks of 32 bytes, 128 KB) 0.4 to 0.6 s, so a key waits less than 1 s;
// 8,000 blocks (256 KB) took 1.4 s, 20,000 (1.1 MB) 2.1 s, 70,000 (3.8 MB) 4.2 s, which is
// why 4 MB was too much. A trace is compared one run a frame (trace_opening.h): at the limit its
// longest task was 0.75 to 1.0 s at load 24 to 28 (in one task, a page's first trace took 2.4 to
// 3.8 s: the variants' code not yet optimised by the browser's JIT; 5.9 s at 256 KB and 16.8 s
// at 2 MB). The largest shipped scene is 60 KB. See the README, "In a browser".
inline constexpr std::uintmax_t kMaxBrowserSceneBytes = 128u << 10;
inline constexpr std::uintmax_t kMaxBrowserTraceBytes = 64u << 10;

// "" when the browser opens the file at `path` of `bytes` bytes (a scene, or a trace when its
// name ends in .csv); otherwise why not, naming the file, its size and the limit.
std::string browserOpenRefusal(const std::string& path, std::uintmax_t bytes);

// What the page says while the file opens: "Opening gas_500.json (92 KB)...".
std::string openingMessage(const std::string& path, std::uintmax_t bytes);

// A size as people read it: "812 bytes", "92 KB", "20.0 MB".
std::string byteSize(std::uintmax_t bytes);
