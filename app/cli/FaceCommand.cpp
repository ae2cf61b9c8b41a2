// `visemelab face build MESH [--landmarks L.json] --out face.vlproj`: the user's own face as the
// deformable model. Finds (or reads) the landmarks, says which it found and how sure, samples the
// mesh over the face domain, carries the bundled fields over, and writes a project with the face and
// its viseme set (ready for refine, visemes and export).
#include "app/cli/Command.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/document/OwnFace.h"
#include "core/face/FaceBuild.h"
#include "core/face/FaceDomain.h"
#include "core/face/LandmarkFinder.h"
#include "core/io/MeshIO.h"
#include "core/project/FaceProject.h"
#include "core/project/LandmarksJson.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace vl::cli {

namespace {

struct FaceBuildCliOptions {
    std::string mesh;
    std::string landmarks;
    std::string out;
    std::string landmarksOut;
    std::string report;
    std::string name;
    int grid = 257;
    int resolution = 38;
    bool ignoreLayout = false;
    bool acceptEstimates = false;
};

face::FaceLandmarks givenLandmarks(const face::UvMesh& mesh, const std::string& file) {
    face::FaceLandmarks given;
    if (file.empty()) return given;
    for (const auto& [landmark, input] : readLandmarkFile(file)) {
        const std::string where = file + ": " + std::string(toString(landmark));
        given[landmark] =
            face::resolveLandmark(mesh, input, face::LandmarkSource::File, 1.0,
                                  "given in " + std::filesystem::path(file).filename().string(), where);
    }
    return given;
}

void printLandmarks(const face::FaceLandmarks& landmarks) {
    std::printf("landmarks:\n");
    for (const auto l : face::allLandmarks()) {
        const auto& f = landmarks[l];
        if (!f.found()) {
            std::printf("  %-19s %-8s %s\n", std::string(toString(l)).c_str(), "missing",
                        face::isRequired(l) ? "(required)" : "(optional)");
            continue;
        }
        std::printf("  %-19s %-8s sure %3.0f%%  uv (%.4f, %.4f)  %s\n", std::string(toString(l)).c_str(),
                    std::string(face::sourceName(f.source)).c_str(), 100.0 * f.confidence, f.uv[0], f.uv[1],
                    f.method.c_str());
    }
}

void printReport(const face::FaceBuildReport& r) {
    std::size_t used = 0, notJoined = 0, overlapping = 0;
    std::string usedText;
    for (std::size_t k = 0; k < r.islands.size(); ++k) {
        const auto& is = r.islands[k];
        if (is.used) {
            ++used;
            usedText += "  island " + std::to_string(k) + ": " + std::to_string(is.island.triangles) +
                        " triangles, " + is.reason + "\n";
        } else if (is.reason.find("overlapping") != std::string::npos) {
            ++overlapping;
        } else {
            ++notJoined;
        }
    }
    std::printf("UV islands: %zu used of %zu\n%s", used, r.islands.size(), usedText.c_str());
    if (overlapping + notJoined > 0)
        std::printf("  not used: %zu not joined to the face, %zu overlapping it in (u,v)\n", notJoined,
                    overlapping);
    if (r.droppedTriangles > 0) std::printf("  %zu triangles without (u,v) ignored\n", r.droppedTriangles);
    if (!r.holes.empty()) {
        std::printf("holes filled:");
        for (const auto& h : r.holes) std::printf(" %s", h.role.c_str());
        std::printf("\n");
    }
    std::printf(
        "face size: %.4g mesh units per bundled-face cm (eye distance %.4g, eyes to mouth %.4g): fields "
        "scaled by it\n",
        r.scale, r.frame.eyeDistance, r.frame.eyeMouthDistance);
    std::printf("orientation: right (%.3f, %.3f, %.3f), up (%.3f, %.3f, %.3f), forward (%.3f, %.3f, %.3f)\n",
                r.frame.right[0], r.frame.right[1], r.frame.right[2], r.frame.up[0], r.frame.up[1],
                r.frame.up[2], r.frame.forward[0], r.frame.forward[1], r.frame.forward[2]);
    std::printf("coverage: the mesh covers %.0f%% of the face domain; %.0f%% is drawn in from the border\n",
                100.0 * r.domainCoverage, 100.0 * r.retracted);
    for (const auto& w : r.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
}

nlohmann::json reportJson(const face::BuiltFace& built, const std::string& layout) {
    const auto& r = built.report;
    nlohmann::json j;
    j["layout"] = layout;
    for (const auto l : face::allLandmarks()) {
        const auto& f = built.landmarks[l];
        nlohmann::json e{{"source", face::sourceName(f.source)}};
        if (f.found()) {
            e["uv"] = {f.uv[0], f.uv[1]};
            e["position"] = {f.position[0], f.position[1], f.position[2]};
            e["confidence"] = f.confidence;
            e["method"] = f.method;
            e["island"] = f.island;
        }
        j["landmarks"][std::string(toString(l))] = e;
    }
    for (std::size_t k = 0; k < r.islands.size(); ++k) {
        const auto& is = r.islands[k];
        j["islands"].push_back({{"index", k},
                                {"used", is.used},
                                {"reason", is.reason},
                                {"triangles", is.island.triangles},
                                {"area", is.island.area},
                                {"landmarks", is.landmarks},
                                {"uv_min", {is.island.uvMin[0], is.island.uvMin[1]}},
                                {"uv_max", {is.island.uvMax[0], is.island.uvMax[1]}}});
    }
    for (const auto& h : r.holes) j["holes_filled"].push_back({{"role", h.role}, {"cells", h.cells}});
    j["dropped_triangles"] = r.droppedTriangles;
    j["scale"] = r.scale;
    j["eye_distance"] = r.frame.eyeDistance;
    j["eye_mouth_distance"] = r.frame.eyeMouthDistance;
    j["frame"] = {{"right", {r.frame.right[0], r.frame.right[1], r.frame.right[2]}},
                  {"up", {r.frame.up[0], r.frame.up[1], r.frame.up[2]}},
                  {"forward", {r.frame.forward[0], r.frame.forward[1], r.frame.forward[2]}}};
    j["domain_coverage"] = r.domainCoverage;
    j["retracted"] = r.retracted;
    j["closed_gap"] = r.closedGap;
    j["folded_samples"] = r.foldedSamples;
    j["filled_samples"] = r.filledSamples;
    j["warnings"] = r.warnings;
    return j;
}

int runFaceBuild(const FaceBuildCliOptions& o) {
    const std::filesystem::path out = o.out;
    if (out.extension() != ".vlproj") throwInputError("--out", "expected a .vlproj project file");
    const std::filesystem::path meshPath = o.mesh;
    for (const auto& [flag, path] :
         {std::pair{"--out", o.out}, {"--landmarks-out", o.landmarksOut}, {"--report", o.report}})
        if (!path.empty() && std::filesystem::exists(path) &&
            (std::filesystem::equivalent(path, meshPath) ||
             (!o.landmarks.empty() && std::filesystem::exists(o.landmarks) &&
              std::filesystem::equivalent(path, o.landmarks))))
            throwUsage(std::string(flag) + " would overwrite an input file");

    const face::UvMesh mesh = loadUvMeshFile(meshPath);
    std::printf("face build: %s (%zu vertices, %zu triangles with (u,v), %zu UV islands)\n", o.mesh.c_str(),
                mesh.positions.size(), mesh.triangles.size(), mesh.islandCount);
    const face::FaceLandmarks given = givenLandmarks(mesh, o.landmarks);
    const face::LandmarkSuggestion suggestion = face::suggestLandmarks(mesh, given, !o.ignoreLayout);
    for (const auto& note : suggestion.notes) std::fprintf(stderr, "%s\n", note.c_str());
    printLandmarks(suggestion.landmarks);
    if (!suggestion.landmarks.hasRequired()) {
        std::string missing;
        for (const auto l : face::allLandmarks())
            if (face::isRequired(l) && !suggestion.landmarks[l].found())
                missing += (missing.empty() ? "" : ", ") + std::string(toString(l));
        throwInputError(o.mesh, "could not find the landmarks " + missing +
                                    ": give them with --landmarks L.json (see docs/deformable-face.md)");
    }
    if (const auto estimated = face::estimatedMouthLandmarks(suggestion.landmarks);
        !estimated.empty() && !o.acceptEstimates) {
        // The guesses are written for editing, then the build stops rather than animate the wrong place.
        if (!o.landmarksOut.empty())
            writeFileAtomically(o.landmarksOut, landmarksToJsonText(suggestion.landmarks));
        std::string names;
        double sure = 1.0;
        for (const auto l : estimated) {
            names += (names.empty() ? "" : ", ") + std::string(toString(l));
            sure = std::min(sure, suggestion.landmarks[l].confidence);
        }
        throwInputError(
            o.mesh, "found no mouth (no opening, no groove between the lips): " + names +
                        " are only estimated from the face's proportions (" +
                        std::to_string(static_cast<int>(100.0 * sure + 0.5)) +
                        "% sure). Check them (--landmarks-out writes them) and give them with --landmarks "
                        "L.json, or pass --accept-estimates to build on the estimates");
    }

    face::FaceBuildOptions options;
    options.gridSize = o.grid;
    options.name = o.name.empty() ? meshPath.stem().string() : o.name;
    const face::BuiltFace built = face::buildFace(mesh, suggestion.landmarks, options);
    printReport(built.report);

    const MeshData domain = face::faceDomainMesh(o.resolution, face::DomainDensity::MouthFocused);
    Project project = makeFaceProject(built.cascade, domain, oculusVisemes(), built.report.scale);
    project.path = out;
    saveProject(out, project);
    if (!o.landmarksOut.empty()) writeFileAtomically(o.landmarksOut, landmarksToJsonText(built.landmarks));
    if (!o.report.empty()) writeFileAtomically(o.report, reportJson(built, suggestion.layout).dump(2) + "\n");
    std::fprintf(stderr, "wrote %s: face '%s', %zu visemes on %zu vertices\n", o.out.c_str(),
                 options.name.c_str(), project.visemes.size(), project.neutral.embedded.positions.size());
    return kExitOk;
}

} // namespace

void addFaceCommand(CLI::App& app, CommandRunner& run) {
    auto* cmd = app.add_subcommand("face", "Your own face as the deformable model");
    cmd->require_subcommand(1, 1);
    auto o = std::make_shared<FaceBuildCliOptions>();
    auto* build = cmd->add_subcommand(
        "build", "Build a deformable face from a mesh with (u,v) on the face (OBJ, PLY, VRML, glb/glTF)");
    build->add_option("mesh", o->mesh, "The face or head mesh")->required()->check(CLI::ExistingFile);
    build
        ->add_option("--landmarks", o->landmarks,
                     "Landmark file (JSON); landmarks it leaves out are found automatically")
        ->check(CLI::ExistingFile);
    build->add_option("--out", o->out, "Project file to write (.vlproj)")->required();
    build->add_option("--landmarks-out", o->landmarksOut,
                      "Write the landmarks used (edit and pass back with --landmarks)");
    build->add_option("--report", o->report,
                      "Write a JSON report (landmarks, islands, holes, scale, coverage)");
    build->add_option("--name", o->name, "Name of the face (default: the mesh file's name)");
    build->add_option("--grid", o->grid, "Samples per side of the base geometry image (17..2049)")
        ->capture_default_str();
    build
        ->add_option("--resolution", o->resolution, "Grid cells across the face domain for the viseme meshes")
        ->capture_default_str();
    build->add_flag("--accept-estimates", o->acceptEstimates,
                    "Build even when the mouth is only estimated from the face's proportions");
    build->add_flag("--ignore-layout", o->ignoreLayout,
                    "Find landmarks from the geometry even on a known layout (to compare the two)");
    build->callback([&run, o] { run = [o] { return runFaceBuild(*o); }; });
    addFaceMouthCommand(*cmd, run);
}

} // namespace vl::cli
