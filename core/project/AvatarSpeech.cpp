#include "core/project/AvatarSpeech.h"

#include "core/common/Error.h"
#include "core/common/JsonParse.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/VisemeMapNames.h"
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

// The member `key` of an object, or null.
const Json& member(const Json& object, const char* key) {
    static const Json none;
    return object.is_object() && object.contains(key) ? object[key] : none;
}

std::vector<std::string> requireStrings(const Json& value, const std::string& where,
                                        const GltfDocument& doc) {
    if (!value.is_array() || value.empty()) doc.fail(where, "expected a non-empty array of names");
    std::vector<std::string> names;
    for (const Json& name : value) {
        if (!name.is_string()) doc.fail(where, "expected a name");
        names.push_back(name.get<std::string>());
    }
    return names;
}

// The reduced face of a reduced avatar: its keys as extras.visemelab lists them (the order its meshes'
// visemeKeys use), each with the geometry of its first member's target (names "original": the
// members share the key's accessors), over the same concatenated geometry as the avatar's set.
ReducedModel reducedModelOf(const GltfDocument& reduced, const AvatarScan& scan, const std::string& targets,
                            const FrequencySource& source) {
    const Json* root = nullptr;
    if (reduced.json.contains("extras") && reduced.json["extras"].is_object() &&
        reduced.json["extras"].contains("visemelab"))
        root = &reduced.json["extras"]["visemelab"];
    if (!root || !root->is_object() || !root->contains("keys"))
        reduced.fail("/extras/visemelab", "missing: not an avatar written by `visemelab avatar reduce`");
    if (root->value("names", std::string()) != "original")
        reduced.fail("/extras/visemelab/names", "say reads reduced avatars written with --names original "
                                                "(the default), where every viseme target keeps its name");
    const AvatarScan reducedScan = scanAvatar(reduced, {targets});
    if (reducedScan.visemes != scan.visemes || reducedScan.set.vertexCount() != scan.set.vertexCount())
        reduced.fail("visemes", "is not a reduction of " + scan.source + " (other visemes or vertices)");
    ReducedModel model;
    model.neutral = scan.set.neutral;
    const Json& keys = (*root)["keys"];
    if (!keys.is_array() || keys.empty())
        reduced.fail("/extras/visemelab/keys", "expected a non-empty array");
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const std::string where = "/extras/visemelab/keys/" + std::to_string(k);
        if (!keys[k].is_object()) reduced.fail(where, "expected an object");
        KeyMesh key;
        key.members = requireStrings(member(keys[k], "members"), where + "/members", reduced);
        key.name = mergedKeyName(key.members);
        if (keys[k].contains("frequency") && keys[k]["frequency"].is_number())
            key.frequency = keys[k]["frequency"].get<double>();
        const int first = reducedScan.set.find(key.members.front());
        if (first < 0)
            reduced.fail(where + "/members", "'" + key.members.front() + "' is not a viseme of the file");
        key.positions = reducedScan.set.visemes[static_cast<std::size_t>(first)].positions;
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

int integerIn(const Json& value, std::size_t size, const GltfDocument& doc, const std::string& where) {
    if (!value.is_number_integer() || value.get<long long>() < 0 ||
        value.get<long long>() >= static_cast<long long>(size))
        doc.fail(where, "expected an index below " + std::to_string(size));
    return value.get<int>();
}

// A reduced avatar's meshes: each key drives the first of its targets (mesh.extras.visemeKeys).
std::vector<MeshDrive> reducedDrives(const GltfDocument& doc, std::size_t keyCount) {
    std::vector<MeshDrive> drives;
    for (std::size_t m = 0; m < doc.model.meshes.size(); ++m) {
        const Json& mesh = doc.json["meshes"][m];
        if (!mesh.contains("extras") || !mesh["extras"].is_object() || !mesh["extras"].contains("visemeKeys"))
            continue;
        const std::string where = "/meshes/" + std::to_string(m) + "/extras/visemeKeys";
        const auto& primitives = doc.model.meshes[m].primitives;
        const std::size_t targets = primitives.empty() ? 0 : primitives.front().targets.size();
        MeshDrive drive{static_cast<int>(m), std::vector<int>(targets, MeshDrive::kDefaultWeight)};
        const Json& keys = mesh["extras"]["visemeKeys"];
        if (!keys.is_array()) doc.fail(where, "expected an array");
        for (std::size_t i = 0; i < keys.size(); ++i) {
            const std::string at = where + "/" + std::to_string(i);
            if (!keys[i].is_object() || !keys[i].contains("targets") || !keys[i]["targets"].is_array())
                doc.fail(at, "expected {key, targets}");
            const int key = integerIn(member(keys[i], "key"), keyCount, doc, at + "/key");
            const Json& list = keys[i]["targets"];
            for (std::size_t j = 0; j < list.size(); ++j)
                drive.keyOfTarget[static_cast<std::size_t>(integerIn(
                    list[j], targets, doc, at + "/targets"))] = j == 0 ? key : MeshDrive::kZeroWeight;
        }
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
    const AvatarScan scan = scanAvatar(*doc, {options.targets});
    if (scan.visemes.size() < 2)
        throwInputError(doc->source, "needs at least 2 visemes to speak, found " +
                                         std::to_string(scan.visemes.size()) + " (" + scan.selection +
                                         "); see `visemelab avatar inspect`");
    AvatarSpeech speech;
    const FrequencySource source = speechFrequencies(scan, options, speech.frequencies);
    std::vector<std::string> names = scan.visemes;
    speech.faces.full = unreducedModel(scan.set, visemeFrequencies(source, names), source);
    speech.faces.weights = computeWeights(WeightMode::Uniform, scan.set.neutral);
    if (options.reduceTo > 0 || options.maxErrorMm > 0) {
        ReduceSettings settings;
        settings.target = options.reduceTo;
        settings.constraints = options.constraints;
        settings.constraintsSource = "--pin/--apart/--together";
        settings.maxErrorMm = options.maxErrorMm;
        settings.closure = options.closure;
        settings.millimetresPerUnit = 1000; // glTF lengths are metres
        settings.rest =
            RestChoice::Free; // as `avatar reduce`: the rest pose of a morph-target avatar is free
        AvatarReduction r = reduceAvatar(*doc, scan, source, settings, {});
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
    speech.drives = speech.reducedFace ? reducedDrives(*speech.animated, speech.faces.reduced.keys.size())
                                       : visemeDrives(scan, speech.faces.full);
    return speech;
}

} // namespace vl
