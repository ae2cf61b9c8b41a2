#pragma once
// Plays the Say section's speech on the default output device with PortAudio (Debian's
// libportaudio2). PortAudio starts on the first play, not with the editor. Without an output
// device (a headless machine, Xvfb) nothing is played and status() says so; the editor then
// animates on its own clock. While it plays, position() is the clock the faces follow, so picture
// and sound stay in sync.
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

struct PaStreamCallbackTimeInfo; // portaudio.h, included only by the .cpp

namespace vl::ui {

class AudioPlayer {
  public:
    AudioPlayer();
    ~AudioPlayer();
    AudioPlayer(const AudioPlayer&) = delete;
    AudioPlayer& operator=(const AudioPlayer&) = delete;

    // Starts `samples` (mono 16-bit at `sampleRate`) from `start` seconds; stops what was playing.
    // Returns false when there is no output device or the stream cannot open (status() says why).
    bool play(std::shared_ptr<const std::vector<std::int16_t>> samples, int sampleRate, double start);
    void stop();
    // True while the stream plays (false once it reached the end).
    bool playing() const;
    // Seconds into the samples that are heard now (handed to the device, less its latency).
    double position() const;
    // "audio: <device>", "no audio device: speech is shown silently", or why the device failed;
    // "" before the first play.
    const std::string& status() const { return status_; }
    // Whether an output device was found (false before the first play).
    bool available() const { return available_; }

  private:
    bool initialise();
    // PortAudio's stream callback (PaStreamCallback), on the audio thread.
    static int callback(const void*, void* output, unsigned long frames, const ::PaStreamCallbackTimeInfo*,
                        unsigned long, void* self);

    bool initialised_ = false;
    bool available_ = false;
    std::string status_;
    void* stream_ = nullptr; // PaStream
    std::shared_ptr<const std::vector<std::int16_t>> samples_;
    int sampleRate_ = 0;
    double start_ = 0.0, latency_ = 0.0; // seconds
    std::atomic<std::size_t> next_{0};   // next sample the callback copies
    std::atomic<bool> finished_{true};
};

} // namespace vl::ui
