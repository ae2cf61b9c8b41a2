#include "core/phonetics/EspeakSynthesizer.h"

#include "core/common/Error.h"
#include "core/phonetics/EspeakApi.h"
#include "core/phonetics/EspeakEngine.h"
#include "core/phonetics/EspeakTiming.h"

#include <algorithm>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <vector>

namespace vl {

namespace {

// What the synthesis callback collects; one at a time, under the engine lock.
struct SynthesisRun {
    std::vector<EspeakPhonemeEvent> events;
    std::int64_t samples = 0;
    bool wordStarted = false;
    std::vector<std::int16_t>* keep = nullptr; // audio kept in memory, or
    const AudioSink* sink = nullptr;           // streamed
    std::exception_ptr failure;                // thrown by the sink, rethrown after espeak returns
};

SynthesisRun* currentRun = nullptr;

int onSynthesis(short* wav, int count, espeak_EVENT* events) {
    SynthesisRun& run = *currentRun;
    for (espeak_EVENT* e = events; e && e->type != espeakEVENT_LIST_TERMINATED; ++e) {
        if (e->type == espeakEVENT_WORD) run.wordStarted = true;
        if (e->type != espeakEVENT_PHONEME) continue;
        char name[sizeof e->id.string + 1] = {}; // not terminated when it fills all 8 bytes
        std::memcpy(name, e->id.string, sizeof e->id.string);
        run.events.push_back({name, e->sample, run.wordStarted});
        run.wordStarted = false;
    }
    if (wav && count > 0) {
        const std::span<const std::int16_t> audio(wav, static_cast<std::size_t>(count));
        try { // no exception may cross espeak-ng's C code
            if (run.sink)
                (*run.sink)(audio);
            else
                run.keep->insert(run.keep->end(), audio.begin(), audio.end());
        } catch (...) {
            run.failure = std::current_exception();
            return 1; // stop synthesis
        }
        run.samples += count;
    }
    return 0; // continue
}

class EspeakSynthesizer final : public SpeechSynthesizer {
  public:
    explicit EspeakSynthesizer(const SpeechVoice& voice) : voice_(voice) {
        if (voice.wordsPerMinute < kMinWordsPerMinute || voice.wordsPerMinute > kMaxWordsPerMinute)
            throwInputError("rate " + std::to_string(voice.wordsPerMinute),
                            "the speaking rate must be " + std::to_string(kMinWordsPerMinute) + " to " +
                                std::to_string(kMaxWordsPerMinute) + " words per minute");
        std::lock_guard lock(espeak::engineMutex());
        sampleRate_ = espeak::ensureInitialised();
        const std::string language = espeak::selectVoice(voice_.voice);
        if (!language.starts_with("en"))
            throwInputError("voice '" + voice_.voice + "'",
                            "timed phonemes need an English voice (ARPAbet; en-us, en-gb, ...), this one "
                            "speaks '" +
                                language + "'");
    }

    void speak(std::string_view text, Utterance& utterance, const AudioSink& audio) override {
        std::string input(text);
        std::replace(input.begin(), input.end(), '\0', ' '); // espeak reads up to the first NUL
        SynthesisRun run;
        run.keep = &utterance.samples;
        run.sink = audio ? &audio : nullptr;
        {
            std::lock_guard lock(espeak::engineMutex());
            espeak::selectVoice(voice_.voice);
            espeak::api().SetParameter(espeakRATE, voice_.wordsPerMinute, 0);
            espeak::api().SetSynthCallback(onSynthesis);
            currentRun = &run;
            espeak::hasSpoken() = true;
            const espeak_ERROR status = espeak::api().Synth(input.c_str(), input.size() + 1, 0, POS_CHARACTER,
                                                            0, espeakCHARS_UTF8, nullptr, nullptr);
            currentRun = nullptr;
            if (run.failure) std::rethrow_exception(run.failure);
            if (status != EE_OK) throw std::runtime_error("espeak-ng synthesis failed");
        }
        utterance.sampleRate = sampleRate_;
        if (run.samples == 0) return;
        const auto timed = timeEspeakPhonemes(run.events, run.samples, skipped_);
        appendTimed(timed, static_cast<double>(run.samples), utterance);
    }

    int sampleRate() const override { return sampleRate_; }
    const std::map<std::string, std::size_t>& skippedSymbols() const override { return skipped_; }

  private:
    // Sample positions -> seconds after what the utterance holds; contiguous by construction.
    void appendTimed(const std::vector<SampleTimedPhoneme>& timed, double totalSamples,
                     Utterance& utterance) const {
        const double offset = utterance.duration();
        const double rate = sampleRate_;
        for (std::size_t i = 0; i < timed.size(); ++i) {
            const double start = i == 0 ? offset : utterance.phonemes.back().end;
            const double endSample = i + 1 < timed.size() ? timed[i + 1].start : totalSamples;
            const double end = offset + endSample / rate;
            auto& phonemes = utterance.phonemes;
            if (!phonemes.empty() && phonemes.back().phoneme == kSilencePhoneme &&
                timed[i].phoneme == kSilencePhoneme)
                phonemes.back().end = end;
            else
                phonemes.push_back({timed[i].phoneme, start, end});
        }
    }

    SpeechVoice voice_;
    int sampleRate_ = 0;
    std::map<std::string, std::size_t> skipped_;
};

} // namespace

std::unique_ptr<SpeechSynthesizer> makeEspeakSynthesizer(const SpeechVoice& voice) {
    return std::make_unique<EspeakSynthesizer>(voice);
}

} // namespace vl
