// The bundled ARPAbet parameter set (assets/phonemes/arpabet_face.json) on the bundled face: it loads,
// names exactly the phonemes of the bundled en-us table, and each phoneme's mouth shape has the
// articulation phonetics gives it, measured on the generated face and head parts (lip gap, mouth
// width, lip protrusion, lower lip against the upper teeth, tongue tip).
#include "core/common/Error.h"
#include "core/face/BundledFace.h"
#include "core/face/HeadParts.h"
#include "core/face/Landmarks.h"
#include "core/import/VisemeFile.h"
#include "core/reduce/Frequencies.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace vl {
namespace {

const std::filesystem::path kAssets = VISEMELAB_ASSETS_DIR;

// What a phoneme's mouth looks like, in centimetres.
struct Mouth {
    double lipGap = 0;          // inner lip contour: upper lip middle above the lower lip middle
    double width = 0;           // mouth corner to mouth corner
    double protrusion = 0;      // lip middles forward (z)
    double aperture = 0;        // area of the lip opening, as an ellipse of lipGap x width
    double lowerLipBack = 0;    // lower lip middle behind the upper lip middle (z)
    double lipToUpperTeeth = 0; // lower lip middle to the nearest vertex of the upper incisors
    double tongueTipY = 0;      // the tongue's foremost point: height
    double tongueTipZ = 0;      // and how far forward
    double upperTeethFrontZ = 0;
};

class ArpabetFace : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        face_ = face::makeBundledFace();
        visemes_ = bundledVisemeSet("arpabet", kAssets, face_);
        parts_ = face::makeHeadParts(face_);
        for (const auto& v : visemes_) mouths_[v.name] = measure(parameterVector(face_, v));
        neutral_ = measure(face_.defaults());
    }

    static Mouth measure(const std::vector<double>& q) {
        const auto at = [&](face::Landmark l) {
            const Vec2 uv = face::canonicalPosition(l);
            return face_.evaluate(uv[0], uv[1], q);
        };
        const Vec3 upper = at(face::Landmark::UpperLipMid), lower = at(face::Landmark::LowerLipMid);
        Mouth m;
        m.lipGap = upper[1] - lower[1];
        m.width = (at(face::Landmark::MouthCornerLeft) - at(face::Landmark::MouthCornerRight)).norm();
        m.protrusion = 0.5 * (upper[2] + lower[2]);
        m.aperture = M_PI / 4 * std::max(0.0, m.lipGap) * m.width;
        m.lowerLipBack = upper[2] - lower[2];
        const face::HeadPartsSampler sampler(face_, parts_);
        const std::vector<Vec3> points = sampler.evaluate(q);
        std::size_t first = 0;
        m.lipToUpperTeeth = 1e9;
        m.upperTeethFrontZ = -1e9;
        m.tongueTipZ = -1e9;
        for (const auto& part : parts_) {
            const std::size_t count = part.rest.positions.size();
            for (std::size_t i = first; i < first + count; ++i) {
                const Vec3& p = points[i];
                if (part.name == "teeth_upper" && std::abs(p[0]) < 0.8) { // the central incisors
                    m.lipToUpperTeeth = std::min(m.lipToUpperTeeth, (p - lower).norm());
                    m.upperTeethFrontZ = std::max(m.upperTeethFrontZ, p[2]);
                }
                if (part.name == "tongue" && p[2] > m.tongueTipZ) {
                    m.tongueTipZ = p[2];
                    m.tongueTipY = p[1];
                }
            }
            first += count;
        }
        return m;
    }

    static const Mouth& of(const std::string& name) {
        const auto it = mouths_.find(name);
        if (it == mouths_.end()) throw std::runtime_error("no phoneme " + name);
        return it->second;
    }

    static inline DeformationCascade face_;
    static inline std::vector<VisemeParameters> visemes_;
    static inline std::vector<face::HeadPart> parts_;
    static inline std::map<std::string, Mouth> mouths_;
    static inline Mouth neutral_;
};

const std::vector<std::string> kBilabial{"P", "B", "M"};
const std::vector<std::string> kLabiodental{"F", "V"};
const std::vector<std::string> kDental{"TH", "DH"};
const std::vector<std::string> kAlveolar{"T", "D", "N", "L"};
const std::vector<std::string> kRounded{"UW", "UH", "OW", "W", "ER", "R", "SH", "ZH", "CH", "JH"};
const std::vector<std::string> kSpread{"IY", "IH", "EY", "Y", "S", "Z"};
const std::vector<std::string> kCloseVowels{"IY", "IH", "UW", "UH"};
const std::vector<std::string> kOpenVowels{"AA", "AE", "AH", "AO", "AW", "AY"};

bool in(const std::vector<std::string>& list, const std::string& name) {
    return std::find(list.begin(), list.end(), name) != list.end();
}

TEST_F(ArpabetFace, NamesExactlyThePhonemesOfTheBundledTable) {
    const FrequencySource table = loadFrequencyFile(kAssets / "phonemes" / "en-us_frequencies.csv");
    std::set<std::string> phonemes, names;
    for (const auto& [name, count] : table.visemeFrequencies.entries) phonemes.insert(name);
    for (const auto& v : visemes_) names.insert(v.name);
    EXPECT_EQ(visemes_.size(), 40u); // no repeats
    EXPECT_EQ(names, phonemes);
    EXPECT_EQ(phonemes.size(), 40u); // the 39 ARPAbet phonemes and the pause
    EXPECT_TRUE(names.count("sil"));
    // The pause is the rest face; every phoneme moves it.
    for (const auto& v : visemes_) {
        EXPECT_NO_THROW(checkParameterValues(face_, parameterVector(face_, v))) << v.name;
        if (v.name == "sil")
            EXPECT_TRUE(v.values.empty());
        else
            EXPECT_FALSE(v.values.empty()) << v.name;
    }
}

TEST_F(ArpabetFace, TheDocumentedTableIsTheFile) {
    // docs/deformable-face.md lists every phoneme's parameters ("risorius 0.3" for both sides).
    std::ifstream in(kAssets.parent_path() / "docs" / "deformable-face.md");
    ASSERT_TRUE(in) << "docs/deformable-face.md not found";
    std::map<std::string, std::map<std::string, double>> documented;
    bool inSection = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("## ", 0) == 0) inSection = line == "## The ARPAbet phoneme set";
        if (!inSection || line.rfind("| ", 0) != 0 || line.rfind("| phoneme", 0) == 0 ||
            line.rfind("| ---", 0) == 0)
            continue;
        std::vector<std::string> cells;
        std::stringstream row(line.substr(2));
        for (std::string cell; std::getline(row, cell, '|');)
            cells.push_back(cell.substr(0, cell.find_last_not_of(' ') + 1));
        ASSERT_GE(cells.size(), 4u) << line;
        std::map<std::string, double> values;
        std::stringstream list(cells[3]);
        for (std::string item; std::getline(list, item, ',');) {
            std::stringstream words(item);
            std::string name;
            double value = 0;
            if (!(words >> name >> value)) continue; // "(neutral)"
            if (face_.findParameter(name) < 0) {
                values[name + "_l"] = value;
                values[name + "_r"] = value;
            } else {
                values[name] = value;
            }
        }
        documented[cells[0].substr(cells[0].find_first_not_of(' '))] = values;
    }
    ASSERT_EQ(documented.size(), visemes_.size());
    for (const auto& v : visemes_) {
        const std::map<std::string, double> values(v.values.begin(), v.values.end());
        EXPECT_EQ(documented[v.name], values) << v.name;
    }
}

TEST_F(ArpabetFace, UnknownSetNamesTheValidOnes) {
    try {
        bundledVisemeSet("ipa", kAssets, face_, "--set");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown viseme set 'ipa' (valid: oculus, arpabet)"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_EQ(bundledVisemeSet("oculus", kAssets, face_), oculusVisemes());
}

TEST_F(ArpabetFace, BilabialsCloseTheLips) {
    // The rest face's lips almost touch (0.06 cm); P, B and M press them together.
    for (const auto& p : kBilabial) {
        EXPECT_LT(std::abs(of(p).lipGap), 0.02) << p;
        EXPECT_LT(of(p).aperture, 0.05) << p;
    }
    // Every other phoneme but the rest parts them.
    for (const auto& [name, m] : mouths_)
        if (!in(kBilabial, name) && name != "sil") {
            EXPECT_GT(m.lipGap, 0.15) << name;
        }
}

TEST_F(ArpabetFace, RoundedPhonemesNarrowTheMouthAndSpreadOnesWidenIt) {
    for (const auto& p : kRounded) {
        EXPECT_LT(of(p).width, neutral_.width - 0.2) << p;
        EXPECT_GT(of(p).protrusion, neutral_.protrusion + 0.1) << p;
    }
    for (const auto& p : kSpread) EXPECT_GT(of(p).width, neutral_.width + 0.2) << p;
    EXPECT_LT(of("UW").width, of("UH").width);
    EXPECT_LT(of("UW").width, of("OW").width);
    EXPECT_GT(of("UW").protrusion, of("IY").protrusion + 0.3);
}

TEST_F(ArpabetFace, OpenVowelsAreMoreOpenThanCloseOnes) {
    // The lip opening of every open vowel is larger than that of any close vowel (a rounded UW has a
    // tall but narrow opening, so area, not height, is compared).
    double smallestOpen = 1e9;
    for (const auto& v : kOpenVowels) smallestOpen = std::min(smallestOpen, of(v).aperture);
    for (const auto& v : kCloseVowels) EXPECT_LT(of(v).aperture, smallestOpen) << v;
    // Front vowels by height: AA (open) > AE > EH > IH > IY (close).
    const std::vector<std::string> byHeight{"AA", "AE", "EH", "IH", "IY"};
    for (std::size_t k = 0; k + 1 < byHeight.size(); ++k)
        EXPECT_GT(of(byHeight[k]).lipGap, of(byHeight[k + 1]).lipGap) << byHeight[k];
    EXPECT_GT(of("AA").lipGap, of("IY").lipGap + 1.0);
}

TEST_F(ArpabetFace, LabiodentalsBringTheLowerLipToTheUpperTeeth) {
    // F and V: the lower lip at the upper incisors with the lips apart (air passes between lip and
    // teeth). The bilabials' pressed lips also roll against the teeth, but with the lips closed.
    for (const auto& p : kLabiodental) {
        EXPECT_LT(of(p).lipToUpperTeeth, 0.25) << p;
        EXPECT_LT(of(p).lipToUpperTeeth, 0.5 * neutral_.lipToUpperTeeth) << p;
        EXPECT_GT(of(p).lipGap, 0.15) << p;
    }
    for (const auto& [name, m] : mouths_)
        if (!in(kLabiodental, name) && !in(kBilabial, name)) {
            EXPECT_GT(m.lipToUpperTeeth, 0.5) << name;
        }
}

TEST_F(ArpabetFace, DentalsPutTheTongueTipAtTheTeethAndAlveolarsRaiseIt) {
    for (const auto& p : kDental) EXPECT_GT(of(p).tongueTipZ, of(p).upperTeethFrontZ - 0.1) << p;
    for (const auto& [name, m] : mouths_)
        if (!in(kDental, name)) {
            EXPECT_LT(m.tongueTipZ, m.upperTeethFrontZ - 0.3) << name;
        }
    // The tip rises to the ridge for the alveolars, and stays low for the bilabials and open vowels.
    for (const auto& p : kAlveolar) EXPECT_GT(of(p).tongueTipY, neutral_.tongueTipY + 0.5) << p;
    for (const auto& p : kBilabial) EXPECT_LT(of(p).tongueTipY, neutral_.tongueTipY + 0.1) << p;
}

TEST_F(ArpabetFace, VoicedAndVoicelessPairsLookAlike) {
    // Voicing is invisible: each pair is closer than either member is to any phoneme of another place
    // of articulation (measured on the mouth features, centimetres).
    const auto distance = [](const Mouth& a, const Mouth& b) {
        return std::hypot(a.lipGap - b.lipGap, a.width - b.width, a.protrusion - b.protrusion) +
               std::abs(a.lipToUpperTeeth - b.lipToUpperTeeth) + std::abs(a.tongueTipY - b.tongueTipY) +
               std::abs(a.tongueTipZ - b.tongueTipZ);
    };
    struct Pair {
        std::string voiceless, voiced;
        std::vector<std::string> place; // the phonemes of the same place of articulation
    };
    const std::vector<Pair> pairs{{"P", "B", kBilabial},
                                  {"F", "V", kLabiodental},
                                  {"TH", "DH", kDental},
                                  {"T", "D", kAlveolar},
                                  {"S", "Z", {"S", "Z"}},
                                  {"SH", "ZH", {"SH", "ZH", "CH", "JH"}},
                                  {"CH", "JH", {"SH", "ZH", "CH", "JH"}},
                                  {"K", "G", {"K", "G", "NG"}}};
    for (const auto& pair : pairs) {
        const double within = distance(of(pair.voiceless), of(pair.voiced));
        for (const auto& [name, m] : mouths_) {
            if (in(pair.place, name)) continue;
            EXPECT_LT(within, distance(of(pair.voiceless), m)) << pair.voiceless << " vs " << name;
            EXPECT_LT(within, distance(of(pair.voiced), m)) << pair.voiced << " vs " << name;
        }
    }
}

} // namespace
} // namespace vl
