// espeak-ng keeps state between synthesis calls in one process; FreshSpeech speaks every sentence
// as a fresh `visemelab say` does, whatever was spoken before and alongside.
#include "BatchTestSupport.h"

#include "core/common/Error.h"
#include "core/phonetics/EspeakFreshSynthesis.h"
#include "core/speech/WavFile.h"

#include <thread>

namespace vl {
namespace {

constexpr const char* kFirst = "Hello there, how are you today?";
constexpr const char* kSecond = "The quick brown fox jumps over the lazy dog.";
constexpr const char* kThird = "She sells sea shells by the sea shore.";

class FreshSpeechTest : public test::BatchFolderTest {
  protected:
    // The samples `visemelab say TEXT --wav` writes: a process that speaks only this sentence.
    std::vector<std::int16_t> fresh(const std::string& text) {
        const std::string command = std::string(VISEMELAB_CLI) + " say '" + text + "' --project " +
                                    VISEMELAB_ASSETS_DIR + "/sample/sample.vlproj --out " +
                                    (dir / "t.json").string() + " --wav " + (dir / "t.wav").string() +
                                    " --quiet >/dev/null 2>&1";
        if (std::system(command.c_str()) != 0) return {};
        return readWav(dir / "t.wav").samples;
    }
};

// One test: a FreshSpeech must be made before the process speaks in-process, which the test does
// to show the problem.
TEST_F(FreshSpeechTest, EverySentenceIsAFreshProcesssBytes) {
    const auto second = fresh(kSecond), third = fresh(kThird);
    if (second.empty()) GTEST_SKIP() << "espeak-ng cannot speak here";
    const FreshSpeech speech;
    // The problem: in one process, a sentence spoken after another is not the fresh bytes.
    auto synthesizer = makeEspeakSynthesizer();
    synthesizer->synthesize(kFirst);
    EXPECT_NE(synthesizer->synthesize(kSecond).samples, second) << "espeak-ng no longer keeps state: "
                                                                   "FreshSpeech may be dropped";
    EXPECT_THROW(FreshSpeech(), std::logic_error); // made after in-process speech: refused
    // FreshSpeech: the same bytes in any order, from any thread.
    speech.speak({}, kFirst);
    const FreshSpeech::Spoken spoken = speech.speak({}, kSecond);
    EXPECT_EQ(spoken.utterance.samples, second);
    EXPECT_EQ(spoken.utterance.sampleRate, 22050);
    EXPECT_NO_THROW(checkTimedPhonemes(spoken.utterance.phonemes, "fresh"));
    EXPECT_EQ(speech.speak({}, kThird).utterance.samples, third);
    std::vector<std::int16_t> a, b;
    std::thread t1([&] { a = speech.speak({}, kSecond).utterance.samples; });
    std::thread t2([&] { b = speech.speak({}, kThird).utterance.samples; });
    t1.join();
    t2.join();
    EXPECT_EQ(a, second);
    EXPECT_EQ(b, third);
    EXPECT_EQ(speech.speak({}, kSecond).utterance.phonemes, spoken.utterance.phonemes);

    // A bad voice or rate is the synthesiser's InputError, with its message.
    try {
        speech.speak({"xx-nonsense", 175}, "Hello.");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("voice 'xx-nonsense'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(speech.speak({"en-us", 5}, "Hello."), InputError);
}

} // namespace
} // namespace vl
