#include "core/document/Commands.h"

#include "core/common/Error.h"
#include "core/common/TextParsing.h"
#include "core/document/AvatarDocument.h"
#include "core/document/CommandSupport.h"
#include "core/document/PhonemeMapCommands.h"
#include "core/document/VisemeCommands.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"
#include "core/face/FaceFrame.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/AvatarRest.h"
#include "core/gltf/TargetNames.h"

#include <algorithm>
#include <cmath>

namespace vl::edit {
namespace {

using detail::checked;
using detail::checkedChange;
using detail::checkedIndex;
using detail::refuseAvatar;
using detail::requireFace;
using detail::requireSet;

void requireFrequency(double value, const std::string& what) {
    if (!std::isfinite(value) || value < 0.0)
        throwInputError(what, "must be a finite number >= 0, got " + formatDouble(value));
}

} // namespace

Document addViseme(const Document& document, const std::string& name, const MeshData& mesh,
                   const std::filesystem::path& file) {
    const std::string where = file.empty() ? "viseme " + name : file.string();
    requireSet(document, where);
    refuseAvatar(document, where);
    if (name.empty()) throwInputError(where, "the viseme needs a name");
    if (document.visemes->find(name) >= 0)
        throwInputError(where, "a viseme named '" + name + "' already exists");
    checkInterpolable(document.visemes->neutral, document.visemes->neutralSource.string(), mesh, where);
    Document next = document;
    auto set = std::make_shared<VisemeSet>(*document.visemes);
    set->visemes.push_back({name, mesh.positions});
    next.visemes = std::move(set);
    next.visemeFiles.push_back(file.empty() ? file : std::filesystem::absolute(file));
    if (!next.frequencies.isPhonemeBased())
        next.frequencies.visemeFrequencies.entries.emplace_back(name, 1.0);
    return checked(std::move(next));
}

Document removeViseme(const Document& document, int index, const std::string& phonemesGoTo) {
    requireSet(document, "remove viseme");
    refuseAvatar(document, "remove viseme");
    const std::size_t i = checkedIndex(index, document.visemeCount(), "remove viseme");
    if (document.visemeCount() <= 2)
        throwInputError("remove viseme", "a viseme set needs at least 2 visemes");
    const std::string name = document.visemes->visemes[i].name;
    Document next = document;
    // Phonemes mapped to it would be orphaned: they move where the caller says, or nothing changes.
    if (const auto orphans = phonemesMappedTo(document.frequencies, name); !orphans.empty()) {
        if (phonemesGoTo.empty())
            throwInputError("remove " + name, "phonemes " + phonemeList(document.frequencies, orphans) +
                                                  " map to it: choose the viseme they map to instead");
        if (phonemesGoTo == name || document.visemes->find(phonemesGoTo) < 0)
            throwInputError("remove " + name, "its phonemes cannot go to '" + phonemesGoTo +
                                                  "' (not another viseme of the set)");
        for (auto& [phoneme, viseme] : next.frequencies.map.entries)
            if (viseme == name) viseme = phonemesGoTo;
    }
    auto set = std::make_shared<VisemeSet>(*document.visemes);
    set->visemes.erase(set->visemes.begin() + index);
    next.visemes = std::move(set);
    next.visemeFiles.erase(next.visemeFiles.begin() + index);
    auto& direct = next.frequencies.visemeFrequencies.entries;
    std::erase_if(direct, [&](const auto& entry) { return entry.first == name; });
    // Constraints that name it go with it.
    std::erase(next.constraints.pinned, name);
    const auto namesIt = [&](const auto& pair) { return pair.first == name || pair.second == name; };
    std::erase_if(next.constraints.apart, namesIt);
    std::erase_if(next.constraints.together, namesIt);
    if (next.restViseme == name) next.restViseme.clear(); // back to sil / viseme_sil
    // So does its preset (a viseme and a preset of the same name are one viseme).
    if (next.face.cascade) {
        std::vector<VisemeParameters> presets = facePresets(next.face);
        std::erase_if(presets, [&](const VisemeParameters& preset) { return preset.name == name; });
        if (!presets.empty() && presets.size() != facePresets(next.face).size()) next.face.presets = presets;
    }
    next.target = std::min(next.target, static_cast<int>(next.visemes->size()));
    return checked(std::move(next));
}

Document setVisemeFrequency(const Document& document, int viseme, double value) {
    requireSet(document, "viseme frequency");
    const std::string& name =
        document.visemes->visemes[checkedIndex(viseme, document.visemeCount(), "viseme frequency")].name;
    requireFrequency(value, "frequency of " + name);
    if (document.frequencies.isPhonemeBased())
        throwInputError("frequency of " + name, "frequencies come from the phoneme table: edit the phonemes");
    Document next = document;
    auto& entries = next.frequencies.visemeFrequencies.entries;
    auto it = std::find_if(entries.begin(), entries.end(), [&](const auto& e) { return e.first == name; });
    if (it == entries.end())
        entries.emplace_back(name, value);
    else
        it->second = value;
    return checked(std::move(next));
}

Document setPhonemeFrequency(const Document& document, int phoneme, double value) {
    const auto& entries = document.frequencies.phonemes.entries;
    const std::size_t i = checkedIndex(phoneme, entries.size(), "phoneme frequency");
    requireFrequency(value, "frequency of phoneme " + entries[i].first);
    Document next = document;
    next.frequencies.phonemes.entries[i].second = value;
    return checked(std::move(next));
}

Document setPhonemeViseme(const Document& document, int phoneme, const std::string& viseme) {
    const auto& table = document.frequencies.phonemes.entries;
    const std::size_t i = checkedIndex(phoneme, table.size(), "phoneme map");
    if (!document.visemes || document.visemes->find(viseme) < 0)
        throwInputError("phoneme map", "unknown viseme '" + viseme + "'");
    Document next = document;
    auto& map = next.frequencies.map.entries;
    auto it = std::find_if(map.begin(), map.end(), [&](const auto& e) { return e.first == table[i].first; });
    if (it == map.end())
        map.emplace_back(table[i].first, viseme);
    else
        it->second = viseme;
    return checked(std::move(next));
}

Document setFrequencies(const Document& document, FrequencySource source) {
    Document next = document;
    next.frequencies = document.avatar.isSet() ? matchVisemeNames(std::move(source), *document.avatar.scan)
                                               : std::move(source);
    return checked(std::move(next));
}

Document setWeightMode(const Document& document, WeightMode mode) {
    Document next = document;
    next.weights.mode = mode;
    // Painting starts from what was shown, not from all ones (an "add" stroke would be lost);
    // weights painted before are kept.
    if (mode == WeightMode::Painted && document.visemes &&
        document.weights.paintedOrEmpty().size() != document.visemes->vertexCount())
        next.weights.painted = std::make_shared<const std::vector<double>>(weightsForPainting(
            document.weights.mode, document.visemes->neutral, document.weights.paintedOrEmpty()));
    return checked(std::move(next));
}

Document setPaintedWeights(const Document& document, std::vector<double> painted) {
    requireSet(document, "weights");
    Document next = document;
    next.weights.mode = WeightMode::Painted;
    next.weights.painted = std::make_shared<const std::vector<double>>(std::move(painted));
    return checked(std::move(next));
}

Document setFace(const Document& document, FaceModel face) {
    if (!face.cascade || !face.domain) throwInputError("face", "a face needs a cascade and a (u,v) mesh");
    validateCascade(*face.cascade);
    Document next = document;
    next.face = std::move(face);
    return checked(std::move(next));
}

Document setParameters(const Document& document, std::vector<double> values) {
    requireFace(document, "parameters");
    checkParameterValues(*document.face.cascade, values);
    Document next = document;
    next.face.parameters = std::move(values);
    return checkedChange(document, std::move(next));
}

Document setParameter(const Document& document, int parameter, double value) {
    requireFace(document, "parameter");
    std::vector<double> q = document.face.parameters;
    q[checkedIndex(parameter, q.size(), "parameter")] = value;
    return setParameters(document, std::move(q));
}

Document applyVisemePreset(const Document& document, const std::string& viseme) {
    requireFace(document, "viseme preset");
    const std::vector<VisemeParameters> presets =
        document.face.presets.empty() ? oculusVisemes() : document.face.presets;
    for (const VisemeParameters& preset : presets)
        if (preset.name == viseme)
            return setParameters(document, parameterVector(*document.face.cascade, preset));
    throwInputError("viseme preset", "unknown viseme '" + viseme + "'");
}

Document setInfluence(const Document& document, int stage, int influence, const InfluenceField& field) {
    requireFace(document, "field");
    auto cascade = std::make_shared<DeformationCascade>(*document.face.cascade);
    auto& influences =
        cascade->stages[checkedIndex(stage, cascade->stages.size(), "field stage")].field.influences;
    influences[checkedIndex(influence, influences.size(), "influence region")] = field;
    validateCascade(*cascade);
    Document next = document;
    next.face.cascade = std::move(cascade);
    return checked(std::move(next));
}

Document retarget(const Document& document, face::Individual individual) {
    requireFace(document, "base geometry");
    if (individual == document.face.individual) return document;
    VectorField base;
    base.sampled = face::makeFaceGeometry(individual);
    Document next = document;
    next.face.cascade = std::make_shared<const DeformationCascade>(
        vl::retarget(*document.face.cascade, base, std::string(toString(individual))));
    next.face.individual = individual;
    return checked(std::move(next));
}

Document setFaceDomain(const Document& document, std::shared_ptr<const MeshData> domain) {
    requireFace(document, "face mesh");
    if (!domain || domain->positions.empty() || domain->uvs.size() != domain->positions.size())
        throwInputError("face mesh", "a (u,v) mesh with one (u,v) per vertex expected");
    Document next = document;
    next.face.domain = std::move(domain);
    return checked(std::move(next));
}

Document generateVisemesFromFace(const Document& document, const FrequencySource* phonemeTable) {
    requireFace(document, "generate visemes");
    const std::vector<VisemeParameters> presets =
        document.face.presets.empty() ? oculusVisemes() : document.face.presets;
    Document next = document;
    next.avatar = {}; // the face's visemes replace the avatar's
    auto set = std::make_shared<VisemeSet>(
        generateVisemeSet(*document.face.cascade, *document.face.domain, presets));
    next.neutralFile.clear();
    next.visemeFiles.assign(set->size(), {});
    next.frequencies = {};
    for (const auto& viseme : set->visemes)
        next.frequencies.visemeFrequencies.entries.emplace_back(viseme.name, 1.0);
    next.weights = {};
    next.target = std::max(1, static_cast<int>(set->size()) * 2 / 3);
    next.visemeColours =
        std::make_shared<const std::vector<Vec3>>(face::faceColours(document.face.domain->uvs));
    next.visemes = std::move(set);
    next = checked(std::move(next));
    if (phonemeTable && !document.visemes) {
        // Spoken frequencies rather than equal ones for a first set: the reduction's weights.
        Document spoken = next;
        spoken.frequencies = *phonemeTable;
        try {
            next = checked(std::move(spoken));
        } catch (const InputError&) {
            // The map names visemes the face's presets lack: equal frequencies.
        }
    }
    // Keep the frequency table, weight mode and target when they still fit the new set (the visemes
    // keep their names; painted weights do not survive a new mesh).
    Document kept = next;
    if (document.visemes) kept.frequencies = document.frequencies;
    if (document.weights.mode != WeightMode::Painted) kept.weights.mode = document.weights.mode;
    if (document.visemes && document.target <= static_cast<int>(next.visemes->size()))
        kept.target = document.target;
    try {
        return checked(std::move(kept));
    } catch (const InputError&) {
        return next;
    }
}

Document setRefinementSettings(const Document& document, const CriterionSettings& settings) {
    validateCriterionSettings(settings);
    Document next = document;
    next.refinement = settings;
    return checked(std::move(next));
}

Document setTarget(const Document& document, int m) {
    const int n = static_cast<int>(document.visemeCount());
    if (m < 1 || m > std::max(n, 1))
        throwInputError("target", "m must be in 1.." + std::to_string(n) + ", got " + std::to_string(m));
    // The resting rest viseme is no key: say so here rather than as an infeasible reduction later.
    if (const RestPose rest = documentRestPose(document); rest.free && rest.viseme >= 0 && m >= n)
        throwInputError("target", "m = " + std::to_string(m) + ": with the rest free, " +
                                      document.visemes->visemes[static_cast<std::size_t>(rest.viseme)].name +
                                      " rests, so at most " + std::to_string(n - 1) + " keys");
    Document next = document;
    next.target = m;
    return checked(std::move(next));
}

Document setConstraints(const Document& document, ConstraintNames constraints) {
    Document next = document;
    next.constraints = std::move(constraints);
    return checked(std::move(next));
}

Document setRest(const Document& document, RestChoice rest, const std::string& restViseme) {
    Document next = document;
    next.rest = rest;
    next.restViseme = restViseme;
    next.target = std::clamp(next.target, 1, std::max(1, documentMaxKeys(next)));
    return checked(std::move(next));
}

Document setSpeech(const Document& document, SpeechSettings speech) {
    checkSpeechSettings(speech, "speech");
    Document next = document;
    next.speech = std::move(speech);
    return next;
}

Document setAvatarPattern(const Document& document, const std::string& pattern,
                          const FrequencySource& oculusTable) {
    if (!document.avatar.isSet()) throwInputError("target pattern", "the document has no avatar");
    if (!pattern.empty()) checkGlobPattern(pattern, "target pattern '" + pattern + "'");
    DocumentAvatar avatar = document.avatar;
    avatar.pattern = pattern;
    AvatarScan scan = scanAvatar(*avatar.gltf, {pattern, true});
    // A rest viseme the designer added stays while the new selection has none of its own.
    if (!document.avatar.scan->addedRest.empty() && !avatarHasRest(scan))
        addAvatarRest(scan, avatarRestName(scan));
    avatar.scan = std::make_shared<const AvatarScan>(std::move(scan));
    if (avatar.scan->visemes.size() < 2)
        throwInputError("target pattern '" + pattern + "'",
                        "selects " + std::to_string(avatar.scan->visemes.size()) +
                            " viseme(s) of the avatar; at least 2 are needed");
    Document next = documentFromAvatar(std::move(avatar), oculusTable);
    // Keep what still fits: each on its own, so one that no longer applies does not drop the others.
    const auto keep = [&](auto&& apply) {
        Document kept = next;
        apply(kept);
        try {
            validateDocument(kept);
            next = std::move(kept);
        } catch (const InputError&) {
        }
    };
    const bool sameGeometry = document.visemes && next.visemes->neutral == document.visemes->neutral;
    keep([&](Document& d) { d.frequencies = document.frequencies; });
    keep([&](Document& d) {
        d.weights.mode = document.weights.mode;
        if (sameGeometry)
            d.weights = document.weights;
        else if (d.weights.mode == WeightMode::Painted)
            d.weights = {};
    });
    keep([&](Document& d) {
        const std::vector<std::string> names = visemeNames(d);
        const auto known = [&](const std::string& name) {
            return std::find(names.begin(), names.end(), name) != names.end();
        };
        d.constraints = document.constraints;
        std::erase_if(d.constraints.pinned, [&](const std::string& name) { return !known(name); });
        const auto unknownPair = [&](const auto& pair) { return !known(pair.first) || !known(pair.second); };
        std::erase_if(d.constraints.apart, unknownPair);
        std::erase_if(d.constraints.together, unknownPair);
        d.rest = document.rest;
        d.restViseme = known(document.restViseme) ? document.restViseme : std::string();
    });
    keep([&](Document& d) { d.target = std::min(document.target, static_cast<int>(d.visemeCount())); });
    keep([&](Document& d) {
        d.face = document.face;
        d.refinement = document.refinement;
    });
    return next;
}

Document useOwnFace(const Document& document, const OwnFaceCandidate& candidate,
                    face::FaceBuildReport* report) {
    if (!candidate.mesh) throwInputError("own face", "no mesh loaded");
    if (const std::string missing = candidate.missingRequired(); !missing.empty())
        throwInputError(candidate.file.string(), "place the landmarks " + missing + " first");
    face::FaceBuildOptions options;
    options.name = candidate.name.empty() ? "own face" : candidate.name;
    face::BuiltFace built = face::buildFace(*candidate.mesh, candidate.landmarks(), options);

    const double previousScale =
        document.face.cascade ? face::faceFrameOf(*document.face.cascade).scaleTo(face::bundledFaceFrame())
                              : 1.0;
    FaceModel model;
    model.cascade = std::make_shared<const DeformationCascade>(std::move(built.cascade));
    model.domain = document.face.domain ? document.face.domain
                                        : std::make_shared<const MeshData>(face::faceDomainMesh(
                                              kFaceDomainResolution, face::DomainDensity::MouthFocused));
    model.parameters = model.cascade->defaults();
    model.presets = document.face.presets;
    Document next = setFace(document, std::move(model));
    const double ratio = built.report.scale / std::max(previousScale, 1e-12);
    next.refinement.contour.averageError *= ratio;
    next.refinement.contour.maximumError *= ratio;
    next.ownFace.reset();
    if (report) *report = std::move(built.report);
    return checked(std::move(next));
}

Document beginOwnFace(const Document& document, OwnFaceCandidate candidate) {
    if (!candidate.mesh) throwInputError("own face", "no mesh loaded");
    Document next = document;
    next.ownFace = std::make_shared<const OwnFaceCandidate>(std::move(candidate));
    return next;
}

Document placeOwnFaceLandmark(const Document& document, face::Landmark landmark, const Vec2& uv) {
    if (!document.ownFace)
        throwInputError(std::string(toString(landmark)), "no own-face step is open (Use my mesh...)");
    Document next = document;
    next.ownFace = std::make_shared<const OwnFaceCandidate>(placeLandmark(*document.ownFace, landmark, uv));
    return next;
}

Document cancelOwnFace(const Document& document) {
    Document next = document;
    next.ownFace.reset();
    return next;
}

} // namespace vl::edit
