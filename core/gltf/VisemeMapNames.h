#pragma once
// Phoneme -> viseme maps and frequency tables written for one viseme naming, used on a set named
// another way. The bundled maps (assets/phonemes) name Oculus visemes ("aa", "ih"), Rhubarb Lip Sync
// mouth shapes ("A".."H", "X") or MPEG-4 visemes ("p_b_m", "A"); avatars name their targets
// "viseme_aa", "viseme_I", "AA". A name is matched to the set's viseme of the same meaning:
// - the same name, else the same join key (core/gltf/AvatarScan.h: Oculus spelling with or without
//   "viseme_", any case, Ready Player Me's I/O/U);
// - when that leaves names unmatched and every name of the map is a Rhubarb shape (or every one an
//   MPEG-4 viseme), the whole map is read in that convention and each shape goes to the Oculus
//   viseme that shows it (Rhubarb's B, "slightly open, clenched teeth" for K S T EE, to SS; its H,
//   the long L, to nn; MPEG-4's Q to oh), then to the set's name for that.
// Names that still match nothing stay as they are, so the usual "visemes the set lacks" error names them.
#include "core/reduce/Frequencies.h"

#include <optional>
#include <string>
#include <vector>

namespace vl {

// The Oculus viseme a Rhubarb mouth shape (A..H, X) or an MPEG-4 viseme name shows, if it is one.
std::optional<std::string> oculusVisemeOfRhubarbShape(std::string_view shape);
std::optional<std::string> oculusVisemeOfMpeg4(std::string_view name);

// `map` with its viseme names replaced by the names `visemes` has for them (see above).
PhonemeVisemeMap mapOntoVisemes(PhonemeVisemeMap map, const std::vector<std::string>& visemes);

// `source` with its viseme frequencies' names matched by join key and its map by mapOntoVisemes.
FrequencySource frequenciesOntoVisemes(FrequencySource source, const std::vector<std::string>& visemes);

} // namespace vl
