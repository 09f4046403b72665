// The poll's URL as a QR code (Debian's libqrcodegencpp): a square of dark and light modules,
// no GL, for whoever draws it (the projector's poll window, a test that decodes it back).
#pragma once

#include <string>
#include <vector>

struct QrModules {
    int size = 0;           // modules per side (without the quiet zone)
    std::vector<bool> dark; // size x size, row by row from the top
    bool at(int x, int y) const { return dark[static_cast<std::size_t>(y * size + x)]; }
};

// Medium error correction (15% of the code may be hidden: a projector's glare, a head).
QrModules qrModules(const std::string& text);
