#include "core/project/AvatarSpeech.h"

#include "core/common/Error.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/AvatarRest.h"
#include "core/gltf/VisemeMapNames.h"
#include "core/project/ReduceInputs.h"
#include "core/reduce/Weights.h"

#include <algorithm>

namespace vl {

namespace {

// The frequencies `avatar reduce` uses (or the given map with the bundled phoneme table), which
// must give phonemes for speech.
FrequencySource speechFrequencies(const AvatarScan& scan, const AvatarSpeechOptions& options,
                                  std::string& chosen) {
    FrequencySource source;
    if (options.map) {
        source = options.phonemeTable;
        source.map = *options.map;
        source = matchVisemeNames(std::move(source), scan);
        chosen = "bundled en-us phoneme table + map " +
                 (options.map->origin.text.empty() ? std::string("given") : options.map->origin.text);
    } else {
        source = defaultAvatarFrequencies(scan, options.phonemeTable, &chosen);
    }
    if (!source.isPhonemeBased() || source.map.entries.empty())
        throwInputError(scan.source, "speech needs a phoneme -> viseme map: the visemes (" + scan.selection +
                                         ") are not all Oculus visemes; give one, e.g. --map "
                                         "assets/phonemes/map_oculus.csv or map_rhubarb.csv");
    return source;
}

// The reduced face of a reduced avatar, as VisemeLab's own output reads (core/gltf/OwnOutput.h):
// its keys in the order extras.visemelab lists them (the order its meshes' visemeKeys use), named as
// the file names them, each with the geometry of the target that carries it (names "merged": the key
// target; "original": the first member's, which every member shares), over the same concatenated
// geometry as the avatar's set.
ReducedModel reducedModelOf(const GltfDocument& reduced, const AvatarScan& scan, const std::string& targets,
                            const FrequencySource& source) {
    AvatarScan reducedScan = scanAvatar(reduced, {targets});
    if (!scan.addedRest.empty() && !avatarHasRest(reducedScan)) addAvatarRest(reducedScan, scan.addedRest);
    const OwnOutput& own = reducedScan.own;
    if (!own.recognised)
        reduced.fail("/extras/visemelab",
                     "not an avatar written by `visemelab avatar reduce`" +
                         (own.notes.empty() ? std::string() : " (" + own.notes.front() + ")"));
    // Every member and listed resting viseme is one of the avatar's; the avatar's others rest too
    // (files written before extras.visemelab.resting existed do not list them).
    std::vector<std::string> named = own.resting;
    for (const OwnKey& key : own.keys) named.insert(named.end(), key.members.begin(), key.members.end());
    const bool known = std::all_of(named.begin(), named.end(), [&](const std::string& v) {
        return std::find(scan.visemes.begin(), scan.visemes.end(), v) != scan.visemes.end();
    });
    if (!known || reducedScan.set.vertexCount() != scan.set.vertexCount() ||
        (!own.mergedNames && reducedScan.visemes != scan.visemes))
        reduced.fail("visemes", "is not a reduction of " + scan.source + " (other visemes or vertices)");
    // Which viseme of the reduced file's set carries each key.
    std::vector<int> carrier(own.keys.size(), -1);
    for (std::size_t k = 0; k < own.keys.size(); ++k)
        if (!own.mergedNames) carrier[k] = reducedScan.set.find(own.keys[k].members.front());
    for (const AvatarMesh& mesh : reducedScan.meshes)
        for (std::size_t t = 0; own.mergedNames && t < mesh.targets.size(); ++t) {
            const int key = own.keyOfTarget(mesh.index, static_cast<int>(t));
            if (key >= 0 && mesh.targets[t].viseme >= 0)
                carrier[static_cast<std::size_t>(key)] = mesh.targets[t].viseme;
        }
    ReducedModel model;
    model.neutral = scan.set.neutral;
    for (std::size_t k = 0; k < own.keys.size(); ++k) {
        if (carrier[k] < 0)
            reduced.fail("/extras/visemelab/keys/" + std::to_string(k),
                         "key '" + own.keys[k].name + "' is carried by no target of the file" +
                             (targets.empty() ? std::string() : " that --targets '" + targets + "' selects"));
        KeyMesh key;
        key.name = own.keys[k].name;
        key.members = own.keys[k].members;
        key.frequency = own.keys[k].frequency;
        key.positions = reducedScan.set.visemes[static_cast<std::size_t>(carrier[k])].positions;
        model.keys.push_back(std::move(key));
    }
    // The rest-free model: a viseme in no key rests (its target is there, moving nothing).
    for (const std::string& viseme : scan.visemes)
        if (std::none_of(model.keys.begin(), model.keys.end(), [&](const KeyMesh& k) {
                return std::find(k.members.begin(), k.members.end(), viseme) != k.members.end();
            }))
            model.resting.push_back(viseme);
    setPhonemeMap(model, source.map, reduced.source + ": phoneme map");
    validateReducedModel(model, reduced.source);
    return model;
}

// A reduced avatar's meshes: each key drives the first of its targets; the other targets of it
// (names "original": every member) stay at 0.
std::vector<MeshDrive> reducedDrives(const GltfDocument& doc, const OwnOutput& own) {
    std::vector<MeshDrive> drives;
    for (const OwnMesh& mesh : own.meshes) {
        const auto& primitives = doc.model.meshes[static_cast<std::size_t>(mesh.mesh)].primitives;
        const std::size_t targets = primitives.empty() ? 0 : primitives.front().targets.size();
        MeshDrive drive{mesh.mesh, std::vector<int>(targets, MeshDrive::kDefaultWeight)};
        for (std::size_t k = 0; k < mesh.keyTargets.size(); ++k)
            for (std::size_t j = 0; j < mesh.keyTargets[k].size(); ++j)
                drive.keyOfTarget[static_cast<std::size_t>(mesh.keyTargets[k][j])] =
                    j == 0 ? static_cast<int>(k) : MeshDrive::kZeroWeight;
        drives.push_back(std::move(drive));
    }
    return drives;
}

// The avatar's own meshes: each viseme target follows its viseme's key (a second target of the
// same viseme on a mesh stays at 0).
std::vector<MeshDrive> visemeDrives(const AvatarScan& scan, const ReducedModel& full) {
    std::vector<MeshDrive> drives;
    for (const AvatarMesh& mesh : scan.meshes) {
        if (!mesh.carriesVisemes) continue;
        MeshDrive drive{mesh.index, std::vector<int>(mesh.targets.size(), MeshDrive::kDefaultWeight)};
        std::vector<bool> driven(full.keys.size(), false);
        for (std::size_t t = 0; t < mesh.targets.size(); ++t) {
            const int viseme = mesh.targets[t].viseme;
            if (viseme < 0) continue;
            const int key = full.findKey(scan.visemes[static_cast<std::size_t>(viseme)]);
            if (key < 0 || driven[static_cast<std::size_t>(key)]) {
                drive.keyOfTarget[t] = MeshDrive::kZeroWeight;
                continue;
            }
            driven[static_cast<std::size_t>(key)] = true;
            drive.keyOfTarget[t] = key;
        }
        drives.push_back(std::move(drive));
    }
    return drives;
}

} // namespace

AvatarSpeech avatarSpeech(const std::filesystem::path& avatar, const AvatarSpeechOptions& options) {
    auto doc = std::make_shared<const GltfDocument>(loadGltfDocument(avatar));
    AvatarScan scan = scanAvatar(*doc, {options.targets});
    if (scan.visemes.size() < 2)
        throwInputError(doc->source, "needs at least 2 visemes to speak, found " +
                                         std::to_string(scan.visemes.size()) + " (" + scan.selection +
                                         "); see `visemelab avatar inspect`");
    // Silence needs a viseme: one without a rest viseme speaks with one added (the base mesh, no target),
    // so the pause is all weights 0 and an Oculus avatar fits the bundled map.
    if (!avatarHasRest(scan)) addAvatarRest(scan, avatarRestName(scan));
    AvatarSpeech speech;
    const FrequencySource source = speechFrequencies(scan, options, speech.frequencies);
    std::vector<std::string> names = scan.visemes;
    speech.faces.full = unreducedModel(scan.set, visemeFrequencies(source, names), source);
    speech.faces.weights = computeWeights(WeightMode::Uniform, scan.set.neutral);
    if (options.reduceTo > 0 || options.maxErrorMm > 0) {
        ReduceSettings settings = avatarReduceSettings(options.reduceTo); // as `avatar reduce`
        settings.constraints = options.constraints;
        settings.maxErrorMm = options.maxErrorMm;
        settings.closure = options.closure;
        AvatarReduction r = reduceAvatar(
            *doc, scan, source, withPolicy(settings, ReducePolicy::batch(), scan.visemes.size()), {});
        speech.faces.reduced = std::move(r.outcome.model);
        speech.animated = std::make_shared<const GltfDocument>(
            parseGltfDocument(std::move(r.glb), doc->source + " (reduced)", {}));
        speech.reducedFace = true;
    } else if (!options.reduced.empty()) {
        speech.animated = std::make_shared<const GltfDocument>(loadGltfDocument(options.reduced));
        speech.faces.reduced = reducedModelOf(*speech.animated, scan, options.targets, source);
        speech.reducedFace = true;
    } else {
        speech.faces.reduced = speech.faces.full;
        speech.animated = doc;
    }
    if (speech.reducedFace) {
        // The key tables of the reduced avatar, read against the reduced face's keys (whatever its root
        // extras hold: a document whose extras are not an object has no extras.visemelab).
        OwnOutput own;
        for (const KeyMesh& key : speech.faces.reduced.keys)
            own.keys.push_back({key.name, key.members, key.frequency});
        own.mergedNames = recogniseOwnOutput(*speech.animated).mergedNames;
        readOwnMeshes(*speech.animated, own);
        speech.drives = reducedDrives(*speech.animated, own);
    } else {
        speech.drives = visemeDrives(scan, speech.faces.full);
    }
    return speech;
}

} // namespace vl
