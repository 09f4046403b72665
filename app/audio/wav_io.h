// --audio-wav: a mono track written as a 16-bit PCM WAV file (libsndfile).
#pragma once

#include <string>
#include <vector>

// Writes `samples` (-1..1, clipped) at `sampleRate`; false with the reason in `error`.
bool writeWav(const std::string& path, const std::vector<float>& samples, int sampleRate,
              std::string* error);
