#pragma once
// The phoneme -> viseme map editor: a document's visemes (whatever their names, e.g. the ICT mouth
// shapes) get phoneme-derived frequencies by starting from a map (a bundled one, a file, or one
// row per phoneme) whose visemes are each assigned to a viseme of the set, then by editing the map
// phoneme by phoneme (edit::setPhonemeViseme). The document never holds an unmapped phoneme (the
// reduction needs every one): what is still unassigned lives in the assignment until it is applied.
#include "core/document/Document.h"

#include <string>
#include <string_view>
#include <vector>

namespace vl::edit {

// The start map's name for the table's phonemes it does not list (a row of the assignment).
inline constexpr std::string_view kPhonemesNotInMap = "(not in the map)";

// One viseme of the start map (or kPhonemesNotInMap) and the viseme of the set it becomes.
struct MapAssignment {
    std::string from;
    std::vector<std::string> phonemes; // the table's phonemes it maps, in table order
    double share = 0.0;                // their share of the table's total
    std::string to;                    // a viseme of the set; empty = not assigned yet
    bool operator==(const MapAssignment&) const = default;
};

// The assignment of `start`'s visemes (in order of first appearance, then kPhonemesNotInMap when
// some phoneme of `table` is not listed): each goes to the set's viseme of the same name, else of
// the same name ignoring case, else to the viseme the document's current phoneme map gives most of
// its phonemes' frequency, else nowhere yet. Visemes of the map no phoneme of the table uses are
// left out.
std::vector<MapAssignment> suggestMapAssignment(const Document& document, const FrequencyTable& table,
                                                const PhonemeVisemeMap& start);

// The frequencies become `table` with the map `start` translated by `assignment` (rows with an
// empty `to` or a `to` outside the set are refused, naming their phonemes).
Document startPhonemeMap(const Document& document, FrequencyTable table, const PhonemeVisemeMap& start,
                         const std::vector<MapAssignment>& assignment);

// A map that sends each phoneme of `table` to a viseme of its own name (an assignment per phoneme).
PhonemeVisemeMap phonemePerVisemeMap(const FrequencyTable& table);

// Every phoneme mapped to viseme `from` maps to `to` afterwards (phoneme-based frequencies only).
Document movePhonemes(const Document& document, const std::string& from, const std::string& to);

// The viseme frequencies as they are now (normalised) become a direct table: the phoneme table and
// the map are dropped.
Document useDirectFrequencies(const Document& document);

// What the map makes of each viseme of the set (phoneme-based frequencies; empty lists otherwise).
struct MapCoverage {
    std::vector<std::vector<std::string>> phonemesOf; // per viseme, in table order
    std::vector<double> share;                        // per viseme: its phonemes' share of the table
    std::vector<int> visemesWithoutPhoneme;           // their frequency is 0
};
MapCoverage mapCoverage(const Document& document);

// The phonemes of `source` mapped to `viseme`, in table order.
std::vector<std::string> phonemesMappedTo(const FrequencySource& source, const std::string& viseme);
// "P, B, M (6.9 % of the phonemes)" for a message.
std::string phonemeList(const FrequencySource& source, const std::vector<std::string>& phonemes);

} // namespace vl::edit
