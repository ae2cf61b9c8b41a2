#pragma once
// The frequencies a reduced model carries back into an editable document (a VisemeLab glTF keeps
// them in mesh.extras, see Gltf.h): importing a model must not reset them to uniform.
#include "core/reduce/Frequencies.h"
#include "core/reduce/ReducedModel.h"

#include <string>

namespace vl {

// In order of preference, the first that gives valid frequencies for the model's keys:
//   1. its phoneme table mapped to the keys (phonemeFrequencies + phonemeToKey, every phoneme of the
//      table mapped), so the phoneme -> key map stays editable;
//   2. the keys' own frequencies (targetFrequencies), as direct viseme frequencies;
//   3. uniform (1 per key), when the model carries none (a glTF from another tool).
// `origin` names the source in later error messages (e.g. the glTF file).
FrequencySource modelFrequencies(const ReducedModel& model, const std::string& origin = {});

} // namespace vl
