// Single-file saves: atomic replace, mode kept, symlinks written through, temporaries of killed
// saves swept, inputs of the run never overwritten.
#include "TempFolder.h"

#include "core/common/AtomicFile.h"
#include "core/common/AtomicFileWriter.h"
#include "core/common/InputRegistry.h"
#include "core/common/OutputPolicy.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace vl {

int test::deadProcessId() {
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    return child;
}

namespace {

using test::listFolder;
using test::readText;
using test::TempFolder;
using test::writeText;

mode_t modeOf(const std::filesystem::path& file) {
    struct stat info {};
    ::stat(file.c_str(), &info);
    return info.st_mode & 07777;
}

TEST(AtomicFile, ReplacesTheFileAndLeavesNoTemporary) {
    TempFolder dir;
    writeFileAtomically(dir / "a.txt", "one");
    writeFileAtomically(dir / "a.txt", "two");
    EXPECT_EQ(readText(dir / "a.txt"), "two");
    EXPECT_EQ(listFolder(dir.path), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, NewFilesFollowTheUmaskAndReplacedFilesKeepTheirMode) {
    TempFolder dir;
    const mode_t mask = ::umask(022);
    ::umask(mask);
    writeFileAtomically(dir / "new.txt", "x");
    EXPECT_EQ(modeOf(dir / "new.txt"), 0666 & ~mask);
    ::chmod((dir / "new.txt").c_str(), 0750);
    writeFileAtomically(dir / "new.txt", "y");
    EXPECT_EQ(modeOf(dir / "new.txt"), 0750u);
    EXPECT_EQ(readText(dir / "new.txt"), "y");
}

TEST(AtomicFile, ASymlinkDestinationIsWrittenThrough) {
    TempFolder dir;
    std::filesystem::create_directories(dir / "real");
    writeText(dir / "real" / "target.txt", "old");
    std::filesystem::create_symlink("real/target.txt", dir / "link.txt");
    std::filesystem::create_symlink("link.txt", dir / "link2.txt"); // a chain of two
    writeFileAtomically(dir / "link2.txt", "new");
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.txt"));
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "link2.txt"));
    EXPECT_EQ(readText(dir / "real" / "target.txt"), "new");
    // A dangling link creates its target.
    std::filesystem::create_symlink("real/missing.txt", dir / "dangling.txt");
    writeFileAtomically(dir / "dangling.txt", "made");
    EXPECT_EQ(readText(dir / "real" / "missing.txt"), "made");
    // A loop is an error naming the file.
    std::filesystem::create_symlink("loop2", dir / "loop1");
    std::filesystem::create_symlink("loop1", dir / "loop2");
    EXPECT_THROW(writeFileAtomically(dir / "loop1", "x"), InputError);
}

TEST(AtomicFile, TemporariesOfKilledSavesAreSweptOnTheNextSave) {
    TempFolder dir;
    const std::string dead = std::to_string(test::deadProcessId());
    writeText(dir / (".a.txt.vltmp-" + dead + "-1234"), std::string(4096, 'x')); // a save killed mid-way
    writeText(dir / ".a.txt.vltmp-1-99", "live");                                // pid 1 is alive
    writeText(dir / (".b.txt.vltmp-" + dead + "-5"), "another file's");          // killed too (say --wav)
    writeFileAtomically(dir / "a.txt", "saved");
    EXPECT_EQ(listFolder(dir.path), (std::vector<std::string>{".a.txt.vltmp-1-99", "a.txt"}));
}

TEST(AtomicFile, ASymlinkIsRefusedUnlessFollowedAndADanglingOneCreatesNoFolder) {
    TempFolder dir;
    writeText(dir / "real.txt", "old");
    std::filesystem::create_symlink(dir / "real.txt", dir / "link.txt");
    std::filesystem::create_symlink(dir / "missing" / "deeper" / "x.txt", dir / "dangling.txt");
    const OutputPolicy saved = outputPolicy();
    setOutputPolicy({.followSymlinks = false, .waitForBusyFolder = true});
    try {
        writeFileAtomically(dir / "link.txt", "new");
        ADD_FAILURE() << "a symlinked output was written through";
    } catch (const OutputRefusedError& e) {
        EXPECT_NE(std::string(e.what()).find((dir / "link.txt").string()), std::string::npos) << e.what();
    }
    EXPECT_EQ(readText(dir / "real.txt"), "old");
    EXPECT_THROW(writeFileAtomically(dir / "dangling.txt", "new"), OutputRefusedError);
    setOutputPolicy({.followSymlinks = true, .waitForBusyFolder = true});
    writeFileAtomically(dir / "link.txt", "new");
    EXPECT_EQ(readText(dir / "real.txt"), "new");
    EXPECT_THROW(writeFileAtomically(dir / "dangling.txt", "new"), OutputRefusedError);
    EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
    setOutputPolicy(saved);
}

TEST(AtomicFile, DashGoesToTheStandardOutputDescriptorWholeAtCommit) {
    TempFolder dir;
    const int fd = ::open((dir / "stdout").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ASSERT_GE(fd, 0);
    const OutputPolicy saved = outputPolicy();
    setOutputPolicy({.standardOutputFd = fd});
    {
        AtomicFileWriter writer("-");
        writer.write("RIFF????data");
        EXPECT_EQ(readText(dir / "stdout"), ""); // nothing before commit: a failed run writes nothing
        writer.overwrite(4, "1234");             // a header patched at the end (WAV) still works
        writer.commit();
    }
    {
        AtomicFileWriter abandoned("-");
        abandoned.write("never");
    } // no commit: nothing written
    setOutputPolicy(saved);
    ::close(fd);
    EXPECT_EQ(readText(dir / "stdout"), "RIFF1234data");
    // Without the policy `-` is a file name like any other (the editor).
    const auto cwd = std::filesystem::current_path();
    std::filesystem::current_path(dir.path);
    writeFileAtomically("-", "a file");
    std::filesystem::current_path(cwd);
    EXPECT_EQ(readText(dir / "-"), "a file");
}

TEST(AtomicFile, AFailedSaveLeavesTheOldFileAndNoTemporary) {
    if (::geteuid() == 0) GTEST_SKIP() << "running as root: permissions cannot make a folder read-only";
    TempFolder dir;
    writeText(dir / "a.txt", "old");
    ::chmod(dir.path.c_str(), 0555);
    EXPECT_THROW(writeFileAtomically(dir / "a.txt", "new"), InputError);
    ::chmod(dir.path.c_str(), 0755);
    EXPECT_EQ(readText(dir / "a.txt"), "old");
    EXPECT_EQ(listFolder(dir.path), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, ADeviceOrFolderIsNotReadAsAFile) {
    EXPECT_THROW(readFileToString("/dev/zero"), InputError);
    EXPECT_THROW(readFileToString("/"), InputError);
}

TEST(InputRegistry, AnInputOfTheRunIsNeverOverwritten) {
    TempFolder dir;
    writeText(dir / "in.obj", "input");
    std::filesystem::create_symlink("in.obj", dir / "alias.obj");
    std::filesystem::create_hard_link(dir / "in.obj", dir / "hard.obj");
    {
        const InputRecording recording;
        (void)readFileToString(dir / "in.obj");
        for (const auto& name : {"in.obj", "alias.obj", "hard.obj"}) {
            try {
                writeFileAtomically(dir / name, "clobbered");
                ADD_FAILURE() << name << " was overwritten";
            } catch (const OutputOverwritesInputError& e) {
                EXPECT_NE(std::string(e.what()).find("would overwrite an input of this run"),
                          std::string::npos);
            }
        }
        EXPECT_NO_THROW(writeFileAtomically(dir / "other.obj", "fine"));
    }
    EXPECT_EQ(readText(dir / "in.obj"), "input");
    // Without a recording (the editor saving what it opened) nothing is refused.
    EXPECT_NO_THROW(writeFileAtomically(dir / "in.obj", "saved"));
}

TEST(InputRegistry, AFileUpdatedInPlaceIsReleasedAndTheOtherInputsStayProtected) {
    TempFolder dir;
    writeText(dir / "p.vlproj", "project");
    writeText(dir / "mesh.obj", "mesh");
    {
        const InputRecording recording;
        (void)readFileToString(dir / "p.vlproj");
        (void)readFileToString(dir / "mesh.obj");
        EXPECT_THROW(writeFileAtomically(dir / "p.vlproj", "updated"), OutputOverwritesInputError);
        allowUpdatingInPlace(dir / "p.vlproj");
        EXPECT_NO_THROW(writeFileAtomically(dir / "p.vlproj", "updated"));
        EXPECT_THROW(writeFileAtomically(dir / "mesh.obj", "clobbered"), OutputOverwritesInputError);
    }
    EXPECT_EQ(readText(dir / "p.vlproj"), "updated");
    EXPECT_EQ(readText(dir / "mesh.obj"), "mesh");
}

} // namespace
} // namespace vl
