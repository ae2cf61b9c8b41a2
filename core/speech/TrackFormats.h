#pragma once
// A speech track in the layouts other lip-sync players read:
// - "oculus": VisemeLab's own track JSON (TrackJson.h): Rhubarb's layout whose cue values are the
//   face's viseme names (Oculus names for avatars), plus reduced cues, phonemes, error, playback.
// - "rhubarb": exactly Rhubarb Lip Sync's JSON ({"metadata": {"soundFile", "duration"},
//   "mouthCues": [{"start", "end", "value"}]}) with its mouth shapes A-H and X. Oculus visemes go
//   through rhubarbShapeOfOculus (documented in docs/speech.md), rest is X, and cues that already
//   hold Rhubarb shapes (a face reduced or mapped with map_rhubarb.csv) stay as they are; runs of
//   one shape are joined, so every cue a Rhubarb consumer reads is one of its nine shapes.
// - "talkinghead": TalkingHead's lip-sync object {"visemes", "vtimes", "vdurations"} with times in
//   milliseconds and its viseme names (Oculus names without "viseme_", I/O/U for ih/oh/ou).
#include "core/common/EnumNames.h"
#include "core/speech/TrackJson.h"

#include <optional>
#include <string>
#include <string_view>

namespace vl {

enum class TrackFormat { Oculus, Rhubarb, TalkingHead };
template <> struct EnumNames<TrackFormat> {
    static constexpr const char* what = "track format";
    static constexpr EnumName<TrackFormat> names[] = {{TrackFormat::Oculus, "oculus"},
                                                      {TrackFormat::Rhubarb, "rhubarb"},
                                                      {TrackFormat::TalkingHead, "talkinghead"}};
};

// Rhubarb's shape for a canonical Oculus viseme name ("sil" -> 'X', "PP" -> 'A', ...).
char rhubarbShapeOfOculus(std::string_view oculus);
// TalkingHead's name for a canonical Oculus viseme name ("ih" -> "I", "PP" -> "PP").
std::string talkingHeadVisemeOfOculus(std::string_view oculus);

// The track's full-face cues (mouthCues) in the format. Throws InputError at `where` naming the
// first cue whose value has no shape in the format (a viseme that is neither Oculus nor Rhubarb).
std::string formatTrack(const SpeechTrackFile& track, TrackFormat format, std::string_view where);
// formatTrack's text on one line (compactJsonText), for JSON Lines.
std::string formatTrackLine(const SpeechTrackFile& track, TrackFormat format, std::string_view where);

} // namespace vl
