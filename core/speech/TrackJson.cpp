#include "core/speech/TrackJson.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/io/JsonRead.h"
#include "core/speech/JsonText.h"

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>

namespace vl {

namespace {

// The track's text, appended into one buffer. The separators are written as the pretty layout's
// literals (one cue a line); `compact` drops their spaces and newlines as they are appended, which
// gives compactJsonText(pretty) without a second pass (`say --stdin` answers every sentence on one
// line). Spaces inside keys and strings cannot be dropped: keys have none, strings are appended
// escaped, not as literals.
class TrackWriter {
  public:
    explicit TrackWriter(bool compact) : compact_(compact) {}

    TrackWriter& operator<<(std::string_view literal) {
        if (!compact_) {
            out_ += literal;
            return *this;
        }
        std::size_t from = 0; // the run of kept characters since the last dropped one
        for (std::size_t i = 0; i < literal.size(); ++i)
            if (literal[i] == ' ' || literal[i] == '\n') {
                out_.append(literal.data() + from, i - from);
                from = i + 1;
            }
        out_.append(literal.data() + from, literal.size() - from);
        return *this;
    }
    // Numbers repeat within a track (a cue's end is the next cue's start; phonemes, cues and
    // keyframes share their times), so each one's text is kept in a small table by its bits: a
    // repeat is a copy, not a second shortest-digits search.
    void number(double value) {
        const auto bits = std::bit_cast<std::uint64_t>(value);
        Memo& memo = memo_[(bits * 0x9E3779B97F4A7C15ull) >> (64 - kMemoBits)];
        if (memo.size > 0 && memo.bits == bits) {
            out_.append(memo.text, memo.size);
            return;
        }
        const std::size_t before = out_.size();
        json_text::appendNumber(out_, value);
        const std::size_t size = out_.size() - before;
        if (size > sizeof memo.text) return;
        memo.bits = bits;
        memo.size = static_cast<std::uint8_t>(size);
        std::memcpy(memo.text, out_.data() + before, size);
    }
    void integer(long long value) { out_ += std::to_string(value); }
    void string(std::string_view text) { json_text::appendString(out_, text); }
    // The literal before a value, then the value.
    void number(std::string_view before, double value) { *this << before, number(value); }
    void integer(std::string_view before, long long value) { *this << before, integer(value); }
    void string(std::string_view before, std::string_view text) { *this << before, string(text); }
    void reserve(std::size_t size) { out_.reserve(size); }
    std::string take() { return std::move(out_); }

  private:
    struct Memo {
        std::uint64_t bits = 0;
        std::uint8_t size = 0; // 0: empty
        char text[31];
    };
    static constexpr int kMemoBits = 8;
    std::string out_;
    bool compact_;
    std::array<Memo, std::size_t{1} << kMemoBits> memo_{};
};

// [{"start": s, "end": e, "value": v}, ...], one element per line.
template <typename Timed, typename ValueOf>
void timedArray(TrackWriter& w, const std::vector<Timed>& items, ValueOf valueOf) {
    if (items.empty()) {
        w << "[]";
        return;
    }
    w << "[";
    for (std::size_t i = 0; i < items.size(); ++i) {
        w << (i == 0 ? "\n" : ",\n") << "    {\"start\": ";
        w.number(items[i].start);
        w.number(", \"end\": ", items[i].end);
        w.string(", \"value\": ", valueOf(items[i]));
        w << "}";
    }
    w << "\n  ]";
}

void numberArray(TrackWriter& w, const std::vector<double>& values) {
    w << "[";
    for (std::size_t i = 0; i < values.size(); ++i) w.number(i > 0 ? ", " : "", values[i]);
    w << "]";
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

void facePlaybackJson(TrackWriter& w, const FacePlayback& face) {
    w << "{\"keys\": [";
    for (std::size_t k = 0; k < face.keys.size(); ++k) {
        w << (k == 0 ? "\n      " : ",\n      ") << "{\"name\": ";
        w.string(face.keys[k].name);
        w << ", \"members\": [";
        for (std::size_t j = 0; j < face.keys[k].members.size(); ++j)
            w.string(j > 0 ? ", " : "", face.keys[k].members[j]);
        w << "]}";
    }
    w << "],\n    \"keyframes\": [";
    for (std::size_t i = 0; i < face.keyframes.size(); ++i) {
        const PlaybackKeyframe& k = face.keyframes[i];
        w << (i == 0 ? "" : (i % 4 == 0 ? ",\n      " : ", ")) << "[";
        w.number(k.time);
        w.integer(", ", k.key);
        w.number(", ", k.dominance);
        w << "]";
    }
    w << "]}";
}

void playbackJson(TrackWriter& w, const TrackPlayback& playback) {
    w.string("{\"interpolation\": ", playback.interpolation);
    w.number(", \"dominanceRate\": ", playback.dominanceRate);
    w << ",\n    \"full\": ";
    facePlaybackJson(w, playback.full);
    w << ",\n    \"reduced\": ";
    facePlaybackJson(w, playback.reduced);
    w << "}";
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

namespace {

std::string writeTrackJson(const SpeechTrackFile& track, bool compact) {
    TrackWriter w(compact);
    // Room for the whole text at once (about 40 characters a cue, 20 a number).
    std::size_t numbers = track.errorCurve.size() * 4;
    if (track.error)
        numbers += track.error->frames.size() +
                   (track.error->displacement ? 2 * track.error->displacement->rmsFrames.size() : 0);
    if (track.playback)
        numbers += 2 * (track.playback->full.keyframes.size() + track.playback->reduced.keyframes.size());
    w.reserve(1024 + 72 * (track.mouthCues.size() + track.reducedCues.size() + track.phonemes.size()) +
              24 * numbers);
    const TrackMetadata& m = track.metadata;
    w.string("{\n  \"metadata\": {\n    \"soundFile\": ", m.soundFile);
    w.number(",\n    \"duration\": ", m.duration);
    w.string(",\n    \"text\": ", m.text);
    w.string(",\n    \"source\": ", m.source);
    w.string(",\n    \"voice\": ", m.voice);
    w.integer(",\n    \"wordsPerMinute\": ", m.wordsPerMinute);
    w.string(",\n    \"project\": ", m.project);
    w.string(",\n    \"interpolation\": ", m.interpolation);
    w.number(",\n    \"fps\": ", m.fps);
    w << ",\n    \"generator\": \"VisemeLab\"\n  },\n";
    const auto cueValue = [](const Cue& c) -> const std::string& { return c.value; };
    w << "  \"mouthCues\": ";
    timedArray(w, track.mouthCues, cueValue);
    w << ",\n  \"reducedCues\": ";
    timedArray(w, track.reducedCues, cueValue);
    w << ",\n  \"phonemes\": ";
    timedArray(w, track.phonemes, [](const TimedPhoneme& p) -> const std::string& { return p.phoneme; });
    if (track.error) {
        const TrackError& e = *track.error;
        w.number(",\n  \"error\": {\"mean\": ", e.mean);
        w.number(", \"max\": ", e.max);
        w.number(", \"maxTime\": ", e.maxTime);
        w.number(", \"relative\": ", e.relative);
        w << ",\n    \"frames\": ";
        numberArray(w, e.frames);
        if (const auto& d = e.displacement) {
            w.string(",\n    \"displacementUnit\": ", d->unit);
            w.number(", \"displacementRms\": ", d->rms);
            w.number(", \"displacementMax\": ", d->max);
            w.number(", \"displacementMaxTime\": ", d->maxTime);
            w << ",\n    \"displacementRmsFrames\": ";
            numberArray(w, d->rmsFrames);
            w << ",\n    \"displacementMaxFrames\": ";
            numberArray(w, d->maxFrames);
        }
        w << "}";
    }
    if (!track.errorCurve.empty()) {
        w << ",\n  \"errorCurve\": [";
        for (std::size_t i = 0; i < track.errorCurve.size(); ++i) {
            const auto& p = track.errorCurve[i];
            w << (i == 0 ? "\n" : ",\n") << "    {\"m\": ";
            w.integer(p.m);
            w.number(", \"cost\": ", p.cost);
            w.number(", \"mean\": ", p.mean);
            w.number(", \"max\": ", p.max);
            w.number(", \"relative\": ", p.relative);
            w << "}";
        }
        w << "\n  ]";
    }
    if (track.playback) {
        w << ",\n  \"playback\": ";
        playbackJson(w, *track.playback);
    }
    w << "\n}\n";
    return w.take();
}

} // namespace

std::string formatTrackJson(const SpeechTrackFile& track) {
    return writeTrackJson(track, false);
}

std::string formatTrackJsonLine(const SpeechTrackFile& track) {
    return writeTrackJson(track, true);
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
