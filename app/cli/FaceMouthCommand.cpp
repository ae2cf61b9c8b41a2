// `visemelab face mouth MESH... [--neutral N] [--json OUT]`: the mouth of viseme meshes of a face (as
// `visemelab visemes` writes them) measured: lip opening at the midline (and half and three quarters
// of the way to the corners: the outline), mouth width, how far the lips stand forward, the teeth and tongue
// seen from the front, the lower lip's distance to the upper incisors; with --neutral, each relative to the
// neutral face. A Markdown table on stdout.
#include "app/cli/Command.h"
#include "core/common/AtomicFile.h"
#include "core/face/MouthMeasures.h"
#include "core/io/MeshIO.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vl::cli {

namespace {

struct FaceMouthCliOptions {
    std::vector<std::string> meshes;
    std::string neutral;
    std::string json;
};

nlohmann::json toJson(const face::MouthMeasures& m) {
    const auto point = [](const Vec3& p) { return nlohmann::json::array({p[0], p[1], p[2]}); };
    nlohmann::json j;
    j["opening"] = m.opening;
    j["opening_profile"] = nlohmann::json::array();
    for (std::size_t k = 0; k < m.openingProfile.size(); ++k)
        j["opening_profile"].push_back({{"at", face::kOpeningProfileAt[k]}, {"height", m.openingProfile[k]}});
    j["lip_distance"] = m.lipDistance;
    j["width"] = m.width;
    j["upper_lip_front"] = m.upperLipFront;
    j["lower_lip_front"] = m.lowerLipFront;
    j["upper_teeth_seen"] = m.upperTeethSeen;
    j["lower_teeth_seen"] = m.lowerTeethSeen;
    j["tongue_seen"] = m.tongueSeen;
    const auto optional = [](const std::optional<double>& v) {
        return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
    };
    j["teeth_gap"] = optional(m.teethGap);
    j["tongue_ahead_of_teeth"] = optional(m.tongueAhead);
    j["lower_lip_to_upper_teeth"] = optional(m.lowerLipToUpperTeeth);
    j["landmarks"] = {{"mouth_corner_right", point(m.cornerRight)},
                      {"mouth_corner_left", point(m.cornerLeft)},
                      {"upper_lip_mid", point(m.upperLip)},
                      {"lower_lip_mid", point(m.lowerLip)}};
    return j;
}

std::string number(double value, int decimals = 2) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    const std::string s = text;
    return s.find_first_not_of("-0.") == std::string::npos ? s.substr(s[0] == '-' ? 1 : 0) : s; // no "-0.00"
}

std::string signedNumber(double value) {
    const std::string s = number(value);
    return s[0] == '-' || s.find_first_not_of("0.") == std::string::npos ? s : "+" + s;
}

int runFaceMouth(const FaceMouthCliOptions& o) {
    std::optional<face::MouthMeasures> neutral;
    if (!o.neutral.empty()) neutral = face::measureMouth(readMesh(o.neutral), o.neutral);
    nlohmann::json report;
    report["units"] = "the meshes' units (centimetres for the bundled faces); areas in squared units";
    if (neutral) report["neutral"] = toJson(*neutral);
    std::printf("| mesh | opening | Δ opening | opening at ½ | opening at ¾ | width | width / neutral | "
                "upper lip forward | lower lip forward "
                "| teeth apart | upper teeth seen | lower teeth seen | tongue seen | tongue ahead of teeth "
                "| lower lip to upper incisors |\n|---");
    for (int k = 0; k < 14; ++k) std::printf("|---:");
    std::printf("|\n");
    const auto row = [&](const std::string& name, const face::MouthMeasures& m) {
        const auto relative = [&](double value, double base) {
            return neutral ? signedNumber(value - base) : std::string("-");
        };
        const auto optional = [](const std::optional<double>& v) {
            return v ? number(*v) : std::string("-");
        };
        const std::string cells[] = {name,
                                     number(m.opening),
                                     relative(m.opening, neutral ? neutral->opening : 0.0),
                                     number(m.openingProfile[2]),
                                     number(m.openingProfile[3]),
                                     number(m.width),
                                     neutral ? number(m.width / neutral->width) : "-",
                                     relative(m.upperLipFront, neutral ? neutral->upperLipFront : 0.0),
                                     relative(m.lowerLipFront, neutral ? neutral->lowerLipFront : 0.0),
                                     optional(m.teethGap),
                                     number(m.upperTeethSeen),
                                     number(m.lowerTeethSeen),
                                     number(m.tongueSeen),
                                     optional(m.tongueAhead),
                                     optional(m.lowerLipToUpperTeeth)};
        for (const auto& cell : cells) std::printf("| %s ", cell.c_str());
        std::printf("|\n");
    };
    if (neutral) row("(neutral)", *neutral);
    report["meshes"] = nlohmann::json::array();
    for (const auto& file : o.meshes) {
        const face::MouthMeasures m = face::measureMouth(readMesh(file), file);
        const std::string name = std::filesystem::path(file).stem().string();
        row(name, m);
        nlohmann::json j = toJson(m);
        j["name"] = name;
        j["file"] = file;
        if (neutral)
            j["relative_to_neutral"] = {{"opening", m.opening - neutral->opening},
                                        {"width_ratio", m.width / neutral->width},
                                        {"upper_lip_forward", m.upperLipFront - neutral->upperLipFront},
                                        {"lower_lip_forward", m.lowerLipFront - neutral->lowerLipFront}};
        report["meshes"].push_back(std::move(j));
    }
    if (!o.json.empty()) {
        writeFileAtomically(o.json, report.dump(2) + "\n");
        std::fprintf(stderr, "wrote %s\n", o.json.c_str());
    }
    return kExitOk;
}

} // namespace

void addFaceMouthCommand(CLI::App& face, CommandRunner& run) {
    auto o = std::make_shared<FaceMouthCliOptions>();
    auto* cmd = face.add_subcommand(
        "mouth", "Measure the mouth of viseme meshes (as `visemes` writes them): lip opening, width, lips "
                 "forward, teeth and tongue seen from the front");
    cmd->add_option("meshes", o->meshes, "Viseme meshes of one face (OBJ, PLY, VRML with (u,v))")->required();
    cmd->add_option("--neutral", o->neutral, "The neutral mesh: report each mesh relative to it");
    cmd->add_option("--json", o->json, "Write the measures as JSON");
    cmd->callback([&run, o] { run = [o] { return runFaceMouth(*o); }; });
}

} // namespace vl::cli
