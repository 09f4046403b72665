// The collisions' knocks as logic (collision_sound.h): loudness logarithmic in the impulse, pitch
// by the lighter block's size, walls lower, the rate limit, the waveform and its mixing.
#include "app.h"
#include "collision_sound.h"
#include "input_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

CollisionRecord hit(double time, double m1, double v1, double v1After, int other = 1,
                    double m2 = 1.0) {
    CollisionRecord c;
    c.time = time;
    c.block = 0;
    c.other = other;
    c.m1 = m1;
    c.m2 = m2;
    c.v1 = v1;
    c.v1After = v1After;
    return c;
}

World twoBlocks(double size0, double size1) {
    World w;
    Block a, b;
    a.size = {size0, size0};
    b.size = {size1, size1};
    w.blocks = {a, b};
    return w;
}

// Float gains: 1e-6 relative.
TEST(Sound, LoudnessIsLogarithmicInTheImpulse) {
    EXPECT_FLOAT_EQ(knockGain(kLoudestImpulse), 1.0f);
    EXPECT_FLOAT_EQ(knockGain(10.0 * kLoudestImpulse), 1.0f);
    // kDecibelsPerDecade for each tenfold impulse: 8 dB is a factor 10^(8/20).
    EXPECT_NEAR(knockGain(10.0) / knockGain(1.0), std::pow(10.0, 8.0 / 20.0), 1e-6);
    EXPECT_NEAR(knockGain(0.1) / knockGain(0.01), std::pow(10.0, 8.0 / 20.0), 1e-6);
    EXPECT_GT(knockGain(kQuietestImpulse), 0.0f);
    EXPECT_EQ(knockGain(0.5 * kQuietestImpulse), 0.0f);
    EXPECT_EQ(knockGain(std::nan("")), 0.0f);
}

TEST(Sound, ImpulseIsTheMomentumChangeOfTheFiniteBody) {
    EXPECT_DOUBLE_EQ(collisionImpulse(hit(0.0, 2.0, 3.0, -1.0)), 8.0); // 2 kg · 4 m/s
    CollisionRecord c = hit(0.0, kInf, 0.0, 0.0, 1, 0.5); // a static body hit by 0.5 kg
    c.v2 = -2.0;
    c.v2After = 2.0;
    EXPECT_DOUBLE_EQ(collisionImpulse(c), 2.0);
}

// Exact: 440 / sqrt(size), halved against an infinite mass, within [110, 1760] Hz.
TEST(Sound, PitchByTheLighterBlocksSizeAndWallsLower) {
    EXPECT_DOUBLE_EQ(knockFrequency(1.0, false), 440.0);
    EXPECT_DOUBLE_EQ(knockFrequency(0.25, false), 880.0);
    EXPECT_DOUBLE_EQ(knockFrequency(0.25, true), 440.0);
    EXPECT_DOUBLE_EQ(knockFrequency(1e-6, false), 1760.0);
    EXPECT_DOUBLE_EQ(knockFrequency(1e6, false), 110.0);
    const World w = twoBlocks(0.25, 4.0);
    // The lighter block is the small one (1 kg against 1000 kg): its size sets the pitch.
    const Knock k = knockFor(hit(1.0, 1.0, 2.0, -2.0, 1, 1000.0), w);
    EXPECT_FLOAT_EQ(k.pitch, 2.0f);
    EXPECT_DOUBLE_EQ(k.time, 1.0);
    // Now the big block is the lighter one.
    EXPECT_FLOAT_EQ(knockFor(hit(1.0, 1000.0, 2.0, 1.9, 1, 1.0), w).pitch, 0.5f);
    // Against a wall: an octave lower.
    EXPECT_FLOAT_EQ(knockFor(hit(1.0, 1.0, 2.0, -2.0, -1, kInf), w).pitch, 1.0f);
}

TEST(Sound, RestingContactsAreSilent) {
    CollisionRecord c = hit(0.0, 1.0, 2.0, 0.0);
    c.rest = true;
    EXPECT_EQ(knockFor(c, twoBlocks(1.0, 1.0)).gain, 0.0f);
    KnockScheduler s;
    EXPECT_TRUE(s.admit({c}, twoBlocks(1.0, 1.0)).empty());
}

TEST(Sound, OneKnockPerCollisionUpToTheRateLimit) {
    const World w = twoBlocks(1.0, 1.0);
    KnockScheduler s;
    // Spaced more than kMinKnockGap: every one knocks; closer: folded into the knock sounding.
    const std::vector<CollisionRecord> log{hit(0.0, 1.0, 1.0, -1.0),   hit(0.01, 1.0, 1.0, -1.0),
                                           hit(0.049, 1.0, 1.0, -1.0), hit(0.05, 1.0, 1.0, -1.0),
                                           hit(0.2, 1.0, 1.0, -1.0),   hit(0.3, 1.0, 1.0, -1.0)};
    const std::vector<Knock> knocks = s.admit(log, w);
    ASSERT_EQ(knocks.size(), 4u);
    EXPECT_DOUBLE_EQ(knocks[1].time, 0.05);
    EXPECT_DOUBLE_EQ(knocks[2].time, 0.2);
    // A gas: 1000 collisions in one second hum at 20 knocks a second.
    std::vector<CollisionRecord> gas;
    for (int i = 0; i < 1000; ++i) gas.push_back(hit(1.0 + i * 0.001, 1.0, 1.0, -1.0));
    EXPECT_EQ(s.admit(gas, w).size(), static_cast<std::size_t>(1.0 / kMinKnockGap));
    // Time going back (a reset): the next collision knocks at once.
    EXPECT_EQ(s.admit({hit(0.0, 1.0, 1.0, -1.0)}, w).size(), 1u);
}

TEST(Sound, TheKnockIsShortAndEndsInSilence) {
    const std::vector<float>& w = knockWaveform();
    ASSERT_EQ(w.size(), static_cast<std::size_t>(kKnockSeconds * kSampleRate));
    float peak = 0.0f;
    std::size_t at = 0;
    for (std::size_t i = 0; i < w.size(); ++i) {
        if (std::abs(w[i]) > peak) {
            peak = std::abs(w[i]);
            at = i;
        }
    }
    EXPECT_FLOAT_EQ(peak, 1.0f);
    EXPECT_LT(at, static_cast<std::size_t>(0.01 * kSampleRate)); // a knock: loudest at once
    EXPECT_EQ(w.front(), 0.0f);                                  // no click at either end
    EXPECT_NEAR(w.back(), 0.0f, 1e-3f);
}

TEST(Sound, MixingPlacesTheKnockAtItsTimeWithItsGain) {
    std::vector<float> track(kSampleRate, 0.0f); // 1 s from t = 2 s
    Knock k;
    k.time = 2.5;
    k.gain = 0.5f;
    k.pitch = 1.0f;
    mixKnock(track, 2.0, k, 0.5f);
    const auto first = std::find_if(track.begin(), track.end(), [](float v) { return v != 0.0f; });
    EXPECT_EQ(first - track.begin(), kSampleRate / 2 + 1); // sample 0 of the knock is 0
    float peak = 0.0f;
    for (float v : track) peak = std::max(peak, std::abs(v));
    EXPECT_NEAR(peak, 0.25f, 0.01f); // gain 0.5 at volume 0.5; between samples at most 1% off
    // At twice the pitch it lasts half as long.
    std::vector<float> high(kSampleRate, 0.0f);
    k.pitch = 2.0f;
    mixKnock(high, 2.0, k, 1.0f);
    const auto last = std::find_if(high.rbegin(), high.rend(), [](float v) { return v != 0.0f; });
    const long length = (high.rend() - last) - kSampleRate / 2;
    EXPECT_NEAR(static_cast<double>(length), kKnockSeconds * kSampleRate / 2.0, 2.0);
}

TEST(Sound, OffByDefaultOutsideLessonsAndMTogglesAndRemembers) {
    SoundControl s;
    EXPECT_FALSE(soundOn(s, false));
    EXPECT_TRUE(soundOn(s, true));
    toggleSound(s, true); // in a lesson: M turns it off, and that is the choice from now on
    EXPECT_FALSE(soundOn(s, true));
    EXPECT_FALSE(soundOn(s, false));
    EXPECT_TRUE(s.chosen);
    toggleSound(s, false);
    EXPECT_TRUE(soundOn(s, false));
    EXPECT_EQ(actionForKey(keys::kM, false), Action::ToggleSound);
    // The app queues knocks only while sound is on: lecture_example_1's one collision at
    // t = 0.625 s, in the 38th frame of 1/60 s.
    App app;
    ASSERT_TRUE(loadScene(app, SANDBOX_SCENES_DIR "/lecture_example_1.json")) << app.ui.messages.error;
    for (int i = 0; i < 40; ++i) stepSimulation(app);
    EXPECT_GE(app.sim.run.totals.collisions, 1);
    EXPECT_TRUE(app.sim.sound.queue.empty());
    toggleSound(app.sim.sound, app.lesson.active());
    resetScene(app);
    for (int i = 0; i < 40; ++i) stepSimulation(app);
    ASSERT_EQ(app.sim.sound.queue.size(), 1u);
    EXPECT_NEAR(app.sim.sound.queue[0].time, 0.625, 1e-12); // the frames sum 1/60 s: rounding
}

} // namespace
