// Folder outputs written as a set: all or nothing visible, stale outputs of the last run removed,
// unrelated files never touched, temporaries cleaned on failure and swept after a kill.
#include "TempFolder.h"

#include "core/common/AtomicFile.h"
#include "core/common/InputRegistry.h"
#include "core/common/OutputPolicy.h"
#include "core/common/OutputSet.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace vl {
namespace {

using test::listFolder;
using test::readText;
using test::TempFolder;
using test::writeText;

void writeSet(const std::filesystem::path& folder, const std::string& setName,
              const std::vector<std::pair<std::string, std::string>>& files) {
    OutputSet set(folder, setName);
    for (const auto& [name, text] : files) set.add(name, text);
    set.commit();
}

TEST(OutputSet, NothingChangesUntilCommit) {
    TempFolder dir;
    writeText(dir / "a.obj", "old a");
    OutputSet set(dir.path, "export-obj");
    set.add("a.obj", "new a");
    set.add("b.obj", {"new", "", " b"}); // parts written one after another
    EXPECT_EQ(readText(dir / "a.obj"), "old a");
    EXPECT_FALSE(std::filesystem::exists(dir / "b.obj"));
    const auto written = set.commit();
    EXPECT_EQ(written, (std::vector<std::filesystem::path>{dir / "a.obj", dir / "b.obj"}));
    EXPECT_EQ(readText(dir / "a.obj"), "new a");
    EXPECT_EQ(readText(dir / "b.obj"), "new b");
    EXPECT_EQ(listFolder(dir.path),
              (std::vector<std::string>{".visemelab-export-obj.manifest", "a.obj", "b.obj"}));
}

TEST(OutputSet, ManyPartsOfAnySizeAreWrittenInOrder) {
    // More parts than one writev takes, empty ones and ones larger than a pipe or a page.
    TempFolder dir;
    std::vector<std::string> texts;
    for (int i = 0; i < 40; ++i)
        texts.push_back(i % 7 == 3 ? std::string()
                                   : std::string(static_cast<std::size_t>(1 + i * i * 97), 'a' + i % 26));
    texts.push_back(std::string(3u << 20, 'z'));
    std::string expected;
    for (const auto& t : texts) expected += t;
    OutputSet set(dir.path, "parts");
    const std::initializer_list<std::string_view> parts{
        texts[0],  texts[1],  texts[2],  texts[3],  texts[4],  texts[5],  texts[6],  texts[7],  texts[8],
        texts[9],  texts[10], texts[11], texts[12], texts[13], texts[14], texts[15], texts[16], texts[17],
        texts[18], texts[19], texts[20], texts[21], texts[22], texts[23], texts[24], texts[25], texts[26],
        texts[27], texts[28], texts[29], texts[30], texts[31], texts[32], texts[33], texts[34], texts[35],
        texts[36], texts[37], texts[38], texts[39], texts[40]};
    set.add("many.txt", parts);
    set.commit();
    EXPECT_EQ(readText(dir / "many.txt"), expected);
}

TEST(OutputSet, AnAbandonedSetLeavesTheOldOutputsAndNoTemporaries) {
    TempFolder dir;
    writeSet(dir.path, "reduce", {{"a.obj", "run 1"}, {"b.obj", "run 1"}});
    try {
        OutputSet set(dir.path, "reduce");
        set.add("a.obj", "run 2");
        throw std::runtime_error("the run fails before its second file");
    } catch (const std::runtime_error&) {
    }
    EXPECT_EQ(readText(dir / "a.obj"), "run 1");
    EXPECT_EQ(listFolder(dir.path),
              (std::vector<std::string>{".visemelab-reduce.manifest", "a.obj", "b.obj"}));
}

TEST(OutputSet, StaleOutputsOfTheLastRunGoAndUnrelatedFilesStay) {
    TempFolder dir;
    writeText(dir / "notes.txt", "the user's");
    writeSet(dir.path, "reduce",
             {{"reduced_0_a.obj", "1"}, {"reduced_1_b.obj", "1"}, {"reduced_2_c.obj", "1"}});
    writeSet(dir.path, "export-obj", {{"neutral.obj", "n"}, {"shared.obj", "export"}});
    // The second reduction has fewer merged meshes: the third of the first run must not linger.
    writeSet(dir.path, "reduce",
             {{"reduced_0_a.obj", "2"}, {"reduced_1_bc.obj", "2"}, {"shared.obj", "reduce"}});
    EXPECT_EQ(listFolder(dir.path),
              (std::vector<std::string>{".visemelab-export-obj.manifest", ".visemelab-reduce.manifest",
                                        "neutral.obj", "notes.txt", "reduced_0_a.obj", "reduced_1_bc.obj",
                                        "shared.obj"}));
    // A file another set also claims stays when one of them stops writing it.
    writeSet(dir.path, "reduce", {{"reduced_0_a.obj", "3"}});
    EXPECT_TRUE(std::filesystem::exists(dir / "shared.obj"));
    EXPECT_EQ(readText(dir / "notes.txt"), "the user's");
}

TEST(OutputSet, AHostileManifestRemovesNothingOutsideTheSet) {
    TempFolder dir;
    std::filesystem::create_directories(dir / "out");
    writeText(dir / "precious.txt", "keep");
    writeText(dir / "out" / ".hidden", "keep");
    writeText(OutputSet::manifestPath(dir / "out", "reduce"),
              "../precious.txt\n" + (dir / "precious.txt").string() + "\n.hidden\n.\n..\n");
    writeSet(dir / "out", "reduce", {{"a.obj", "x"}});
    EXPECT_EQ(readText(dir / "precious.txt"), "keep");
    EXPECT_EQ(readText(dir / "out" / ".hidden"), "keep");
}

TEST(OutputSet, APlantedOrStaleManifestDeletesOnlyFilesStillHoldingWhatItRecorded) {
    TempFolder dir;
    writeText(dir / "thesis.txt", "years of work");
    // A manifest of the old layout (bare names) and one with a made-up hash: nothing they list goes.
    writeText(OutputSet::manifestPath(dir.path, "reduce"), "thesis.txt\n");
    writeSet(dir.path, "reduce", {{"a.obj", "1"}});
    EXPECT_EQ(readText(dir / "thesis.txt"), "years of work");
    writeText(OutputSet::manifestPath(dir.path, "reduce"), "13 0123456789abcdef thesis.txt\n");
    writeSet(dir.path, "reduce", {{"a.obj", "1"}});
    EXPECT_EQ(readText(dir / "thesis.txt"), "years of work");
    // A stale output the user edited since the run wrote it is kept; an untouched one goes.
    writeSet(dir.path, "reduce", {{"a.obj", "1"}, {"b.obj", "2"}, {"c.obj", "3"}});
    writeText(dir / "b.obj", "edited by hand");
    writeSet(dir.path, "reduce", {{"a.obj", "1"}});
    EXPECT_EQ(listFolder(dir.path),
              (std::vector<std::string>{".visemelab-reduce.manifest", "a.obj", "b.obj", "thesis.txt"}));
    EXPECT_EQ(readText(dir / "b.obj"), "edited by hand");
}

TEST(OutputSet, TheFolderIsReplacedWholeAndTheUsersFilesKeepTheirInode) {
    TempFolder dir;
    const auto out = dir / "out";
    writeSet(out, "reduce", {{"a.obj", "1"}, {"b.obj", "1"}});
    writeText(out / "thesis.txt", "mine");
    struct stat before {
    }, thesis{}, after{}, thesisAfter{};
    ASSERT_EQ(::stat(out.c_str(), &before), 0);
    ASSERT_EQ(::stat((out / "thesis.txt").c_str(), &thesis), 0);
    writeSet(out, "reduce", {{"a.obj", "2"}});
    ASSERT_EQ(::stat(out.c_str(), &after), 0);
    ASSERT_EQ(::stat((out / "thesis.txt").c_str(), &thesisAfter), 0);
    EXPECT_NE(before.st_ino, after.st_ino); // a new folder was swapped in
    EXPECT_EQ(thesis.st_ino, thesisAfter.st_ino);
    EXPECT_EQ(listFolder(out),
              (std::vector<std::string>{".visemelab-reduce.manifest", "a.obj", "thesis.txt"}));
    EXPECT_EQ(listFolder(dir.path), (std::vector<std::string>{"out"})); // no staging folder left
}

TEST(OutputSet, AFolderWithASubfolderOrASymlinkedMemberIsRefused) {
    TempFolder dir;
    std::filesystem::create_directories(dir / "out" / "sub");
    EXPECT_THROW(OutputSet(dir / "out", "s"), OutputRefusedError);
    std::filesystem::create_directories(dir / "out2");
    writeText(dir / "real.obj", "old");
    std::filesystem::create_symlink(dir / "real.obj", dir / "out2" / "linked.obj");
    OutputSet set(dir / "out2", "s");
    EXPECT_THROW(set.add("linked.obj", "new"), OutputRefusedError);
    EXPECT_EQ(readText(dir / "real.obj"), "old");
}

TEST(OutputSet, DebrisOfKilledRunsIsSweptAndOnlyDebris) {
    TempFolder dir;
    const auto out = dir / "out";
    writeSet(out, "reduce", {{"a.obj", "1"}});
    const std::string dead = std::to_string(test::deadProcessId());
    // Never swapped in: staged files and links, removed whole.
    const auto staging = dir / (".out.vlstage-" + dead + "-1");
    std::filesystem::create_directories(staging);
    writeText(staging / ".visemelab-staging", "staging\n");
    writeText(staging / "a.obj", "2");
    // Swapped in, the replaced folder left: its outputs go, a file someone made meanwhile moves in.
    const auto replaced = dir / (".out.vlstage-" + dead + "-2");
    std::filesystem::create_directories(replaced);
    writeText(replaced / ".visemelab-staging", "replaced\n");
    writeText(replaced / ".visemelab-reduce.manifest", "0 0123456789abcdef old.obj\n");
    writeText(replaced / "old.obj", "0");
    writeText(replaced / "late.txt", "made during the swap");
    // Killed before its marker was written; and a folder that is not provably ours.
    std::filesystem::create_directories(dir / (".out.vlstage-" + dead + "-3"));
    const auto foreign = dir / (".out.vlstage-" + dead + "-4");
    std::filesystem::create_directories(foreign);
    writeText(foreign / "data", "not ours");
    writeText(out / ".visemelab-staging", "replaced\n");
    writeSet(out, "reduce", {{"a.obj", "3"}});
    EXPECT_EQ(listFolder(dir.path), (std::vector<std::string>{".out.vlstage-" + dead + "-4", "out"}));
    EXPECT_EQ(readText(foreign / "data"), "not ours");
    EXPECT_EQ(listFolder(out), (std::vector<std::string>{".visemelab-reduce.manifest", "a.obj", "late.txt"}));
    EXPECT_EQ(readText(out / "a.obj"), "3");
}

TEST(OutputSet, AFolderHoldingAnInputOrAReferencedFileIsRefused) {
    TempFolder dir;
    std::filesystem::create_directories(dir / "project" / "meshes");
    writeText(dir / "project" / "meshes" / "aa.obj", "referenced");
    const InputRecording recording;
    noteReferencedFile(dir / "project" / "meshes" / "aa.obj");
    for (const auto& folder : {dir / "project", dir / "project" / "meshes"})
        EXPECT_THROW(OutputSet(folder, "s"), OutputRefusedError) << folder;
    EXPECT_NO_THROW(OutputSet(dir / "project" / "out", "s"));
    EXPECT_EQ(readText(dir / "project" / "meshes" / "aa.obj"), "referenced");
}

TEST(OutputSet, ASymlinkedFolderIsRefusedUnlessFollowedAndADanglingOneCreatesNothing) {
    TempFolder dir;
    std::filesystem::create_directories(dir / "real");
    std::filesystem::create_symlink(dir / "real", dir / "link");
    std::filesystem::create_symlink(dir / "missing" / "deeper", dir / "dangling");
    const OutputPolicy saved = outputPolicy();
    setOutputPolicy({.followSymlinks = false, .waitForBusyFolder = true});
    EXPECT_THROW(OutputSet(dir / "link", "s"), OutputRefusedError);
    EXPECT_THROW(OutputSet(dir / "dangling", "s"), OutputRefusedError);
    setOutputPolicy({.followSymlinks = true, .waitForBusyFolder = true});
    writeSet(dir / "link", "s", {{"a.obj", "x"}});
    EXPECT_EQ(readText(dir / "real" / "a.obj"), "x");
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "link"));
    EXPECT_THROW(OutputSet(dir / "dangling", "s"), OutputRefusedError);
    EXPECT_THROW(OutputSet(dir / "dangling" / "below", "s"), InputError);
    EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
    setOutputPolicy(saved);
}

TEST(OutputSet, ABusyFolderIsWaitedForOrRefusedNamingItsHolder) {
    TempFolder dir;
    std::filesystem::create_directories(dir / "out");
    int ready[2], done[2];
    ASSERT_EQ(::pipe(ready), 0);
    ASSERT_EQ(::pipe(done), 0);
    const pid_t holder = ::fork();
    if (holder == 0) { // holds the lock until the parent closes `done`
        const int fd = ::open((dir / "out").c_str(), O_RDONLY | O_DIRECTORY);
        ::flock(fd, LOCK_EX);
        (void)!::write(ready[1], "x", 1);
        char c;
        ::close(done[1]);
        (void)!::read(done[0], &c, 1);
        ::_exit(0);
    }
    char c;
    ASSERT_EQ(::read(ready[0], &c, 1), 1);
    const OutputPolicy saved = outputPolicy();
    setOutputPolicy({.followSymlinks = true, .waitForBusyFolder = false});
    try {
        OutputSet set(dir / "out", "s");
        ADD_FAILURE() << "a busy folder was not refused";
    } catch (const OutputRefusedError& e) {
        EXPECT_NE(std::string(e.what()).find("pid " + std::to_string(holder)), std::string::npos) << e.what();
    }
    setOutputPolicy({.followSymlinks = true, .waitForBusyFolder = true});
    ::close(done[1]); // the holder exits; the waiting writer goes on
    writeSet(dir / "out", "s", {{"a.obj", "x"}});
    EXPECT_EQ(readText(dir / "out" / "a.obj"), "x");
    ::waitpid(holder, nullptr, 0);
    setOutputPolicy(saved);
}

TEST(OutputSet, TemporariesOfAKilledRunAreSwept) {
    TempFolder dir;
    const std::string dead = std::to_string(test::deadProcessId());
    writeText(dir / (".a.obj.vltmp-" + dead + "-77"), std::string(10000, 'v'));
    writeSet(dir.path, "reduce", {{"a.obj", "x"}});
    EXPECT_EQ(listFolder(dir.path), (std::vector<std::string>{".visemelab-reduce.manifest", "a.obj"}));
}

TEST(OutputSet, NamesAndInputsAreChecked) {
    TempFolder dir;
    OutputSet set(dir.path, "s");
    for (const char* bad : {"../x.obj", "sub/x.obj", ".hidden", "", "..", ".visemelab-s.manifest"})
        EXPECT_THROW(set.add(bad, "x"), InputError) << bad;
    set.add("x.obj", "1");
    EXPECT_THROW(set.add("x.obj", "2"), InputError);
    EXPECT_THROW(OutputSet(dir.path, "../s"), InputError);

    writeText(dir / "input.obj", "input");
    const InputRecording recording;
    (void)readFileToString(dir / "input.obj");
    EXPECT_THROW(set.add("input.obj", "clobber"), OutputOverwritesInputError);
    noteInputFolder(dir / "in");
    std::filesystem::create_directories(dir / "in");
    noteInputFolder(dir / "in");
    EXPECT_THROW(OutputSet(dir / "in", "s"), OutputOverwritesInputError);
    EXPECT_EQ(readText(dir / "input.obj"), "input");
}

TEST(OutputSet, UnchangedOutputsStayAndChangedOnesAreReplaced) {
    TempFolder dir;
    writeSet(dir.path, "reduce",
             {{"same.obj", "v 1 2 3\n"}, {"edited.obj", "v 1 2 3\n"}, {"grown.obj", "v"}});
    auto inode = [&](const std::string& name) {
        struct stat info {};
        EXPECT_EQ(::stat((dir / name).c_str(), &info), 0) << name;
        return info.st_ino;
    };
    const auto same = inode("same.obj"), edited = inode("edited.obj"), grown = inode("grown.obj");
    const auto manifest = inode(".visemelab-reduce.manifest");
    const auto stamp = std::filesystem::last_write_time(dir / "same.obj");
    OutputSet set(dir.path, "reduce");
    set.add("same.obj", {"v 1 ", "", "2 3\n"}); // the same bytes in other parts
    set.add("edited.obj", "v 1 2 4\n");         // the same size, the last digit differs
    set.add("grown.obj", "v 1");
    EXPECT_EQ(set.commit(),
              (std::vector<std::filesystem::path>{dir / "same.obj", dir / "edited.obj", dir / "grown.obj"}));
    EXPECT_EQ(inode("same.obj"), same);
    EXPECT_EQ(std::filesystem::last_write_time(dir / "same.obj"), stamp);
    EXPECT_NE(inode(".visemelab-reduce.manifest"), manifest); // it records the new contents' hashes
    EXPECT_NE(inode("edited.obj"), edited);
    EXPECT_NE(inode("grown.obj"), grown);
    EXPECT_EQ(readText(dir / "same.obj"), "v 1 2 3\n");
    EXPECT_EQ(readText(dir / "edited.obj"), "v 1 2 4\n");
    EXPECT_EQ(readText(dir / "grown.obj"), "v 1");
    EXPECT_EQ(listFolder(dir.path), (std::vector<std::string>{".visemelab-reduce.manifest", "edited.obj",
                                                              "grown.obj", "same.obj"}));
    const auto manifestNow = inode(".visemelab-reduce.manifest");
    writeSet(dir.path, "reduce",
             {{"same.obj", "v 1 2 3\n"}, {"edited.obj", "v 1 2 4\n"}, {"grown.obj", "v 1"}});
    EXPECT_EQ(inode(".visemelab-reduce.manifest"), manifestNow); // an unchanged run changes no file
    writeSet(dir.path, "reduce", {{"same.obj", "v 1 2 3\n"}});   // the others are stale now
    EXPECT_EQ(inode("same.obj"), same);
    EXPECT_EQ(listFolder(dir.path), (std::vector<std::string>{".visemelab-reduce.manifest", "same.obj"}));
}

TEST(OutputSet, DestinationsKeepTheirMode) {
    TempFolder dir;
    std::filesystem::create_directories(dir / "out");
    writeText(dir / "out" / "script.obj", "old");
    std::filesystem::permissions(dir / "out" / "script.obj", std::filesystem::perms(0754));
    std::filesystem::permissions(dir / "out", std::filesystem::perms(0750));
    writeSet(dir / "out", "s", {{"script.obj", "new"}});
    EXPECT_EQ(std::filesystem::status(dir / "out" / "script.obj").permissions(),
              std::filesystem::perms(0754));
    EXPECT_EQ(std::filesystem::status(dir / "out").permissions(), std::filesystem::perms(0750));
}

} // namespace
} // namespace vl
