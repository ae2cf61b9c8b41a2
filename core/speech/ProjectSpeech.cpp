#include "core/speech/ProjectSpeech.h"

#include "core/common/Error.h"
#include "core/export/Export.h"
#include "core/project/ProjectRun.h"

namespace vl {

namespace {

void requirePhonemeMap(const Project& project) {
    if (!project.frequencies.isPhonemeBased())
        throwInputError(project.path.empty() ? std::string("project")
                                             : project.path.string() + ": /frequencies",
                        "speech needs phoneme frequencies with a phoneme -> viseme map; this project gives "
                        "frequencies per viseme (set them from a phoneme table and a map, e.g. "
                        "assets/phonemes/map_oculus.csv)");
}

std::vector<int> groupOfGrouping(const Grouping& grouping, std::size_t visemes) {
    std::vector<int> groupOf(visemes, 0);
    for (std::size_t g = 0; g < grouping.groups.size(); ++g)
        for (const int member : grouping.groups[g])
            groupOf[static_cast<std::size_t>(member)] = static_cast<int>(g);
    return groupOf;
}

} // namespace

SpeechFaces projectSpeechFaces(const Project& project) {
    requirePhonemeMap(project);
    const VisemeSet set = loadProjectVisemeSet(project);
    SpeechFaces faces;
    faces.full = projectReducedModel(project, set, true);
    faces.reduced = projectReducedModel(project, set, false);
    faces.weights = computeWeights(project.weights.mode, set.neutral, project.weights.painted,
                                   project.path.string() + ": /weights");
    return faces;
}

std::vector<ErrorCurvePoint> projectErrorCurve(const Project& project, std::span<const TimedPhoneme> phonemes,
                                               const PlaybackSettings& settings, double fps,
                                               const ProgressCallback& progress) {
    requirePhonemeMap(project);
    const VisemeSet set = loadProjectVisemeSet(project);
    Project everyTarget = project;
    everyTarget.reduction.target = static_cast<int>(set.size());
    const ReduceOutcome outcome = reduceProject(everyTarget, set, [&](double f) {
        if (progress) progress(0.5 * f);
    });
    const std::string where = project.path.empty() ? std::string("project") : project.path.string();
    const FaceTrack full(unreducedModel(set, outcome.frequencies, project.frequencies), phonemes, settings,
                         where);
    std::vector<ErrorCurvePoint> curve;
    for (std::size_t p = 0; p < outcome.result.curve.size(); ++p) {
        const Grouping& grouping = outcome.result.curve[p];
        const ReducedModel model = buildReducedModel(
            set, outcome.frequencies, groupOfGrouping(grouping, set.size()), project.frequencies);
        const FaceTrack reduced(model, phonemes, settings, where);
        curve.push_back({static_cast<int>(p + 1), grouping.cost,
                         measureUtteranceError(full, reduced, outcome.weights, fps)});
        if (progress) progress(0.5 + 0.5 * double(p + 1) / double(outcome.result.curve.size()));
    }
    return curve;
}

} // namespace vl
