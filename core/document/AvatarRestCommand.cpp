// edit::addAvatarRestViseme: an avatar document whose visemes lack a rest viseme gains one (the base
// mesh, no target), so silence has a viseme and, with the rest free, rests at all weights 0.
#include "core/document/AvatarDocument.h"
#include "core/document/CommandSupport.h"
#include "core/document/Commands.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/AvatarRest.h"
#include "core/speech/Utterance.h"

#include <algorithm>

namespace vl::edit {

Document addAvatarRestViseme(const Document& document, const FrequencySource& oculusTable,
                             const std::string& requestedName) {
    if (!document.avatar.isSet()) throwInputError("rest viseme", "the document has no avatar");
    const AvatarScan& before = *document.avatar.scan;
    const std::string name = requestedName.empty() ? avatarRestName(before) : requestedName;
    auto scan = std::make_shared<AvatarScan>(before);
    addAvatarRest(*scan, name);
    Document next = document;
    next.avatar.scan = scan;
    applyAvatarSculpts(next, sculptedAvatarVisemes(document), "rest viseme"); // the rest goes last
    next.visemeFiles.emplace_back();
    if (document.frequencies == defaultAvatarFrequencies(before, oculusTable)) {
        // Still the defaults: those of the avatar with its rest (an Oculus avatar now fits the bundled
        // en-us table and Oculus map, whose pause 'sil' goes to the new viseme).
        next.frequencies = defaultAvatarFrequencies(*scan, oculusTable);
    } else if (next.frequencies.isPhonemeBased()) {
        auto& entries = next.frequencies.map.entries;
        const std::string silence(kSilencePhoneme);
        const auto it = std::find_if(entries.begin(), entries.end(),
                                     [&](const auto& entry) { return entry.first == silence; });
        if (it != entries.end())
            it->second = name;
        else
            entries.emplace_back(silence, name);
    } else {
        next.frequencies.visemeFrequencies.entries.emplace_back(name, 1.0);
    }
    return detail::checked(std::move(next));
}

} // namespace vl::edit
