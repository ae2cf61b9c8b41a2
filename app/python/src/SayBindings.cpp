// visemelab.say: `visemelab say TEXT` on bytes, through the core's speech use cases
// (core/project/SpeakingFace.h, SpokenTrack.h): the track file and the WAV the command writes.
#include "app/python/src/Arrays.h"
#include "app/python/src/Bindings.h"
#include "app/python/src/Options.h"
#include "core/common/Error.h"
#include "core/gltf/TargetNames.h"
#include "core/phonetics/EspeakFreshSynthesis.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/project/SpeakingFace.h"
#include "core/project/SpeechCache.h"
#include "core/project/SpokenTrack.h"
#include "core/speech/TrackFormats.h"
#include "core/speech/TrackKeyframes.h"
#include "core/speech/WavFile.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

namespace py = pybind11;

namespace vl::python {

namespace {

using Pairs = std::vector<std::pair<std::string, std::string>>;

struct SayArguments {
    std::string text;
    std::optional<std::filesystem::path> project, avatar, reduced, map;
    std::string voice;
    int rate = 175;
    double fps = 60;
    std::string blend, format, targets;
    int m = 0;
    ConstraintNames constraints;
    double maxErrorMm = 0;
    std::string closure;
    std::filesystem::path trackName, wavName;
    bool glb = false;
};

// espeak-ng keeps state between sentences that its API cannot reset (EspeakFreshSynthesis.h): each
// sentence is spoken by a fresh child of one helper process, so a sentence's bytes do not depend on
// what this process said before (the same bytes as `visemelab say`). The helper starts on first use.
const FreshSpeech& freshSpeech() {
    static const FreshSpeech speech;
    return speech;
}

SpeakingFaceRequest faceRequest(const SayArguments& a) {
    SpeakingFaceRequest request;
    std::optional<PhonemeVisemeMap> map;
    if (a.map) map = loadPhonemeMapFile(*a.map);
    if (a.avatar) {
        request.avatar = *a.avatar;
        AvatarSpeechOptions& options = request.avatarOptions;
        options.targets = a.targets;
        options.reduceTo = a.m;
        options.constraints = a.constraints;
        options.maxErrorMm = a.maxErrorMm;
        options.closure = a.closure == "none" ? std::string() : a.closure;
        options.reduced = a.reduced.value_or(std::filesystem::path());
        options.phonemeTable = bundledPhonemeFrequencies(VISEMELAB_ASSETS_DIR, "oculus");
        options.map = map;
    } else {
        request.project = *a.project;
        request.map = map;
        request.speechCacheFolder = speechCacheFolder();
    }
    return request;
}

// The checks `say` makes on its flags, as ValueError (a programming mistake, not bad data).
void checkArguments(const SayArguments& a) {
    if (a.project.has_value() == a.avatar.has_value()) throw py::value_error("give project or avatar");
    const bool reducing =
        a.m > 0 || a.reduced || !a.targets.empty() || !a.constraints.empty() || a.maxErrorMm > 0;
    if (a.project && reducing)
        throw py::value_error("m, reduced, targets and the constraints go with avatar");
    if (a.m > 0 && a.reduced) throw py::value_error("give m or reduced, not both");
    if (a.m > 0 && a.maxErrorMm > 0) throw py::value_error("max_error_mm chooses the number of keys: drop m");
    if (!(a.fps > 0 && a.fps <= 1000)) throw py::value_error("fps must be in (0, 1000]");
    if (!a.targets.empty()) checkGlobPattern(a.targets, "targets");
}

py::dict say(const SayArguments& a) {
    checkArguments(a);
    const auto interpolation = fromString<runtime::Interpolation>(a.blend);
    if (!interpolation) throw py::value_error("blend must be linear, cubic or dominance");
    const auto format = fromString<TrackFormat>(a.format);
    if (!format) throw py::value_error("format must be oculus, rhubarb or talkinghead");
    std::string track, wav, glb;
    {
        py::gil_scoped_release release;
        const SpeakingFace face = loadSpeakingFace(faceRequest(a));
        const Utterance utterance = freshSpeech().speak({a.voice, a.rate}, a.text).utterance;
        bool spoken = false;
        for (const auto& p : utterance.phonemes) spoken = spoken || p.phoneme != kSilencePhoneme;
        if (!spoken) throwInputError("text", "nothing to say: the text has no words espeak-ng speaks");
        const SpokenTrackOptions options{
            a.trackName,    a.wavName, {}, a.voice, a.rate, a.project ? a.project->string() : std::string(),
            *interpolation, a.fps};
        const SpokenTrack spokenTrack = vl::spokenTrack(face, utterance, options, a.text);
        track = formatTrack(spokenTrack.file, *format, a.trackName.string());
        wav = formatWav(utterance.samples, utterance.sampleRate);
        if (a.glb) glb = spokenGlb(face, spokenTrack, a.fps);
    }
    py::dict result;
    result["track"] = track;
    result["wav"] = toBytes(wav);
    result["glb"] = a.glb ? py::object(toBytes(glb)) : py::none();
    return result;
}

} // namespace

void bindSay(py::module_& m) {
    m.def(
        "say",
        [](const std::string& text, const std::optional<std::filesystem::path>& project,
           const std::optional<std::filesystem::path>& avatar, const std::string& voice, int rate, double fps,
           const std::string& blend, const std::string& format,
           const std::optional<std::filesystem::path>& map, int mKeys,
           const std::optional<std::filesystem::path>& reduced, const std::string& targets,
           const std::vector<std::string>& pin, const Pairs& apart, const Pairs& together, double maxErrorMm,
           const std::string& closure, const std::filesystem::path& trackName,
           const std::filesystem::path& wavName, bool glb) {
            return say({text, project, avatar, reduced, map, voice, rate, fps, blend, format, targets, mKeys,
                        ConstraintNames{pin, apart, together}, maxErrorMm, closure, trackName, wavName, glb});
        },
        py::arg("text"), py::kw_only(), py::arg("project") = py::none(), py::arg("avatar") = py::none(),
        py::arg("voice") = "en-us", py::arg("rate") = 175, py::arg("fps") = 60.0, py::arg("blend") = "cubic",
        py::arg("format") = "oculus", py::arg("map") = py::none(), py::arg("m") = 0,
        py::arg("reduced") = py::none(), py::arg("targets") = "", py::arg("pin") = std::vector<std::string>{},
        py::arg("apart") = Pairs{}, py::arg("together") = Pairs{}, py::arg("max_error_mm") = 0.0,
        py::arg("closure") = kClosureAuto, py::arg("track_name") = "track.json",
        py::arg("wav_name") = "audio.wav", py::arg("glb") = false,
        "Says `text` as `visemelab say TEXT --project P | --avatar A [-m M] --out TRACK_NAME --wav WAV_NAME` "
        "does: {'track': the track file's text, 'wav': the WAV's bytes, 'glb': the --glb bytes (with "
        "glb=True) or None}; the same bytes as the command with those names (the track names the WAV "
        "relative to itself)");
}

} // namespace vl::python
