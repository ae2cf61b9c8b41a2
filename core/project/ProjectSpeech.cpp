#include "core/project/ProjectSpeech.h"

#include "core/common/Error.h"
#include "core/gltf/VisemeMapNames.h"
#include "core/project/ProjectRun.h"

#include <algorithm>

namespace vl {

namespace {

void requirePhonemeMap(const Project& project, const PhonemeVisemeMap* map) {
    if (!map && !project.frequencies.isPhonemeBased())
        throwInputError(project.path.empty() ? std::string("project")
                                             : project.path.string() + ": /frequencies",
                        "speech needs a phoneme -> viseme map; this project gives frequencies per viseme "
                        "(give a map, e.g. assets/phonemes/map_oculus.csv, or set the frequencies from a "
                        "phoneme table and a map)");
}

} // namespace

void setPhonemeMap(ReducedModel& model, const PhonemeVisemeMap& map, std::string_view where) {
    std::vector<std::pair<std::string, int>> phonemeToKey;
    std::string missing;
    for (const auto& [phoneme, viseme] : map.entries) {
        // Captured by name: clang 14 (the sanitizer build) cannot capture a structured binding.
        const auto key =
            std::find_if(model.keys.begin(), model.keys.end(), [&name = viseme](const KeyMesh& k) {
                return std::find(k.members.begin(), k.members.end(), name) != k.members.end();
            });
        if (key == model.keys.end() &&
            std::find(model.resting.begin(), model.resting.end(), viseme) != model.resting.end()) {
            phonemeToKey.emplace_back(phoneme, kRestingKey); // it rests: the neutral face
            continue;
        }
        if (key == model.keys.end()) {
            if (missing.find("'" + viseme + "'") == std::string::npos)
                missing += (missing.empty() ? "'" : ", '") + viseme + "'";
            continue;
        }
        phonemeToKey.emplace_back(phoneme, static_cast<int>(key - model.keys.begin()));
    }
    if (!missing.empty())
        throwInputError(where, "the map names visemes the project does not have: " + missing);
    model.phonemeToKey = std::move(phonemeToKey);
}

SpeechFaces projectSpeechFaces(const Project& project, const PhonemeVisemeMap* map) {
    requirePhonemeMap(project, map);
    const VisemeSet set = loadProjectVisemeSet(project);
    SpeechFaces faces;
    faces.full = projectReducedModel(project, set, true);
    faces.reduced = projectReducedModel(project, set, false);
    if (map) {
        // A map of another naming (Rhubarb shapes on Oculus visemes, "viseme_aa" for "aa") by meaning.
        std::vector<std::string> names;
        for (const Viseme& viseme : set.visemes) names.push_back(viseme.name);
        const PhonemeVisemeMap matched = mapOntoVisemes(*map, names);
        setPhonemeMap(faces.full, matched, "phoneme map");
        setPhonemeMap(faces.reduced, matched, "phoneme map");
    }
    faces.weights = computeWeights(project.weights.mode, set.neutral, project.weights.painted,
                                   project.path.string() + ": /weights");
    return faces;
}

std::vector<ErrorCurvePoint> projectErrorCurve(const Project& project, std::span<const TimedPhoneme> phonemes,
                                               const PlaybackSettings& settings, double fps,
                                               const ProgressCallback& progress,
                                               const PhonemeVisemeMap* map) {
    requirePhonemeMap(project, map);
    const VisemeSet set = loadProjectVisemeSet(project);
    // Every number of keys the project's model has: with the rest free, its rest viseme is no key.
    std::vector<std::string> names;
    for (const Viseme& viseme : set.visemes) names.push_back(viseme.name);
    const int rest = restVisemeIndex(names, project.reduction.restViseme, "/reduction/restViseme");
    Project everyTarget = project;
    everyTarget.reduction.target =
        static_cast<int>(set.size()) - (rest >= 0 && restIsFree(project.reduction.rest, rest) ? 1 : 0);
    const ReduceOutcome outcome = reduceProject(everyTarget, set, [&](double f) {
        if (progress) progress(0.5 * f);
    });
    const std::string where = project.path.empty() ? std::string("project") : project.path.string();
    const FaceTrack full(unreducedModel(set, outcome.frequencies, project.frequencies), phonemes, settings,
                         where);
    std::vector<ErrorCurvePoint> curve;
    for (std::size_t p = 0; p < outcome.result.curve.size(); ++p) {
        const Grouping& grouping = outcome.result.curve[p];
        ReducedModel model =
            buildReducedModel(set, outcome.frequencies, grouping.groupOf(), project.frequencies);
        const FaceTrack reduced(std::move(model), phonemes, settings, where);
        curve.push_back({static_cast<int>(p + 1), grouping.cost,
                         measureUtteranceError(full, reduced, outcome.weights, fps)});
        if (progress) progress(0.5 + 0.5 * double(p + 1) / double(outcome.result.curve.size()));
    }
    return curve;
}

} // namespace vl
