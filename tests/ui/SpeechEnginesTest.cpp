// The session speaks and counts phonemes with the engines it is given (core/phonetics/
// SpeechEngines.h), not with ones it makes: a scripted synthesizer's phonemes become the Say clip.
#include "ui/session/EditorSession.h"

#include <gtest/gtest.h>

namespace vl::ui {
namespace {

// Says "PP aa" for any text: 0.1 s of silence, then PP and aa, with a tone as audio.
class ScriptedSynthesizer : public SpeechSynthesizer {
  public:
    explicit ScriptedSynthesizer(int* calls) : calls_(calls) {}
    void speak(std::string_view, Utterance& utterance, const AudioSink&) override {
        ++*calls_;
        utterance.sampleRate = 16000;
        utterance.phonemes = {{"sil", 0.0, 0.1}, {"P", 0.1, 0.25}, {"AA", 0.25, 0.5}, {"sil", 0.5, 0.6}};
        utterance.samples.assign(9600, 0);
        for (std::size_t i = 0; i < utterance.samples.size(); ++i)
            utterance.samples[i] = static_cast<std::int16_t>((i % 40) * 100);
    }
    int sampleRate() const override { return 16000; }
    const std::map<std::string, std::size_t>& skippedSymbols() const override { return skipped_; }

  private:
    int* calls_;
    std::map<std::string, std::size_t> skipped_;
};

TEST(SpeechEngines, SayUsesTheInjectedSynthesizer) {
    int calls = 0;
    SpeechEngines engines;
    engines.synthesizer = [&calls](const SpeechVoice& voice) {
        EXPECT_EQ(voice.voice, "en-us");
        return std::make_unique<ScriptedSynthesizer>(&calls);
    };
    EditorSession session(engines);
    session.files().loadSample();
    SpeechSettings speech = session.document().speech;
    speech.text = "anything at all";
    session.speech().setSettings(speech);
    session.speech().say();
    session.finishBackgroundWork();
    ASSERT_EQ(calls, 1);
    ASSERT_TRUE(session.speech().clip());
    const auto& phonemes = session.speech().clip()->phonemes;
    ASSERT_EQ(phonemes.size(), 4u);
    EXPECT_EQ(phonemes[1].phoneme, "P");
    EXPECT_EQ(phonemes[2].phoneme, "AA");
    EXPECT_DOUBLE_EQ(phonemes[2].end, 0.5);
}

} // namespace
} // namespace vl::ui
