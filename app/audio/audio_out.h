// The knocks of collision_sound.h, heard: OpenAL Soft on the desktop and emscripten's OpenAL over
// Web Audio in the browser (one code path, this file). The device opens at the first knock;
// without one (CI, a server, a browser before the page's first click) the app runs on silently.
#pragma once

#include "collision_sound.h"

class AudioOut {
  public:
    AudioOut() = default;
    AudioOut(const AudioOut&) = delete;
    AudioOut& operator=(const AudioOut&) = delete;
    ~AudioOut();
    // Plays the knocks queued in `sound` (and empties the queue) at its volume.
    void play(SoundControl& sound);

  private:
    bool open();
    bool tried_ = false;
    bool ok_ = false;
    void* device_ = nullptr;
    void* context_ = nullptr;
    unsigned buffer_ = 0;
    static constexpr int kSources = 16; // knocks sounding at once: 20/s of 0.15 s need 3
    unsigned sources_[kSources] = {};
    int next_ = 0;
};
