// Text from outside (scene files, file names, command lines) made safe to echo to a terminal or a
// log: the one function every message that quotes such text goes through (scene errors, the
// CLI's summaries and option errors, the app's option errors).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

// Default cut for names, keys and values quoted in a message.
inline constexpr std::size_t kPrintableDefault = 80;
// For file paths, which are longer but still bounded (PATH_MAX is 4096).
inline constexpr std::size_t kPrintablePath = 1024;

// Control bytes (C0, DEL), C1 controls, the bidirectional-text controls and bytes that are not
// UTF-8 become \xNN (so a file cannot set a terminal's title, move its cursor or reorder the
// line); the rest, valid UTF-8 included, is kept. Text longer than `maxBytes` is cut at a
// character boundary and ends in "...(N bytes)", N the length of the original text.
std::string printable(std::string_view text, std::size_t maxBytes = kPrintableDefault);
