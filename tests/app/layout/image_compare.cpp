#include "image_compare.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstdlib>

Image loadPng(const std::string& path) {
    Image image;
    int channels = 0;
    stbi_uc* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 4);
    if (!data) return {};
    image.rgba.assign(data, data + static_cast<std::size_t>(image.width) *
                                       static_cast<std::size_t>(image.height) * 4);
    stbi_image_free(data);
    return image;
}

bool savePng(const std::string& path, const Image& image) {
    if (image.empty()) return false;
    return stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(),
                          image.width * 4) != 0;
}

Comparison compareImages(const Image& a, const Image& b, int threshold, Region region) {
    Comparison result;
    result.sameSize = a.width == b.width && a.height == b.height && !a.empty();
    if (!result.sameSize) return result;
    if (region.width < 0) region = {0, 0, a.width, a.height};
    const int x0 = std::clamp(region.x, 0, a.width), y0 = std::clamp(region.y, 0, a.height);
    const int x1 = std::clamp(region.x + region.width, 0, a.width);
    const int y1 = std::clamp(region.y + region.height, 0, a.height);
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            ++result.total;
            for (int c = 0; c < 3; ++c) {
                if (std::abs(a.at(x, y, c) - b.at(x, y, c)) > threshold) {
                    ++result.differing;
                    break;
                }
            }
        }
    }
    return result;
}

Image diffImage(const Image& expected, const Image& actual, int threshold) {
    Image out = expected;
    if (expected.width != actual.width || expected.height != actual.height) return actual;
    for (int y = 0; y < expected.height; ++y) {
        for (int x = 0; x < expected.width; ++x) {
            bool differs = false;
            for (int c = 0; c < 3; ++c) {
                differs |= std::abs(expected.at(x, y, c) - actual.at(x, y, c)) > threshold;
            }
            const std::size_t i =
                (static_cast<std::size_t>(y) * static_cast<std::size_t>(expected.width) +
                 static_cast<std::size_t>(x)) *
                4;
            const int grey =
                (expected.at(x, y, 0) + expected.at(x, y, 1) + expected.at(x, y, 2)) / 9;
            out.rgba[i + 0] = static_cast<std::uint8_t>(differs ? 255 : grey);
            out.rgba[i + 1] = static_cast<std::uint8_t>(differs ? 0 : grey);
            out.rgba[i + 2] = static_cast<std::uint8_t>(differs ? 0 : grey);
            out.rgba[i + 3] = 255;
        }
    }
    return out;
}
