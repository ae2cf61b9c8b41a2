// Adaptive mesh benchmarks on the bundled face (base mesh: faceBaseDomain(10), 200 triangles):
// unconditional refinement to three levels (goal <= 10 ms), normals-based and contour-based
// refinement (goal <= 30 ms), and re-adaptation after a slider change. Each iteration builds the
// RBMT base mesh from the domain and refines it, as `visemelab refine` does.
#include "core/adaptive/CascadeSurface.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"

#include <benchmark/benchmark.h>

namespace {

using namespace vl;

CascadeSurface bundledSurface() {
    const DeformationCascade cascade = face::makeBundledFace();
    return CascadeSurface(cascade, face::faceBaseDomain(10), cascade.defaults());
}

void refineSurface(benchmark::State& state, const CascadeSurface& surface,
                   const CriterionSettings& settings) {
    const auto criterion = makeCriterion(settings);
    std::size_t faces = 0;
    for (auto _ : state) {
        AdaptiveMesh mesh(surface);
        mesh.refine(*criterion);
        faces = mesh.faceCount();
        benchmark::DoNotOptimize(faces);
    }
    state.counters["triangles"] = static_cast<double>(faces);
}

void refineBundled(benchmark::State& state, const CriterionSettings& settings) {
    refineSurface(state, bundledSurface(), settings);
}

void BM_RefineDepth3(benchmark::State& state) {
    CriterionSettings s;
    s.kind = CriterionKind::Depth;
    s.depth.depth = 3;
    refineBundled(state, s);
}
BENCHMARK(BM_RefineDepth3)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RefineNormals(benchmark::State& state) {
    CriterionSettings s;
    s.kind = CriterionKind::Normals; // defaults: 20 degrees, max depth 10
    refineBundled(state, s);
}
BENCHMARK(BM_RefineNormals)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RefineContour(benchmark::State& state) {
    CriterionSettings s;
    s.kind = CriterionKind::Contour; // defaults: average 0.02 cm, maximum 0.08 cm, 16 samples
    refineBundled(state, s);
}
BENCHMARK(BM_RefineContour)->Unit(benchmark::kMillisecond)->UseRealTime();

// `visemelab refine --criterion contour --param jaw_open=1 --param lip_pucker=0.5`, split as the CLI's
// reported timing_ms is: building the surface (every field sampled on the base domain) and refining.
std::vector<double> openPuckerPose(const DeformationCascade& cascade) {
    auto q = cascade.defaults();
    q[static_cast<std::size_t>(cascade.findParameter("jaw_open"))] = 1.0;
    q[static_cast<std::size_t>(cascade.findParameter("lip_pucker"))] = 0.5;
    return q;
}

void BM_CliRefineSurface(benchmark::State& state) {
    const DeformationCascade cascade = face::makeBundledFace();
    const auto q = openPuckerPose(cascade);
    for (auto _ : state) {
        CascadeSurface surface(cascade, face::faceBaseDomain(10), q);
        benchmark::DoNotOptimize(surface);
    }
}
BENCHMARK(BM_CliRefineSurface)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_CliRefineContour(benchmark::State& state) {
    const DeformationCascade cascade = face::makeBundledFace();
    CriterionSettings s;
    s.kind = CriterionKind::Contour;
    refineSurface(state, CascadeSurface(cascade, face::faceBaseDomain(10), openPuckerPose(cascade)), s);
}
BENCHMARK(BM_CliRefineContour)->Unit(benchmark::kMillisecond)->UseRealTime();

// A slider change (0 <-> 1) followed by re-adaptation (resample, weld, refine) under contour, told
// where the surface changed (CascadeSurface::setParameters). The jaw reaches the lower third of the
// face; the brow (frontalis_l) a small patch.
void readaptContour(benchmark::State& state, const char* parameter) {
    CascadeSurface surface = bundledSurface();
    CriterionSettings s;
    s.kind = CriterionKind::Contour;
    const auto criterion = makeCriterion(s);
    AdaptiveMesh mesh(surface);
    mesh.refine(*criterion);
    const auto k = static_cast<std::size_t>(surface.cascade().findParameter(parameter));
    auto q = surface.parameters();
    int step = 0;
    bool rebuilt = false;
    for (auto _ : state) {
        q[k] = (step++ % 2) ? 0.0 : 1.0;
        const UvBox changed = surface.setParameters(q);
        rebuilt = mesh.adapt(*criterion, changed).rebuilt;
    }
    state.counters["triangles"] = static_cast<double>(mesh.faceCount());
    state.SetLabel(rebuilt ? "rebuilt from the base mesh" : "re-adapted where it changed");
}
void BM_ReadaptContourJaw(benchmark::State& state) {
    readaptContour(state, "jaw_open");
}
BENCHMARK(BM_ReadaptContourJaw)->Unit(benchmark::kMillisecond)->UseRealTime();
void BM_ReadaptContourBrow(benchmark::State& state) {
    readaptContour(state, "frontalis_l");
}
BENCHMARK(BM_ReadaptContourBrow)->Unit(benchmark::kMillisecond)->UseRealTime();

// The baseline of re-adaptation, measured in the same run: the same slider change answered by building
// the mesh from the base domain again and refining it.
void rebuildContour(benchmark::State& state, const char* parameter) {
    CascadeSurface surface = bundledSurface();
    CriterionSettings s;
    s.kind = CriterionKind::Contour;
    const auto criterion = makeCriterion(s);
    const auto k = static_cast<std::size_t>(surface.cascade().findParameter(parameter));
    auto q = surface.parameters();
    int step = 0;
    std::size_t faces = 0;
    for (auto _ : state) {
        q[k] = (step++ % 2) ? 0.0 : 1.0;
        surface.setParameters(q);
        AdaptiveMesh mesh(surface);
        mesh.refine(*criterion);
        faces = mesh.faceCount();
        benchmark::DoNotOptimize(faces);
    }
    state.counters["triangles"] = static_cast<double>(faces);
}
void BM_RebuildContourJaw(benchmark::State& state) {
    rebuildContour(state, "jaw_open");
}
BENCHMARK(BM_RebuildContourJaw)->Unit(benchmark::kMillisecond)->UseRealTime();
void BM_RebuildContourBrow(benchmark::State& state) {
    rebuildContour(state, "frontalis_l");
}
BENCHMARK(BM_RebuildContourBrow)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
