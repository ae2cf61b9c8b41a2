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

// Appends the ARPAbet phonemes of one word, given as espeak mnemonics (stress marks ' , % = may
// prefix a mnemonic). Pauses and markers (_:, ;, ||, ...) are ignored; a mnemonic with no English
// equivalent (e.g. from a foreign letter name) is counted in `skipped` and left out.
void appendArpabetForEspeakWord(std::span<const std::string_view> mnemonics, std::vector<std::string>& out,
                                std::map<std::string, std::size_t>& skipped);

// The same for IPA output of a non-English voice: stress marks are removed, each remaining
// symbol (with its length mark or diacritics) is kept as the phoneme's name.
void appendIpaForEspeakWord(std::span<const std::string_view> symbols, std::vector<std::string>& out);

} // namespace vl
