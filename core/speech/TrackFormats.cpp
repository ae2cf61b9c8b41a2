#include "core/speech/TrackFormats.h"

#include "core/common/Error.h"
#include "core/common/JsonParse.h"
#include "core/gltf/TargetNames.h"
#include "core/io/JsonWrite.h"
#include "core/speech/JsonText.h"
#include "core/speech/VisemeTrack.h"

#include <array>
#include <utility>

namespace vl {

namespace {

// Oculus viseme -> Rhubarb mouth shape, by what the mouth does (Rhubarb's shape guide): A closed
// lips (P B M), B slightly open with teeth together (most consonants, EE), C open (EH AE), D wide
// open (AA), E slightly rounded (AO ER), F puckered (UW OW W), G upper teeth on the lower lip
// (F V), H tongue raised (L), X rest. The same pairs as assets/phonemes/map_oculus.csv and
// map_rhubarb.csv give for each viseme's most frequent phoneme.
constexpr std::array<std::pair<std::string_view, char>, 15> kOculusToRhubarb = {{
    {"sil", 'X'},
    {"PP", 'A'},
    {"FF", 'G'},
    {"TH", 'B'},
    {"DD", 'B'},
    {"kk", 'B'},
    {"CH", 'B'},
    {"SS", 'B'},
    {"nn", 'B'},
    {"RR", 'B'},
    {"aa", 'D'},
    {"E", 'C'},
    {"ih", 'B'},
    {"oh", 'E'},
    {"ou", 'F'},
}};

bool isRhubarbShape(std::string_view value) {
    return value.size() == 1 && ((value[0] >= 'A' && value[0] <= 'H') || value[0] == 'X');
}

// The cue's viseme as a canonical Oculus name; rest is "sil".
std::optional<std::string> oculusOfCue(std::string_view value) {
    if (value == kRestCue) return std::string("sil");
    return oculusVisemeOf(value);
}

[[noreturn]] void unknownValue(std::string_view where, std::size_t cue, std::string_view value,
                               TrackFormat format) {
    throwInputError(where, "mouth cue " + std::to_string(cue) + ": '" + std::string(value) + "' is not an " +
                               "Oculus viseme" +
                               (format == TrackFormat::Rhubarb ? " or a Rhubarb shape" : "") +
                               ", so it has no " + toString(format) +
                               " name (say with --map assets/phonemes/map_rhubarb.csv, or a face with Oculus "
                               "viseme names)");
}

std::string rhubarbJson(const SpeechTrackFile& track, std::string_view where) {
    std::vector<Cue> cues;
    for (std::size_t i = 0; i < track.mouthCues.size(); ++i) {
        const Cue& cue = track.mouthCues[i];
        std::string shape;
        if (isRhubarbShape(cue.value))
            shape = cue.value;
        else if (const auto oculus = oculusOfCue(cue.value))
            shape = std::string(1, rhubarbShapeOfOculus(*oculus));
        else
            unknownValue(where, i, cue.value, TrackFormat::Rhubarb);
        if (!cues.empty() && cues.back().value == shape)
            cues.back().end = cue.end;
        else
            cues.push_back({cue.start, cue.end, std::move(shape)});
    }
    std::string text =
        "{\n  \"metadata\": {\n    \"soundFile\": " + json_text::string(track.metadata.soundFile) +
        ",\n    \"duration\": " + json_text::number(track.metadata.duration) + "\n  },\n  \"mouthCues\": [";
    for (std::size_t i = 0; i < cues.size(); ++i)
        text += std::string(i == 0 ? "\n" : ",\n") + "    {\"start\": " + json_text::number(cues[i].start) +
                ", \"end\": " + json_text::number(cues[i].end) +
                ", \"value\": " + json_text::string(cues[i].value) + "}";
    return text + "\n  ]\n}\n";
}

std::string talkingHeadJson(const SpeechTrackFile& track, std::string_view where) {
    std::string visemes, times, durations;
    for (std::size_t i = 0; i < track.mouthCues.size(); ++i) {
        const Cue& cue = track.mouthCues[i];
        const auto oculus = oculusOfCue(cue.value);
        if (!oculus) unknownValue(where, i, cue.value, TrackFormat::TalkingHead);
        const char* separator = i == 0 ? "" : ", ";
        visemes += separator + json_text::string(talkingHeadVisemeOfOculus(*oculus));
        times += separator + json_text::number(1000 * cue.start);
        durations += separator + json_text::number(1000 * (cue.end - cue.start));
    }
    return "{\n  \"metadata\": {\"soundFile\": " + json_text::string(track.metadata.soundFile) +
           ", \"durationMs\": " + json_text::number(1000 * track.metadata.duration) +
           ", \"generator\": \"VisemeLab\"},\n" + "  \"visemes\": [" + visemes + "],\n  \"vtimes\": [" +
           times + "],\n  \"vdurations\": [" + durations + "]\n}\n";
}

} // namespace

char rhubarbShapeOfOculus(std::string_view oculus) {
    for (const auto& [name, shape] : kOculusToRhubarb)
        if (name == oculus) return shape;
    return 'X';
}

std::string talkingHeadVisemeOfOculus(std::string_view oculus) {
    if (oculus == "ih") return "I";
    if (oculus == "oh") return "O";
    if (oculus == "ou") return "U";
    return std::string(oculus);
}

std::string formatTrack(const SpeechTrackFile& track, TrackFormat format, std::string_view where) {
    switch (format) {
    case TrackFormat::Rhubarb:
        return rhubarbJson(track, where);
    case TrackFormat::TalkingHead:
        return talkingHeadJson(track, where);
    case TrackFormat::Oculus:
        break;
    }
    return formatTrackJson(track);
}

std::string formatTrackLine(const SpeechTrackFile& track, TrackFormat format, std::string_view where) {
    return format == TrackFormat::Oculus ? formatTrackJsonLine(track)
                                         : compactJsonText(formatTrack(track, format, where));
}

} // namespace vl
