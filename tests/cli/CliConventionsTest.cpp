// What pipelines rely on (issue 34, point 4): --version, an unknown command named as such, and
// numeric option errors a user can read.
#include "tests/cli/CliRunner.h"

#include <gtest/gtest.h>

namespace vl {
namespace {

TEST(CliConventions, VersionPrintsTheProjectVersion) {
    const auto r = test::runCli("--version");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.rfind("visemelab ", 0), 0u) << r.output;
    EXPECT_NE(r.output.find('.'), std::string::npos) << r.output;
}

TEST(CliConventions, AnUnknownCommandIsNamed) {
    const auto r = test::runCli("frobnicate --out x");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("unknown command 'frobnicate'"), std::string::npos) << r.output;
    // A known command still parses as before.
    const auto help = test::runCli("reduce --help");
    EXPECT_EQ(help.exitCode, 0) << help.output;
}

TEST(CliConventions, NumericErrorsAreReadable) {
    for (const char* arguments :
         {"avatar reduce in.glb -m 0 --out out.glb", "say hi --avatar in.glb -m 0 --out t.json",
          "reduce --project p.vlproj --max-error-mm -1"}) {
        const auto r = test::runCli(arguments);
        EXPECT_EQ(r.exitCode, 2) << arguments << "\n" << r.output;
        EXPECT_NE(r.output.find("must be greater than 0"), std::string::npos) << arguments << "\n"
                                                                              << r.output;
        EXPECT_LT(r.output.size(), 400u) << r.output; // no 309-digit bound
    }
}

} // namespace
} // namespace vl
