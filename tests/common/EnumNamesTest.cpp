#include "core/common/EnumNames.h"

#include <gtest/gtest.h>

namespace vl {
namespace {

enum class Colour { Red, Green, Blue };

} // namespace

template <> struct EnumNames<Colour> {
    static constexpr const char* what = "colour";
    static constexpr EnumName<Colour> names[] = {
        {Colour::Red, "red"}, {Colour::Green, "green"}, {Colour::Blue, "blue"}};
};

namespace {

TEST(EnumNames, NameAndValueRoundTrip) {
    for (const Colour c : {Colour::Red, Colour::Green, Colour::Blue})
        EXPECT_EQ(fromString<Colour>(toString(c)), c);
    EXPECT_STREQ(toString(Colour::Green), "green");
    static_assert(fromString<Colour>("blue") == Colour::Blue); // usable in constant expressions
    EXPECT_STREQ(toString(static_cast<Colour>(7)), "?");
}

TEST(EnumNames, OnlyExactNamesParse) {
    EXPECT_EQ(fromString<Colour>("Red"), std::nullopt);
    EXPECT_EQ(fromString<Colour>("red "), std::nullopt);
    EXPECT_EQ(fromString<Colour>(""), std::nullopt);
    EXPECT_EQ(parseEnum<Colour>("red", "--colour"), Colour::Red);
}

TEST(EnumNames, ErrorNamesWhereTheTextAndTheAcceptedNames) {
    try {
        parseEnum<Colour>("purple", "scene.json:/light/colour");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "scene.json:/light/colour: unknown colour 'purple' (expected red, green or blue)");
    }
    EXPECT_EQ(enumNameList<Colour>(", "), "red, green, blue");
}

} // namespace
} // namespace vl
