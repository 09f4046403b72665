#include "wav_io.h"

#include <sndfile.h>

bool writeWav(const std::string& path, const std::vector<float>& samples, int sampleRate,
              std::string* error) {
    SF_INFO info{};
    info.samplerate = sampleRate;
    info.channels = 1;
    info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
    SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
    if (!file) {
        if (error) *error = "cannot write " + path + ": " + sf_strerror(nullptr);
        return false;
    }
    // Floats beyond +-1 clip rather than wrap around.
    sf_command(file, SFC_SET_CLIPPING, nullptr, SF_TRUE);
    const sf_count_t n = static_cast<sf_count_t>(samples.size());
    const bool ok = sf_write_float(file, samples.data(), n) == n;
    if (!ok && error) *error = "cannot write " + path + ": " + sf_strerror(file);
    return sf_close(file) == 0 && ok;
}
