// The optional "speech" section: {"text": "...", "voice": "en-us", "wordsPerMinute": 175}, every key
// optional (defaults: empty text, en-us, 175), checked by checkSpeechSettings with the key's path.
#include "core/project/ProjectJson.h"

namespace vl {

Json speechToJson(const SpeechSettings& speech) {
    return Json{{"text", speech.text}, {"voice", speech.voice}, {"wordsPerMinute", speech.wordsPerMinute}};
}

SpeechSettings speechFromJson(const JsonNode& node) {
    node.expectObject();
    node.allowOnly({"text", "voice", "wordsPerMinute"});
    SpeechSettings speech;
    if (node.has("text")) speech.text = node["text"].string();
    if (node.has("voice")) speech.voice = node["voice"].string();
    if (node.has("wordsPerMinute"))
        speech.wordsPerMinute =
            static_cast<int>(node["wordsPerMinute"].integerInRange(kMinWordsPerMinute, kMaxWordsPerMinute));
    checkSpeechSettings(speech, node.path()); // the caller puts the file's name in front
    return speech;
}

} // namespace vl
