// Deformation cascade benchmarks: re-evaluating a ~100,000-vertex deformed face after a slider change
// (goal <= 2 ms on the 2-core CI machine), against the per-point reference and a dense worst case.
#include "core/deform/CascadeSampler.h"
#include "core/deform/Visemes.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"

#include <benchmark/benchmark.h>

namespace {

using namespace vl;

// 316 x 316 cells: 100,489 grid vertices (+ the cut along the mouth).
const MeshData& bigMesh() {
    static const MeshData mesh = face::faceDomainMesh(316, face::DomainDensity::Uniform);
    return mesh;
}

const DeformationCascade& bundled() {
    static const DeformationCascade cascade = face::makeBundledFace();
    return cascade;
}

// Every parameter set (a mid-range expression), then one slider moved per iteration.
void BM_SliderChange(benchmark::State& state) {
    const CascadeSampler sampler(bundled(), bigMesh().uvs);
    std::vector<double> q(bundled().parameters.size(), 0.4);
    const auto jaw = static_cast<std::size_t>(bundled().findParameter("jaw_open"));
    std::vector<Vec3> out(sampler.vertexCount());
    int step = 0;
    for (auto _ : state) {
        q[jaw] = 0.01 * (step++ % 100);
        sampler.evaluate(q, out);
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["vertices"] = static_cast<double>(sampler.vertexCount());
}
BENCHMARK(BM_SliderChange)->Unit(benchmark::kMillisecond)->UseRealTime();

// A viseme: only the few parameters it uses are non-zero.
void BM_VisemeEvaluate(benchmark::State& state) {
    const CascadeSampler sampler(bundled(), bigMesh().uvs);
    const auto q = parameterVector(bundled(), oculusVisemes()[12]); // "ih"
    std::vector<Vec3> out(sampler.vertexCount());
    for (auto _ : state) {
        sampler.evaluate(q, out);
        benchmark::DoNotOptimize(out.data());
    }
}
BENCHMARK(BM_VisemeEvaluate)->Unit(benchmark::kMillisecond)->UseRealTime();

// Worst case for the sparse layout: every parameter has a field that is non-zero everywhere.
void BM_SliderChangeDenseFields(benchmark::State& state) {
    DeformationCascade dense = bundled();
    for (auto& stage : dense.stages)
        if (stage.kind == StageKind::AddVector)
            stage.field.sampled =
                sampleGrid(17, 17, [](double u, double v) { return Vec3(u, v, 1.0 + u * v); });
    const CascadeSampler sampler(dense, bigMesh().uvs);
    std::vector<double> q(dense.parameters.size(), 0.4);
    std::vector<Vec3> out(sampler.vertexCount());
    int step = 0;
    for (auto _ : state) {
        q[6] = 0.01 * (step++ % 100);
        sampler.evaluate(q, out);
        benchmark::DoNotOptimize(out.data());
    }
}
BENCHMARK(BM_SliderChangeDenseFields)->Unit(benchmark::kMillisecond)->UseRealTime();

// Once per mesh change: sampling every field at every vertex.
void BM_SamplerBuild(benchmark::State& state) {
    for (auto _ : state) {
        const CascadeSampler sampler(bundled(), bigMesh().uvs);
        benchmark::DoNotOptimize(sampler.vertexCount());
    }
}
BENCHMARK(BM_SamplerBuild)->Unit(benchmark::kMillisecond)->UseRealTime();

// The obvious per-point evaluation the sampler replaces.
void BM_PerPointReference(benchmark::State& state) {
    const auto& uvs = bigMesh().uvs;
    const std::vector<double> q(bundled().parameters.size(), 0.4);
    std::vector<Vec3> out(uvs.size());
    for (auto _ : state) {
        for (std::size_t i = 0; i < uvs.size(); ++i)
            out[i] = bundled().evaluateUnchecked(uvs[i][0], uvs[i][1], q);
        benchmark::DoNotOptimize(out.data());
    }
}
BENCHMARK(BM_PerPointReference)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
