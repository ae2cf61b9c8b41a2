#include "core/speech/WavFile.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"

#include <limits>

namespace vl {

namespace {

constexpr std::uint64_t kHeaderBytes = 44;
// The RIFF size field (file size - 8) is 32 bits.
constexpr std::uint64_t kMaxDataBytes = std::numeric_limits<std::uint32_t>::max() - (kHeaderBytes - 8);

void putLe(std::string& out, std::uint64_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xFF));
}

std::uint64_t getLe(std::string_view in, std::size_t at, int bytes) {
    std::uint64_t value = 0;
    for (int i = 0; i < bytes; ++i) value |= std::uint64_t(static_cast<unsigned char>(in[at + i])) << (8 * i);
    return value;
}

std::string header(std::uint64_t dataBytes, int sampleRate, const std::string& where) {
    if (dataBytes > kMaxDataBytes) throwInputError(where, "audio too long for a WAV file (over 4 GiB)");
    if (sampleRate <= 0) throwInputError(where, "invalid sample rate " + std::to_string(sampleRate));
    constexpr int kChannels = 1, kBytesPerSample = 2;
    std::string h = "RIFF";
    putLe(h, kHeaderBytes - 8 + dataBytes, 4);
    h += "WAVEfmt ";
    putLe(h, 16, 4); // PCM fmt chunk size
    putLe(h, 1, 2);  // PCM
    putLe(h, kChannels, 2);
    putLe(h, static_cast<std::uint64_t>(sampleRate), 4);
    putLe(h, static_cast<std::uint64_t>(sampleRate) * kChannels * kBytesPerSample, 4); // bytes per second
    putLe(h, kChannels * kBytesPerSample, 2);                                          // block align
    putLe(h, 16, 2);                                                                   // bits per sample
    h += "data";
    putLe(h, dataBytes, 4);
    return h;
}

std::string littleEndianSamples(std::span<const std::int16_t> samples) {
    std::string bytes;
    bytes.reserve(samples.size() * 2);
    for (const std::int16_t s : samples) putLe(bytes, static_cast<std::uint16_t>(s), 2);
    return bytes;
}

} // namespace

std::string formatWav(std::span<const std::int16_t> samples, int sampleRate) {
    return header(samples.size() * 2, sampleRate, "WAV audio") + littleEndianSamples(samples);
}

void writeWav(const std::filesystem::path& path, std::span<const std::int16_t> samples, int sampleRate) {
    writeFileAtomically(path,
                        header(samples.size() * 2, sampleRate, path.string()) + littleEndianSamples(samples));
}

WavStreamWriter::WavStreamWriter(const std::filesystem::path& path, int sampleRate)
    : path_(path), file_(path) {
    file_.write(header(0, sampleRate, path.string()));
}

void WavStreamWriter::append(std::span<const std::int16_t> samples) {
    if ((samples_ + samples.size()) * 2 > kMaxDataBytes)
        throwInputError(path_.string(), "audio too long for a WAV file (over 4 GiB)");
    file_.write(littleEndianSamples(samples));
    samples_ += samples.size();
}

void WavStreamWriter::finish() {
    const std::uint64_t dataBytes = samples_ * 2;
    std::string size;
    putLe(size, kHeaderBytes - 8 + dataBytes, 4);
    file_.overwrite(4, size);
    size.clear();
    putLe(size, dataBytes, 4);
    file_.overwrite(kHeaderBytes - 4, size);
    file_.commit();
}

WavAudio parseWav(std::string_view bytes, std::string_view source) {
    const std::string where(source);
    if (bytes.size() < 12 || bytes.substr(0, 4) != "RIFF" || bytes.substr(8, 4) != "WAVE")
        throwInputError(where, "not a WAV file (no RIFF/WAVE header)");
    WavAudio audio;
    bool haveFormat = false, haveData = false;
    int bits = 0;
    std::size_t at = 12;
    while (at + 8 <= bytes.size()) {
        const std::string id(bytes.substr(at, 4));
        const std::uint64_t size = getLe(bytes, at + 4, 4);
        const std::size_t body = at + 8;
        if (size > bytes.size() - body)
            throwInputError(where + ": chunk '" + id + "'",
                            "truncated (" + std::to_string(size) + " bytes declared, " +
                                std::to_string(bytes.size() - body) + " present)");
        // A second 'fmt ' after 'data' would reinterpret the samples already read (found by fuzzing:
        // a later chunk changed the channel count so the samples no longer filled whole frames).
        if ((id == "fmt " && haveFormat) || (id == "data" && haveData))
            throwInputError(where + ": chunk '" + id + "'", "appears twice");
        if (id == "fmt ") {
            if (size < 16) throwInputError(where + ": chunk 'fmt '", "too short");
            const auto format = getLe(bytes, body, 2);
            audio.channels = static_cast<int>(getLe(bytes, body + 2, 2));
            audio.sampleRate = static_cast<int>(getLe(bytes, body + 4, 4));
            bits = static_cast<int>(getLe(bytes, body + 14, 2));
            if (format != 1 || bits != 16)
                throwInputError(where + ": chunk 'fmt '", "only 16-bit PCM is read (format " +
                                                              std::to_string(format) + ", " +
                                                              std::to_string(bits) + " bits)");
            if (audio.channels < 1 || audio.sampleRate < 1)
                throwInputError(where + ": chunk 'fmt '", "no channels or no sample rate");
            haveFormat = true;
        } else if (id == "data") {
            if (!haveFormat) throwInputError(where + ": chunk 'data'", "comes before the 'fmt ' chunk");
            // Every sample belongs to a frame of one 16-bit value per channel (found by fuzzing: 16 bytes
            // of "65535-channel" audio were accepted as 8 samples of no whole frame).
            const std::uint64_t frameBytes = 2 * static_cast<std::uint64_t>(audio.channels);
            if (size % frameBytes != 0)
                throwInputError(where + ": chunk 'data'",
                                std::to_string(size) + " bytes are not whole frames of " +
                                    std::to_string(audio.channels) + " channels x 16 bits");
            audio.samples.resize(size / 2);
            for (std::size_t i = 0; i < audio.samples.size(); ++i)
                audio.samples[i] =
                    static_cast<std::int16_t>(static_cast<std::uint16_t>(getLe(bytes, body + 2 * i, 2)));
            haveData = true;
        }
        at = body + size + (size & 1); // chunks are padded to even sizes
    }
    if (!haveFormat) throwInputError(where, "no 'fmt ' chunk");
    if (!haveData) throwInputError(where, "no 'data' chunk");
    return audio;
}

WavAudio readWav(const std::filesystem::path& path) {
    return parseWav(readFileToString(path), path.string());
}

} // namespace vl
