// `visemelab visemes`: writes the interpolable viseme set of a bundled deformable face (neutral +
// the 15 Oculus visemes, the 39 ARPAbet phonemes and sil of --set arpabet, or those of --viseme-file,
// as OBJ) and visemes.json with the names and parameter vectors.
#include "app/cli/Command.h"
#include "app/cli/CriterionOptions.h"
#include "core/adaptive/CascadeSurface.h"
#include "core/common/Error.h"
#include "core/common/OutputSet.h"
#include "core/deform/Visemes.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"
#include "core/face/HeadParts.h"
#include "core/import/VisemeFile.h"
#include "core/io/MeshIO.h"
#include "core/project/Project.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace vl::cli {

namespace {

struct VisemesOptions {
    std::string face = "bundled";
    std::string project; // a project's deformable face instead of a bundled one
    std::string outDir = "visemes";
    int resolution = 38;
    std::string density = "mouth";
    CriterionOptions adaptive; // --criterion given: adaptive refinement instead of the grid
    int decimals = 6;
    std::string visemeFile; // empty: the 15 Oculus visemes
    std::string set;        // a bundled parameter set (oculus, arpabet); empty: the default
    bool skinOnly = false;  // leave out the eyeballs, teeth, tongue and mouth cavity
};

// Rounds coordinates to `decimals` decimal places (file size: short numbers); < 0 keeps them exact.
void roundCoordinates(VisemeSet& set, int decimals) {
    if (decimals < 0) return;
    const double scale = std::pow(10.0, decimals);
    const auto round = [scale](double x) { return std::round(x * scale) / scale; };
    const auto roundAll = [&](std::vector<Vec3>& points) {
        for (auto& p : points) p = Vec3(round(p[0]), round(p[1]), round(p[2]));
    };
    roundAll(set.neutral.positions);
    for (auto& uv : set.neutral.uvs) uv = Vec2(round(uv[0]), round(uv[1]));
    for (auto& v : set.visemes) roundAll(v.positions);
}

// The (u,v) mesh every viseme is generated on. One place, so other ways of building it (adaptive
// refinement criteria) plug in here.
MeshData buildVisemeMesh(const VisemesOptions& o, const DeformationCascade& face,
                         const std::vector<VisemeParameters>& visemes) {
    if (!o.adaptive.criterion.empty()) {
        // Refined until the criterion holds for the neutral face and every viseme (one shared mesh).
        std::vector<std::vector<double>> poses{face.defaults()};
        for (const auto& v : visemes) poses.push_back(parameterVector(face, v));
        return refineFaceMesh(face, o.adaptive.baseResolution, criterionSettings(o.adaptive), poses);
    }
    face::DomainDensity density;
    if (o.density == "uniform")
        density = face::DomainDensity::Uniform;
    else if (o.density == "mouth")
        density = face::DomainDensity::MouthFocused;
    else
        throwInputError("--density", "unknown density '" + o.density + "' (expected uniform or mouth)");
    return face::faceDomainMesh(o.resolution, density);
}

nlohmann::json describe(const VisemesOptions& o, const DeformationCascade& face, const VisemeSet& set,
                        const std::vector<VisemeParameters>& visemes) {
    nlohmann::json j;
    j["face"] = o.project.empty() ? o.face : o.project;
    j["resolution"] = o.resolution;
    j["density"] = o.density;
    j["decimals"] = o.decimals;
    if (!o.adaptive.criterion.empty()) j["criterion"] = o.adaptive.criterion;
    j["vertices"] = set.vertexCount();
    j["triangles"] = set.neutral.triangles.size();
    j["neutral"] = "neutral.obj";
    for (const auto& p : face.parameters)
        j["parameters"].push_back(
            {{"name", p.name}, {"min", p.min}, {"max", p.max}, {"default", p.defaultValue}});
    for (const auto& v : visemes) {
        const auto q = parameterVector(face, v);
        nlohmann::json values = nlohmann::json::object();
        for (std::size_t k = 0; k < q.size(); ++k) values[face.parameters[k].name] = q[k];
        j["visemes"].push_back({{"name", v.name}, {"file", v.name + ".obj"}, {"parameters", values}});
    }
    return j;
}

int runVisemes(const VisemesOptions& o) {
    if (!o.set.empty() && !o.visemeFile.empty())
        throwUsage("use either --set NAME or --viseme-file FILE, not both");
    DeformationCascade cascade;
    std::vector<VisemeParameters> visemes;
    if (!o.project.empty()) {
        const Project project = loadProject(o.project);
        if (!project.deformation.isSet()) throwInputError(o.project, "the project has no deformable face");
        cascade = project.deformation.cascade;
        visemes = project.deformation.visemes.empty() ? oculusVisemes() : project.deformation.visemes;
    } else {
        cascade = face::makeFaceCascade(parseEnum<face::Individual>(o.face, "--face"));
        visemes = oculusVisemes();
    }
    if (!o.set.empty()) visemes = bundledVisemeSet(o.set, VISEMELAB_ASSETS_DIR, cascade, "--set");
    if (!o.visemeFile.empty()) visemes = readVisemeFile(o.visemeFile, cascade);
    const MeshData uvMesh = buildVisemeMesh(o, cascade, visemes);
    checkVisemeSetSize(visemes.size(), uvMesh.positions.size(),
                       o.visemeFile.empty() ? std::string("visemes") : o.visemeFile);
    if (o.decimals > 15) throwInputError("--decimals", "must be at most 15 (or negative for exact values)");
    const auto parts = o.skinOnly ? std::vector<face::HeadPart>{} : face::makeHeadParts(cascade);
    VisemeSet set = face::generateHeadVisemeSet(cascade, uvMesh, visemes, parts);
    roundCoordinates(set, o.decimals);

    const std::filesystem::path out = o.outDir;
    OutputSet files(out, "visemes"); // visemes of an earlier run that this one does not write are removed
    files.add("neutral.obj", formatObj(set.neutral));
    for (std::size_t k = 0; k < set.size(); ++k)
        files.add(set.visemes[k].name + ".obj", formatObj(set.meshOf(k)));
    files.add("visemes.json", describe(o, cascade, set, visemes).dump(2) + "\n");
    files.commit();
    std::fprintf(stderr, "wrote neutral + %zu visemes (%zu vertices, %zu triangles) to %s\n", set.size(),
                 set.vertexCount(), set.neutral.triangles.size(), out.string().c_str());
    return kExitOk;
}

} // namespace

void addVisemesCommand(CLI::App& app, CommandRunner& run) {
    auto options = std::make_shared<VisemesOptions>();
    auto* cmd =
        app.add_subcommand("visemes", "Write the interpolable viseme set of a bundled deformable face");
    cmd->add_option("--face", options->face, "Individual: bundled or retarget")->capture_default_str();
    cmd->add_option(
        "--project", options->project,
        "Use the deformable face and viseme parameter vectors of this project (e.g. from `face build`)");
    cmd->add_option("--out", options->outDir, "Output folder (neutral.obj, <viseme>.obj, visemes.json)")
        ->capture_default_str();
    cmd->add_option("--resolution", options->resolution, "Grid cells across the (u,v) domain (10..4096)")
        ->capture_default_str();
    cmd->add_option("--density", options->density,
                    "Grid line spacing: uniform, or mouth (denser at mouth and eyes)")
        ->capture_default_str();
    addCriterionOptions(cmd, options->adaptive);
    cmd->add_option(
        "--viseme-file", options->visemeFile,
        "JSON with the visemes' parameter vectors (the format of visemes.json; default: Oculus 15)");
    cmd->add_option(
        "--set", options->set,
        "Bundled parameter set: oculus (the 15 Oculus visemes, the default) or arpabet (sil and the 39 "
        "ARPAbet phonemes, named as in assets/phonemes/en-us_frequencies.csv)");
    cmd->add_flag("--skin-only", options->skinOnly,
                  "Only the face's skin: leave out the eyeballs, teeth, tongue and mouth cavity");
    cmd->add_option("--decimals", options->decimals,
                    "Round coordinates to this many decimals (centimetres; negative: exact doubles)")
        ->capture_default_str();
    cmd->callback([&run, options] { run = [options] { return runVisemes(*options); }; });
}

} // namespace vl::cli
