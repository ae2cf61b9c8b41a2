#include "core/speech/WavFile.h"
#include "core/common/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <unistd.h>

using namespace vl;

namespace {

std::filesystem::path scratch(const std::string& name) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("visemelab-speech-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir / name;
}

std::vector<std::int16_t> tone(std::size_t n) {
    std::vector<std::int16_t> samples(n);
    for (std::size_t i = 0; i < n; ++i)
        samples[i] = static_cast<std::int16_t>(32767 * std::sin(0.05 * double(i)));
    samples[0] = -32768;
    return samples;
}

} // namespace

TEST(WavFile, RoundTripIsExact) {
    const auto samples = tone(22050);
    const auto path = scratch("tone.wav");
    writeWav(path, samples, 22050);
    EXPECT_EQ(std::filesystem::file_size(path), 44u + 2 * samples.size());
    const WavAudio audio = readWav(path);
    EXPECT_EQ(audio.sampleRate, 22050);
    EXPECT_EQ(audio.channels, 1);
    EXPECT_EQ(audio.samples, samples);
}

TEST(WavFile, StreamedFileEqualsTheOneWrittenAtOnceAndAppearsOnlyWhenFinished) {
    const auto samples = tone(1001);
    const auto path = scratch("stream.wav");
    std::filesystem::remove(path);
    {
        WavStreamWriter unfinished(path, 16000);
        unfinished.append(samples);
    }
    EXPECT_FALSE(std::filesystem::exists(path));
    WavStreamWriter writer(path, 16000);
    writer.append(std::span(samples).first(500));
    writer.append(std::span(samples).subspan(500));
    writer.finish();
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    EXPECT_EQ(bytes, formatWav(samples, 16000));
}

TEST(WavFile, BadFilesNameTheFileAndChunk) {
    const auto expectError = [](std::string_view bytes, const std::string& phrase) {
        try {
            parseWav(bytes, "clip.wav");
            FAIL() << "expected InputError: " << phrase;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
        }
    };
    const std::string good = formatWav(tone(10), 8000);
    expectError("hello", "clip.wav: not a WAV file");
    expectError(good.substr(0, good.size() - 3), "clip.wav: chunk 'data': truncated");
    std::string eightBit = good;
    eightBit[34] = 8;
    expectError(eightBit, "only 16-bit PCM");
    expectError(good.substr(0, 12), "no 'fmt ' chunk");
    std::string threeChannels = good; // 10 samples are not whole frames of 3 channels
    threeChannels[22] = 3;
    expectError(threeChannels, "clip.wav: chunk 'data': 20 bytes are not whole frames of 3 channels");
    // A second 'fmt ' after the data would reinterpret the samples already read (found by fuzzing).
    expectError(good + good.substr(12, 24), "clip.wav: chunk 'fmt ': appears twice");
    expectError(good + good.substr(36), "clip.wav: chunk 'data': appears twice");
    EXPECT_EQ(parseWav(good, "clip.wav").samples, tone(10));
}
