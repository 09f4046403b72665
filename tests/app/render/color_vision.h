// Colour science for the palette test: sRGB to CIELab (D65), the CIEDE2000 colour difference
// (Sharma, Wu and Dalal 2005), and dichromacy simulated with the matrices of Machado, Oliveira and
// Fernandes 2009 at severity 1.0, applied to linear RGB (as colorspacious does).
#pragma once

#include "palette.h"

struct Lab {
    double L = 0.0, a = 0.0, b = 0.0;
};

enum class Vision { Normal, Protanopia, Deuteranopia, Tritanopia };
constexpr Vision kVisions[] = {Vision::Normal, Vision::Protanopia, Vision::Deuteranopia,
                               Vision::Tritanopia};
const char* visionName(Vision vision);

// CIELab of an sRGB colour (alpha ignored), D65 white.
Lab toLab(const Color& color);
// CIEDE2000 difference (kL = kC = kH = 1).
double ciede2000(const Lab& x, const Lab& y);
// What a viewer with `vision` sees of `color`, as sRGB (clamped to the gamut).
Color simulateVision(const Color& color, Vision vision);
