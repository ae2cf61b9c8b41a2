#include "core/phonetics/EspeakTiming.h"

#include "core/phonetics/EspeakMnemonics.h"
#include "core/speech/Utterance.h"

#include <algorithm>
#include <string_view>

namespace vl {

namespace {

struct TimedMnemonic {
    std::string_view mnemonic;
    double start = 0, end = 0;
};

class TimedPhonemeList {
  public:
    // Adds a phoneme starting at `start`; a phoneme before it that would last 0 samples is
    // replaced, a pause after a pause extends the first.
    void push(std::string_view phoneme, double start) {
        if (!out_.empty() && out_.back().phoneme == kSilencePhoneme && phoneme == kSilencePhoneme) return;
        if (!out_.empty() && !(start > out_.back().start)) {
            out_.back().phoneme = std::string(phoneme);
            mergeLastPauses();
            return;
        }
        out_.push_back({std::string(phoneme), start});
    }

    // The ARPAbet phonemes of one word, timed from its mnemonics' spans.
    void pushWord(const std::vector<TimedMnemonic>& word, std::map<std::string, std::size_t>& skipped) {
        if (word.empty()) return;
        std::vector<std::string_view> mnemonics;
        for (const auto& m : word) mnemonics.push_back(m.mnemonic);
        std::vector<std::string> phonemes;
        std::vector<std::size_t> sources;
        appendArpabetForEspeakWord(mnemonics, phonemes, skipped, &sources);
        for (std::size_t o = 0; o < phonemes.size(); ++o) {
            const std::size_t j = sources[o];
            const auto first = std::find(sources.begin(), sources.end(), j) - sources.begin();
            const auto count = std::count(sources.begin(), sources.end(), j);
            const double rank = static_cast<double>(static_cast<std::ptrdiff_t>(o) - first);
            push(phonemes[o],
                 word[j].start + rank * (word[j].end - word[j].start) / static_cast<double>(count));
        }
    }

    std::vector<SampleTimedPhoneme> finish(double total) {
        while (!out_.empty() && !(out_.back().start < total)) out_.pop_back(); // nothing left for it
        if (total > 0 && out_.empty()) out_.push_back({std::string(kSilencePhoneme), 0.0});
        if (!out_.empty()) out_.front().start = 0.0; // skipped leading symbols: the first covers them
        return std::move(out_);
    }

  private:
    void mergeLastPauses() {
        if (out_.size() >= 2 && out_.back().phoneme == kSilencePhoneme &&
            out_[out_.size() - 2].phoneme == kSilencePhoneme)
            out_.pop_back();
    }

    std::vector<SampleTimedPhoneme> out_;
};

} // namespace

std::vector<SampleTimedPhoneme> timeEspeakPhonemes(std::span<const EspeakPhonemeEvent> events,
                                                   std::int64_t totalSamples,
                                                   std::map<std::string, std::size_t>& skipped) {
    const double total = static_cast<double>(std::max<std::int64_t>(totalSamples, 0));
    TimedPhonemeList list;
    // Positions clamped into [0, total] and made non-decreasing, whatever the events say.
    double previous = 0;
    const auto positionOf = [&](std::size_t i) {
        const double at = i < events.size() ? static_cast<double>(events[i].sample) : total;
        return std::clamp(at, previous, total);
    };
    if (events.empty() || positionOf(0) > 0) list.push(kSilencePhoneme, 0.0);
    std::vector<TimedMnemonic> word;
    const auto flushWord = [&] {
        list.pushWord(word, skipped);
        word.clear();
    };
    for (std::size_t i = 0; i < events.size(); ++i) {
        const double start = positionOf(i);
        previous = start;
        const double end = positionOf(i + 1);
        const EspeakSymbol symbol = splitEspeakSymbol(events[i].mnemonic);
        if (events[i].startsWord || symbol.isPause()) flushWord();
        if (symbol.isPause()) {
            // A phoneme written right after the pause marker gets the second half of the span.
            list.push(kSilencePhoneme, start);
            if (!symbol.phoneme.empty()) word.push_back({symbol.phoneme, (start + end) / 2, end});
        } else if (!symbol.phoneme.empty()) {
            word.push_back({symbol.phoneme, start, end});
        }
    }
    flushWord();
    return list.finish(total);
}

} // namespace vl
