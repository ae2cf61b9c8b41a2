#include "core/phonetics/Arpabet.h"

#include <algorithm>
#include <array>

namespace vl {

namespace {

// IPA as in General American dictionaries; AH is /ʌ/ when stressed and /ə/ otherwise, ER /ɝ/ or /ɚ/.
constexpr std::array<ArpabetPhoneme, 39> kInventory{{
    {"AA", "ɑ", "odd", true},   {"AE", "æ", "at", true},       {"AH", "ʌ", "hut", true},
    {"AO", "ɔ", "ought", true}, {"AW", "aʊ", "cow", true},     {"AY", "aɪ", "hide", true},
    {"B", "b", "be", false},    {"CH", "tʃ", "cheese", false}, {"D", "d", "dee", false},
    {"DH", "ð", "thee", false}, {"EH", "ɛ", "Ed", true},       {"ER", "ɝ", "hurt", true},
    {"EY", "eɪ", "ate", true},  {"F", "f", "fee", false},      {"G", "ɡ", "green", false},
    {"HH", "h", "he", false},   {"IH", "ɪ", "it", true},       {"IY", "i", "eat", true},
    {"JH", "dʒ", "gee", false}, {"K", "k", "key", false},      {"L", "l", "lee", false},
    {"M", "m", "me", false},    {"N", "n", "knee", false},     {"NG", "ŋ", "ping", false},
    {"OW", "oʊ", "oat", true},  {"OY", "ɔɪ", "toy", true},     {"P", "p", "pee", false},
    {"R", "ɹ", "read", false},  {"S", "s", "sea", false},      {"SH", "ʃ", "she", false},
    {"T", "t", "tea", false},   {"TH", "θ", "theta", false},   {"UH", "ʊ", "hood", true},
    {"UW", "u", "two", true},   {"V", "v", "vee", false},      {"W", "w", "we", false},
    {"Y", "j", "yield", false}, {"Z", "z", "zee", false},      {"ZH", "ʒ", "seizure", false},
}};

} // namespace

std::span<const ArpabetPhoneme> arpabetInventory() {
    return kInventory;
}

const ArpabetPhoneme* findArpabet(std::string_view symbol) {
    const auto it =
        std::lower_bound(kInventory.begin(), kInventory.end(), symbol,
                         [](const ArpabetPhoneme& p, std::string_view s) { return p.symbol < s; });
    return it != kInventory.end() && it->symbol == symbol ? &*it : nullptr;
}

std::vector<std::string> arpabetSymbols() {
    std::vector<std::string> symbols;
    for (const auto& p : kInventory) symbols.emplace_back(p.symbol);
    return symbols;
}

} // namespace vl
