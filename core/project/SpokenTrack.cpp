#include "core/project/SpokenTrack.h"

#include "core/export/GltfExport.h"
#include "core/project/AvatarSpeechGlb.h"
#include "core/project/Project.h"
#include "core/speech/SpeechErrors.h"
#include "core/speech/SpeechGltf.h"
#include "core/speech/TrackPlayback.h"

namespace vl {

SpokenTrack spokenTrack(const SpeakingFace& face, const Utterance& utterance, const SpokenTrackOptions& o,
                        const std::string& text) {
    const PlaybackSettings settings{o.interpolation};
    // loadSpeakingFace validated the models (and made the basis); a face made by hand is checked here.
    const auto validated =
        face.errorBasis ? FaceTrack::ModelCheck::AlreadyValidated : FaceTrack::ModelCheck::Validate;
    SpokenTrack spoken{FaceTrack(face.full, utterance.phonemes, settings, face.where, validated),
                       FaceTrack(face.reduced, utterance.phonemes, settings, face.where, validated),
                       {}};
    const FaceTrack& full = spoken.full;
    const FaceTrack& reduced = spoken.reduced;
    // A face made by hand (no basis) gets one for this sentence.
    const std::shared_ptr<const SpeechErrorBasis> basis =
        face.errorBasis ? face.errorBasis
                        : std::make_shared<const SpeechErrorBasis>(*face.full, *face.reduced, face.weights);
    const SpeechErrors errors = measureSpeechErrors(*basis, full, reduced, o.fps, face.unit);
    const UtteranceError& error = errors.utterance;
    const DisplacementError& displacement = errors.displacement;
    SpeechTrackFile& track = spoken.file;
    track.metadata = {o.wav.empty() ? std::string() : projectRelativePath(o.out, o.wav).generic_string(),
                      utterance.duration(),
                      text,
                      o.textFile,
                      o.voice,
                      o.wordsPerMinute,
                      o.project,
                      toString(o.interpolation),
                      o.fps};
    track.mouthCues = full.cues();
    track.reducedCues = reduced.cues();
    track.phonemes = utterance.phonemes;
    track.error = TrackError{error.mean,
                             error.max,
                             error.maxTime,
                             error.relative,
                             error.frames,
                             TrackDisplacementError{displacement.unit, displacement.rms, displacement.max,
                                                    displacement.maxTime, displacement.rmsFrames,
                                                    displacement.maxFrames}};
    track.playback = TrackPlayback{toString(o.interpolation), settings.dominanceRate, playbackOf(full),
                                   playbackOf(reduced)};
    return spoken;
}

std::string spokenGlb(const SpeakingFace& face, const SpokenTrack& spoken, double fps) {
    if (face.avatar)
        return speakingAvatarGlb(*face.avatar, face.avatar->reducedFace ? spoken.reduced : spoken.full, fps);
    const GltfMorphAnimation animation = gltfAnimationOf(spoken.reduced, fps);
    return formatGlb(spoken.reduced.model(), &animation);
}

} // namespace vl
