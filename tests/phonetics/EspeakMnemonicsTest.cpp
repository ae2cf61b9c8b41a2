#include "core/phonetics/EspeakMnemonics.h"
#include "core/phonetics/Arpabet.h"

#include <gtest/gtest.h>

using namespace vl;

namespace {

// One word of espeak mnemonics, separated by spaces here for readability.
std::string toArpabet(std::string_view word, std::map<std::string, std::size_t>* skipped = nullptr) {
    std::vector<std::string_view> tokens;
    std::size_t start = 0;
    while (start <= word.size()) {
        const auto end = std::min(word.find(' ', start), word.size());
        tokens.push_back(word.substr(start, end - start));
        start = end + 1;
    }
    std::vector<std::string> out;
    std::map<std::string, std::size_t> ignored;
    appendArpabetForEspeakWord(tokens, out, skipped ? *skipped : ignored);
    std::string joined;
    for (const auto& p : out) joined += (joined.empty() ? "" : " ") + p;
    return joined;
}

} // namespace

TEST(EspeakMnemonics, StressMarksAreDropped) {
    EXPECT_EQ(toArpabet("k 'a t"), "K AE T");
    EXPECT_EQ(toArpabet("h @ l 'oU"), "HH AH L OW");
    EXPECT_EQ(toArpabet(",I n t 3 n 'a S @- n @L"), "IH N T ER N AE SH AH N AH L");
    EXPECT_EQ(toArpabet("%s =m ''I T"), "S M IH TH");
}

TEST(EspeakMnemonics, RColouredVowelsAbsorbTheFollowingR) {
    EXPECT_EQ(toArpabet("k 'A@"), "K AA R");             // car
    EXPECT_EQ(toArpabet("f 'o@"), "F AO R");             // four
    EXPECT_EQ(toArpabet("p 'U@ r-"), "P UH R");          // poor + linking r
    EXPECT_EQ(toArpabet("b 'e@ r I N"), "B EH R IH NG"); // bearing: one R, not two
    EXPECT_EQ(toArpabet("p 'eI p 3 r-"), "P EY P ER");   // paper + linking r
    EXPECT_EQ(toArpabet("h '3: r i"), "HH ER IY");       // hurry
    EXPECT_EQ(toArpabet("f 'aI3 r-"), "F AY ER");        // fire
    EXPECT_EQ(toArpabet("'aU 3 r-"), "AW ER");           // hour
    EXPECT_EQ(toArpabet("m 'I r 3"), "M IH R ER");       // mirror: the r before 3 stays
    EXPECT_EQ(toArpabet("f 'i@3"), "F IH R");            // fear
}

TEST(EspeakMnemonics, OptionalSchwasAndCentringDiphthongsBeforeR) {
    EXPECT_EQ(toArpabet("'a v @- r I2 dZ"), "AE V R IH JH"); // average
    EXPECT_EQ(toArpabet("n 'a S @- n @L"), "N AE SH AH N AH L");
    EXPECT_EQ(toArpabet("z 'i@ r oU"), "Z IY R OW");   // zero
    EXPECT_EQ(toArpabet("aI d 'i@"), "AY D IY AH");    // idea
    EXPECT_EQ(toArpabet("s 'aI@ n s"), "S AY AH N S"); // science
}

TEST(EspeakMnemonics, SyllabicConsonantsFlapsAndGlottalStops) {
    EXPECT_EQ(toArpabet("b 'V ? n-"), "B AH T AH N");    // button
    EXPECT_EQ(toArpabet("l 'I t# @L"), "L IH T AH L");   // little
    EXPECT_EQ(toArpabet("r 'oU z I# z"), "R OW Z IH Z"); // roses (ᵻ)
    EXPECT_EQ(toArpabet("D I2 ;"), "DH IH");             // ';' marks linking, no phoneme
}

TEST(EspeakMnemonics, PausesAndMarkersGiveNothing) {
    EXPECT_EQ(toArpabet("_: _ _! || ; : -"), "");
    EXPECT_EQ(toArpabet("f 'U t _: _:"), "F UH T");
}

TEST(EspeakMnemonics, ForeignSymbolsAreSkippedAndCounted) {
    std::map<std::string, std::size_t> skipped;
    EXPECT_EQ(toArpabet("'E: m 'a: R2 u", &skipped), "M");
    EXPECT_EQ(skipped.size(), 4u);
    EXPECT_EQ(skipped["E:"], 1u);
    EXPECT_EQ(toArpabet("'a: 'a:", &skipped), "");
    EXPECT_EQ(skipped["a:"], 3u);
}

// Every vowel and consonant of espeak-ng's en and en-us phoneme tables (from its phontab) must
// normalise to inventory phonemes, so English text never loses a phoneme.
TEST(EspeakMnemonics, EveryEnglishTableMnemonicMapsIntoTheInventory) {
    const char* mnemonics[] = {
        "@",   "3",  "3:", "@2", "@5",  "@L", "@#",  "@-",  "a",  "a#", "a2",  "a#2", "aa",  "A:", "A@", "A#",
        "A~",  "E",  "E#", "E2", "e:",  "e#", "e@",  "eI",  "I",  "I#", "I2",  "I2#", "IR",  "i",  "i:", "i@",
        "i@3", "0",  "0#", "02", "O",   "O:", "O2",  "O~",  "O@", "o@", "o:",  "oU",  "oU#", "OI", "V",  "VR",
        "U",   "U@", "u:", "aU", "aU@", "aI", "aI@", "aI3", "p",  "b",  "t",   "t#",  "t2",  "d",  "d#", "k",
        "g",   "?",  "x",  "f",  "v",   "T",  "D",   "s",   "z",  "z#", "z/2", "S",   "Z",   "h",  "m",  "n",
        "N",   "l",  "r",  "r-", "r/",  "w",  "w#",  "j",   "tS", "dZ", "n-",  "m-",  "l-"};
    for (const char* m : mnemonics) {
        std::map<std::string, std::size_t> skipped;
        std::vector<std::string> out;
        const std::string_view token(m);
        appendArpabetForEspeakWord(std::span(&token, 1), out, skipped);
        EXPECT_TRUE(skipped.empty()) << m;
        ASSERT_FALSE(out.empty()) << m;
        for (const auto& p : out) EXPECT_NE(findArpabet(p), nullptr) << m << " -> " << p;
    }
}

TEST(EspeakMnemonics, IpaSymbolsKeepLengthButLoseStress) {
    std::vector<std::string> out;
    const std::string_view symbols[] = {"h", "\u02C8a\u02D0", "\u02CCz", "", "\u0259"};
    appendIpaForEspeakWord(symbols, out);
    EXPECT_EQ(out, (std::vector<std::string>{"h", "a\u02D0", "z", "\u0259"}));
}
