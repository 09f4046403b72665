// What `sandbox-offscreen SCENE --frames N --audio-wav FILE` writes: a knock for each collision
// up to the rate limit (their onsets counted in the file and compared with the collisions the
// engine reports for the same frames), a louder onset for a larger impulse, and silence when
// nothing collides.
#include "collision_sound.h"
#include "scene.h"

#include <gtest/gtest.h>
#include <sndfile.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Track {
    int rate = 0;
    std::vector<float> samples;
};

// Runs sandbox-offscreen on `scene` for `frames` frames and reads the WAV it writes.
Track listen(const std::string& scene, int frames) {
    const fs::path dir = fs::path(SANDBOX_AUDIO_OUTPUT_DIR);
    fs::create_directories(dir);
    const fs::path wav = dir / (scene + "_" + std::to_string(frames) + ".wav");
    fs::remove(wav);
    const std::string command = std::string("'") + SANDBOX_OFFSCREEN_EXE + "' " + scene +
                                " --frames " + std::to_string(frames) + " --audio-wav '" +
                                wav.string() + "' > /dev/null 2>&1";
    const int status = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command;
    Track t;
    SF_INFO info{};
    SNDFILE* f = sf_open(wav.string().c_str(), SFM_READ, &info);
    if (!f) {
        ADD_FAILURE() << "cannot read " << wav;
        return t;
    }
    EXPECT_EQ(info.channels, 1);
    t.rate = info.samplerate;
    t.samples.resize(static_cast<std::size_t>(info.frames));
    sf_read_float(f, t.samples.data(), info.frames);
    sf_close(f);
    return t;
}

struct Onset {
    double time; // s from the track's start
    float peak;  // the loudest sample of the knock's first 15 ms
};

// Onsets: 5 ms blocks whose peak is above -60 dB and more than twice the louder of the two
// blocks before (a knock's 110 Hz and up fit in 10 ms, so its own waves never count twice), at
// least 30 ms after the last onset (less than the rate limit's 50 ms).
std::vector<Onset> onsets(const Track& t) {
    const std::size_t block = static_cast<std::size_t>(t.rate / 200);
    std::vector<float> env;
    for (std::size_t i = 0; i + block <= t.samples.size(); i += block) {
        float peak = 0.0f;
        for (std::size_t k = i; k < i + block; ++k) peak = std::max(peak, std::abs(t.samples[k]));
        env.push_back(peak);
    }
    std::vector<Onset> out;
    double last = -1.0;
    for (std::size_t i = 0; i < env.size(); ++i) {
        const float before = std::max(i >= 1 ? env[i - 1] : 0.0f, i >= 2 ? env[i - 2] : 0.0f);
        const double time = static_cast<double>(i * block) / t.rate;
        if (env[i] > 1e-3f && env[i] > 2.0f * before && time - last > 0.03) {
            float peak = 0.0f;
            for (std::size_t k = i; k < std::min(env.size(), i + 3); ++k)
                peak = std::max(peak, env[k]);
            out.push_back({time, peak});
            last = time;
        }
    }
    return out;
}

// The engine's collisions for the same frames, as the app steps them.
std::vector<CollisionRecord> collisions(const std::string& scene, int frames) {
    const SceneResult loaded =
        loadSceneFile(std::string(SANDBOX_SCENES_DIR) + "/" + scene + ".json");
    EXPECT_TRUE(loaded.scene) << loaded.error.text();
    if (!loaded.scene) return {};
    World world = makeWorld(*loaded.scene);
    std::vector<CollisionRecord> all, log;
    for (int i = 0; i < frames; ++i) {
        log.clear();
        world.step(&log);
        all.insert(all.end(), log.begin(), log.end());
    }
    return all;
}

// high_mass_ratio for 10 s: the giant's first hit at 4.75 s, then the small block rattles ever
// faster between wall and giant. Every collision more than kMinKnockGap after the last knock
// starts one; the rest fold in.
TEST(AudioWav, HighMassRatioHasOneOnsetPerCollisionUpToTheRateLimit) {
    const int frames = 600;
    const std::vector<Onset> heard = onsets(listen("high_mass_ratio", frames));
    std::vector<double> expected;
    double last = -1e9;
    std::size_t audible = 0;
    for (const CollisionRecord& c : collisions("high_mass_ratio", frames)) {
        if (c.rest) continue;
        ++audible;
        if (c.time - last < kMinKnockGap) continue;
        expected.push_back(c.time);
        last = c.time;
    }
    EXPECT_GT(audible, expected.size()) << "the rate limit was never reached: a weak test";
    ASSERT_EQ(heard.size(), expected.size());
    // Each onset where its collision is: within one 5 ms block (and the sample of the onset).
    for (std::size_t i = 0; i < heard.size(); ++i)
        EXPECT_NEAR(heard[i].time, expected[i], 0.006) << "onset " << i;
    // Never more than the rate limit allows in any second.
    for (std::size_t i = 0; i < heard.size(); ++i) {
        std::size_t inSecond = 0;
        for (std::size_t k = i; k < heard.size() && heard[k].time < heard[i].time + 1.0; ++k)
            ++inSecond;
        EXPECT_LE(inSecond, static_cast<std::size_t>(1.0 / kMinKnockGap) + 1);
    }
}

// bounce_exact: a block bouncing on the floor with C < 1, each bounce's impulse smaller than the
// last: each onset quieter than the one before.
TEST(AudioWav, ALargerImpulseKnocksLouder) {
    const int frames = 420; // 7 s: the first bounces, each more than kMinKnockGap apart
    std::vector<double> impulses;
    for (const CollisionRecord& c : collisions("bounce_exact", frames))
        if (!c.rest) impulses.push_back(collisionImpulse(c));
    const std::vector<Onset> heard = onsets(listen("bounce_exact", frames));
    ASSERT_EQ(heard.size(), impulses.size());
    ASSERT_GE(heard.size(), 5u);
    for (std::size_t i = 1; i < heard.size(); ++i) {
        ASSERT_LT(impulses[i], impulses[i - 1]) << "the scene's premise: bounces get softer";
        EXPECT_LT(heard[i].peak, heard[i - 1].peak) << "onset " << i;
    }
}

// lecture_example_1's first collision is at 0.625 s: half a second of it is silence, and the
// file still lasts the frames simulated plus one knock's length.
TEST(AudioWav, ASceneWithoutCollisionsIsSilent) {
    const Track t = listen("lecture_example_1", 30);
    ASSERT_EQ(t.rate, kSampleRate);
    EXPECT_EQ(t.samples.size(),
              static_cast<std::size_t>(std::ceil((30.0 / 60.0 + kKnockSeconds) * kSampleRate)));
    EXPECT_TRUE(std::all_of(t.samples.begin(), t.samples.end(), [](float v) { return v == 0.0f; }));
    // The check can fail: a few frames more take in the collision.
    EXPECT_EQ(onsets(listen("lecture_example_1", 40)).size(), 1u);
}

} // namespace
