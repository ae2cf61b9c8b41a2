// The paper's validation, measured with VisemeLab's runtime: the unreduced viseme set (n key
// meshes) against the reduced one (m = 10) on a paper-sized face and on a large real mesh.
// Figures: package size, load time (runtime package, and the XfaceEd-style start-up that reads
// one VRML file per key mesh), heap memory of the loaded package, and keyframe-evaluation
// throughput (frames per second of a phoneme animation over all keys, linear and cubic).
//
// Data sets (each skipped with a message when its files are absent):
//  - sample: the bundled face's project assets/sample/sample.vlproj (its 16 visemes with its
//    phoneme frequencies and weights), n -> 10;
//  - synthetic: a 39 x 39 grid (1,521 vertices, 2,888 triangles: the paper's 3,000-triangle head)
//    with 16 random smooth visemes, always available;
//  - ict: ICT FaceKit (26,719 vertices, 52,220 triangles) from ../shared/data/ict-facekit-mouth:
//    its 7 mouth shapes plus 9 pairwise blends = 16 visemes, -> 10.
// For synthetic and ict, frequencies are equal (they change which visemes merge, not the runtime's
// costs) and weights uniform.
#include "core/export/Export.h"
#include "core/export/KeyMeshFiles.h"
#include "core/export/RuntimePackageWriter.h"
#include "core/io/MeshIO.h"
#include "core/io/VisemeSetFiles.h"
#include "core/project/Project.h"
#include "core/project/ProjectRun.h"
#include "core/reduce/Frequencies.h"
#include "core/reduce/ReducedModel.h"
#include "core/reduce/Reduction.h"
#include "core/runtime/Animation.h"

#include <benchmark/benchmark.h>
#include <malloc.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <random>

namespace {

namespace fs = std::filesystem;
using namespace vl;

constexpr int kTarget = 10;

struct Variant {
    std::string label; // e.g. "ict/reduced/float"
    fs::path package;
    fs::path vrmlDir; // one VRML file per key mesh plus the neutral
    std::size_t keys = 0;
};

struct Figures {
    std::string label;
    std::size_t keys = 0, vertices = 0, packageBytes = 0, heapBytes = 0, memoryBytes = 0;
};
std::vector<Figures> gFigures;

std::optional<Project> sampleProject() {
    const fs::path file = fs::path(VISEMELAB_ASSETS_DIR) / "sample" / "sample.vlproj";
    if (!fs::exists(file)) return std::nullopt;
    Project project = loadProject(file);
    project.reduction.target = kTarget;
    project.reduction.result.reset();
    return project;
}

VisemeSet syntheticSet() {
    VisemeSet set;
    set.neutral = [] {
        MeshData mesh;
        const int n = 39;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                mesh.positions.emplace_back(x / 38.0, y / 38.0, 0.1 * std::sin(x / 6.0) * std::cos(y / 5.0));
                mesh.uvs.emplace_back(x / 38.0, y / 38.0);
            }
        for (int y = 0; y + 1 < n; ++y)
            for (int x = 0; x + 1 < n; ++x) {
                const auto i = static_cast<std::uint32_t>(y * n + x);
                mesh.triangles.push_back({i, i + 1, i + n + 1});
                mesh.triangles.push_back({i, i + n + 1, i + n});
            }
        return mesh;
    }();
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int v = 0; v < 16; ++v) {
        // A smooth bump around a random centre: how a mouth shape moves a region.
        const Vec3 centre(0.5 + 0.2 * u(rng), 0.3 + 0.1 * u(rng), 0), direction(u(rng), u(rng), u(rng));
        Viseme viseme{"v" + std::to_string(v), set.neutral.positions};
        for (Vec3& p : viseme.positions) {
            const double d2 = (p - centre).sqrnorm();
            p += 0.05 * std::exp(-d2 / 0.02) * direction;
        }
        set.visemes.push_back(std::move(viseme));
    }
    return set;
}

std::optional<VisemeSet> ictSet() {
    const fs::path dir = fs::path(VISEMELAB_SHARED_DATA_DIR) / "ict-facekit-mouth";
    const char* shapes[] = {"jawOpen",        "mouthClose",   "mouthFunnel",   "mouthPucker",
                            "mouthRollLower", "mouthSmile_L", "mouthStretch_L"};
    if (!fs::exists(dir / "generic_neutral_mesh.obj")) return std::nullopt;
    std::vector<std::pair<std::string, fs::path>> files;
    for (const char* s : shapes) files.emplace_back(s, dir / (std::string(s) + ".obj"));
    VisemeSet set = loadVisemeSet(dir / "generic_neutral_mesh.obj", files);
    // Nine blends of two shapes (e.g. "O" = jawOpen + mouthFunnel) make a 16-viseme set.
    const int pairs[9][2] = {{0, 2}, {0, 3}, {0, 5}, {0, 6}, {1, 4}, {2, 5}, {3, 6}, {4, 5}, {1, 6}};
    for (const auto& pair : pairs) {
        const Viseme& a = set.visemes[static_cast<std::size_t>(pair[0])];
        const Viseme& b = set.visemes[static_cast<std::size_t>(pair[1])];
        Viseme blend{a.name + "&" + b.name, set.neutral.positions};
        for (std::size_t i = 0; i < blend.positions.size(); ++i)
            blend.positions[i] += 0.6 * (a.positions[i] - set.neutral.positions[i]) +
                                  0.6 * (b.positions[i] - set.neutral.positions[i]);
        set.visemes.push_back(std::move(blend));
    }
    return set;
}

// Bytes malloc has handed out, including the large blocks it maps separately.
std::size_t heapInUse() {
    const struct mallinfo2 info = mallinfo2();
    return info.uordblks + info.hblkhd;
}

void measure(const Variant& v) {
    runtime::Package package;
    std::string error;
    const std::size_t before = heapInUse();
    if (!package.loadFile(v.package.c_str(), error)) throw std::runtime_error(error);
    gFigures.push_back({v.label, v.keys, package.vertexCount(),
                        static_cast<std::size_t>(fs::file_size(v.package)), heapInUse() - before,
                        package.memoryBytes()});
}

void benchLoadPackage(benchmark::State& state, Variant v) {
    for (auto _ : state) {
        runtime::Package package;
        std::string error;
        if (!package.loadFile(v.package.c_str(), error)) state.SkipWithError(error.c_str());
        benchmark::DoNotOptimize(package.vertexCount());
    }
    state.counters["bytes"] = static_cast<double>(fs::file_size(v.package));
}

void benchLoadVrml(benchmark::State& state, Variant v) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(v.vrmlDir))
        if (isMeshFile(entry.path())) files.push_back(entry.path()); // not the export's manifest
    for (auto _ : state)
        for (const fs::path& f : files) benchmark::DoNotOptimize(readMesh(f).positions.data());
    state.counters["files"] = static_cast<double>(files.size());
}

void benchEvaluate(benchmark::State& state, Variant v, runtime::Interpolation interpolation) {
    runtime::Package package;
    std::string error;
    if (!package.loadFile(v.package.c_str(), error)) {
        state.SkipWithError(error.c_str());
        return;
    }
    // 400 phonemes, 80 ms apart, drawn from every phoneme of the package: every key is used.
    std::mt19937 rng(7);
    std::vector<runtime::Keyframe> keyframes;
    for (int i = 0; i < 400; ++i)
        keyframes.push_back(
            {0.08 * i, package.keyOfPhoneme(static_cast<std::uint32_t>(rng() % package.phonemeCount()))});
    runtime::KeyframeAnimation animation;
    if (!animation.setKeyframes(package, keyframes, interpolation, error)) {
        state.SkipWithError(error.c_str());
        return;
    }
    std::vector<float> out(3ull * package.vertexCount());
    double t = 0;
    for (auto _ : state) {
        animation.evaluate(t, out.data());
        benchmark::ClobberMemory();
        t += 1.0 / 60.0;
        if (t > animation.endTime()) t = 0;
    }
    state.counters["frames/s"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// Equal frequencies, uniform weights, n -> kTarget.
std::pair<ReducedModel, ReducedModel> fullAndReduced(const VisemeSet& set) {
    const std::vector<double> frequencies(set.size(), 1.0 / static_cast<double>(set.size()));
    FrequencySource source; // visemes stand for themselves as phonemes
    std::vector<std::vector<Vec3>> shapes;
    for (const Viseme& v : set.visemes) shapes.push_back(v.positions);
    const std::vector<double> weights(set.vertexCount(), 1.0);
    const ReductionResult result = reduceVisemes({shapes, frequencies, weights, kTarget});
    return {unreducedModel(set, frequencies, source),
            buildReducedModel(set, frequencies, result.groupOf(), source)};
}

void prepare(const std::string& name, const std::pair<ReducedModel, ReducedModel>& models,
             const fs::path& work, std::vector<Variant>& variants) {
    const ReducedModel& full = models.first;
    const ReducedModel& reduced = models.second;
    for (const auto& [kind, model] : {std::pair{"full", &full}, std::pair{"reduced", &reduced}}) {
        const fs::path vrml = work / (name + "_" + kind + "_vrml");
        writeKeyMeshFiles(vrml, *model, ".wrl");
        for (bool quantise : {false, true}) {
            Variant v;
            v.label = name + "/" + kind + "(" + std::to_string(model->keys.size()) + ")/" +
                      (quantise ? "int16" : "float");
            v.package = work / (name + "_" + kind + (quantise ? "_q" : "") + ".vlrt");
            v.vrmlDir = vrml;
            v.keys = model->keys.size();
            writeRuntimePackage(v.package, *model, {.quantise = quantise});
            variants.push_back(v);
        }
    }
}

} // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    const fs::path work = fs::temp_directory_path() / "visemelab_bench_runtime";
    fs::create_directories(work);
    std::vector<Variant> variants;
    if (const auto sample = sampleProject())
        prepare("sample", {projectReducedModel(*sample, true), projectReducedModel(*sample)}, work, variants);
    else
        std::fprintf(stderr, "bench_runtime: assets/sample not present: skipping the sample face\n");
    prepare("synthetic", fullAndReduced(syntheticSet()), work, variants);
    if (const auto ict = ictSet())
        prepare("ict", fullAndReduced(*ict), work, variants);
    else
        std::fprintf(stderr,
                     "bench_runtime: ../shared/data/ict-facekit-mouth not present: skipping ICT FaceKit\n");

    for (const Variant& v : variants) {
        measure(v);
        benchmark::RegisterBenchmark(("load_package/" + v.label).c_str(), benchLoadPackage, v)
            ->Unit(benchmark::kMillisecond);
        if (v.label.ends_with("float"))
            benchmark::RegisterBenchmark(
                ("load_vrml_startup/" + v.label.substr(0, v.label.size() - 6)).c_str(), benchLoadVrml, v)
                ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("evaluate_linear/" + v.label).c_str(), benchEvaluate, v,
                                     runtime::Interpolation::Linear)
            ->Unit(benchmark::kMicrosecond);
        benchmark::RegisterBenchmark(("evaluate_cubic/" + v.label).c_str(), benchEvaluate, v,
                                     runtime::Interpolation::Cubic)
            ->Unit(benchmark::kMicrosecond);
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();

    std::printf("\n%-34s %6s %9s %14s %14s %14s\n", "variant", "keys", "vertices", "package bytes",
                "heap bytes", "memoryBytes()");
    for (const Figures& f : gFigures)
        std::printf("%-34s %6zu %9zu %14zu %14zu %14zu\n", f.label.c_str(), f.keys, f.vertices,
                    f.packageBytes, f.heapBytes, f.memoryBytes);
    fs::remove_all(work);
    return 0;
}
