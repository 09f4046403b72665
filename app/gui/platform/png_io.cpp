#include "png_io.h"

#include "chart.h"
#include "printable.h"

bool writePng(const std::string& path, const std::vector<std::uint8_t>& rgba, int width, int height,
              std::string* error) {
    if (width <= 0 || height <= 0 ||
        rgba.size() < static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
        if (error) *error = printable(path, kPrintablePath) + ": no image to write";
        return false;
    }
    return writePngFile(path, rgba.data(), width, height, 4, error);
}
