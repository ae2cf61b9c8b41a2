#pragma once
// Normalisation of espeak-ng's English phoneme mnemonics (the ASCII names of its phoneme tables
// en / en-us, as espeak_TextToPhonemes writes them in mode 0) to the 39 ARPAbet phonemes.
// Pure string handling, no espeak-ng dependency: docs/phonemes.md lists every rule.
#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

// The non-empty pieces of `text` between `separator`s.
std::vector<std::string_view> splitNonEmpty(std::string_view text, char separator);

// Appends the ARPAbet phonemes of one word, given as espeak mnemonics (stress marks ' , % = may
// prefix a mnemonic). Pauses and markers (_:, ;, ||, ...) are ignored; a mnemonic with no English
// equivalent (e.g. from a foreign letter name) is counted in `skipped` and left out. When `sources`
// is given, the index into `mnemonics` each appended phoneme comes from is appended to it (a
// mnemonic gives 0, 1 or 2 phonemes), for timing phonemes from the synthesiser's mnemonic events.
void appendArpabetForEspeakWord(std::span<const std::string_view> mnemonics, std::vector<std::string>& out,
                                std::map<std::string, std::size_t>& skipped,
                                std::vector<std::size_t>* sources = nullptr);

// An espeak symbol split into a leading marker ("_:", "_", "_!", "_|", ...) and the phoneme written
// right after it without a separator ("_:k" in a clause that starts at a quotation mark).
struct EspeakSymbol {
    std::string_view marker; // empty when the symbol does not start with '_'
    std::string_view phoneme;
    // "_" and "_:" are pauses (the synthesiser is silent there); "_!" and "_|" mark a glottal onset.
    bool isPause() const { return marker == "_" || marker.starts_with("_:"); }
};
EspeakSymbol splitEspeakSymbol(std::string_view symbol);

// Appends kSilencePhoneme unless `out` is empty or already ends with it: an utterance never starts
// with a counted pause and two pauses in a row are one.
void appendSilence(std::vector<std::string>& out);

// Appends one clause of espeak_TextToPhonemes output in mnemonic mode (words separated by spaces,
// phonemes by `separator`) as ARPAbet, with a silence for each pause inside the clause.
void appendArpabetForEspeakClause(std::string_view clause, char separator, std::vector<std::string>& out,
                                  std::map<std::string, std::size_t>& skipped);

// The same for IPA output of a non-English voice: stress marks are removed, each remaining
// symbol (with its length mark or diacritics) is kept as the phoneme's name.
void appendIpaForEspeakWord(std::span<const std::string_view> symbols, std::vector<std::string>& out);

} // namespace vl
