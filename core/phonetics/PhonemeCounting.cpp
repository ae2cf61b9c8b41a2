#include "core/phonetics/PhonemeCounting.h"

#include "core/common/Error.h"
#include "core/phonetics/Arpabet.h"
#include "core/speech/Utterance.h"

#include <algorithm>

namespace vl {

namespace {

using Counter = std::map<std::string, std::uint64_t>;

CorpusChunkFn countingChunkFn(PhonemeTranscriber& transcriber, Counter& counts,
                              const CountProgressFn& progress) {
    return
        [&transcriber, &counts, &progress](std::string_view chunk, std::uint64_t done, std::uint64_t total) {
            for (const auto& phoneme : transcriber.transcribe(chunk)) ++counts[phoneme];
            if (progress) progress(done, total);
        };
}

PhonemeCountResult finishCount(const Counter& counts, const CorpusStats& corpus,
                               PhonemeTranscriber& transcriber,
                               const std::map<std::string, std::size_t>& skippedBefore,
                               std::string_view source) {
    PhonemeCountResult result;
    result.notation = transcriber.notation();
    result.corpus = corpus;
    for (const auto& [phoneme, count] : counts) result.phonemeTotal += count;
    if (result.phonemeTotal == 0)
        throwInputError(source, "no phonemes found in " + std::to_string(corpus.bytes) + " bytes of text");
    result.counts = sortedCountTable(counts, result.notation);
    for (const auto& [symbol, count] : transcriber.skippedSymbols()) {
        const auto before = skippedBefore.find(symbol);
        const std::size_t earlier = before == skippedBefore.end() ? 0 : before->second;
        if (count > earlier) result.skippedSymbols[symbol] = count - earlier;
    }
    return result;
}

} // namespace

FrequencyTable sortedCountTable(const std::map<std::string, std::uint64_t>& counts,
                                PhonemeNotation notation) {
    std::vector<std::pair<std::string, std::uint64_t>> rows(counts.begin(), counts.end());
    if (notation == PhonemeNotation::Arpabet) {
        for (const auto& phoneme : arpabetInventory())
            if (!counts.contains(std::string(phoneme.symbol))) rows.emplace_back(phoneme.symbol, 0);
        if (!counts.contains(std::string(kSilencePhoneme))) rows.emplace_back(kSilencePhoneme, 0);
    }
    std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) {
        return a.second != b.second ? a.second > b.second : a.first < b.first;
    });
    FrequencyTable table;
    for (auto& [phoneme, count] : rows)
        table.entries.emplace_back(std::move(phoneme), static_cast<double>(count));
    return table;
}

PhonemeCountResult countPhonemesInFile(const std::filesystem::path& corpus, PhonemeTranscriber& transcriber,
                                       const CountProgressFn& progress) {
    const auto skippedBefore = transcriber.skippedSymbols();
    Counter counts;
    const CorpusStats stats = forEachCorpusChunk(corpus, countingChunkFn(transcriber, counts, progress));
    return finishCount(counts, stats, transcriber, skippedBefore, corpus.string());
}

PhonemeCountResult countPhonemesInText(std::string_view text, std::string_view source,
                                       PhonemeTranscriber& transcriber, const CountProgressFn& progress) {
    const auto skippedBefore = transcriber.skippedSymbols();
    Counter counts;
    const CorpusStats stats = forEachTextChunk(text, source, countingChunkFn(transcriber, counts, progress));
    return finishCount(counts, stats, transcriber, skippedBefore, source);
}

} // namespace vl
