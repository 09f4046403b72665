// Collisions you can hear (lecture, "Bounce elasticity": with C < 1 some kinetic energy turns into
// sound and heat). Each collision makes a short synthesised knock (no sample files): louder for a
// larger impulse (logarithmic: kDecibelsPerDecade), pitched by the size of the lighter block
// (smaller is higher), lower against a wall or another body of infinite mass. At most one knock
// starts per kMinKnockGap, so a gas hums instead of roaring. Everything here is plain logic: the
// window and the browser play the knocks through OpenAL (audio_out.h), the offscreen renderer
// mixes the same knocks into a WAV file (--audio-wav), and tests/app checks both.
#pragma once

#include "stats.h"
#include "world.h"

#include <vector>

constexpr int kSampleRate = 44100;        // Hz, of the knock's waveform and of --audio-wav
constexpr double kBaseKnockHz = 440.0;    // the waveform's pitch; a knock plays it at `pitch`
constexpr double kKnockSeconds = 0.15;    // how long one knock sounds
constexpr double kMinKnockGap = 0.05;     // s between onsets: at most 20 knocks a second
constexpr double kQuietestImpulse = 1e-3; // N·s: softer collisions are silent
constexpr double kLoudestImpulse = 1e3;   // N·s: full loudness from here on
constexpr double kDecibelsPerDecade = 8.0;
constexpr double kWallPitchFactor = 0.5; // an octave lower against an infinite mass

struct Knock {
    double time = 0.0;  // s, the collision's world time
    float gain = 0.0f;  // 0..1 (before the volume)
    float pitch = 1.0f; // playback rate of the waveform: frequency / kBaseKnockHz
};

// The impulse of a collision on its first body (N·s): m1 · |v1' - v1|, or the second body's when
// the first has infinite mass.
double collisionImpulse(const CollisionRecord& c);
// Loudness for an impulse: kDecibelsPerDecade per decade below kLoudestImpulse, 0 from
// kQuietestImpulse down.
float knockGain(double impulse);
// Frequency (Hz) of a knock whose lighter block is `size` m across (its larger side): 440 Hz for
// 1 m, sqrt(2) higher for each halving, within [110, 1760] Hz; times kWallPitchFactor against an
// infinite mass.
double knockFrequency(double size, bool againstInfiniteMass);
// The knock of one collision in `world` (the block sizes); gain 0 for a resting contact (the
// rest rule's: a stack is silent) and for impulses below kQuietestImpulse.
Knock knockFor(const CollisionRecord& c, const World& world);

// The rate limit: the first audible collision after a gap of kMinKnockGap starts a knock; those
// within the gap are folded into the knock already sounding.
class KnockScheduler {
  public:
    // The knocks that sound of one frame's collisions (in the order of their time).
    std::vector<Knock> admit(const std::vector<CollisionRecord>& log, const World& world);
    // Time went back (reset, a jump on the timeline): the next collision knocks at once.
    void restart() { lastOnset_ = -1e300; }

  private:
    double lastOnset_ = -1e300;
};

// The knock's waveform at kSampleRate, peak 1: two damped partials (a wood block's 1 : 2.76) with
// a 1 ms attack, kKnockSeconds long.
const std::vector<float>& knockWaveform();
// Adds `knock` at `volume` into `out`, a mono track whose sample 0 is at time `start` (s):
// the waveform read at the knock's pitch (linear interpolation), as OpenAL plays it. Samples
// past the end of `out` are dropped.
void mixKnock(std::vector<float>& out, double start, const Knock& knock, float volume);

// The app's sound: on or off (M), the volume (the View section's slider), and the knocks waiting
// for the platform to play them. Off by default outside lessons, on in a lesson, until the user
// chooses (then remembered in the settings).
struct SoundControl {
    bool chosen = false; // the user pressed M or used the checkbox (saved)
    bool on = false;     // their choice, when chosen
    float volume = 0.8f; // 0..1 (saved)
    KnockScheduler scheduler;
    std::vector<Knock> queue; // admitted this frame, drained by the platform's audio output
};
// Whether knocks sound now: the user's choice, else on only with a lesson open.
bool soundOn(const SoundControl& sound, bool lessonOpen);
// M: turns sound off when it is on and on when it is off, and remembers the choice.
void toggleSound(SoundControl& sound, bool lessonOpen);
