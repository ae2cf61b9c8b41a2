#include "core/speech/TrackPlayback.h"

#include "core/common/Error.h"
#include "core/runtime/PackageFormat.h"
#include "core/speech/FaceTrack.h"
#include "core/speech/TrackKeyframes.h"

namespace vl {

FacePlayback playbackOf(const FaceTrack& face) {
    FacePlayback playback;
    for (const KeyMesh& key : face.model().keys) playback.keys.push_back({key.name, key.members});
    for (const runtime::Keyframe& k : face.curve().keyframes())
        playback.keyframes.push_back({k.time, k.key == runtime::kRestKey ? -1 : static_cast<int>(k.key),
                                      static_cast<double>(k.dominance)});
    return playback;
}

runtime::KeyframeCurve curveOf(const FacePlayback& face, const TrackPlayback& playback,
                               std::string_view where) {
    const auto interpolation = fromString<runtime::Interpolation>(playback.interpolation);
    if (!interpolation)
        throwInputError(where, "interpolation must be linear, cubic or dominance, not '" +
                                   playback.interpolation + "'");
    std::vector<runtime::Keyframe> keyframes;
    keyframes.reserve(face.keyframes.size());
    for (const PlaybackKeyframe& k : face.keyframes) {
        if (k.key < -1 || k.key >= static_cast<int>(face.keys.size()))
            throwInputError(where, "keyframe key " + std::to_string(k.key) + " of " +
                                       std::to_string(face.keys.size()) + " keys");
        keyframes.push_back({k.time, k.key < 0 ? runtime::kRestKey : static_cast<std::uint32_t>(k.key),
                             static_cast<float>(k.dominance)});
    }
    runtime::KeyframeCurve curve;
    std::string error;
    if (!curve.setKeyframes(static_cast<std::uint32_t>(face.keys.size()), std::move(keyframes),
                            *interpolation, error, playback.dominanceRate))
        throwInputError(where, "keyframes: " + error);
    return curve;
}

} // namespace vl
