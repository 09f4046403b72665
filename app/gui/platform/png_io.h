// Writing PNG files (stb_image_write from libstb).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

// Writes RGBA8 pixels, top row first, through a SafeFile. False on failure, with `error` naming
// the file.
bool writePng(const std::string& path, const std::vector<std::uint8_t>& rgba, int width, int height,
              std::string* error = nullptr);
