#pragma once
// The speaking avatar as one GLB: the animated document of an AvatarSpeech (every mesh, skin,
// material, node, animation and extra kept, core/gltf/GlbRepack.h) plus one glTF animation "speech"
// whose channels (path "weights") drive every node instancing a mesh that carries visemes. Each
// mesh's sampler gives all of its morph targets: the viseme targets follow the track's key weights
// (core/speech/SpeechGltf.h: its keyframes, CUBICSPLINE for cubic blending), other targets keep the
// mesh's default weights.
#include "core/project/AvatarSpeech.h"
#include "core/speech/FaceTrack.h"

#include <string>

namespace vl {

// `track` is the face driving the animated document (the reduced face when there is one). Throws
// InputError when no node instances a mesh carrying visemes.
std::string speakingAvatarGlb(const AvatarSpeech& speech, const FaceTrack& track, double fps);

} // namespace vl
