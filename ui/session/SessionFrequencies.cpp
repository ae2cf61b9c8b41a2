#include "ui/session/SessionFrequencies.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/document/Commands.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/phonetics/PhonemeTableIO.h"
#include "core/reduce/Frequencies.h"
#include "ui/session/BundledAssets.h"

namespace vl::ui {

SessionFrequencies::SessionFrequencies(SessionCore& core, decltype(SpeechEngines::transcriber) transcriber)
    : core_(core), transcriber_(std::move(transcriber)) {}

void SessionFrequencies::setVisemeFrequency(int viseme, double value) {
    Document next = edit::setVisemeFrequency(core_.document(), viseme, value);
    const std::string& name = core_.document().visemes->visemes[static_cast<std::size_t>(viseme)].name;
    core_.commit("Set frequency of " + name, std::move(next), "viseme-frequency:" + name);
}

void SessionFrequencies::setPhonemeFrequency(int phoneme, double value) {
    Document next = edit::setPhonemeFrequency(core_.document(), phoneme, value);
    const std::string name =
        core_.document().frequencies.phonemes.entries[static_cast<std::size_t>(phoneme)].first;
    core_.commit("Set frequency of phoneme " + name, std::move(next), "phoneme-frequency:" + name);
}

void SessionFrequencies::setPhonemeViseme(int phoneme, const std::string& viseme) {
    Document next = edit::setPhonemeViseme(core_.document(), phoneme, viseme);
    const std::string name =
        core_.document().frequencies.phonemes.entries[static_cast<std::size_t>(phoneme)].first;
    core_.commit("Map phoneme " + name + " to " + viseme, std::move(next));
}

void SessionFrequencies::load(const std::filesystem::path& file) {
    core_.commit("Load frequencies " + file.filename().string(),
                 edit::setFrequencies(core_.document(), loadFrequencyFile(file)));
    core_.messages().info("Loaded frequencies from " + file.string());
}

void SessionFrequencies::setSource(FrequencySource source, const std::string& actionName) {
    core_.commit(actionName, edit::setFrequencies(core_.document(), std::move(source)));
}

void SessionFrequencies::useBundledPhonemeMap(const std::string& mapId) {
    const auto dir = assetsDirectory();
    for (const BundledPhonemeMap& map : bundledPhonemeMaps(dir))
        if (map.id == mapId)
            return setSource(loadPhonemeFrequencySource(defaultPhonemeTablePath(dir), map.file),
                             "Phoneme table with map " + map.title);
    throwInputError("phoneme map", "no bundled map '" + mapId + "'");
}

void SessionFrequencies::useDirectFrequencies() {
    core_.commit("Direct viseme frequencies", edit::useDirectFrequencies(core_.document()));
}

void SessionFrequencies::saveCsv(const std::filesystem::path& file) const {
    writeFileAtomically(file, formatFrequencyCsv(core_.document().frequencies));
}

FrequencyTable SessionFrequencies::startingPhonemeTable() const {
    if (core_.document().frequencies.isPhonemeBased()) return core_.document().frequencies.phonemes;
    return loadPhonemeTable(defaultPhonemeTablePath(assetsDirectory()));
}

void SessionFrequencies::startPhonemeMap(FrequencyTable table, const PhonemeVisemeMap& start,
                                         const std::vector<edit::MapAssignment>& assignment,
                                         const std::string& startName) {
    core_.commit("Phoneme map from " + startName,
                 edit::startPhonemeMap(core_.document(), std::move(table), start, assignment));
}

void SessionFrequencies::movePhonemes(const std::string& from, const std::string& to) {
    core_.commit("Map the phonemes of " + from + " to " + to, edit::movePhonemes(core_.document(), from, to));
}

void SessionFrequencies::savePhonemeMap(const std::filesystem::path& file) const {
    if (!core_.document().frequencies.isPhonemeBased())
        throwInputError(file.string(), "the frequencies are direct: there is no phoneme map to save");
    vl::savePhonemeMap(file, core_.document().frequencies.map);
}

void SessionFrequencies::startPhonemeCount(const std::filesystem::path& corpus, const std::string& voice) {
    if (!core_.document().visemes) throwInputError("phoneme count", "load a viseme set first");
    if (count_.running()) throwInputError("phoneme count", "a count is already running");
    countCorpus_ = corpus;
    count_.start("Counting phonemes", [corpus, voice, make = transcriber_](const auto& progress) {
        auto transcriber = make(voice);
        return countPhonemesInFile(corpus, *transcriber, [&](std::uint64_t done, std::uint64_t total) {
            progress(total ? static_cast<double>(done) / static_cast<double>(total) : 0.0);
        });
    });
}

void SessionFrequencies::poll() {
    auto outcome = count_.take();
    if (!outcome) return;
    if (outcome->index() == 1) {
        core_.messages().error("Phoneme count: " + std::get<1>(*outcome));
        return;
    }
    const PhonemeCountResult& counted = std::get<0>(*outcome);
    core_.messages().attempt("Phoneme frequencies", [&] {
        FrequencySource source;
        source.phonemes = counted.counts;
        const Document& document = core_.document();
        source.map = document.frequencies.isPhonemeBased()
                         ? document.frequencies.map
                         : bundledPhonemeFrequencies(assetsDirectory(), "oculus").map;
        setSource(std::move(source), "Phoneme frequencies from " + countCorpus_.filename().string());
        core_.messages().info("Counted " + std::to_string(counted.phonemeTotal) + " phonemes");
    });
}

} // namespace vl::ui
