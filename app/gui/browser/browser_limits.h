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

// The largest scene file and the largest trace (a student's engine's CSV) the browser opens.
// Measured with tests/web/big_inputs_test.py on headless Chromium (SwiftShader, 2 shared cores):
// see the README, "In a browser".
inline constexpr std::uintmax_t kMaxBrowserSceneBytes = 4u << 20;
inline constexpr std::uintmax_t kMaxBrowserTraceBytes = 2u << 20;

// "" when the browser opens the file at `path` of `bytes` bytes (a scene, or a trace when its
// name ends in .csv); otherwise why not, naming the file, its size and the limit.
std::string browserOpenRefusal(const std::string& path, std::uintmax_t bytes);

// What the page says while the file opens: "Opening gas_500.json (92 KB)...".
std::string openingMessage(const std::string& path, std::uintmax_t bytes);

// A size as people read it: "812 bytes", "92 KB", "20.0 MB".
std::string byteSize(std::uintmax_t bytes);
