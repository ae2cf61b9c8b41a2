// The Say panel's saved state: text, voice and rate in the document, the project's optional
// "speech" section, and the command that edits them.
#include "DocumentTestSupport.h"
#include "core/common/Error.h"
#include "core/document/Commands.h"
#include "core/document/Document.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace vl {
namespace {

using test::faceDocument;
using test::refusal;
using test::tempDir;

TEST(SpeechSettings, DocumentProjectFileRoundTrip) {
    const Document document = edit::setSpeech(
        faceDocument(), {"Four \"poor\" fire fighters.\nSecond line: é ü", "en-gb-scotland", 212});
    const auto dir = tempDir("speech");
    const Project project = projectFromDocument(document);
    EXPECT_EQ(project.speech, document.speech);
    saveProject(dir / "p.vlproj", project);
    const Project loaded = loadProject(dir / "p.vlproj");
    EXPECT_EQ(loaded.speech, document.speech);
    EXPECT_EQ(documentFromProject(loaded).document.speech, document.speech);
    // Default settings leave the file as it was before the section existed.
    EXPECT_EQ(projectToJsonText(projectFromDocument(faceDocument())).find("\"speech\""), std::string::npos);
    EXPECT_NE(projectToJsonText(project).find("\"speech\""), std::string::npos);
}

TEST(SpeechSettings, CommandRefusesBadSettingsAndChangesNothing) {
    const Document document = faceDocument();
    EXPECT_EQ(edit::setSpeech(document, {"Hello", "en-us", 175}).speech.text, "Hello");
    EXPECT_NE(refusal([&] {
                  edit::setSpeech(document, {"Hello", "en-us", 79});
              }).find("speech/wordsPerMinute"),
              std::string::npos);
    EXPECT_NE(refusal([&] {
                  edit::setSpeech(document, {"Hello", "", 175});
              }).find("speech/voice"),
              std::string::npos);
    EXPECT_NE(refusal([&] {
                  edit::setSpeech(document, {"Hello", "en us; rm", 175});
              }).find("not a voice name"),
              std::string::npos);
    EXPECT_NE(refusal([&] {
                  edit::setSpeech(document, {std::string(kMaxSpeechTextBytes + 1, 'a'), "en", 175});
              }).find("speech/text"),
              std::string::npos);
    EXPECT_EQ(document.speech, SpeechSettings{});
}

TEST(SpeechSettings, BadSectionsNameTheFileAndPath) {
    const auto dir = tempDir("speech-bad");
    const std::string base =
        R"({"format": "visemelab-project", "version": 1, "neutral": null, "visemes": [], )";
    const auto messageFor = [&](const std::string& speech) {
        return refusal([&] { projectFromJsonText(base + R"("speech": )" + speech + "}", dir / "p.vlproj"); });
    };
    EXPECT_NE(messageFor(R"({"wordsPerMinute": 900})").find("/speech/wordsPerMinute"), std::string::npos);
    EXPECT_NE(messageFor(R"({"voice": "x y"})").find("/speech/voice"), std::string::npos);
    EXPECT_NE(messageFor(R"({"pitch": 3})").find("/speech"), std::string::npos);
    EXPECT_NE(messageFor(R"({"text": 3})").find("/speech/text"), std::string::npos);
    EXPECT_EQ(messageFor(R"({"text": "Hi"})"), "(not refused)");
    EXPECT_EQ(projectFromJsonText(base + R"("speech": {"text": "Hi"}})", dir / "p.vlproj").speech,
              (SpeechSettings{"Hi", "en-us", 175}));
}

} // namespace
} // namespace vl
