#include "collision_sound.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr double kPi = 3.14159265358979323846;

} // namespace

double collisionImpulse(const CollisionRecord& c) {
    if (std::isfinite(c.m1)) return c.m1 * std::abs(c.v1After - c.v1);
    if (std::isfinite(c.m2)) return c.m2 * std::abs(c.v2After - c.v2);
    return 0.0;
}

float knockGain(double impulse) {
    if (!(impulse >= kQuietestImpulse)) return 0.0f;
    const double decadesBelow = std::max(0.0, std::log10(kLoudestImpulse / impulse));
    return static_cast<float>(std::pow(10.0, -kDecibelsPerDecade * decadesBelow / 20.0));
}

double knockFrequency(double size, bool againstInfiniteMass) {
    const double s = size > 0.0 && std::isfinite(size) ? size : 1.0;
    const double f = std::clamp(kBaseKnockHz / std::sqrt(s), 110.0, 1760.0);
    return againstInfiniteMass ? f * kWallPitchFactor : f;
}

Knock knockFor(const CollisionRecord& c, const World& world) {
    Knock k;
    k.time = c.time;
    const auto sizeOf = [&world](int index) {
        if (index < 0 || index >= static_cast<int>(world.blocks.size())) return 1.0;
        const Vec2 s = world.blocks[static_cast<std::size_t>(index)].size;
        return std::max(s.x, s.y);
    };
    const bool finite1 = std::isfinite(c.m1), finite2 = c.other >= 0 && std::isfinite(c.m2);
    // The lighter block's size: the only finite mass against a wall, static or kinematic body.
    const int lighter = finite1 && (!finite2 || c.m1 <= c.m2) ? c.block : c.other;
    k.pitch =
        static_cast<float>(knockFrequency(sizeOf(lighter), !(finite1 && finite2)) / kBaseKnockHz);
    k.gain = c.rest ? 0.0f : knockGain(collisionImpulse(c));
    return k;
}

std::vector<Knock> KnockScheduler::admit(const std::vector<CollisionRecord>& log,
                                         const World& world) {
    std::vector<Knock> out;
    for (const CollisionRecord& c : log) {
        const Knock k = knockFor(c, world);
        if (k.gain <= 0.0f) continue;
        if (k.time < lastOnset_) lastOnset_ = -1e300; // time went back without restart()
        if (k.time - lastOnset_ < kMinKnockGap) continue;
        lastOnset_ = k.time;
        out.push_back(k);
    }
    return out;
}

const std::vector<float>& knockWaveform() {
    static const std::vector<float> wave = [] {
        const int n = static_cast<int>(kKnockSeconds * kSampleRate);
        std::vector<float> w(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) {
            const double t = static_cast<double>(i) / kSampleRate;
            const double attack = std::min(1.0, t / 0.001);
            const double body = std::exp(-t / 0.030) * std::sin(2.0 * kPi * kBaseKnockHz * t);
            const double click =
                0.5 * std::exp(-t / 0.010) * std::sin(2.0 * kPi * 2.76 * kBaseKnockHz * t);
            // The last 5 ms fade to zero: no click at the end.
            const double release = std::min(1.0, (kKnockSeconds - t) / 0.005);
            w[static_cast<std::size_t>(i)] = static_cast<float>(attack * release * (body + click));
        }
        float peak = 0.0f;
        for (float v : w) peak = std::max(peak, std::abs(v));
        for (float& v : w) v /= peak;
        return w;
    }();
    return wave;
}

void mixKnock(std::vector<float>& out, double start, const Knock& knock, float volume) {
    const std::vector<float>& wave = knockWaveform();
    const double first = std::ceil((knock.time - start) * kSampleRate);
    const double gain = static_cast<double>(knock.gain) * static_cast<double>(volume);
    const double rate = static_cast<double>(knock.pitch);
    const double offset = (knock.time - start) * kSampleRate; // fractional sample of the onset
    for (double i = std::max(0.0, first); i < static_cast<double>(out.size()); i += 1.0) {
        const double at = (i - offset) * rate; // position in the waveform, samples
        const std::size_t k = static_cast<std::size_t>(at);
        if (k + 1 >= wave.size()) break;
        const double frac = at - static_cast<double>(k);
        const double v = wave[k] * (1.0 - frac) + wave[k + 1] * frac;
        out[static_cast<std::size_t>(i)] += static_cast<float>(gain * v);
    }
}

bool soundOn(const SoundControl& sound, bool lessonOpen) {
    return sound.chosen ? sound.on : lessonOpen;
}

void toggleSound(SoundControl& sound, bool lessonOpen) {
    sound.on = !soundOn(sound, lessonOpen);
    sound.chosen = true;
}
