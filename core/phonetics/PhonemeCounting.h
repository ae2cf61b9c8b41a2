#pragma once
// Phoneme frequencies of a text corpus: transcribe it piece by piece and count.
#include "core/phonetics/CorpusText.h"
#include "core/phonetics/PhonemeTranscriber.h"
#include "core/reduce/Frequencies.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <string_view>

namespace vl {

struct PhonemeCountResult {
    // phoneme -> count, most frequent first (ties by name), pauses counted as "sil". With ARPAbet
    // all 39 phonemes and sil are listed, unseen ones with 0, so a map checked against the table
    // covers the inventory.
    FrequencyTable counts;
    PhonemeNotation notation = PhonemeNotation::Arpabet;
    std::uint64_t phonemeTotal = 0;
    CorpusStats corpus;
    std::map<std::string, std::size_t> skippedSymbols; // left out during this count
};

using CountProgressFn = std::function<void(std::uint64_t bytesDone, std::uint64_t bytesTotal)>;

// Throws InputError naming the file for a missing, empty or binary file, and when the text
// yields no phoneme at all.
PhonemeCountResult countPhonemesInFile(const std::filesystem::path& corpus, PhonemeTranscriber& transcriber,
                                       const CountProgressFn& progress = {});

PhonemeCountResult countPhonemesInText(std::string_view text, std::string_view source,
                                       PhonemeTranscriber& transcriber, const CountProgressFn& progress = {});

// counts -> table sorted by count (descending), then name; `notation` Arpabet adds unseen
// inventory phonemes and sil with 0.
FrequencyTable sortedCountTable(const std::map<std::string, std::uint64_t>& counts, PhonemeNotation notation);

} // namespace vl
