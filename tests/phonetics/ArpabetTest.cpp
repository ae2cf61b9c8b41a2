#include "core/phonetics/Arpabet.h"
#include "core/common/AtomicFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

using namespace vl;

TEST(Arpabet, InventoryHas39DistinctSortedPhonemes) {
    const auto inventory = arpabetInventory();
    ASSERT_EQ(inventory.size(), 39u);
    std::set<std::string_view> symbols, ipa;
    int vowels = 0;
    for (std::size_t i = 0; i < inventory.size(); ++i) {
        symbols.insert(inventory[i].symbol);
        ipa.insert(inventory[i].ipa);
        vowels += inventory[i].vowel ? 1 : 0;
        EXPECT_FALSE(inventory[i].example.empty()) << inventory[i].symbol;
        if (i > 0) {
            EXPECT_LT(inventory[i - 1].symbol, inventory[i].symbol); // findArpabet relies on it
        }
    }
    EXPECT_EQ(symbols.size(), 39u);
    EXPECT_EQ(ipa.size(), 39u);
    EXPECT_EQ(vowels, 15); // 9 monophthongs, ER and the diphthongs AW AY EY OW OY
}

TEST(Arpabet, FindsEverySymbolAndNothingElse) {
    for (const auto& phoneme : arpabetInventory()) {
        const ArpabetPhoneme* found = findArpabet(phoneme.symbol);
        ASSERT_NE(found, nullptr) << phoneme.symbol;
        EXPECT_EQ(found->symbol, phoneme.symbol);
    }
    EXPECT_EQ(findArpabet("AX"), nullptr);
    EXPECT_EQ(findArpabet("ah"), nullptr);
    EXPECT_EQ(findArpabet(""), nullptr);
    EXPECT_EQ(findArpabet("ZZ"), nullptr);
    EXPECT_EQ(findArpabet("SH")->ipa, "ʃ");
    EXPECT_EQ(arpabetSymbols().front(), "AA");
    EXPECT_EQ(arpabetSymbols().back(), "ZH");
}

// docs/phonemes.md shows the inventory; keep it in step with the code.
TEST(Arpabet, DocumentedTableMatchesTheInventory) {
    const auto docs = std::filesystem::path(VISEMELAB_ASSETS_DIR).parent_path() / "docs" / "phonemes.md";
    const std::string text = readFileToString(docs);
    for (const auto& p : arpabetInventory()) {
        const std::string row =
            "| " + std::string(p.symbol) + " | " + std::string(p.ipa) + " | " + std::string(p.example) + " |";
        EXPECT_NE(text.find(row), std::string::npos) << "docs/phonemes.md lacks the row " << row;
    }
}
