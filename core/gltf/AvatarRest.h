#pragma once
// An avatar whose visemes lack a rest viseme (sil / viseme_sil) can gain one (issue 29): the base
// mesh's shape, zero displacement, carried by no morph target. Silence maps to it, and with the rest
// free it rests, so a player shows the neutral (every weight 0) and the writer has no target to write
// for it (core/gltf/AvatarWriter.h: a viseme no mesh carries has no target on any mesh).
#include "core/gltf/AvatarScan.h"

#include <string>

namespace vl {

// True when a viseme of the scan is a rest viseme (sil / viseme_sil in any spelling, or the one added).
bool avatarHasRest(const AvatarScan& scan);

// The name an added rest viseme takes: "viseme_sil" when the avatar's visemes use the "viseme_"
// prefix (Ready Player Me, TalkingHead), else "sil".
std::string avatarRestName(const AvatarScan& scan);

// Appends the rest viseme `name` (one of kRestVisemeNames) with the neutral's positions to the set,
// carried by no target; records it as scan.addedRest. Throws InputError naming the avatar when the
// scan has a rest viseme already, the name is not a rest viseme's, or the set is at its size bound.
void addAvatarRest(AvatarScan& scan, const std::string& name);

} // namespace vl
