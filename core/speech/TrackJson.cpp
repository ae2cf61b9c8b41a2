#include "core/speech/TrackJson.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/io/JsonRead.h"
#include "core/speech/JsonText.h"

namespace vl {

namespace {

// [{"start": s, "end": e, "value": v}, ...], one element per line.
template <typename Timed, typename ValueOf>
std::string timedArray(const std::vector<Timed>& items, ValueOf valueOf) {
    if (items.empty()) return "[]";
    std::string text = "[";
    for (std::size_t i = 0; i < items.size(); ++i)
        text += std::string(i == 0 ? "\n" : ",\n") + "    {\"start\": " + json_text::number(items[i].start) +
                ", \"end\": " + json_text::number(items[i].end) +
                ", \"value\": " + json_text::string(valueOf(items[i])) + "}";
    return text + "\n  ]";
}

std::string numberArray(const std::vector<double>& values) {
    std::string text = "[";
    text.reserve(values.size() * 22);
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i > 0) text += ", ";
        json_text::appendNumber(text, values[i]);
    }
    return text + "]";
}

struct TimedElement {
    double start, end;
    std::string value;
};

std::vector<TimedElement> readTimedArray(const JsonNode& node) {
    std::vector<TimedElement> items;
    for (const JsonNode& element : node.elements()) {
        element.expectObject();
        element.allowOnly({"start", "end", "value"});
        items.push_back(
            {element["start"].number(), element["end"].number(), element["value"].nonEmptyString()});
    }
    return items;
}

std::vector<Cue> readCues(const JsonNode& node) {
    std::vector<Cue> cues;
    for (auto& item : readTimedArray(node)) cues.push_back({item.start, item.end, std::move(item.value)});
    checkCues(cues, node.path());
    return cues;
}

std::string optionalString(const JsonNode& object, std::string_view key) {
    return object.has(key) ? object[key].string() : std::string();
}

double optionalNumber(const JsonNode& object, std::string_view key) {
    return object.has(key) ? object[key].nonNegativeNumber() : 0.0;
}

std::string facePlaybackJson(const FacePlayback& face) {
    std::string text = "{\"keys\": [";
    for (std::size_t k = 0; k < face.keys.size(); ++k) {
        text += std::string(k == 0 ? "\n      " : ",\n      ") +
                "{\"name\": " + json_text::string(face.keys[k].name) + ", \"members\": [";
        for (std::size_t j = 0; j < face.keys[k].members.size(); ++j)
            text += (j == 0 ? "" : ", ") + json_text::string(face.keys[k].members[j]);
        text += "]}";
    }
    text += "],\n    \"keyframes\": [";
    for (std::size_t i = 0; i < face.keyframes.size(); ++i) {
        const PlaybackKeyframe& k = face.keyframes[i];
        text += std::string(i == 0 ? "" : (i % 4 == 0 ? ",\n      " : ", ")) + "[" +
                json_text::number(k.time) + ", " + std::to_string(k.key) + ", " +
                json_text::number(k.dominance) + "]";
    }
    return text + "]}";
}

std::string playbackJson(const TrackPlayback& playback) {
    return "{\"interpolation\": " + json_text::string(playback.interpolation) +
           ", \"dominanceRate\": " + json_text::number(playback.dominanceRate) +
           ",\n    \"full\": " + facePlaybackJson(playback.full) +
           ",\n    \"reduced\": " + facePlaybackJson(playback.reduced) + "}";
}

FacePlayback readFacePlayback(const JsonNode& node) {
    node.expectObject();
    node.allowOnly({"keys", "keyframes"});
    FacePlayback face;
    for (const JsonNode& key : node["keys"].elements()) {
        key.expectObject();
        key.allowOnly({"name", "members"});
        PlaybackKey k{key["name"].nonEmptyString(), {}};
        for (const JsonNode& member : key["members"].elements()) k.members.push_back(member.nonEmptyString());
        face.keys.push_back(std::move(k));
    }
    const auto keyCount = static_cast<std::int64_t>(face.keys.size());
    for (const JsonNode& keyframe : node["keyframes"].elements()) {
        keyframe.expectSize(3); // [time, key, dominance]
        face.keyframes.push_back({keyframe[std::size_t{0}].number(),
                                  static_cast<int>(keyframe[std::size_t{1}].integerInRange(-1, keyCount - 1)),
                                  keyframe[std::size_t{2}].number()});
    }
    return face;
}

TrackPlayback readPlayback(const JsonNode& node) {
    node.expectObject();
    node.allowOnly({"interpolation", "dominanceRate", "full", "reduced"});
    TrackPlayback playback;
    playback.interpolation = node["interpolation"].nonEmptyString();
    playback.dominanceRate = node["dominanceRate"].nonNegativeNumber();
    playback.full = readFacePlayback(node["full"]);
    playback.reduced = readFacePlayback(node["reduced"]);
    // The curves must be valid for the runtime: a player can rely on every index and time.
    curveOf(playback.full, playback, node["full"].path());
    curveOf(playback.reduced, playback, node["reduced"].path());
    return playback;
}

TrackDisplacementError readDisplacement(const JsonNode& error) {
    TrackDisplacementError d;
    d.unit = error["displacementUnit"].nonEmptyString();
    d.rms = error["displacementRms"].nonNegativeNumber();
    d.max = error["displacementMax"].nonNegativeNumber();
    d.maxTime = optionalNumber(error, "displacementMaxTime");
    if (error.has("displacementRmsFrames")) d.rmsFrames = error["displacementRmsFrames"].nonNegativeNumbers();
    if (error.has("displacementMaxFrames")) d.maxFrames = error["displacementMaxFrames"].nonNegativeNumbers();
    return d;
}

} // namespace

std::string formatTrackJson(const SpeechTrackFile& track) {
    const TrackMetadata& m = track.metadata;
    std::string text = "{\n  \"metadata\": {\n    \"soundFile\": " + json_text::string(m.soundFile) +
                       ",\n    \"duration\": " + json_text::number(m.duration) +
                       ",\n    \"text\": " + json_text::string(m.text) +
                       ",\n    \"source\": " + json_text::string(m.source) +
                       ",\n    \"voice\": " + json_text::string(m.voice) +
                       ",\n    \"wordsPerMinute\": " + std::to_string(m.wordsPerMinute) +
                       ",\n    \"project\": " + json_text::string(m.project) +
                       ",\n    \"interpolation\": " + json_text::string(m.interpolation) +
                       ",\n    \"fps\": " + json_text::number(m.fps) +
                       ",\n    \"generator\": \"VisemeLab\"\n  },\n";
    const auto cueValue = [](const Cue& c) -> const std::string& { return c.value; };
    text += "  \"mouthCues\": " + timedArray(track.mouthCues, cueValue) + ",\n";
    text += "  \"reducedCues\": " + timedArray(track.reducedCues, cueValue) + ",\n";
    text += "  \"phonemes\": " +
            timedArray(track.phonemes, [](const TimedPhoneme& p) -> const std::string& { return p.phoneme; });
    if (track.error) {
        const TrackError& e = *track.error;
        text += ",\n  \"error\": {\"mean\": " + json_text::number(e.mean) +
                ", \"max\": " + json_text::number(e.max) + ", \"maxTime\": " + json_text::number(e.maxTime) +
                ", \"relative\": " + json_text::number(e.relative) +
                ",\n    \"frames\": " + numberArray(e.frames);
        if (const auto& d = e.displacement)
            text += ",\n    \"displacementUnit\": " + json_text::string(d->unit) +
                    ", \"displacementRms\": " + json_text::number(d->rms) +
                    ", \"displacementMax\": " + json_text::number(d->max) +
                    ", \"displacementMaxTime\": " + json_text::number(d->maxTime) +
                    ",\n    \"displacementRmsFrames\": " + numberArray(d->rmsFrames) +
                    ",\n    \"displacementMaxFrames\": " + numberArray(d->maxFrames);
        text += "}";
    }
    if (!track.errorCurve.empty()) {
        text += ",\n  \"errorCurve\": [";
        for (std::size_t i = 0; i < track.errorCurve.size(); ++i) {
            const auto& p = track.errorCurve[i];
            text += std::string(i == 0 ? "\n" : ",\n") + "    {\"m\": " + std::to_string(p.m) +
                    ", \"cost\": " + json_text::number(p.cost) + ", \"mean\": " + json_text::number(p.mean) +
                    ", \"max\": " + json_text::number(p.max) +
                    ", \"relative\": " + json_text::number(p.relative) + "}";
        }
        text += "\n  ]";
    }
    if (track.playback) text += ",\n  \"playback\": " + playbackJson(*track.playback);
    return text + "\n}\n";
}

SpeechTrackFile parseTrackJson(std::string_view text, std::string_view source) {
    const Json doc = parseJsonStrict(text, source);
    const JsonNode root(doc, std::string(source) + ":");
    root.expectObject();
    SpeechTrackFile track;
    if (root.has("metadata")) {
        const JsonNode metadata = root["metadata"];
        metadata.expectObject();
        TrackMetadata& m = track.metadata;
        m.soundFile = optionalString(metadata, "soundFile");
        m.duration = optionalNumber(metadata, "duration");
        m.text = optionalString(metadata, "text");
        m.source = optionalString(metadata, "source");
        m.voice = optionalString(metadata, "voice");
        m.wordsPerMinute = metadata.has("wordsPerMinute")
                               ? static_cast<int>(metadata["wordsPerMinute"].integerInRange(0, 100000))
                               : 0;
        m.project = optionalString(metadata, "project");
        m.interpolation = optionalString(metadata, "interpolation");
        m.fps = optionalNumber(metadata, "fps");
    }
    track.mouthCues = readCues(root["mouthCues"]);
    if (root.has("reducedCues") && root["reducedCues"].size() > 0)
        track.reducedCues = readCues(root["reducedCues"]);
    if (root.has("phonemes") && root["phonemes"].size() > 0) {
        for (auto& item : readTimedArray(root["phonemes"]))
            track.phonemes.push_back({std::move(item.value), item.start, item.end});
        checkTimedPhonemes(track.phonemes, root["phonemes"].path());
    }
    if (root.has("error")) {
        const JsonNode error = root["error"];
        error.expectObject();
        error.allowOnly({"mean", "max", "maxTime", "relative", "frames", "displacementUnit",
                         "displacementRms", "displacementMax", "displacementMaxTime", "displacementRmsFrames",
                         "displacementMaxFrames"});
        TrackError e;
        e.mean = error["mean"].nonNegativeNumber();
        e.max = error["max"].nonNegativeNumber();
        e.maxTime = optionalNumber(error, "maxTime");
        e.relative = optionalNumber(error, "relative");
        if (error.has("frames")) e.frames = error["frames"].nonNegativeNumbers();
        if (error.has("displacementUnit")) e.displacement = readDisplacement(error);
        track.error = std::move(e);
    }
    if (root.has("errorCurve")) {
        for (const JsonNode& point : root["errorCurve"].elements()) {
            point.expectObject();
            point.allowOnly({"m", "cost", "mean", "max", "relative"});
            track.errorCurve.push_back({static_cast<int>(point["m"].integerInRange(1, 1000000)),
                                        point["cost"].nonNegativeNumber(), point["mean"].nonNegativeNumber(),
                                        point["max"].nonNegativeNumber(), optionalNumber(point, "relative")});
        }
    }
    if (root.has("playback")) track.playback = readPlayback(root["playback"]);
    return track;
}

SpeechTrackFile loadTrackJson(const std::filesystem::path& path) {
    return parseTrackJson(readFileToString(path), path.string());
}

} // namespace vl
