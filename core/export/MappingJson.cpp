#include "core/export/MappingJson.h"

#include "core/export/KeyMeshFiles.h"

#include <nlohmann/json.hpp>

namespace vl {

std::string formatMappingJson(const ReducedModel& model, const std::vector<KeyFileField>& keyFiles) {
    // Names only: a model whose keys a writer merges as it writes them (KeyPositions::Deferred, no
    // neutral either) maps as well.
    if (model.neutral.positions.empty())
        validateDeferredModel(model, "mapping.json");
    else
        validateReducedModel(model, "mapping.json");
    nlohmann::ordered_json visemes = nlohmann::ordered_json::object(),
                           reduced = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < model.keys.size(); ++k) {
        const KeyMesh& key = model.keys[k];
        for (const std::string& member : key.members) visemes[member] = k;
        nlohmann::ordered_json entry{
            {"index", k}, {"name", key.name}, {"members", key.members}, {"frequency", key.frequency}};
        for (const KeyFileField& file : keyFiles) entry[file.field] = keyFileName(model, k, file.extension);
        reduced.push_back(entry);
    }
    for (const std::string& viseme : model.resting) visemes[viseme] = kRestingKey; // the neutral face
    nlohmann::ordered_json phonemes = nlohmann::ordered_json::object();
    for (const auto& [phoneme, key] : model.phonemeToKey) phonemes[phoneme] = key;
    nlohmann::ordered_json mapping{{"format", "visemelab-mapping"},
                                   {"version", 1},
                                   {"visemes", visemes},
                                   {"phonemes", phonemes},
                                   {"reduced", reduced}};
    return mapping.dump(2) + "\n";
}

} // namespace vl
