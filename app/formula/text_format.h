// How numbers and names read on screen: short, readable numbers with floating-point noise shown
// as 0 (a student must never see "t = 6.56e-13 of the frame"), and block names that carry the
// current mass ("m1 = 1 kg" becomes "m1 = 3 kg" when the mass is changed to 3). Pure functions.
#pragma once

#include <functional>
#include <string>

// Values this close to zero, relative to the scale of what they are compared with, are rounding
// noise (a double carries about 16 digits; the engine's sums lose a few).
constexpr double kNoiseRelative = 1e-9;

// True when |value| <= kNoiseRelative · max(|scale|, 1): noise around zero for a quantity of that
// scale (scale 1 for fractions and for values in SI units of everyday size).
bool isRoundingNoise(double value, double scale = 1.0);
// A number as the UI writes it: rounding noise as "0"; up to 3 decimals, trailing zeros dropped
// ("2", "-0.5", "0.625", "999997.136", "1000001.5"); 3 significant digits below 0.0005
// ("0.000123") and from a trillion ("1.5e+12"); "inf" for infinity.
std::string formatNumber(double value, double scale = 1.0);
// formatNumber with `extra` more digits (decimals; significant digits below 0.0005 and from a
// trillion): what an equation prints when three decimals would not add up
// (a giant's 0.99999354 is not 1). extra 0 is formatNumber.
std::string formatNumberWithDigits(double value, int extra, double scale = 1.0);
// What formatNumber rounds to (3 decimals, trailing zeros dropped): its "1" stands for 1.000.
constexpr double kFormatNumberUnit = 1e-3;
// The most extra digits a line gets (formatNumberWithDigits): 3 + 14 decimals is all a double
// carries.
constexpr int kMostExtraDigits = 14;
// formatNumberWithDigits, in parentheses when negative (an operand after an operator: "1·(-2)").
std::string operand(double value, int extra = 0);
// formatNumber with a unit: "0.625 s", "6 m/s".
std::string formatQuantity(double value, const char* unit);

// A block's name without a mass written into it: "m1 = 1 kg" -> "m1", "heavy (5 kg)" -> "heavy";
// other names unchanged.
std::string baseBlockName(const std::string& name);
// True when the scene's name for a block states its mass ("m1 = 1 kg", "A (2 kg)", "big ship,
// 4 kg", "feather, 50 g").
bool nameStatesMass(const std::string& name);
// The name to show for a block of `mass` (kg; infinite for static and kinematic blocks): a name
// that states a mass states this one ("m1 = 3 kg"); others are shown as they are.
std::string nameWithMass(const std::string& name, double mass);
// The suffix the lecture's formula gives a body's symbols (m1, v1): "1" for "m1", "A" for "A";
// "" when the name is not a short symbol.
std::string formulaSymbol(const std::string& name);

// Text broken into lines of at most `width` (as `measure` gives a line's width) at spaces only,
// so a number such as 58.152 or a formula's operand is never split (ImGui's TextWrapped also
// breaks after '.' and ','). A word wider than a line is broken between characters; the text's
// own newlines are kept.
std::string wrapAtSpaces(const std::string& text, double width,
                         const std::function<double(const std::string&)>& measure);
// Text whose parts are set apart by `separator` ("P to play   ·   N one step   ·   F1 help")
// broken into lines of at most `width`: between parts, the separator left out at a break; a part
// wider than a line at its spaces (wrapAtSpaces).
std::string wrapAtSeparators(const std::string& text, const std::string& separator, double width,
                             const std::function<double(const std::string&)>& measure);
// An equation or a line of prose with equations in it (the collision inspector's lines) broken
// into lines of at most `width`: at spaces only, before an operator or a relation (the next
// line starts "  = 999997.136", indented, and equation_check reads the chain on), never right
// after one, never inside a short group in parentheses ("(6, 0)": three words at most), and never
// leaving one word alone on the last line when the line before can give it
// company. A piece that fits nowhere overflows its line rather than being cut inside a number.
std::string wrapFormula(const std::string& text, double width,
                        const std::function<double(const std::string&)>& measure);

// `text` says `word` as a word of its own, not inside a longer one ("m1" is in "m1 hits m2" and
// "m1 = 1 kg", not in "m12"): how a lesson step's texts name its blocks (the magnifier, tests).
bool saysWord(const std::string& text, const std::string& word);
