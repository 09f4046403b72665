// png_diff A.png B.png [X Y W H]: prints how many pixels differ (any channel by more than 24
// counts) inside the region, for the end-to-end window test. Exit 2 when an image cannot be read
// or the sizes differ.
#include "image_compare.h"

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
    if (argc != 3 && argc != 7) {
        std::fprintf(stderr, "usage: png_diff A.png B.png [X Y W H]\n");
        return 2;
    }
    const Image a = loadPng(argv[1]);
    const Image b = loadPng(argv[2]);
    Region region;
    if (argc == 7) {
        region = {std::atoi(argv[3]), std::atoi(argv[4]), std::atoi(argv[5]), std::atoi(argv[6])};
    }
    const Comparison c = compareImages(a, b, 24, region);
    if (!c.sameSize) {
        std::fprintf(stderr, "png_diff: cannot compare %s and %s\n", argv[1], argv[2]);
        return 2;
    }
    std::printf("%lld\n", c.differing);
    return 0;
}
