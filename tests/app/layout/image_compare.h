// PNG images for the screenshot tests: load (stb_image), compare under a tolerance, write a diff.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba; // top row first

    bool empty() const { return width == 0 || height == 0; }
    // Channel c (0 r, 1 g, 2 b) of pixel (x, y); x, y must be inside.
    int at(int x, int y, int c) const {
        return rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                     static_cast<std::size_t>(x)) *
                        4 +
                    static_cast<std::size_t>(c)];
    }
};

// Loads a PNG as RGBA; an empty image when it cannot.
Image loadPng(const std::string& path);
bool savePng(const std::string& path, const Image& image);

struct Region {
    int x = 0, y = 0, width = -1, height = -1; // width -1: the whole image
};

struct Comparison {
    bool sameSize = false;
    long long differing = 0; // pixels with a channel differing by more than the threshold
    long long total = 0;
    double fraction() const { return total ? double(differing) / double(total) : 1.0; }
};

// Pixels whose r, g or b differ by more than `threshold` counts, inside `region`.
Comparison compareImages(const Image& a, const Image& b, int threshold, Region region = {});
// The expected image dimmed to grey, with differing pixels in red.
Image diffImage(const Image& expected, const Image& actual, int threshold);
