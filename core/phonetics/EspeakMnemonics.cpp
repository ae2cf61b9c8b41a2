#include "core/phonetics/EspeakMnemonics.h"

#include "core/speech/Utterance.h"

#include <array>
#include <unordered_map>

namespace vl {

namespace {

struct MnemonicRule {
    std::string_view mnemonic;
    std::array<std::string_view, 2> arpabet; // second may be empty
    // The last symbol is dropped before r: [i@ r] "zero" is IY R, not IY AH R.
    bool dropLastBeforeR = false;
};

// Every mnemonic of espeak-ng's en and en-us phoneme tables (plus the base-table consonants they
// use). The IPA in the comments is what espeak-ng 1.51 writes for en-us.
constexpr MnemonicRule kRules[] = {
    {"0", {"AA", ""}},           // ɑː lot (ɒ in British voices)
    {"0#", {"AA", ""}},          // unstressed o that may reduce
    {"02", {"AH", ""}},          // becomes ʌ in en-us
    {"3", {"ER", ""}},           // ɚ butter
    {"3:", {"ER", ""}},          // ɜː (r-coloured in en-us) bird
    {"?", {"T", ""}},            // ʔ glottal stop, an allophone of /t/ (button)
    {"@", {"AH", ""}},           // ə
    {"@#", {"AH", ""}},          // fronted ə
    {"@-", {"AH", ""}, true},    // optional ə (nation-al); espeak drops it before r
    {"@2", {"AH", ""}},          // ə of "the"
    {"@5", {"AH", ""}},          // ə of "to"
    {"@L", {"AH", "L"}},         // əl syllabic l (little)
    {"A#", {"AE", ""}},          // a in British, used for bath words
    {"A:", {"AA", ""}},          // ɑː father
    {"A@", {"AA", "R"}},         // ɑːɹ car
    {"A~", {"AA", ""}},          // nasal ɑ̃ (French loans)
    {"D", {"DH", ""}},           // ð
    {"E", {"EH", ""}},           // ɛ
    {"E#", {"EH", ""}},          // ɛ that may reduce
    {"E2", {"EH", ""}},          // ɛ that does not reduce
    {"I", {"IH", ""}},           // ɪ
    {"I#", {"IH", ""}},          // ᵻ roses, wanted (en-us)
    {"I2", {"IH", ""}},          // ɪ unstressed (intend)
    {"I2#", {"IH", ""}},         // ɪ of -ed adjectives
    {"IR", {"ER", ""}},          // əɹ (Scottish split 3:)
    {"N", {"NG", ""}},           // ŋ
    {"O", {"AO", ""}},           // ɔ
    {"O2", {"AO", ""}},          // ɔ off, cloth (en-us)
    {"O:", {"AO", ""}},          // ɔː thought
    {"O@", {"AO", "R"}},         // ɔːɹ for
    {"OI", {"OY", ""}},          // ɔɪ boy
    {"O~", {"AO", ""}},          // nasal ɔ̃ (French loans)
    {"S", {"SH", ""}},           // ʃ
    {"T", {"TH", ""}},           // θ
    {"U", {"UH", ""}},           // ʊ
    {"U@", {"UH", "R"}},         // ʊɹ poor
    {"V", {"AH", ""}},           // ʌ
    {"VR", {"ER", ""}},          // ʌɹ (Scottish split 3:)
    {"Z", {"ZH", ""}},           // ʒ
    {"a", {"AE", ""}},           // æ
    {"a#", {"AH", ""}},          // ɐ about, a
    {"a#2", {"AH", ""}},         // "an"
    {"a2", {"AE", ""}},          // æ that does not reduce
    {"aI", {"AY", ""}},          // aɪ
    {"aI3", {"AY", "ER"}},       // aɪɚ fire
    {"aI@", {"AY", "AH"}, true}, // aɪə science
    {"aU", {"AW", ""}},          // aʊ
    {"aU@", {"AW", "ER"}},       // aʊɚ hour
    {"aa", {"AE", ""}},          // æ bath, ask (en-us)
    {"b", {"B", ""}},
    {"d", {"D", ""}},
    {"d#", {"D", ""}},   // past tense -d
    {"dZ", {"JH", ""}},  // dʒ
    {"e#", {"EH", ""}},  // ɛ explore
    {"e:", {"EY", ""}},  // e: (loans)
    {"e@", {"EH", "R"}}, // ɛɹ care
    {"eI", {"EY", ""}},  // eɪ
    {"f", {"F", ""}},
    {"g", {"G", ""}},
    {"h", {"HH", ""}},
    {"i", {"IY", ""}},          // i happy
    {"i:", {"IY", ""}},         // iː
    {"i@", {"IY", "AH"}, true}, // iə idea; IY before r (zero)
    {"i@3", {"IH", "R"}},       // ɪɹ fear
    {"j", {"Y", ""}},
    {"k", {"K", ""}},
    {"l", {"L", ""}},
    {"l-", {"AH", "L"}}, // syllabic l
    {"m", {"M", ""}},
    {"m-", {"AH", "M"}}, // syllabic m
    {"n", {"N", ""}},
    {"n-", {"AH", "N"}}, // n̩ button
    {"o:", {"OW", ""}},  // o: (loans)
    {"o@", {"AO", "R"}}, // oːɹ four
    {"oU", {"OW", ""}},  // oʊ
    {"oU#", {"OW", ""}}, // o that may reduce (going)
    {"p", {"P", ""}},
    {"r", {"R", ""}},
    {"r-", {"R", ""}}, // linking r
    {"r/", {"R", ""}},
    {"s", {"S", ""}},
    {"t", {"T", ""}},
    {"t#", {"T", ""}},  // ɾ flap (city, water); T as in CMUdict
    {"t2", {"T", ""}},  // t that does not reduce
    {"tS", {"CH", ""}}, // tʃ
    {"u:", {"UW", ""}}, // uː
    {"v", {"V", ""}},
    {"w", {"W", ""}},
    {"w#", {"W", ""}}, // ʍ which (Scottish)
    {"x", {"K", ""}},  // x loch, Bach: K as in CMUdict
    {"z", {"Z", ""}},
    {"z#", {"Z", ""}},    // plural -s
    {"z/2", {"Z", ""}},   // 's suffix
    {"N-", {"AH", "NG"}}, // syllabic ŋ (base table)
    {"R", {"R", ""}},     // base-table r variants
    {"r.", {"R", ""}},
    {"w/", {"W", ""}},
};

const MnemonicRule* findRule(std::string_view mnemonic) {
    static const std::unordered_map<std::string_view, const MnemonicRule*> index = [] {
        std::unordered_map<std::string_view, const MnemonicRule*> byName;
        for (const auto& rule : kRules) byName.emplace(rule.mnemonic, &rule);
        return byName;
    }();
    const auto it = index.find(mnemonic);
    return it == index.end() ? nullptr : it->second;
}

std::string_view stripStress(std::string_view token) {
    while (!token.empty() &&
           (token.front() == '\'' || token.front() == ',' || token.front() == '%' || token.front() == '='))
        token.remove_prefix(1);
    return token;
}

// Pauses (_:, _, _!), syllable and linking markers (;, -, :) and intonation bars carry no phoneme.
bool isMarker(std::string_view m) {
    return m.empty() || m.front() == '_' || m == ";" || m == ":" || m == "-" || m == "|" || m == "||";
}

bool isRhotic(std::string_view m) {
    return m == "r" || m == "r-" || m == "r/";
}

} // namespace

std::vector<std::string_view> splitNonEmpty(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= text.size(); ++i) {
        if (i == text.size() || text[i] == separator) {
            if (i > start) parts.push_back(text.substr(start, i - start));
            start = i + 1;
        }
    }
    return parts;
}

void appendArpabetForEspeakWord(std::span<const std::string_view> mnemonics, std::vector<std::string>& out,
                                std::map<std::string, std::size_t>& skipped,
                                std::vector<std::size_t>* sources) {
    bool lastWasRhotic = false; // the previous phoneme already was R or ER
    for (std::size_t i = 0; i < mnemonics.size(); ++i) {
        const std::string_view m = stripStress(mnemonics[i]);
        if (isMarker(m)) continue;
        // [3 r], [e@ r-], [aI3 r-]: espeak spells the r of an r-coloured vowel again before a vowel.
        if (isRhotic(m) && lastWasRhotic) {
            lastWasRhotic = false;
            continue;
        }
        const MnemonicRule* rule = findRule(m);
        if (!rule) {
            ++skipped[std::string(m)];
            lastWasRhotic = false;
            continue;
        }
        std::size_t count = rule->arpabet[1].empty() ? 1 : 2;
        if (rule->dropLastBeforeR) {
            std::size_t next = i + 1;
            while (next < mnemonics.size() && isMarker(stripStress(mnemonics[next]))) ++next;
            if (next < mnemonics.size() && isRhotic(stripStress(mnemonics[next]))) --count;
        }
        for (std::size_t k = 0; k < count; ++k) {
            out.emplace_back(rule->arpabet[k]);
            if (sources) sources->push_back(i);
        }
        lastWasRhotic = count > 0 && (out.back() == "R" || out.back() == "ER");
    }
}

EspeakSymbol splitEspeakSymbol(std::string_view symbol) {
    if (!symbol.starts_with('_')) return {{}, symbol};
    // Marker characters after the '_': no English mnemonic starts with one of them.
    const std::size_t end = symbol.find_first_not_of(":!|;^_#", 1);
    if (end == std::string_view::npos) return {symbol, {}};
    return {symbol.substr(0, end), symbol.substr(end)};
}

void appendSilence(std::vector<std::string>& out) {
    if (!out.empty() && out.back() != kSilencePhoneme) out.emplace_back(kSilencePhoneme);
}

void appendArpabetForEspeakClause(std::string_view clause, char separator, std::vector<std::string>& out,
                                  std::map<std::string, std::size_t>& skipped) {
    std::vector<std::string_view> word;
    const auto flushWord = [&] {
        appendArpabetForEspeakWord(word, out, skipped);
        word.clear();
    };
    for (const auto token : splitNonEmpty(clause, ' ')) {
        for (const auto symbol : splitNonEmpty(token, separator)) {
            const EspeakSymbol parts = splitEspeakSymbol(symbol);
            if (parts.isPause()) {
                flushWord();
                appendSilence(out);
            }
            if (!parts.phoneme.empty()) word.push_back(parts.phoneme);
        }
        flushWord();
    }
}

void appendIpaForEspeakWord(std::span<const std::string_view> symbols, std::vector<std::string>& out) {
    constexpr std::string_view kPrimary = "\u02C8", kSecondary = "\u02CC";
    for (std::string_view s : symbols) {
        for (bool stripped = true; stripped;) {
            stripped = false;
            for (auto mark : {kPrimary, kSecondary})
                if (s.starts_with(mark)) {
                    s.remove_prefix(mark.size());
                    stripped = true;
                }
        }
        if (!s.empty()) out.emplace_back(s);
    }
}

} // namespace vl
