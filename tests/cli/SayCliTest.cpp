#include "tests/cli/CliRunner.h"
#include "tests/cli/SanitizerBuild.h"

#include "core/common/AtomicFile.h"
#include "core/speech/TrackJson.h"
#include "core/speech/WavFile.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace vl;

namespace {

std::string quotedPath(const std::filesystem::path& path) {
    return "'" + path.string() + "'";
}

std::string sampleProject() {
    return quotedPath(std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample" / "sample.vlproj");
}

class SayCli : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = std::filesystem::temp_directory_path() /
              ("visemelab-say-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
    std::filesystem::path dir;
};

} // namespace

TEST_F(SayCli, WritesTrackAudioAndAnimation) {
    const auto out = dir / "track.json", wav = dir / "audio.wav", glb = dir / "anim.glb";
    const auto result =
        test::runCli("say 'Hello, world. How are you?' --project " + sampleProject() + " --out " +
                     quotedPath(out) + " --wav " + quotedPath(wav) + " --glb " + quotedPath(glb));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("utterance error (m = 10"), std::string::npos) << result.output;
    const SpeechTrackFile track = loadTrackJson(out);
    const WavAudio audio = readWav(wav);
    EXPECT_DOUBLE_EQ(track.metadata.duration, double(audio.samples.size()) / audio.sampleRate);
    EXPECT_EQ(track.metadata.soundFile, "audio.wav");
    EXPECT_EQ(track.mouthCues.back().end, track.metadata.duration);
    EXPECT_EQ(track.reducedCues.back().end, track.metadata.duration);
    EXPECT_EQ(track.phonemes.back().end, track.metadata.duration);
    ASSERT_TRUE(track.error);
    EXPECT_GT(track.error->mean, 0.0);
    EXPECT_EQ(track.error->frames.size(),
              static_cast<std::size_t>(std::ceil(track.metadata.duration * 60)) + 1);
    EXPECT_TRUE(track.errorCurve.empty());
    EXPECT_GT(std::filesystem::file_size(glb), 1000u);
    // Pauses at the comma and the full stop show the rest viseme.
    int rests = 0;
    for (const auto& cue : track.mouthCues) rests += cue.value == "sil";
    EXPECT_GE(rests, 3);
}

TEST_F(SayCli, CorpusFileGivesTheErrorCurve) {
    const auto corpus = dir / "corpus.txt";
    writeFileAtomically(corpus, "The judge measures the house.\nFour poor fire fighters came at noon!\n");
    const auto out = dir / "track.json";
    const auto result =
        test::runCli("say --text-file " + quotedPath(corpus) + " --project " + sampleProject() + " --out " +
                     quotedPath(out) + " --blend dominance --fps 30");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const SpeechTrackFile track = loadTrackJson(out);
    ASSERT_EQ(track.errorCurve.size(), 14u); // m = 1..n - 1: the sample's sil rests (the rest is free)
    EXPECT_EQ(track.errorCurve.back().mean, 0.0);
    EXPECT_GT(track.errorCurve.front().mean, track.errorCurve[9].mean);
    EXPECT_EQ(track.metadata.interpolation, "dominance");
    EXPECT_EQ(track.metadata.source, corpus.string());
}

TEST_F(SayCli, UsageAndDataErrorsGetTheirExitCodes) {
    const auto out = quotedPath(dir / "t.json");
    const std::string project = " --project " + sampleProject();
    EXPECT_EQ(test::runCli("say" + project + " --out " + out).exitCode, 2);
    EXPECT_EQ(test::runCli("say hi --text-file x.txt" + project + " --out " + out).exitCode, 2);
    EXPECT_EQ(test::runCli("say hi --fps 0" + project + " --out " + out).exitCode, 2);
    EXPECT_EQ(test::runCli("say hi --blend spline" + project + " --out " + out).exitCode, 2);
    auto result = test::runCli("say hi" + project + " --out " + sampleProject());
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("would overwrite the input --project"), std::string::npos) << result.output;
    EXPECT_EQ(test::runCli("say hi" + project + " --out " + out + " --wav " + out).exitCode, 2);

    result = test::runCli("say hi --voice xx-none" + project + " --out " + out);
    EXPECT_EQ(result.exitCode, 3) << result.output;
    EXPECT_NE(result.output.find("xx-none"), std::string::npos);
    EXPECT_EQ(test::runCli("say hi --voice de" + project + " --out " + out).exitCode, 3);
    EXPECT_EQ(test::runCli("say hi --rate 5" + project + " --out " + out).exitCode, 3);
    EXPECT_EQ(test::runCli("say ' ... ,,, '" + project + " --out " + out).exitCode, 3);
    EXPECT_EQ(test::runCli("say hi --project " + quotedPath(dir / "none.vlproj") + " --out " + out).exitCode,
              3);
    const auto binary = dir / "blob.txt";
    writeFileAtomically(binary, std::string("\x7F"
                                            "ELF\0\0\0\0",
                                            8));
    result = test::runCli("say --text-file " + quotedPath(binary) + project + " --out " + out);
    EXPECT_EQ(result.exitCode, 3) << result.output;
    EXPECT_NE(result.output.find("blob.txt: binary file"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "t.json"));
}

// espeak-ng (and the audio libraries it pulls in) is loaded on first use only: commands that never
// speak do not load it. glibc's loader lists every library it opens under LD_DEBUG=files.
TEST_F(SayCli, OnlySpeechLoadsEspeak) {
    ::setenv("LD_DEBUG", "files", 1);
    const auto exported =
        test::runCli("export " + sampleProject() + " --format glb --out " + quotedPath(dir / "a.glb"));
    const auto said =
        test::runCli("say hi --project " + sampleProject() + " --out " + quotedPath(dir / "t.json"));
    ::unsetenv("LD_DEBUG");
    ASSERT_EQ(exported.exitCode, 0) << exported.output;
    ASSERT_EQ(said.exitCode, 0) << said.output;
    EXPECT_EQ(exported.output.find("libespeak-ng"), std::string::npos);
    EXPECT_NE(said.output.find("libespeak-ng"), std::string::npos);
}

namespace {

// Runs `visemelab say --stdin ARGS` with pipes on both ends: sends `first`, reads the first answer
// line while stdin is still open (a server's way), then sends `rest`, closes stdin and reads the
// remaining answers. Returns the answer lines and the exit code.
struct ServedRun {
    std::vector<std::string> answers;
    bool firstAnsweredBeforeEof = false;
    int exitCode = -1;
};

ServedRun serve(const std::string& args, const std::string& first, const std::string& rest) {
    int in[2], out[2];
    if (::pipe(in) != 0 || ::pipe(out) != 0) return {};
    const pid_t child = ::fork();
    if (child == 0) {
        ::dup2(in[0], 0);
        ::dup2(out[1], 1);
        ::close(in[1]);
        ::close(out[0]);
        ::execl("/bin/sh", "sh", "-c",
                (std::string(VISEMELAB_CLI) + " say --stdin " + args + " 2>/dev/null").c_str(),
                static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ::close(in[0]);
    ::close(out[1]);
    ServedRun run;
    std::string buffer;
    const auto readLine = [&](int timeoutMs) {
        while (buffer.find('\n') == std::string::npos) {
            pollfd p{out[0], POLLIN, 0};
            if (::poll(&p, 1, timeoutMs) <= 0) return false;
            char chunk[4096];
            const ssize_t n = ::read(out[0], chunk, sizeof chunk);
            if (n <= 0) return false;
            buffer.append(chunk, static_cast<std::size_t>(n));
        }
        const auto end = buffer.find('\n');
        run.answers.push_back(buffer.substr(0, end));
        buffer.erase(0, end + 1);
        return true;
    };
    (void)!::write(in[1], first.data(), first.size());
    run.firstAnsweredBeforeEof = readLine(60000);
    (void)!::write(in[1], rest.data(), rest.size());
    ::close(in[1]);
    while (readLine(60000)) {
    }
    ::close(out[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

} // namespace

TEST_F(SayCli, StdinServesOneJsonLinePerSentenceAsSayWould) {
    const auto single = dir / "single.json";
    ASSERT_EQ(test::runCli("say 'Hello world' --project " + sampleProject() + " --out " + quotedPath(single))
                  .exitCode,
              0);
    const ServedRun run =
        serve("--project " + sampleProject() + " --out -", "Hello world\n", "\n... ,,,\nHow are you today\n");
    EXPECT_TRUE(run.firstAnsweredBeforeEof) << "the first answer waited for the end of the input";
    ASSERT_EQ(run.answers.size(), 4u);
    EXPECT_EQ(run.exitCode, 3) << "two lines failed";
    const auto first = nlohmann::json::parse(run.answers[0]);
    EXPECT_EQ(first["line"], 1);
    EXPECT_EQ(first["track"], nlohmann::json::parse(readFileToString(single))); // the same bytes' meaning
    for (const int failed : {1, 2}) {
        const auto answer = nlohmann::json::parse(run.answers[static_cast<std::size_t>(failed)]);
        EXPECT_EQ(answer["line"], failed + 1);
        EXPECT_NE(answer["error"].get<std::string>().find("nothing to say"), std::string::npos) << answer;
    }
    const auto last = nlohmann::json::parse(run.answers[3]);
    EXPECT_EQ(last["track"]["metadata"]["text"], "How are you today");
    // All lines good: exit 0; usage errors are refused before reading anything.
    EXPECT_EQ(serve("--project " + sampleProject() + " --out -", "Hi\n", "").exitCode, 0);
    EXPECT_EQ(test::runCli("say hi --stdin --project " + sampleProject() + " --out -").exitCode, 2);
    EXPECT_EQ(test::runCli("say --stdin --wav x.wav --project " + sampleProject() + " --out -").exitCode, 2);
}

constexpr bool kSanitized = test::kAddressSanitizer;

// `visemelab say` runs the lean visemelab-say (app/cli/SayMain.cpp): a sentence on a project in the
// speech cache is served without loading the libraries the commands link (glibc's LD_DEBUG names
// every library a process loads); a miss is handed to the commands, which fill the cache. Both answer
// the same, also with the standard output as the output (`--stdin --out -`, taken and given back).
TEST_F(SayCli, ACachedSentenceLoadsNoLibraryOfTheCommands) {
    const std::string cache = "VISEMELAB_CACHE_DIR=" + quotedPath(dir / "cache") + " ";
    const std::string say = "say 'Paper birds move in the wind.' --project " + sampleProject() + " --out ";
    const auto miss = test::runCliWith(cache + "LD_DEBUG=libs ", say + quotedPath(dir / "miss.json"));
    ASSERT_EQ(miss.exitCode, 0) << miss.output;
    EXPECT_NE(miss.output.find("libOpenMeshCore"), std::string::npos) << "the commands computed the faces";
    const auto hit = test::runCliWith(cache + "LD_DEBUG=libs ", say + quotedPath(dir / "hit.json"));
    ASSERT_EQ(hit.exitCode, 0) << hit.output;
    EXPECT_NE(hit.output.find("libespeak-ng"), std::string::npos);
    // A sanitized build links visemelab-say as any program (app/CMakeLists.txt: the instrumentation
    // keeps every global alive, so the lean link cannot drop the commands' libraries), and the
    // sanitizers' runtimes load libstdc++ themselves: the libraries are checked in the release build.
    if (!kSanitized) {
        for (const char* library : {"libOpenMeshCore", "libtbb", "libdraco", "libtinygltf", "libstdc++"})
            EXPECT_EQ(hit.output.find(library), std::string::npos)
                << library << " loaded for a cached sentence";
    }
    auto track = nlohmann::json::parse(readFileToString(dir / "hit.json"));
    auto reference = nlohmann::json::parse(readFileToString(dir / "miss.json"));
    track.erase("metadata");
    reference.erase("metadata");
    EXPECT_EQ(track, reference);

    const std::string serve = "printf 'Hello world\\n' | " + cache;
    const std::string lines = "say --stdin --project " + sampleProject() + " --out -";
    const auto served = test::runCliWith(serve, lines);
    EXPECT_EQ(served.exitCode, 0) << served.output;
    EXPECT_EQ(served.output.rfind("{\"line\":1,\"track\":", 0), 0u) << served.output;
    const auto servedMiss =
        test::runCliWith(serve.substr(0, serve.size() - cache.size()) +
                             "VISEMELAB_CACHE_DIR=" + quotedPath(dir / "other-cache") + " ",
                         lines);
    EXPECT_EQ(servedMiss.exitCode, 0) << servedMiss.output;
    EXPECT_EQ(servedMiss.output, served.output);
}

// The speech cache (core/project/SpeechCache.h): the second call reads the faces from the cache and
// writes the same bytes as a call without it; a mesh edited between calls is seen at once.
TEST_F(SayCli, TheSpeechCacheChangesNoByteAndSeesAnEditedMesh) {
    std::filesystem::copy(std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample", dir / "sample",
                          std::filesystem::copy_options::recursive);
    // `cache`: the cache folder, or "off".
    const auto sayWith = [&](const std::string& cache, const std::string& name) {
        const auto result = test::runCliWith("VISEMELAB_CACHE_DIR=" + quotedPath(cache) + " ",
                                             "say 'Paper birds move in the wind.' --project " +
                                                 quotedPath(dir / "sample" / "sample.vlproj") + " --out " +
                                                 quotedPath(dir / (name + ".json")) + " --glb " +
                                                 quotedPath(dir / (name + ".glb")) + " --quiet");
        EXPECT_EQ(result.exitCode, 0) << result.output;
    };
    const auto expectSameOutputs = [&](const std::string& name, const std::string& expected) {
        EXPECT_TRUE(readFileToString(dir / (name + ".glb")) == readFileToString(dir / (expected + ".glb")))
            << name;
        // The track names its own file: compared without the metadata.
        auto track = nlohmann::json::parse(readFileToString(dir / (name + ".json")));
        auto reference = nlohmann::json::parse(readFileToString(dir / (expected + ".json")));
        track.erase("metadata");
        reference.erase("metadata");
        EXPECT_EQ(track, reference) << name;
    };
    const std::string cache = (dir / "cache").string();
    sayWith(cache, "first");
    sayWith(cache, "second");
    sayWith("off", "uncached");
    EXPECT_FALSE(std::filesystem::is_empty(dir / "cache" / "speech"));
    expectSameOutputs("first", "uncached");
    expectSameOutputs("second", "uncached");

    // aa given oh's shape: both the cached call and a call without the cache show it.
    std::filesystem::copy_file(dir / "sample" / "oh.obj", dir / "sample" / "aa.obj",
                               std::filesystem::copy_options::overwrite_existing);
    sayWith(cache, "edited");
    sayWith("off", "edited-uncached");
    expectSameOutputs("edited", "edited-uncached");
    EXPECT_TRUE(readFileToString(dir / "edited.glb") != readFileToString(dir / "first.glb"));
}
