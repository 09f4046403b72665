#include "audio_out.h"

#include <AL/al.h>
#include <AL/alc.h>

#include <algorithm>
#include <cstdint>
#include <vector>

bool AudioOut::open() {
    tried_ = true;
    ALCdevice* device = alcOpenDevice(nullptr);
    if (!device) return false;
    ALCcontext* context = alcCreateContext(device, nullptr);
    if (!context || !alcMakeContextCurrent(context)) {
        if (context) alcDestroyContext(context);
        alcCloseDevice(device);
        return false;
    }
    device_ = device;
    context_ = context;
    std::vector<std::int16_t> pcm;
    for (float v : knockWaveform()) pcm.push_back(static_cast<std::int16_t>(v * 32767.0f));
    alGenBuffers(1, &buffer_);
    alBufferData(buffer_, AL_FORMAT_MONO16, pcm.data(),
                 static_cast<ALsizei>(pcm.size() * sizeof(std::int16_t)), kSampleRate);
    alGenSources(kSources, sources_);
    for (unsigned s : sources_) alSourcei(s, AL_BUFFER, static_cast<ALint>(buffer_));
    ok_ = alGetError() == AL_NO_ERROR;
    return ok_;
}

AudioOut::~AudioOut() {
    if (!context_) return;
    alDeleteSources(kSources, sources_);
    alDeleteBuffers(1, &buffer_);
    alcMakeContextCurrent(nullptr);
    alcDestroyContext(static_cast<ALCcontext*>(context_));
    alcCloseDevice(static_cast<ALCdevice*>(device_));
}

void AudioOut::play(SoundControl& sound) {
    std::vector<Knock> knocks;
    knocks.swap(sound.queue);
    if (knocks.empty() || sound.volume <= 0.0f) return;
    if (!tried_) open();
    if (!ok_) return;
    for (const Knock& k : knocks) {
        // The source that started longest ago (a knock lasts 0.15 s, at most 20 start a second).
        const unsigned s = sources_[next_];
        next_ = (next_ + 1) % kSources;
        alSourceStop(s);
        alSourcef(s, AL_GAIN, std::clamp(k.gain * sound.volume, 0.0f, 1.0f));
        alSourcef(s, AL_PITCH, k.pitch);
        alSourcePlay(s);
    }
}
