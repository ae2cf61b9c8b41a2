// `visemelab say` in visemelab-cli: the parts of the command only the full commands have (SayRun.cpp
// runs it; app/cli/Say.h): loading a project (through the speech cache) or an avatar, the error curve
// over m = 1..n, and the --glb and --html views.
#include "app/cli/PlayerModule.h"
#include "app/cli/Progress.h"
#include "app/cli/Say.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/gltf/TargetNames.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/project/Project.h"
#include "core/project/ProjectSpeech.h"
#include "core/project/SpeechCache.h"
#include "core/speech/SpeechPage.h"
#include "core/speech/TrackFormats.h"
#include "core/speech/TrackPlayback.h"

#include <filesystem>
#include <memory>

namespace vl::cli {

namespace {

std::vector<TrackErrorCurvePoint> errorCurve(const SayOptions& o, const Project& project,
                                             const Utterance& utterance, const PlaybackSettings& settings,
                                             const PhonemeVisemeMap* map) {
    ProgressLine progress("error curve");
    std::vector<TrackErrorCurvePoint> points;
    for (const auto& p :
         projectErrorCurve(project, utterance.phonemes, settings, o.fps, progress.callback(), map))
        points.push_back({p.m, p.cost, p.error.mean, p.error.max, p.error.relative});
    return points;
}

// What the avatar speaks with (AvatarSpeechOptions), checking the avatar options.
AvatarSpeechOptions avatarOptions(const SayOptions& o, const std::optional<PhonemeVisemeMap>& map) {
    if (!o.project.empty()) throwUsage("give --project or --avatar, not both");
    if (o.target > 0 && !o.reduced.empty()) throwUsage("give -m or --reduced, not both");
    if (o.curve) throwUsage("--curve needs --project (the error curve reduces a project to every m)");
    if (!o.glb.empty() && std::filesystem::path(o.glb).extension() == ".gltf")
        throwUsage("--glb " + o.glb +
                   ": the speaking avatar is written as binary glTF; name it .glb (or .vrm)");
    if (!o.targets.empty()) checkGlobPattern(o.targets, "--targets");
    AvatarSpeechOptions options;
    options.targets = o.targets;
    options.reduceTo = o.target;
    options.constraints = o.constraints.names();
    options.maxErrorMm = o.constraints.maxErrorMm;
    options.closure = closureSetting(o.constraints);
    options.reduced = o.reduced;
    options.phonemeTable = bundledPhonemeFrequencies(VISEMELAB_ASSETS_DIR, "oculus");
    options.map = map;
    return options;
}

SpeakingFace sayFace(const SayOptions& o, const std::optional<PhonemeVisemeMap>& map) {
    SpeakingFaceRequest request;
    if (!o.avatar.empty()) {
        request.avatar = o.avatar;
        request.avatarOptions = avatarOptions(o, map);
    } else {
        request.project = o.project;
        request.map = map;
        request.speechCacheFolder = speechCacheFolder();
    }
    return loadSpeakingFace(request);
}

SayHooks::Curve sayCurve(const SayOptions& o, const std::optional<PhonemeVisemeMap>& map) {
    auto project = std::make_shared<const Project>(loadProject(o.project));
    return [o, project, map](const Utterance& utterance) {
        const auto interpolation = fromString<runtime::Interpolation>(o.blend);
        return errorCurve(o, *project, utterance, PlaybackSettings{*interpolation}, map ? &*map : nullptr);
    };
}

void sayViews(const SayOptions& o, const SpeakingFace& face, const SpokenTrack& spoken,
              const std::string& trackText) {
    // The face the --glb file and the --html page show: the avatar itself (animated), or the reduced face.
    const std::string glb = spokenGlb(face, spoken, o.fps);
    if (!o.glb.empty()) writeFileAtomically(o.glb, glb);
    if (o.html.empty()) return;
    // The page always carries VisemeLab's own track (the player needs its playback section).
    const std::string ownTrack =
        *fromString<TrackFormat>(o.format) == TrackFormat::Oculus ? trackText : formatTrackJson(spoken.file);
    const std::string audio = o.wav.empty() ? std::string() : readFileToString(o.wav);
    writeFileAtomically(o.html, speechPageHtml({o.text.empty() ? o.textFile : o.text, glb, ownTrack, audio,
                                                playerModuleSource(), o.three}));
}

} // namespace

void addSayCommand(CLI::App& app, CommandRunner& run) {
    addSayCommand(app, run, SayHooks{sayFace, sayCurve, sayViews});
}

} // namespace vl::cli
