// The speech cache (core/project/SpeechCache.h): a hit gives exactly what computing gives, any change
// of an input's bytes or of the map is a miss, a damaged entry is recomputed, and a hit protects the
// project's files from outputs as computing does.
#include "core/project/SpeechCache.h"
#include "core/common/AtomicFile.h"
#include "core/common/InputRegistry.h"
#include "core/project/Project.h"
#include "tests/project/ProjectTestUtil.h"

#include <algorithm>
#include <chrono>
#include <gtest/gtest.h>
#include <thread>

namespace vl {
namespace {

const std::filesystem::path kSample = std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample";

void expectSameModel(const ReducedModel& a, const ReducedModel& b) {
    EXPECT_EQ(a.neutral, b.neutral);
    ASSERT_EQ(a.keys.size(), b.keys.size());
    for (std::size_t k = 0; k < a.keys.size(); ++k) {
        EXPECT_EQ(a.keys[k].name, b.keys[k].name);
        EXPECT_EQ(a.keys[k].members, b.keys[k].members);
        EXPECT_EQ(a.keys[k].frequency, b.keys[k].frequency);
        EXPECT_EQ(a.keys[k].positions, b.keys[k].positions);
    }
    EXPECT_EQ(a.resting, b.resting);
    EXPECT_EQ(a.phonemeToKey, b.phonemeToKey);
    EXPECT_EQ(a.phonemeFrequencies, b.phonemeFrequencies);
}

void expectSameFaces(const ProjectSpeechFaces& got, const std::filesystem::path& project,
                     const PhonemeVisemeMap* map = nullptr) {
    const SpeechFaces expected = projectSpeechFaces(loadProject(project), map);
    expectSameModel(got.faces.full, expected.full);
    expectSameModel(got.faces.reduced, expected.reduced);
    EXPECT_EQ(got.faces.weights, expected.weights);
    EXPECT_FALSE(got.metres);
    // The error basis, read back from the entry or made with it, is the one the faces give.
    ASSERT_TRUE(got.basis);
    const SpeechErrorBasis basis(expected.full, expected.reduced, expected.weights);
    const SpeechErrorBasis::Stored a = got.basis->stored(), b = basis.stored();
    EXPECT_EQ(a.mouth, b.mouth);
    EXPECT_EQ(a.gram, b.gram);
    EXPECT_EQ(a.lengths, b.lengths);
    ASSERT_EQ(got.basis->vectorCount(), basis.vectorCount());
    ASSERT_EQ(got.basis->paddedSize(), basis.paddedSize());
    EXPECT_EQ(got.basis->mouthWeights(), basis.mouthWeights());
    for (std::size_t v = 0; v < basis.vectorCount(); ++v)
        for (int c = 0; c < 3; ++c)
            EXPECT_TRUE(std::equal(basis.coordinate(v, c), basis.coordinate(v, c) + basis.paddedSize(),
                                   got.basis->coordinate(v, c)))
                << "vector " << v << ", coordinate " << c;
}

// The bundled sample copied into a scratch folder, with a cache folder beside it.
struct SampleCopy {
    test::ScratchDir dir{"speech_cache"};
    std::filesystem::path project = dir / "sample" / "sample.vlproj";
    std::filesystem::path cache = dir / "cache";
    SampleCopy() { std::filesystem::copy(kSample, dir / "sample", std::filesystem::copy_options::recursive); }
    std::vector<std::filesystem::path> entries() const {
        std::vector<std::filesystem::path> files;
        std::error_code ec;
        for (const auto& e : std::filesystem::directory_iterator(cache / "speech", ec))
            files.push_back(e.path());
        return files;
    }
};

TEST(SpeechCache, AHitGivesExactlyWhatComputingGives) {
    const SampleCopy s;
    const ProjectSpeechFaces first = cachedProjectSpeechFaces(s.project, nullptr, s.cache);
    EXPECT_FALSE(first.fromCache);
    ASSERT_EQ(s.entries().size(), 1u);
    const ProjectSpeechFaces second = cachedProjectSpeechFaces(s.project, nullptr, s.cache);
    EXPECT_TRUE(second.fromCache);
    expectSameFaces(first, s.project);
    expectSameFaces(second, s.project);
}

TEST(SpeechCache, ChangedBytesOfAMeshOrOfTheProjectAreAMiss) {
    const SampleCopy s;
    (void)cachedProjectSpeechFaces(s.project, nullptr, s.cache);
    // One vertex of PP moved: the reduced faces change, and the cache must not hide it.
    const auto pp = s.project.parent_path() / "PP.obj";
    std::string obj = readFileToString(pp);
    const auto v = obj.find("\nv ");
    ASSERT_NE(v, std::string::npos);
    const auto x = obj.find(' ', v + 3); // the first vertex's x replaced by 0.25
    obj.replace(v + 3, x - (v + 3), "0.25");
    test::writeText(pp, obj);
    const ProjectSpeechFaces moved = cachedProjectSpeechFaces(s.project, nullptr, s.cache);
    EXPECT_FALSE(moved.fromCache);
    expectSameFaces(moved, s.project);
    EXPECT_TRUE(cachedProjectSpeechFaces(s.project, nullptr, s.cache).fromCache);

    // The project's own bytes (a space is enough: the cache does not parse to compare).
    test::writeText(s.project, readFileToString(s.project) + " ");
    EXPECT_FALSE(cachedProjectSpeechFaces(s.project, nullptr, s.cache).fromCache);
    EXPECT_TRUE(cachedProjectSpeechFaces(s.project, nullptr, s.cache).fromCache);
    EXPECT_EQ(s.entries().size(), 1u); // one entry per project and map, replaced
}

// Inputs last changed well before the entry was written are checked by their stat stamp, not their
// bytes; a later edit of the same size moves the file's change time, and is a miss.
TEST(SpeechCache, AnEditOfTheSameSizeIsAMissAfterTheStampsAreTrusted) {
    const SampleCopy s;
    std::this_thread::sleep_for(std::chrono::milliseconds(2100)); // past the racy margin (2 s)
    EXPECT_FALSE(cachedProjectSpeechFaces(s.project, nullptr, s.cache).fromCache);
    EXPECT_TRUE(cachedProjectSpeechFaces(s.project, nullptr, s.cache).fromCache);
    const auto pp = s.project.parent_path() / "PP.obj";
    std::string obj = readFileToString(pp);
    const auto v = obj.find("\nv ");
    ASSERT_NE(v, std::string::npos);
    const std::size_t digit = obj.find_first_of("123456789", v + 3); // one digit of a vertex, same size
    ASSERT_NE(digit, std::string::npos);
    obj[digit] = obj[digit] == '9' ? '1' : char(obj[digit] + 1);
    const auto size = std::filesystem::file_size(pp);
    const auto modified = std::filesystem::last_write_time(pp);
    test::writeText(pp, obj);
    std::filesystem::last_write_time(pp, modified); // the edit hides its size and time; not its ctime
    ASSERT_EQ(std::filesystem::file_size(pp), size);
    const ProjectSpeechFaces edited = cachedProjectSpeechFaces(s.project, nullptr, s.cache);
    EXPECT_FALSE(edited.fromCache);
    expectSameFaces(edited, s.project);
}

TEST(SpeechCache, AnotherMapIsAnotherEntry) {
    const SampleCopy s;
    const Project project = loadProject(s.project);
    PhonemeVisemeMap map = project.frequencies.map;
    ASSERT_FALSE(map.entries.empty());
    (void)cachedProjectSpeechFaces(s.project, nullptr, s.cache);
    const ProjectSpeechFaces mapped = cachedProjectSpeechFaces(s.project, &map, s.cache);
    EXPECT_FALSE(mapped.fromCache);
    expectSameFaces(mapped, s.project, &map);
    map.entries.front().second = map.entries.back().second; // one phoneme shown by another viseme
    const ProjectSpeechFaces changed = cachedProjectSpeechFaces(s.project, &map, s.cache);
    EXPECT_FALSE(changed.fromCache);
    expectSameFaces(changed, s.project, &map);
    EXPECT_EQ(s.entries().size(), 3u);
}

TEST(SpeechCache, ADamagedEntryIsRecomputedNotAnError) {
    const SampleCopy s;
    (void)cachedProjectSpeechFaces(s.project, nullptr, s.cache);
    const auto entry = s.entries().at(0);
    const std::string whole = readFileToString(entry);
    for (const std::string& damaged : {whole.substr(0, whole.size() / 2), std::string(), whole.substr(0, 7),
                                       std::string(whole).replace(40, 1, "X")}) {
        test::writeText(entry, damaged);
        const ProjectSpeechFaces again = cachedProjectSpeechFaces(s.project, nullptr, s.cache);
        EXPECT_FALSE(again.fromCache);
        expectSameFaces(again, s.project);
    }
    EXPECT_TRUE(cachedProjectSpeechFaces(s.project, nullptr, s.cache).fromCache);
}

TEST(SpeechCache, NoCacheFolderOrAnUnwritableOneStillGivesTheFaces) {
    const SampleCopy s;
    EXPECT_FALSE(cachedProjectSpeechFaces(s.project, nullptr, {}).fromCache);
    EXPECT_FALSE(std::filesystem::exists(s.cache));
    test::writeText(s.cache, "a file where the cache folder would be");
    const ProjectSpeechFaces faces = cachedProjectSpeechFaces(s.project, nullptr, s.cache);
    EXPECT_FALSE(faces.fromCache);
    expectSameFaces(faces, s.project);
}

TEST(SpeechCache, AHitProtectsTheProjectsFilesFromOutputsAsComputingDoes) {
    const SampleCopy s;
    (void)cachedProjectSpeechFaces(s.project, nullptr, s.cache);
    const InputRecording recording;
    ASSERT_TRUE(cachedProjectSpeechFaces(s.project, nullptr, s.cache).fromCache);
    EXPECT_THROW(refuseOverwritingInput(s.project.parent_path() / "PP.obj", "--out"), InputError);
    EXPECT_THROW(refuseOverwritingInput(s.project, "--out"), InputError);
}

TEST(SpeechCache, ABadProjectIsRefusedAsWithoutTheCache) {
    const SampleCopy s;
    std::filesystem::remove(s.project.parent_path() / "PP.obj");
    EXPECT_INPUT_ERROR(cachedProjectSpeechFaces(s.project, nullptr, s.cache), "PP.obj");
    EXPECT_TRUE(s.entries().empty());
}

} // namespace
} // namespace vl
