#pragma once
// What `say` speaks with, loaded once for any number of sentences: the full and the reduced face of
// a project (through the speech cache, core/project/SpeechCache.h) or of an avatar
// (core/project/AvatarSpeech.h), the vertex weights of the error and the unit of displacements. The
// CLI's `say` loads one per run; `visemelab batch` shares one between every job that names the same
// face (core/batch).
#include "core/project/AvatarSpeech.h"
#include "core/project/SpeechCache.h"
#include "core/reduce/ReducedModel.h"
#include "core/speech/DisplacementError.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vl {

struct SpeakingFaceRequest {
    std::filesystem::path project;           // a project, or
    std::filesystem::path avatar;            // an avatar, with
    AvatarSpeechOptions avatarOptions;       // its reduction (its map: avatarOptions.map)
    std::optional<PhonemeVisemeMap> map;     // with a project: instead of the project's map
    std::filesystem::path speechCacheFolder; // with a project; empty: no cache file
};

struct SpeakingFace {
    std::shared_ptr<const ReducedModel> full, reduced; // validated (validateReducedModel) by the loader
    std::vector<double> weights;                       // per vertex
    // What the speech error measures need of full, reduced and weights, made once for every sentence.
    std::shared_ptr<const SpeechErrorBasis> errorBasis;
    DisplacementUnit unit; // mm for avatars and avatar projects (glTF metres), else model units
    std::string where;     // the project or avatar, for messages
    // With an avatar: its speech (without the faces, moved into full / reduced), for the animated GLB
    // and the frequencies it chose.
    std::shared_ptr<const AvatarSpeech> avatar;
};

// Throws what cachedProjectSpeechFaces or avatarSpeech throw (InputError naming the file).
SpeakingFace loadSpeakingFace(const SpeakingFaceRequest& request);

// The speaking face of a project's speech faces (cachedProjectSpeechFaces), for messages `project`.
SpeakingFace speakingProjectFace(ProjectSpeechFaces faces, const std::filesystem::path& project);

} // namespace vl
