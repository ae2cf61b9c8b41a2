#include "core/project/SpeakingFace.h"

#include "core/project/SpeechCache.h"

namespace vl {

SpeakingFace loadSpeakingFace(const SpeakingFaceRequest& request) {
    SpeakingFace face;
    SpeechFaces faces;
    if (!request.avatar.empty()) {
        auto speech = std::make_shared<AvatarSpeech>(avatarSpeech(request.avatar, request.avatarOptions));
        // Moved, not copied: an avatar's keys are the size of its meshes.
        faces = std::move(speech->faces);
        face.avatar = std::move(speech);
        face.unit = millimetresFromMetres(); // glTF lengths are metres
        face.where = request.avatar.string();
    } else {
        ProjectSpeechFaces cached = cachedProjectSpeechFaces(
            request.project, request.map ? &*request.map : nullptr, request.speechCacheFolder);
        faces = std::move(cached.faces);
        if (cached.metres) face.unit = millimetresFromMetres(); // a project of mesh files has no unit
        face.where = request.project.string();
    }
    face.full = std::make_shared<const ReducedModel>(std::move(faces.full));
    face.reduced = std::make_shared<const ReducedModel>(std::move(faces.reduced));
    face.weights = std::move(faces.weights);
    // Once for every sentence the face speaks (spokenTrack's tracks skip it).
    validateReducedModel(*face.full, face.where);
    validateReducedModel(*face.reduced, face.where);
    face.errorBasis = std::make_shared<const SpeechErrorBasis>(*face.full, *face.reduced, face.weights);
    return face;
}

} // namespace vl
