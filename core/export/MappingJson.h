#pragma once
// mapping.json of a reduced model: the document `visemelab reduce` writes beside its meshes (format
// "visemelab-mapping", version 1), so that a player of any export format can turn an original
// viseme or a phoneme into a key: {"visemes": {viseme: key}, "phonemes": {phoneme: key},
// "reduced": [{"index", "name", "members", "frequency"[, file fields]}]}.
#include "core/reduce/ReducedModel.h"

#include <string>
#include <vector>

namespace vl {

// A field of each "reduced" entry naming the key's file in the same folder (keyFileName with
// `extension`): a folder export has {"file", ".obj"}, `visemelab reduce` {"obj", ".obj"} and {"wrl", ".wrl"}.
struct KeyFileField {
    std::string field;
    std::string extension;
};

std::string formatMappingJson(const ReducedModel& model, const std::vector<KeyFileField>& keyFiles = {});

} // namespace vl
