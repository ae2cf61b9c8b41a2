#include "core/project/SpeakingFace.h"

#include "core/project/SpeechCache.h"

namespace vl {

namespace {

// The models validated once and the error basis made once (unless given), for every sentence the
// face speaks (spokenTrack's tracks skip the validation).
SpeakingFace completed(SpeakingFace face, SpeechFaces faces, std::shared_ptr<const SpeechErrorBasis> basis) {
    face.full = std::make_shared<const ReducedModel>(std::move(faces.full));
    face.reduced = std::make_shared<const ReducedModel>(std::move(faces.reduced));
    face.weights = std::move(faces.weights);
    validateReducedModel(*face.full, face.where);
    validateReducedModel(*face.reduced, face.where);
    face.errorBasis = basis
                          ? std::move(basis)
                          : std::make_shared<const SpeechErrorBasis>(*face.full, *face.reduced, face.weights);
    return face;
}

} // namespace

SpeakingFace speakingProjectFace(ProjectSpeechFaces faces, const std::filesystem::path& project) {
    SpeakingFace face;
    if (faces.metres) face.unit = millimetresFromMetres(); // a project of mesh files has no unit
    face.where = project.string();
    return completed(std::move(face), std::move(faces.faces), std::move(faces.basis));
}

SpeakingFace loadSpeakingFace(const SpeakingFaceRequest& request) {
    if (request.avatar.empty())
        return speakingProjectFace(cachedProjectSpeechFaces(request.project,
                                                            request.map ? &*request.map : nullptr,
                                                            request.speechCacheFolder),
                                   request.project);
    SpeakingFace face;
    auto speech = std::make_shared<AvatarSpeech>(avatarSpeech(request.avatar, request.avatarOptions));
    // Moved, not copied: an avatar's keys are the size of its meshes.
    SpeechFaces faces = std::move(speech->faces);
    face.avatar = std::move(speech);
    face.unit = millimetresFromMetres(); // glTF lengths are metres
    face.where = request.avatar.string();
    return completed(std::move(face), std::move(faces), nullptr);
}

} // namespace vl
