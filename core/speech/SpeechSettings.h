#pragma once
// What a designer has the face say in the editor: the text, the voice and the speaking rate. Saved
// with the project (its optional "speech" section), so a test sentence stays with the face.
#include <cstddef>
#include <string>
#include <string_view>

namespace vl {

// espeak-ng's range of speaking rates.
inline constexpr int kMinWordsPerMinute = 80;
inline constexpr int kMaxWordsPerMinute = 450;
// Longer texts are spoken from a file (`visemelab say --text-file`), not kept in a project.
inline constexpr std::size_t kMaxSpeechTextBytes = 20000;
inline constexpr std::size_t kMaxVoiceNameBytes = 64;

struct SpeechSettings {
    std::string text;            // UTF-8; empty = nothing to say yet
    std::string voice = "en-us"; // an English espeak-ng voice: en-us, en-gb, en-gb-scotland, en-029, ...
    int wordsPerMinute = 175;

    bool isDefault() const { return *this == SpeechSettings{}; }
    bool operator==(const SpeechSettings&) const = default;
};

// Throws InputError at `where` (e.g. "/speech/voice") for a text longer than kMaxSpeechTextBytes
// or with a NUL byte, a voice name that is empty, too long or holds characters other than letters,
// digits and "-_+" (whether espeak-ng knows it is checked when it speaks), and a rate outside
// kMinWordsPerMinute..kMaxWordsPerMinute.
void checkSpeechSettings(const SpeechSettings& settings, std::string_view where);

} // namespace vl
