#pragma once
// RIFF WAVE files of 16-bit PCM audio (the format every player and editor reads): writing mono
// speech, streamed or at once, and reading it back.
#include "core/common/AtomicFileWriter.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace vl {

struct WavAudio {
    std::vector<std::int16_t> samples; // interleaved when channels > 1
    int sampleRate = 0;
    int channels = 1;
};

// The whole file as bytes: 44-byte header ("RIFF", "WAVE", a 16-byte PCM "fmt " chunk, "data").
std::string formatWav(std::span<const std::int16_t> samples, int sampleRate);

// Writes mono audio atomically. Throws InputError naming the file on failure or when the audio is
// longer than a WAV file can hold (4 GiB).
void writeWav(const std::filesystem::path& path, std::span<const std::int16_t> samples, int sampleRate);

// A mono WAV file written while the audio is made; the sizes in the header are set by finish(),
// which makes the file appear at its path. Without finish() nothing is written.
class WavStreamWriter {
  public:
    WavStreamWriter(const std::filesystem::path& path, int sampleRate);
    void append(std::span<const std::int16_t> samples);
    void finish();

  private:
    std::filesystem::path path_;
    AtomicFileWriter file_;
    std::uint64_t samples_ = 0;
};

// Reads 16-bit PCM WAV (any channel count, chunks in any order, unknown chunks skipped). Throws
// InputError naming the file and the chunk for anything else or a truncated file.
WavAudio readWav(const std::filesystem::path& path);
WavAudio parseWav(std::string_view bytes, std::string_view source);

} // namespace vl
