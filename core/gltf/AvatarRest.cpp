#include "core/gltf/AvatarRest.h"

#include "core/common/Error.h"
#include "core/reduce/ReduceRun.h"

#include <algorithm>
#include <cctype>
#include <iterator>

namespace vl {

namespace {

bool startsWithVisemePrefix(const std::string& name) {
    static constexpr std::string_view prefix = "viseme_";
    return name.size() > prefix.size() &&
           std::equal(prefix.begin(), prefix.end(), name.begin(),
                      [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
}

} // namespace

bool avatarHasRest(const AvatarScan& scan) {
    return std::find(scan.visemeKeys.begin(), scan.visemeKeys.end(), kRestVisemeNames[0]) !=
           scan.visemeKeys.end();
}

std::string avatarRestName(const AvatarScan& scan) {
    const bool prefixed = std::any_of(scan.visemes.begin(), scan.visemes.end(), startsWithVisemePrefix);
    return prefixed ? kRestVisemeNames[1] : kRestVisemeNames[0];
}

void addAvatarRest(AvatarScan& scan, const std::string& name) {
    const std::string where = scan.source + ": rest viseme '" + name + "'";
    if (std::find(std::begin(kRestVisemeNames), std::end(kRestVisemeNames), name) ==
        std::end(kRestVisemeNames))
        throwInputError(where, "an added rest viseme is named sil or viseme_sil");
    if (avatarHasRest(scan))
        throwInputError(where, "the avatar's visemes (" + scan.selection + ") have a rest viseme already");
    if (scan.visemes.size() >= kMaxAvatarVisemes)
        throwInputError(where, "the avatar has " + std::to_string(kMaxAvatarVisemes) + " visemes already");
    scan.visemes.push_back(name);
    scan.visemeKeys.push_back(visemeJoinKey(name));
    scan.set.visemes.push_back(Viseme{name, scan.set.neutral.positions});
    scan.addedRest = name;
}

} // namespace vl
