#pragma once
// The phoneme inventory VisemeLab counts English text in: the 39 ARPAbet phonemes of the CMU
// Pronouncing Dictionary (stress digits dropped), each with its IPA symbol and an example word.
// docs/phonemes.md shows the same table.
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

struct ArpabetPhoneme {
    std::string_view symbol;  // "AA"
    std::string_view ipa;     // "ɑ"
    std::string_view example; // "odd"
    bool vowel;
};

// The 39 phonemes in alphabetical order of their symbols.
std::span<const ArpabetPhoneme> arpabetInventory();

// nullptr when `symbol` is not one of the 39.
const ArpabetPhoneme* findArpabet(std::string_view symbol);

std::vector<std::string> arpabetSymbols();

} // namespace vl
