#include "core/common/FileNames.h"

#include <gtest/gtest.h>

namespace vl {
namespace {

TEST(FileNames, NamesAreFileSafe) {
    EXPECT_EQ(fileSafeName("f+th"), "f+th");
    EXPECT_EQ(fileSafeName("a b/c\\d:e"), "a_b_c_d_e");
    EXPECT_EQ(fileSafeName("../x"), "___x");
}

} // namespace
} // namespace vl
