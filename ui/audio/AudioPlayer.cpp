#include "ui/audio/AudioPlayer.h"

#include <portaudio.h>

#include <algorithm>
#include <cstdio>
#include <fcntl.h>
#include <unistd.h>

namespace vl::ui {

namespace {

// ALSA and JACK print dozens of lines to stderr while PortAudio probes for devices that a headless
// machine does not have; they say nothing the status line does not. Silenced during the probe only.
class QuietStderr {
  public:
    QuietStderr() {
        std::fflush(stderr);
        saved_ = dup(STDERR_FILENO);
        const int null = open("/dev/null", O_WRONLY);
        if (saved_ >= 0 && null >= 0) dup2(null, STDERR_FILENO);
        if (null >= 0) close(null);
    }
    ~QuietStderr() {
        std::fflush(stderr);
        if (saved_ >= 0) {
            dup2(saved_, STDERR_FILENO);
            close(saved_);
        }
    }
    QuietStderr(const QuietStderr&) = delete;
    QuietStderr& operator=(const QuietStderr&) = delete;

  private:
    int saved_ = -1;
};

} // namespace

AudioPlayer::AudioPlayer() = default;

AudioPlayer::~AudioPlayer() {
    stop();
    if (initialised_) Pa_Terminate();
}

bool AudioPlayer::initialise() {
    if (initialised_) return available_;
    initialised_ = true;
    PaError error = paNoError;
    PaDeviceIndex device = paNoDevice;
    {
        const QuietStderr quiet;
        error = Pa_Initialize();
        if (error == paNoError) device = Pa_GetDefaultOutputDevice();
    }
    if (error != paNoError) {
        status_ =
            std::string("no audio (PortAudio: ") + Pa_GetErrorText(error) + "): speech is shown silently";
        initialised_ = false; // nothing to terminate
        return false;
    }
    if (device == paNoDevice) {
        status_ = "no audio device: speech is shown silently";
        return false;
    }
    available_ = true;
    status_ = std::string("audio: ") + Pa_GetDeviceInfo(device)->name;
    return true;
}

int AudioPlayer::callback(const void*, void* output, unsigned long frames, const PaStreamCallbackTimeInfo*,
                          unsigned long, void* self) {
    auto& player = *static_cast<AudioPlayer*>(self);
    auto* out = static_cast<std::int16_t*>(output);
    const std::vector<std::int16_t>& samples = *player.samples_;
    const std::size_t at = player.next_.load();
    const std::size_t count = std::min<std::size_t>(frames, samples.size() - std::min(at, samples.size()));
    std::copy_n(samples.begin() + static_cast<std::ptrdiff_t>(at), count, out);
    std::fill(out + count, out + frames, std::int16_t(0));
    player.next_ = at + count;
    if (at + count >= samples.size()) {
        player.finished_ = true;
        return paComplete;
    }
    return paContinue;
}

bool AudioPlayer::play(std::shared_ptr<const std::vector<std::int16_t>> samples, int sampleRate,
                       double start) {
    stop();
    if (!samples || samples->empty() || sampleRate <= 0 || !initialise()) return false;
    samples_ = std::move(samples);
    sampleRate_ = sampleRate;
    next_ = std::min(samples_->size(), static_cast<std::size_t>(std::max(0.0, start) * sampleRate));
    finished_ = false;
    PaStream* stream = nullptr;
    PaError error = Pa_OpenDefaultStream(&stream, 0, 1, paInt16, sampleRate, paFramesPerBufferUnspecified,
                                         &AudioPlayer::callback, this);
    if (error == paNoError) error = Pa_StartStream(stream);
    if (error != paNoError) {
        if (stream) Pa_CloseStream(stream);
        finished_ = true;
        status_ =
            std::string("audio device failed (") + Pa_GetErrorText(error) + "): speech is shown silently";
        return false;
    }
    stream_ = stream;
    const PaStreamInfo* info = Pa_GetStreamInfo(stream);
    latency_ = info ? info->outputLatency : 0.0;
    start_ = static_cast<double>(next_.load()) / sampleRate;
    return true;
}

void AudioPlayer::stop() {
    if (!stream_) return;
    auto* stream = static_cast<PaStream*>(stream_);
    Pa_AbortStream(stream);
    Pa_CloseStream(stream);
    stream_ = nullptr;
    finished_ = true;
}

bool AudioPlayer::playing() const {
    return stream_ != nullptr && !finished_;
}

double AudioPlayer::position() const {
    if (sampleRate_ <= 0) return 0.0;
    // What is heard now left the callback one output latency ago.
    return std::max(start_, static_cast<double>(next_.load()) / sampleRate_ - latency_);
}

} // namespace vl::ui
