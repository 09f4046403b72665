#include "wav_io.h"

#include "printable.h"
#include "safe_file.h"

#include <sndfile.h>

#include <algorithm>
#include <cstring>

namespace {

// libsndfile's virtual I/O onto a string: the WAV is made in memory, then written through a
// SafeFile (the old file kept on failure).
struct MemoryFile {
    std::string bytes;
    sf_count_t at = 0;
};

sf_count_t memoryLength(void* user) {
    return static_cast<sf_count_t>(static_cast<MemoryFile*>(user)->bytes.size());
}
sf_count_t memorySeek(sf_count_t offset, int whence, void* user) {
    MemoryFile& m = *static_cast<MemoryFile*>(user);
    const sf_count_t base = whence == SEEK_SET   ? 0
                            : whence == SEEK_CUR ? m.at
                                                 : static_cast<sf_count_t>(m.bytes.size());
    m.at = std::max<sf_count_t>(0, base + offset);
    return m.at;
}
sf_count_t memoryRead(void* to, sf_count_t count, void* user) {
    MemoryFile& m = *static_cast<MemoryFile*>(user);
    const sf_count_t size = static_cast<sf_count_t>(m.bytes.size());
    const sf_count_t n = std::max<sf_count_t>(0, std::min(count, size - m.at));
    if (n > 0) std::memcpy(to, m.bytes.data() + m.at, static_cast<std::size_t>(n));
    m.at += n;
    return n;
}
sf_count_t memoryWrite(const void* from, sf_count_t count, void* user) {
    MemoryFile& m = *static_cast<MemoryFile*>(user);
    const std::size_t end = static_cast<std::size_t>(m.at + count);
    if (m.bytes.size() < end) m.bytes.resize(end);
    std::memcpy(m.bytes.data() + m.at, from, static_cast<std::size_t>(count));
    m.at += count;
    return count;
}
sf_count_t memoryTell(void* user) {
    return static_cast<MemoryFile*>(user)->at;
}

} // namespace

bool writeWav(const std::string& path, const std::vector<float>& samples, int sampleRate,
              std::string* error) {
    SF_INFO info{};
    info.samplerate = sampleRate;
    info.channels = 1;
    info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
    SF_VIRTUAL_IO io{memoryLength, memorySeek, memoryRead, memoryWrite, memoryTell};
    MemoryFile memory;
    SNDFILE* file = sf_open_virtual(&io, SFM_WRITE, &info, &memory);
    if (!file) {
        if (error) *error = printable(path, kPrintablePath) + ": " + sf_strerror(nullptr);
        return false;
    }
    // Floats beyond +-1 clip rather than wrap around.
    sf_command(file, SFC_SET_CLIPPING, nullptr, SF_TRUE);
    const sf_count_t n = static_cast<sf_count_t>(samples.size());
    const bool encoded = sf_write_float(file, samples.data(), n) == n;
    if (!encoded && error) *error = printable(path, kPrintablePath) + ": " + sf_strerror(file);
    if (sf_close(file) != 0 || !encoded) return false;
    return writeFileSafely(path, memory.bytes, error);
}
