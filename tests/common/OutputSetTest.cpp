// Folder outputs written as a set: all or nothing visible, stale outputs of the last run removed,
// unrelated files never touched, temporaries cleaned on failure and swept after a kill.
#include "TempFolder.h"

#include "core/common/AtomicFile.h"
#include "core/common/InputRegistry.h"
#include "core/common/OutputSet.h"

#include <sys/stat.h>

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
    std::filesystem::create_directories(dir / "out" / "folder");
    writeText(OutputSet::manifestPath(dir / "out", "reduce"),
              "../precious.txt\n" + (dir / "precious.txt").string() + "\n.hidden\nfolder\n.\n..\n");
    writeSet(dir / "out", "reduce", {{"a.obj", "x"}});
    EXPECT_EQ(readText(dir / "precious.txt"), "keep");
    EXPECT_EQ(readText(dir / "out" / ".hidden"), "keep");
    EXPECT_TRUE(std::filesystem::is_directory(dir / "out" / "folder"));
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
    EXPECT_EQ(inode(".visemelab-reduce.manifest"), manifest); // it lists the same files
    EXPECT_NE(inode("edited.obj"), edited);
    EXPECT_NE(inode("grown.obj"), grown);
    EXPECT_EQ(readText(dir / "same.obj"), "v 1 2 3\n");
    EXPECT_EQ(readText(dir / "edited.obj"), "v 1 2 4\n");
    EXPECT_EQ(readText(dir / "grown.obj"), "v 1");
    EXPECT_EQ(listFolder(dir.path), (std::vector<std::string>{".visemelab-reduce.manifest", "edited.obj",
                                                              "grown.obj", "same.obj"}));
    writeSet(dir.path, "reduce", {{"same.obj", "v 1 2 3\n"}}); // the others are stale now
    EXPECT_EQ(inode("same.obj"), same);
    EXPECT_EQ(listFolder(dir.path), (std::vector<std::string>{".visemelab-reduce.manifest", "same.obj"}));
}

TEST(OutputSet, DestinationsKeepModeAndSymlinks) {
    TempFolder dir;
    std::filesystem::create_directories(dir / "elsewhere");
    writeText(dir / "elsewhere" / "real.obj", "old");
    std::filesystem::create_symlink(
        "../elsewhere/real.obj",
        (std::filesystem::create_directories(dir / "out"), dir / "out" / "linked.obj"));
    writeText(dir / "out" / "script.obj", "old");
    std::filesystem::permissions(dir / "out" / "script.obj", std::filesystem::perms(0754));
    writeSet(dir / "out", "s", {{"linked.obj", "new"}, {"script.obj", "new"}});
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "out" / "linked.obj"));
    EXPECT_EQ(readText(dir / "elsewhere" / "real.obj"), "new");
    EXPECT_EQ(std::filesystem::status(dir / "out" / "script.obj").permissions(),
              std::filesystem::perms(0754));
}

} // namespace
} // namespace vl
