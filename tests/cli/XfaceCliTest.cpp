// `visemelab reduce --fdp`: an XfaceEd face written by the exporter is read back as a viseme set.
#include "core/common/AtomicFile.h"
#include "core/export/Xface.h"
#include "tests/cli/CliRunner.h"
#include "tests/export/TestModels.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace vl {
namespace {

// An Xface face is a viseme set for `visemelab reduce --fdp`; its .dic maps a phoneme table.
TEST(Xface, ReduceReadsAnXfaceFaceFromTheCommandLine) {
    const ReducedModel model = test::randomModel(6, 5, 4, true, 83);
    const auto dir = std::filesystem::temp_directory_path() / "visemelab_xface_reduce";
    std::filesystem::remove_all(dir);
    writeXfaceFace(dir / "face", model, "face");
    std::string table = "phoneme,frequency\n";
    for (const auto& [phoneme, f] : model.phonemeFrequencies)
        table += phoneme + "," + std::to_string(f) + "\n";
    table += "#,0.5\n_,0.1\n";
    writeFileAtomically(dir / "phonemes.csv", table);
    const auto r =
        test::runCli("reduce --fdp " + (dir / "face" / "face.fdp").string() + " --freq-file " +
                     (dir / "phonemes.csv").string() + " --target 2 --out " + (dir / "out").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("Reduced 4 visemes to 2"), std::string::npos) << r.output;
    const std::string mapping = readFileToString(dir / "out" / "mapping.json");
    EXPECT_NE(mapping.find("\"p7\""), std::string::npos) << mapping; // phonemes came through the .dic
    const auto both =
        test::runCli("reduce --fdp " + (dir / "face" / "face.fdp").string() + " --neutral x.obj -m 2");
    EXPECT_EQ(both.exitCode, 2) << both.output;
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace vl
