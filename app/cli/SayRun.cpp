// `visemelab say "TEXT" | --text-file F --project P --out track.json [--wav audio.wav] [--glb anim.glb]`:
// text -> speech (espeak-ng) -> timed phonemes -> the full and the reduced viseme tracks, the
// utterance error between them, and (for a corpus) the error curve over m = 1..n.
// `--avatar IN.glb [-m M | --reduced R.glb]` instead of a project: the avatar speaks, and --glb
// writes the avatar itself with the speech animation (core/project/AvatarSpeech.h).
// What only the full commands do is behind SayHooks (Say.h; SayCommand.cpp).
#include "app/cli/Progress.h"
#include "app/cli/Say.h"
#include "app/cli/StandardOutput.h"
#include "core/common/AtomicFile.h"
#include "core/common/AtomicFileWriter.h"
#include "core/common/Error.h"
#include "core/common/OutputPolicy.h"
#include "core/phonetics/CorpusText.h"
#include "core/phonetics/EspeakSynthesizer.h"
#include "core/speech/DisplacementError.h"
#include "core/speech/TrackFormats.h"
#include "core/speech/TrackPlayback.h"
#include "core/speech/WavFile.h"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

namespace vl::cli {

namespace {

constexpr double kMaxFps = 1000;

// Outputs must differ from each other and from the inputs (a typo must not destroy the project).
void checkOutputs(const SayOptions& o) {
    const auto same = [](const std::string& a, const std::string& b) {
        if (a.empty() || b.empty()) return false;
        std::error_code ec;
        if (std::filesystem::equivalent(a, b, ec)) return true;
        return std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec);
    };
    const std::pair<const char*, const std::string*> outputs[] = {
        {"--out", &o.out}, {"--wav", &o.wav}, {"--glb", &o.glb}, {"--html", &o.html}};
    const std::pair<const char*, const std::string*> inputs[] = {{"--project", &o.project},
                                                                 {"--text-file", &o.textFile},
                                                                 {"--avatar", &o.avatar},
                                                                 {"--reduced", &o.reduced}};
    for (std::size_t i = 0; i < std::size(outputs); ++i) {
        for (std::size_t j = i + 1; j < std::size(outputs); ++j)
            if (same(*outputs[i].second, *outputs[j].second))
                throwUsage(std::string(outputs[i].first) + " and " + outputs[j].first +
                           " name the same file");
        for (const auto& [name, path] : inputs)
            if (same(*outputs[i].second, *path))
                throwUsage(std::string(outputs[i].first) + " would overwrite the input " + name + " " +
                           *path);
    }
}

// Throws InputError at `where` when the utterance is all pauses (`what`: "the text", "the line").
void requireSpeech(const Utterance& utterance, const std::string& where, const char* what) {
    for (const auto& p : utterance.phonemes)
        if (p.phoneme != kSilencePhoneme) return;
    throwInputError(where, std::string("nothing to say: ") + what + " has no words espeak-ng speaks");
}

// Speaks the inline text or the text file, streaming audio to the WAV writer when there is one.
Utterance speak(const SayOptions& o, SpeechSynthesizer& synthesizer, WavStreamWriter* wav) {
    Utterance utterance;
    const AudioSink sink = [wav](std::span<const std::int16_t> samples) {
        if (wav) wav->append(samples);
    };
    if (o.textFile.empty()) {
        synthesizer.speak(o.text, utterance, sink);
    } else {
        ProgressLine progress("speaking " + std::filesystem::path(o.textFile).filename().string());
        const auto fraction = progress.callback();
        forEachCorpusChunk(o.textFile, [&](std::string_view chunk, std::uint64_t done, std::uint64_t total) {
            synthesizer.speak(chunk, utterance, sink);
            if (fraction && total > 0) fraction(double(done) / double(total));
        });
    }
    requireSpeech(utterance, o.textFile.empty() ? "text" : o.textFile, "the text");
    return utterance;
}

void printDisplacement(const TrackError& e, std::size_t keys) {
    if (!e.displacement) return;
    const TrackDisplacementError& d = *e.displacement;
    std::printf(
        "speech error (m = %zu): RMS %.3g %s, max %.3g %s at %.2f s (vertex displacement over the mouth)\n",
        keys, d.rms, d.unit.c_str(), d.max, d.unit.c_str(), d.maxTime);
}

void printSummary(const SpeechTrackFile& track, std::size_t reducedKeys, std::size_t fullKeys) {
    const auto& e = *track.error;
    std::size_t pauses = 0;
    for (const auto& p : track.phonemes) pauses += p.phoneme == kSilencePhoneme;
    std::printf("%.2f s of speech: %zu phonemes (%zu pauses), %zu cues on %zu visemes, %zu cues on %d keys\n",
                track.metadata.duration, track.phonemes.size() - pauses, pauses, track.mouthCues.size(),
                fullKeys, track.reducedCues.size(), static_cast<int>(reducedKeys));
    std::printf("utterance error (m = %d, %s, %g fps): mean %.6g, max %.6g at %.2f s, %.2f %% of the mouth's "
                "motion\n",
                static_cast<int>(reducedKeys), track.metadata.interpolation.c_str(), track.metadata.fps,
                e.mean, e.max, e.maxTime, 100 * e.relative);
    printDisplacement(e, reducedKeys);
    if (track.errorCurve.empty()) return;
    std::printf("   m   reduction cost     error mean      error max   of motion\n");
    for (const auto& p : track.errorCurve)
        std::printf("%4d %16.6g %14.6g %14.6g %10.2f %%\n", p.m, p.cost, p.mean, p.max, 100 * p.relative);
}

// What the track file records of this run (core/project/SpokenTrack.h).
SpokenTrackOptions trackOptions(const SayOptions& o, runtime::Interpolation interpolation) {
    return {o.out, o.wav, o.textFile, o.voice, o.rate, o.project, interpolation, o.fps};
}

// `say --stdin`: one sentence per line of the standard input, one JSON line out per line in
// ({"line": N, "track": {...}} or {"line": N, "error": "..."}), flushed at once when the output is the
// standard output (a server reads each answer before it sends the next sentence). The faces are
// loaded once. A bad line is answered with its error and the run goes on; exit 3 if any line failed.
int sayLines(const SayOptions& o, const SpeakingFace& face, SpeechSynthesizer& synthesizer,
             runtime::Interpolation interpolation, TrackFormat format) {
    const bool streaming = isStandardOutput(o.out);
    std::optional<AtomicFileWriter> file;
    if (!streaming) file.emplace(o.out);
    std::size_t lineNumber = 0, failed = 0;
    std::string line;
    while (std::getline(std::cin, line)) {
        ++lineNumber;
        std::string text;
        try {
            if (!isValidUtf8(line)) throwInputError("stdin:" + std::to_string(lineNumber), "not UTF-8 text");
            Utterance utterance;
            synthesizer.speak(line, utterance, [](std::span<const std::int16_t>) {});
            requireSpeech(utterance, "stdin:" + std::to_string(lineNumber), "the line");
            const SpokenTrack spoken = spokenTrack(face, utterance, trackOptions(o, interpolation), line);
            // Spliced, not parsed again: the track is valid JSON text of our own writer.
            text = "{\"line\":" + std::to_string(lineNumber) + ",\"track\":";
            text += formatTrackLine(spoken.file, format, o.out);
            text += "}\n";
        } catch (const InputError& e) {
            const nlohmann::ordered_json answer{{"line", lineNumber}, {"error", e.what()}};
            text = answer.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
            ++failed;
        }
        if (file) {
            file->write(text);
        } else if (!writeToStandardOutput(text)) {
            throwInputError("the standard output",
                            "closed by its reader after line " + std::to_string(lineNumber));
        }
    }
    if (file) file->commit();
    std::fprintf(stderr, "said %zu lines (%zu failed)%s%s\n", lineNumber, failed, file ? "; wrote " : "",
                 file ? o.out.c_str() : "");
    return failed == 0 ? kExitOk : kExitInvalidInput;
}

int runSay(const SayOptions& o, const SayHooks& hooks) {
    if (o.lines) {
        if (!o.text.empty() || !o.textFile.empty() || !o.wav.empty() || !o.glb.empty() || !o.html.empty() ||
            o.curve)
            throwUsage("--stdin reads the sentences from the standard input: drop the text, --text-file, "
                       "--wav, --glb, --html and --curve");
    } else if (o.text.empty() == o.textFile.empty()) {
        throwUsage("give the text to say, or --text-file, not both");
    }
    if (!(o.fps > 0 && o.fps <= kMaxFps)) throwUsage("--fps must be in (0, 1000]");
    const auto interpolation = fromString<runtime::Interpolation>(o.blend);
    if (!interpolation) throwUsage("--blend must be linear, cubic or dominance, not '" + o.blend + "'");
    const auto format = fromString<TrackFormat>(o.format);
    if (!format) throwUsage("--format must be oculus, rhubarb or talkinghead, not '" + o.format + "'");
    if (o.project.empty() == o.avatar.empty()) throwUsage("give --project or --avatar");
    const bool constrained = !o.constraints.names().empty() || o.constraints.maxErrorMm > 0;
    if (o.avatar.empty() && (o.target > 0 || !o.reduced.empty() || !o.targets.empty() || constrained))
        throwUsage("-m, --reduced, --targets and the constraints go with --avatar");
    if (o.target > 0 && o.constraints.maxErrorMm > 0)
        throwUsage("--max-error-mm chooses the number of keys: drop -m");
    if (constrained && !o.reduced.empty())
        throwUsage("constraints apply to a reduction in memory (-m or --max-error-mm), not to --reduced");
    checkOutputs(o);

    std::optional<PhonemeVisemeMap> map;
    if (!o.map.empty()) map = loadPhonemeMapFile(o.map);
    const SpeakingFace face = hooks.loadFace(o, map);
    const AvatarSpeech* avatar = face.avatar.get();
    SayHooks::Curve curve;
    if (!avatar && (o.curve || !o.textFile.empty())) curve = hooks.curve(o, map);
    auto synthesizer = makeEspeakSynthesizer({o.voice, o.rate});
    if (o.lines) return sayLines(o, face, *synthesizer, *interpolation, *format);
    std::optional<WavStreamWriter> wav;
    if (!o.wav.empty()) wav.emplace(o.wav, synthesizer->sampleRate());
    const Utterance utterance = speak(o, *synthesizer, wav ? &*wav : nullptr);

    SpokenTrack spoken = spokenTrack(face, utterance, trackOptions(o, *interpolation), o.text);
    const FaceTrack& full = spoken.full;
    const FaceTrack& reduced = spoken.reduced;
    SpeechTrackFile& track = spoken.file;
    if (curve) track.errorCurve = curve(utterance);

    // Formatted before anything is written: a face whose names have no shape in the format is
    // refused without leaving other outputs behind.
    const std::string trackText = formatTrack(track, *format, o.out);
    if (wav) wav->finish();
    if (!o.glb.empty() || !o.html.empty()) hooks.views(o, face, spoken, trackText);
    writeFileAtomically(o.out, trackText);
    if (!o.quiet) {
        if (avatar) std::printf("%s: frequencies %s\n", o.avatar.c_str(), avatar->frequencies.c_str());
        printSummary(track, reduced.model().keys.size(), full.model().keys.size());
    }
    for (const auto& [symbol, count] : synthesizer->skippedSymbols())
        std::fprintf(stderr,
                     "visemelab: note: espeak symbol '%s' (%zu) has no ARPAbet equivalent; its time went to "
                     "the phoneme before it\n",
                     symbol.c_str(), count);
    std::fprintf(stderr, "Wrote %s", o.out.c_str());
    if (!o.wav.empty()) std::fprintf(stderr, ", %s", o.wav.c_str());
    if (!o.glb.empty()) std::fprintf(stderr, ", %s", o.glb.c_str());
    if (!o.html.empty()) std::fprintf(stderr, ", %s", o.html.c_str());
    std::fprintf(stderr, "\n");
    return kExitOk;
}

} // namespace

void addSayCommand(CLI::App& app, CommandRunner& run, SayHooks hooks) {
    auto o = std::make_shared<SayOptions>();
    auto* cmd = app.add_subcommand(
        "say", "Speak text (espeak-ng) and lip-sync it with the full and reduced visemes of a "
               "project or an avatar: Rhubarb-style track JSON, utterance error, WAV, animated glTF");
    cmd->add_option("text", o->text, "The text to say (or --text-file)");
    cmd->add_option("--text-file", o->textFile,
                    "UTF-8 text file of any length: also prints the error curve over m = 1..n");
    cmd->add_option("--project", o->project, "Project (.vlproj) with a phoneme -> viseme map");
    cmd->add_option("--avatar", o->avatar,
                    "Avatar (.glb, .gltf, .vrm) to speak with instead of a project: its visemes are the full "
                    "face");
    cmd->add_option("--target,-m", o->target,
                    "With --avatar: reduce its visemes to m keys in memory (as `avatar reduce`)")
        ->check(kPositive);
    addConstraintOptions(*cmd, o->constraints, kClosureAuto);
    cmd->add_option("--reduced", o->reduced,
                    "With --avatar: the avatar `avatar reduce` wrote from it, as the reduced face");
    cmd->add_option("--targets", o->targets,
                    "With --avatar: glob selecting the viseme targets (default: the Oculus visemes)");
    cmd->add_option("--out", o->out, "Track JSON to write (Rhubarb layout + reducedCues, phonemes, error)")
        ->required();
    cmd->add_option("--map", o->map,
                    "Phoneme -> viseme map (CSV/JSON) to use instead of the project's, e.g. for a project "
                    "with frequencies per viseme");
    cmd->add_option("--wav", o->wav, "Write the speech audio (16-bit mono WAV)");
    cmd->add_option("--glb", o->glb,
                    "Write the reduced face with the speech as a glTF morph weight animation (with --avatar: "
                    "the avatar itself, reduced with -m / --reduced, plus the animation)");
    cmd->add_option(
        "--html", o->html,
        "Write a web page that plays the face (with --avatar: the avatar) with the audio in three.js "
        "(everything embedded but three: see --three)");
    cmd->add_option("--three", o->three,
                    "URL of three.js's package folder for --html (default node_modules/three, beside the "
                    "page: npm install three)");
    cmd->add_option("--voice", o->voice,
                    "English espeak-ng voice: en-us (default), en-gb, en-gb-scotland, ...");
    cmd->add_option("--rate", o->rate, "Speaking rate in words per minute, 80..450 (default 175)");
    cmd->add_option("--fps", o->fps,
                    "Frames per second of the error curve and sampled animation (default 60)");
    cmd->add_option("--blend", o->blend,
                    "Playback blending: cubic (Catmull-Rom, default), linear, dominance");
    cmd->add_option("--format", o->format,
                    "Track layout: oculus (VisemeLab's track JSON, the face's viseme names; default), "
                    "rhubarb (Rhubarb Lip Sync's JSON, shapes A-H and X), talkinghead (TalkingHead's "
                    "visemes/vtimes/vdurations in ms)");
    cmd->add_flag("--curve", o->curve, "Also compute the error curve over m = 1..n for inline text");
    cmd->add_flag("--quiet", o->quiet, "Print only the written files");
    cmd->add_flag("--stdin", o->lines,
                  "Serve: read one sentence per line of the standard input and write one JSON line per "
                  "sentence to --out (`--out -`: the standard output, flushed per line); the face is loaded "
                  "once");
    cmd->callback([&run, o, hooks = std::move(hooks)] { run = [o, hooks] { return runSay(*o, hooks); }; });
}

} // namespace vl::cli
