// What the arithmetic can carry: the one table of limits for scene files (scene.cpp) and for the
// command-line flags (sandbox-cli run; the app's options). A value outside its range is refused
// with a message that names the limit, e.g. "must be from 1e-6 to 1 s, not 5e-324", and the
// caller puts the place (JSON path or flag) in front. New settings add a Range here and call
// violation(); flags parse their text with parseNumber(), so flags accept what files accept.
//
// Why these numbers (a teaching sandbox of blocks of centimetres to kilometres):
// - coordinates, speeds and gravity up to 1e9 in size: products such as m·v² and m·g·y stay
//   below 1e40 for 200,000 blocks (finite energies, never `null` in JSON);
// - masses from 1e-15 to 1e15 kg: 1/m (move-and-correct's share of a correction) stays finite
//   (5e-324 kg made it overflow to a NaN position), the ratio 1e30 is still exact in the formula;
// - sizes of at least 1e-6 m (a thousand touch tolerances, 1e-9 m) and at least 1e-9 of the
//   block's coordinates: a box then spans millions of ulps of its position, so its edges never
//   round onto its centre (a 1e-12 m block at 5e8 m was a point: nothing met it);
// - dt from 1e-6 to 1 s; 1 to 1000 substeps; frames: the budget of one run (10 million frames,
//   46 hours at 60 frames per second), so a typo cannot start a run of years.
#pragma once

#include <string>
#include <string_view>

namespace limits {

// A closed range of one quantity, for its messages: the unit ("" for none) and whether only
// whole numbers are allowed.
struct Range {
    double min;
    double max;
    const char* unit;
    bool whole = false;
};

inline constexpr Range kMagnitude{-1e9, 1e9, ""};        // any other number (lesson files)
inline constexpr Range kCoordinate{-1e9, 1e9, "m"};      // positions, world bounds
inline constexpr Range kSpeed{-1e9, 1e9, "m/s"};         // each velocity component
inline constexpr Range kGravity{-1e9, 1e9, "m/s^2"};     // each gravity component
inline constexpr Range kSize{1e-6, 1e9, "m"};            // block width and height
inline constexpr Range kExtent{1e-6, 2e9, "m"};          // world bounds' width and height
inline constexpr Range kMass{1e-15, 1e15, "kg"};         // dynamic blocks
inline constexpr Range kBounciness{0.0, 1.0, ""};        // C
inline constexpr Range kDt{1e-6, 1.0, "s"};              // seconds per frame
inline constexpr Range kSubsteps{1.0, 1000.0, "", true}; // steps per frame
inline constexpr Range kForce{-1e9, 1e9, "N"};           // each force component (and F/m <= 1e9)
inline constexpr Range kDrag{0.0, 1e6, "kg/m^3"};        // the medium's density (water: 1e3)
inline constexpr Range kFriction{0.0, 1e3, ""};          // μ, Coulomb friction (rubber on dry: ~1)
inline constexpr Range kThrust{0.01, 1e4, "N"};          // the keyboard thrust (app, lessons)
inline constexpr Range kPlayerForce{0.0, 1e4, "N"};      // a scene's player: its left/right push
inline constexpr Range kJumpSpeed{0.0, 1e3, "m/s"};      // a scene's player: its jump
inline constexpr Range kFrameRate{1.0 / kDt.max, 1.0 / kDt.min, "Hz"}; // 1/dt (the app's field)
inline constexpr Range kTimeScale{0.01, 100.0, ""}; // simulated s per real s (app, lessons)
inline constexpr Range kFrames{0.0, 1e7, "", true}; // frames of one run (the frame budget)
inline constexpr Range kBenchmarkFrames{1.0, kFrames.max, "", true}; // frames a benchmark renders
inline constexpr Range kTime{0.0, kFrames.max* kDt.max, "s"};        // simulated time of one run
inline constexpr Range kDuration{1e-6, kTime.max, "s"};              // a scene's "duration"
// A length must be at least this fraction of the magnitude of the coordinates it sits at.
inline constexpr double kResolution = 1e-9;

// "from 1e-6 to 1 s", or "a whole number from 1 to 1000".
std::string describe(const Range& range);
// "" when `value` is in `range`; otherwise "must be <describe(range)>, not <value>".
std::string violation(const Range& range, double value);
// A flag's text: "" when it is a decimal number (parseNumber()) in `range`, stored in `value`;
// otherwise why not ("must be a decimal number from 1e-6 to 1 s", or violation()'s message).
// sandbox-cli and the app's options both check their numbers with it: the same messages.
std::string textViolation(std::string_view text, const Range& range, double& value);
// "" when a length (a block's size, or with kExtent the bounds' extent) at coordinates of
// magnitude up to `magnitude` is within `range` and at least kResolution·magnitude; otherwise
// why not.
std::string lengthViolation(double length, double magnitude, const Range& range = kSize);

// "" when a force of magnitude `force` (N) on `mass` (kg) accelerates it at most as much as
// gravity may (kGravity: 1e9 m/s^2); otherwise why not. The scene loader and the app's force and
// mass fields use it, so what the app saves loads back.
std::string accelerationViolation(double force, double mass);

// The shortest text that reads back to the same double, exponents without padding ("1e-6").
std::string formatNumber(double value);

// Parses the whole text as a decimal number: an optional sign, digits with an optional fraction
// (or a fraction alone), an optional exponent. No hex, no inf or nan, no spaces. Numbers too
// large for a double give ±inf and too small ones 0 (the range check then refuses them).
bool parseNumber(std::string_view text, double& value);

} // namespace limits
