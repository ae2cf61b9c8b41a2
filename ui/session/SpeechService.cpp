#include "ui/session/SpeechService.h"

#include "core/common/Error.h"
#include "core/project/ReduceInputs.h"
#include "core/reduce/ReducedModel.h"
#include "core/speech/SpeechErrors.h"

#include <algorithm>
#include <sstream>
#include <utility>

namespace vl::ui {

namespace {

std::string quotedText(const std::string& text) {
    constexpr std::size_t kShown = 40;
    std::string shown = text.substr(0, kShown);
    std::replace(shown.begin(), shown.end(), '\n', ' ');
    return "\"" + shown + (text.size() > kShown ? "...\"" : "\"");
}

// A typed sequence's key in `model` for each viseme name (the key whose members include it).
std::vector<int> keysOfVisemes(const std::vector<std::string>& visemes, const ReducedModel& model) {
    std::vector<int> keys;
    for (const std::string& name : visemes) {
        int key = kNeutralKey;
        for (std::size_t k = 0; k < model.keys.size() && key == kNeutralKey; ++k)
            if (std::find(model.keys[k].members.begin(), model.keys[k].members.end(), name) !=
                model.keys[k].members.end())
                key = static_cast<int>(k);
        keys.push_back(key);
    }
    return keys;
}

FaceTrack trackOf(ReducedModel model, const SpeechClip& clip, const char* where) {
    const PlaybackSettings settings; // the CLI's default blending (cubic)
    if (clip.visemes.empty()) return FaceTrack(std::move(model), clip.phonemes, settings, where);
    std::vector<int> keys = keysOfVisemes(clip.visemes, model);
    return FaceTrack(std::move(model), clip.phonemes, std::move(keys), settings, where);
}

} // namespace

void SpeechService::clear() {
    task_.cancel();
    clip_.reset();
    playback_ = {};
    builtClip_ = 0;
}

void SpeechService::say(const SpeechSettings& settings) {
    checkSpeechSettings(settings, "speech");
    if (settings.text.find_first_not_of(" \t\r\n") == std::string::npos)
        throwInputError("text", "type the text to say first");
    const std::uint64_t id = nextId_++;
    task_.start("Speaking", [settings, id, make = synthesizer_](const auto&) {
        auto synthesizer = make({settings.voice, settings.wordsPerMinute});
        Utterance utterance = synthesizer->synthesize(settings.text);
        if (std::none_of(utterance.phonemes.begin(), utterance.phonemes.end(),
                         [](const TimedPhoneme& p) { return p.phoneme != kSilencePhoneme; }))
            throwInputError("text", "nothing to say: the text has no words espeak-ng speaks");
        SpeechClip clip;
        clip.phonemes = std::move(utterance.phonemes);
        clip.samples = std::move(utterance.samples);
        clip.sampleRate = utterance.sampleRate;
        clip.label = "Say " + quotedText(settings.text) + " (" + settings.voice + ", " +
                     std::to_string(settings.wordsPerMinute) + " wpm)";
        clip.id = id;
        return clip;
    });
}

std::optional<std::string> SpeechService::poll() {
    auto outcome = task_.take();
    if (!outcome) return std::nullopt;
    if (outcome->index() == 1) return std::get<1>(*outcome);
    clip_ = std::make_shared<const SpeechClip>(std::move(std::get<0>(*outcome)));
    return std::nullopt;
}

void SpeechService::playSequence(const Document& document, const std::string& sequence,
                                 double secondsPerKey) {
    const VisemeSet* set = document.visemes.get();
    if (!set) throwInputError("Playback", "load a viseme set first");
    if (!(secondsPerKey > 0)) throwInputError("Playback", "the time per key must be > 0");
    std::vector<std::string> typed, visemes; // as typed (the timeline's phoneme row), and their visemes
    std::istringstream tokens(sequence);
    std::string token;
    while (tokens >> token) {
        typed.push_back(token);
        const std::string* viaMap = document.frequencies.map.visemeOf(token);
        const std::string name = viaMap ? *viaMap : token;
        if (set->find(name) < 0)
            throwInputError("Playback", "'" + token + "' is neither a viseme nor a phoneme of the map");
        visemes.push_back(name);
    }
    if (visemes.empty())
        for (const auto& viseme : set->visemes) visemes.push_back(viseme.name);
    if (typed.empty()) typed = visemes;
    SpeechClip clip;
    for (std::size_t i = 0; i < visemes.size(); ++i)
        clip.phonemes.push_back({typed[i], double(i) * secondsPerKey, double(i + 1) * secondsPerKey});
    clip.visemes = std::move(visemes);
    clip.sequence = sequence;
    clip.loops = true;
    clip.label = sequence.empty() ? "every viseme" : "sequence " + quotedText(sequence);
    clip.id = nextId_++;
    task_.cancel(); // a typed sequence replaces speech still being synthesised
    clip_ = std::make_shared<const SpeechClip>(std::move(clip));
}

const SpeechPlayback* SpeechService::playback(const Document& document, const DocumentInputs& inputs) {
    if (!clip_) return nullptr;
    const Grouping* grouping = inputs.grouping();
    const bool hasGrouping = grouping != nullptr;
    const std::uint64_t inputsRevision = inputs.reductionRevision(), curveRevision = inputs.curveRevision();
    if (builtClip_ == clip_->id && builtRevision_ == inputsRevision && builtCurve_ == curveRevision &&
        builtGrouping_ == hasGrouping && builtTarget_ == document.target)
        return &playback_;
    builtClip_ = clip_->id;
    builtRevision_ = inputsRevision;
    builtCurve_ = curveRevision;
    builtGrouping_ = hasGrouping;
    builtTarget_ = document.target;
    playback_ = SpeechPlayback();
    playback_.clip = clip_;
    const VisemeSet* set = document.visemes.get();
    if (!set) {
        playback_.problem = "no viseme set";
        return &playback_;
    }
    try {
        if (clip_->visemes.empty() && !document.frequencies.isPhonemeBased())
            throwInputError("Say", "speech needs a phoneme -> viseme map; the frequencies are per viseme "
                                   "(Frequencies panel: use a phoneme table and a map)");
        // The models every view of the document shows (DocumentInputs, memoized).
        playback_.full.emplace(trackOf(inputs.fullModel(), *clip_, "full viseme set"));
        if (grouping && grouping->feasible()) {
            playback_.reduced.emplace(trackOf(*inputs.reducedModel(), *clip_, "reduced set"));
            playback_.groups = static_cast<int>(grouping->groups.size());
            const std::vector<double>& weights = inputs.weights();
            const SpeechErrorBasis basis(playback_.full->model(), playback_.reduced->model(), weights);
            // glTF lengths are metres; mesh files carry no unit.
            SpeechErrors errors =
                measureSpeechErrors(basis, *playback_.full, *playback_.reduced, kSpeechErrorFps,
                                    document.avatar.isSet() ? millimetresFromMetres() : DisplacementUnit{});
            playback_.error = std::move(errors.utterance);
            playback_.displacement = std::move(errors.displacement);
        }
    } catch (const InputError& e) {
        playback_ = SpeechPlayback();
        playback_.clip = clip_;
        playback_.problem = e.what();
    }
    return &playback_;
}

} // namespace vl::ui
