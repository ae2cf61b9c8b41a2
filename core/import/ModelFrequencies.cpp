#include "core/import/ModelFrequencies.h"

#include "core/common/Error.h"

#include <cmath>

namespace vl {
namespace {

bool resolves(const FrequencySource& source, const std::vector<std::string>& names) {
    try {
        visemeFrequencies(source, names);
        return true;
    } catch (const InputError&) {
        return false;
    }
}

} // namespace

FrequencySource modelFrequencies(const ReducedModel& model, const std::string& origin) {
    std::vector<std::string> names;
    for (const KeyMesh& key : model.keys) names.push_back(key.name);
    const int keyCount = static_cast<int>(model.keys.size());

    FrequencySource phonemeBased;
    phonemeBased.origin.text = origin;
    phonemeBased.map.origin.text = origin;
    for (const auto& [phoneme, frequency] : model.phonemeFrequencies)
        phonemeBased.phonemes.entries.emplace_back(phoneme, frequency);
    for (const auto& [phoneme, key] : model.phonemeToKey)
        if (key >= 0 && key < keyCount)
            phonemeBased.map.entries.emplace_back(phoneme, names[static_cast<std::size_t>(key)]);
    if (phonemeBased.isPhonemeBased() && resolves(phonemeBased, names)) return phonemeBased;

    FrequencySource direct;
    direct.origin.text = origin;
    for (const KeyMesh& key : model.keys)
        direct.visemeFrequencies.entries.emplace_back(key.name, key.frequency);
    if (resolves(direct, names)) return direct;

    FrequencySource uniform;
    uniform.origin.text = origin;
    for (const std::string& name : names) uniform.visemeFrequencies.entries.emplace_back(name, 1.0);
    return uniform;
}

} // namespace vl
