#include "png_io.h"

#include <stb_image_write.h>

bool writePng(const std::string& path, const std::vector<std::uint8_t>& rgba, int width,
              int height) {
    if (width <= 0 || height <= 0 ||
        rgba.size() < static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
        return false;
    }
    return stbi_write_png(path.c_str(), width, height, 4, rgba.data(), width * 4) != 0;
}
