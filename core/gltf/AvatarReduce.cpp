#include "core/gltf/AvatarReduce.h"

#include "core/common/Error.h"
#include "core/gltf/GltfDocument.h"
#include "core/gltf/OwnOutput.h"
#include "core/gltf/VisemeMapNames.h"

#include <algorithm>

namespace vl {
FrequencySource matchVisemeNames(FrequencySource source, const AvatarScan& scan) {
    return frequenciesOntoVisemes(std::move(source), scan.visemes);
}

bool mapFitsAvatar(const PhonemeVisemeMap& map, const AvatarScan& scan) {
    return std::all_of(map.entries.begin(), map.entries.end(), [&](const auto& entry) {
        const std::string key = visemeJoinKey(entry.second);
        return std::find(scan.visemeKeys.begin(), scan.visemeKeys.end(), key) != scan.visemeKeys.end();
    });
}

FrequencySource uniformFrequencies(const AvatarScan& scan) {
    FrequencySource source;
    for (const std::string& name : scan.visemes) source.visemeFrequencies.entries.emplace_back(name, 1.0);
    return source;
}

FrequencySource defaultAvatarFrequencies(const AvatarScan& scan, const FrequencySource& oculusTable,
                                         std::string* chosen) {
    const bool fits = oculusTable.isPhonemeBased() && !oculusTable.map.entries.empty() &&
                      mapFitsAvatar(oculusTable.map, scan);
    if (scan.oculusNames && fits) {
        if (chosen) *chosen = "bundled en-us phoneme table + map oculus (bundled)";
        return matchVisemeNames(oculusTable, scan);
    }
    if (chosen)
        *chosen = scan.oculusNames
                      ? "equal (the avatar lacks some of the Oculus map's visemes)"
                      : "equal (not Oculus viseme names: give --freq-file, or --map for phonemes)";
    return uniformFrequencies(scan);
}

AvatarReduction reduceAvatar(const GltfDocument& doc, const AvatarScan& scan,
                             const FrequencySource& frequencies, const ReduceSettings& settings,
                             const AvatarWriteOptions& write, const ProgressCallback& progress) {
    if (scan.visemes.size() < 2)
        throwInputError(doc.source, "needs at least 2 visemes to reduce, found " +
                                        std::to_string(scan.visemes.size()) + " (" + scan.selection +
                                        "); see `visemelab avatar inspect`");
    const FrequencySource matched = matchVisemeNames(frequencies, scan);
    AvatarReduction r;
    r.outcome = runReduction(scan.set, matched, settings, progress);
    const std::vector<int> groupOf = r.outcome.result.groupOf();
    r.glb = writeReducedAvatar(doc, scan, r.outcome.model, groupOf, r.outcome.frequencies, write, &r.summary);
    if (scan.own.recognised) // reducing a reduction: say what was reduced
        r.summary.notes.push_back(
            doc.source + ": " + describeOwnOutput(scan.own) +
            (scan.own.mergedNames ? "; its key targets were reduced as visemes"
                                  : "; its visemes, which share their keys' shapes, were reduced again"));
    for (std::size_t i = 0; i < scan.visemes.size(); ++i)
        if (r.outcome.frequencies[i] == 0.0 && groupOf[i] != kRestGroup)
            r.summary.notes.push_back(scan.visemes[i] +
                                      " has frequency 0 (no phoneme maps to it): it costs nothing " +
                                      "wherever it goes and takes the shape of key '" +
                                      r.outcome.model.keys[static_cast<std::size_t>(groupOf[i])].name + "'");
    return r;
}

ReduceSettings avatarReduceSettings(int target) {
    ReduceSettings settings;
    settings.target = target;
    settings.rest = RestChoice::Free;
    settings.closure = kClosureAuto;
    settings.millimetresPerUnit = 1000; // glTF lengths are metres
    settings.constraintsSource = "--pin/--apart/--together";
    return settings;
}

} // namespace vl
