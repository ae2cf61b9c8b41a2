#pragma once
// A test with a folder of its own (ctest runs tests in parallel) holding the Ready Player Me-like
// fixture as rpm.glb.
#include "core/common/AtomicFile.h"
#include "tests/gltf/AvatarFixtures.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace vl::test {

class AvatarFolderTest : public ::testing::Test {
  protected:
    std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                (std::string("visemelab_") +
                                 ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name() +
                                 "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    void SetUp() override {
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
        writeFileAtomically(dir / "rpm.glb", rpmLikeAvatar());
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
    std::string path(const char* name) const { return (dir / name).string(); }
};

} // namespace vl::test
