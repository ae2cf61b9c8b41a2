#pragma once
// A web page that plays speech on an avatar or face: the glb, the track (with its playback section)
// and the audio are embedded, so the page is one file; three.js comes from `threeBase` (an import
// map), and the player is app/web/visemelab-player.js, passed in by the caller (the CLI embeds it).
// Opening the page shows the face at rest with a Play button; `page.html#t=0.42` freezes the face at
// 0.42 s (for screenshots), `#t=rest` shows it with every viseme weight at 0. When the face is
// drawn, the page sets its title to "ready".
#include <string>
#include <string_view>

namespace vl {

struct SpeechPageInputs {
    std::string_view title;        // what was said, shown in the page's title
    std::string_view glb;          // the avatar or face, binary glTF
    std::string_view trackJson;    // the say track (TrackJson.h, with "playback")
    std::string_view wav;          // the audio, "" for none
    std::string_view playerModule; // the source of visemelab-player.js
    std::string threeBase;         // URL of three's package folder (holding build/ and examples/)
};

std::string speechPageHtml(const SpeechPageInputs& inputs);

// RFC 4648 base64 with padding.
std::string base64Encode(std::string_view bytes);

} // namespace vl
