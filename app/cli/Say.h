#pragma once
// `visemelab say`, shared by the two programs that run it: visemelab-cli (every command) and the
// lean visemelab-say (app/cli/SayMain.cpp, what the launcher runs for `say`), which links only what a
// project's sentence through the speech cache needs. The parts only the full commands have (loading
// a project or an avatar, the error curve, the --glb and --html views) are hooks: visemelab-cli
// passes them (SayCommand.cpp), visemelab-say hands the whole call to visemelab-cli instead.
#include "app/cli/Command.h"
#include "app/cli/ConstraintOptions.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/project/SpeakingFace.h"
#include "core/project/SpokenTrack.h"
#include "core/speech/TrackJson.h"
#include "core/speech/Utterance.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace vl::cli {

struct SayOptions {
    std::string text;
    std::string textFile;
    std::string project;
    std::string avatar;  // instead of a project
    std::string reduced; // with --avatar: that avatar reduced by `avatar reduce`
    std::string targets; // with --avatar: glob over target names
    int target = 0;      // with --avatar: reduce to m keys in memory
    std::string out;
    std::string wav;
    std::string glb;
    std::string html;
    std::string three = "node_modules/three";
    std::string map;
    std::string voice = "en-us";
    int rate = 175;
    double fps = 60;
    std::string blend = "cubic";
    std::string format = "oculus";
    ConstraintOptions constraints; // with --avatar -m
    bool curve = false;
    bool quiet = false;
    bool lines = false; // --stdin
};

struct SayHooks {
    // The face to speak with, after the options were checked and before anything is spoken.
    std::function<SpeakingFace(const SayOptions&, const std::optional<PhonemeVisemeMap>& map)> loadFace;
    // With --curve or --text-file on a project: loads the project (before speaking, so a broken
    // project is named first) and returns what computes an utterance's error curve.
    using Curve = std::function<std::vector<TrackErrorCurvePoint>(const Utterance&)>;
    std::function<Curve(const SayOptions&, const std::optional<PhonemeVisemeMap>& map)> curve;
    // Writes --glb and --html (`trackText`: the track file's text in the --format asked).
    std::function<void(const SayOptions&, const SpeakingFace&, const SpokenTrack&,
                       const std::string& trackText)>
        views;
};

// Registers `say` with its options; the run calls the hooks.
void addSayCommand(CLI::App& app, CommandRunner& run, SayHooks hooks);

} // namespace vl::cli
