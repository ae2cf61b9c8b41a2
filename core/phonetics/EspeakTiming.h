#pragma once
// espeak-ng's phoneme events during synthesis -> timed ARPAbet phonemes. Pure (no espeak-ng), so
// the rules are tested on made-up event lists; EspeakSynthesizer feeds it the real events.
#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace vl {

// One espeakEVENT_PHONEME: the phoneme's espeak mnemonic and the audio sample it starts at.
struct EspeakPhonemeEvent {
    std::string mnemonic;    // "h", "oU", "_:" (a pause), ...
    std::int64_t sample = 0; // from the start of this synthesis
    bool startsWord = false; // the first phoneme after an espeakEVENT_WORD
};

struct SampleTimedPhoneme {
    std::string phoneme; // ARPAbet or "sil"
    double start = 0.0;  // in samples; the phoneme ends where the next starts (the last at the end)
};

// Each event lasts until the next one (the last until `totalSamples`). Words (runs of phonemes
// between word starts and pauses) are converted by appendArpabetForEspeakWord; a mnemonic that
// gives two ARPAbet phonemes (A@ -> AA R) has its time split evenly, one that gives none (a
// repeated r, an unknown symbol counted in `skipped`, a glottal onset _!) leaves its time to the
// phoneme before it. Pauses (_: and _) and the audio before the first phoneme are "sil"; two
// pauses in a row are one. The result starts at sample 0, is strictly increasing and empty only
// when there is no audio.
std::vector<SampleTimedPhoneme> timeEspeakPhonemes(std::span<const EspeakPhonemeEvent> events,
                                                   std::int64_t totalSamples,
                                                   std::map<std::string, std::size_t>& skipped);

} // namespace vl
