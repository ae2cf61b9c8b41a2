#pragma once
// Speech on the avatar fixtures without espeak-ng: a small phoneme table with an Oculus map (the
// shape of the bundled en-us table and map_oculus.csv) and a timed utterance of its phonemes.
#include "core/project/AvatarSpeech.h"
#include "core/project/AvatarSpeechGlb.h"
#include "core/speech/FaceTrack.h"

#include <string>
#include <vector>

namespace vl::test {

inline FrequencySource fixturePhonemeTable() {
    FrequencySource table;
    const std::pair<const char*, const char*> map[] = {{"sil", "sil"}, {"AA", "aa"}, {"M", "PP"},
                                                       {"F", "FF"},    {"IY", "ih"}, {"UW", "ou"},
                                                       {"S", "SS"},    {"OW", "oh"}};
    double frequency = 1.0;
    for (const auto& [phoneme, viseme] : map) {
        table.phonemes.entries.emplace_back(phoneme, frequency++);
        table.map.entries.emplace_back(phoneme, viseme);
    }
    return table;
}

// "sil M AA F IY S UW OW sil": AA from 0.2 s to 0.5 s.
inline std::vector<TimedPhoneme> fixtureUtterance() {
    return {{"sil", 0.0, 0.1}, {"M", 0.1, 0.2},   {"AA", 0.2, 0.5}, {"F", 0.5, 0.6},  {"IY", 0.6, 0.75},
            {"S", 0.75, 0.85}, {"UW", 0.85, 1.0}, {"OW", 1.0, 1.2}, {"sil", 1.2, 1.4}};
}

// The avatar file speaking the fixture utterance (reduced to `m` keys when m > 0) as a GLB.
inline std::string speakingFixtureGlb(const std::filesystem::path& avatar, int m,
                                      runtime::Interpolation interpolation) {
    AvatarSpeechOptions options;
    options.reduceTo = m;
    options.phonemeTable = fixturePhonemeTable();
    const AvatarSpeech speech = avatarSpeech(avatar, options);
    const FaceTrack track(speech.reducedFace ? speech.faces.reduced : speech.faces.full, fixtureUtterance(),
                          PlaybackSettings{interpolation}, avatar.string());
    return speakingAvatarGlb(speech, track, 30.0);
}

// The avatar file speaking the fixture utterance on `reduced`, a reduction of it `avatar reduce`
// wrote (say --avatar AVATAR --reduced REDUCED --glb).
inline std::string speakingReducedFixtureGlb(const std::filesystem::path& avatar,
                                             const std::filesystem::path& reduced,
                                             runtime::Interpolation interpolation) {
    AvatarSpeechOptions options;
    options.reduced = reduced;
    options.phonemeTable = fixturePhonemeTable();
    const AvatarSpeech speech = avatarSpeech(avatar, options);
    const FaceTrack track(speech.faces.reduced, fixtureUtterance(), PlaybackSettings{interpolation},
                          avatar.string());
    return speakingAvatarGlb(speech, track, 30.0);
}

} // namespace vl::test
