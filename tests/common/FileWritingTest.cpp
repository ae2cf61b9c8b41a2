// fileio::holdsExactly, the check that lets an output set leave an unchanged file alone, against the
// obvious reference: read the whole file and compare it with the joined parts.
#include "TempFolder.h"

#include "core/common/FileWriting.h"

#include <random>
#include <sys/stat.h>

namespace vl {
namespace {

using test::readText;
using test::TempFolder;
using test::writeText;

bool holds(const std::filesystem::path& file, const std::vector<std::string>& parts) {
    const std::vector<std::string_view> views(parts.begin(), parts.end());
    return fileio::holdsExactly(file, views);
}

TEST(FileWriting, HoldsExactlyAgreesWithReadingTheWholeFile) {
    TempFolder dir;
    std::mt19937 random(20261127);
    for (int trial = 0; trial < 300; ++trial) {
        // Sizes around the 32 KiB reading chunk and beyond; parts of any size, empty ones included.
        const std::size_t size =
            std::uniform_int_distribution<std::size_t>(0, trial % 3 ? 70'000 : 40)(random);
        std::string contents(size, '\0');
        for (char& c : contents) c = static_cast<char>('a' + random() % 4);
        std::vector<std::string> parts;
        for (std::size_t at = 0; at < size || parts.empty();) {
            const std::size_t length = std::min(
                size - at, std::uniform_int_distribution<std::size_t>(0, trial % 2 ? 9 : 40'000)(random));
            parts.push_back(contents.substr(at, length));
            at += length;
        }
        std::string onDisk = contents;
        switch (random() % 5) {
        case 0:
            break; // the same
        case 1:
            if (!onDisk.empty()) onDisk[random() % onDisk.size()] ^= 1;
            break; // one byte
        case 2:
            if (!onDisk.empty()) onDisk.back() = 'z';
            break; // the last
        case 3:
            onDisk.resize(random() % (onDisk.size() + 1));
            break; // shorter
        default:
            onDisk += std::string(1 + random() % 3, 'a');
            break; // longer
        }
        const auto file = dir / "file.txt";
        writeText(file, onDisk);
        EXPECT_EQ(holds(file, parts), readText(file) == contents) << "trial " << trial << ", size " << size;
    }
}

TEST(FileWriting, HoldsExactlyIsFalseForWhatIsNotARegularFile) {
    TempFolder dir;
    EXPECT_FALSE(holds(dir / "missing.txt", {""}));
    std::filesystem::create_directories(dir / "folder");
    EXPECT_FALSE(holds(dir / "folder", {""}));
    writeText(dir / "real.txt", "text");
    std::filesystem::create_symlink("real.txt", dir / "link.txt");
    EXPECT_TRUE(holds(dir / "real.txt", {"te", "", "xt"}));
    EXPECT_FALSE(holds(dir / "link.txt", {"text"})); // the caller resolves links (writeTarget)
    // A named pipe is not opened (that would wait for a writer forever); an empty one "holds" "".
    ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
    EXPECT_FALSE(holds(dir / "pipe", {""}));
    EXPECT_FALSE(holds("/dev/null", {""}));
}

} // namespace
} // namespace vl
