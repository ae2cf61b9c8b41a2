// Mesh I/O benchmarks: loading the real 26,719-vertex ICT FaceKit neutral (2.5 MB OBJ; goal well
// under 50 ms), and parsing/formatting every format at the sample size (1,500 vertices) and the
// ICT size, in memory so disk speed does not blur the figures.
#include "core/common/AtomicFile.h"
#include "core/io/MeshIO.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <random>

namespace {

const std::filesystem::path kIctNeutral =
    std::filesystem::path(VISEMELAB_SHARED_DATA_DIR) / "ict-facekit-mouth/generic_neutral_mesh.obj";

// A (side x side) grid of vertices with (u,v), jittered with full-precision doubles.
vl::MeshData gridMesh(int side) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> jitter(-0.01, 0.01);
    vl::MeshData mesh;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            mesh.positions.emplace_back(x + jitter(rng), y + jitter(rng), jitter(rng));
            mesh.uvs.emplace_back(x / double(side - 1), y / double(side - 1));
        }
    for (int y = 0; y + 1 < side; ++y)
        for (int x = 0; x + 1 < side; ++x) {
            const auto v = static_cast<std::uint32_t>(y * side + x);
            const auto s = static_cast<std::uint32_t>(side);
            mesh.triangles.push_back({v, v + 1, v + s + 1});
            mesh.triangles.push_back({v, v + s + 1, v + s});
        }
    return mesh;
}

void BM_ReadIctNeutralObj(benchmark::State& state) {
    if (!std::filesystem::exists(kIctNeutral)) {
        state.SkipWithError("shared data absent: ../shared/data/ict-facekit-mouth");
        return;
    }
    for (auto _ : state) benchmark::DoNotOptimize(vl::readMesh(kIctNeutral));
    state.SetBytesProcessed(state.iterations() *
                            static_cast<std::int64_t>(std::filesystem::file_size(kIctNeutral)));
}
BENCHMARK(BM_ReadIctNeutralObj)->Unit(benchmark::kMillisecond);

void BM_ParseIctNeutralObjInMemory(benchmark::State& state) {
    if (!std::filesystem::exists(kIctNeutral)) {
        state.SkipWithError("shared data absent: ../shared/data/ict-facekit-mouth");
        return;
    }
    const std::string text = vl::readFileToString(kIctNeutral);
    for (auto _ : state) benchmark::DoNotOptimize(vl::parseObj(text, "ict.obj"));
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(text.size()));
}
BENCHMARK(BM_ParseIctNeutralObjInMemory)->Unit(benchmark::kMillisecond);

// Arg is the grid side: 39 -> 1,521 vertices (the sample size), 163 -> 26,569 (the ICT size).
using Formatter = std::string (*)(const vl::MeshData&);
using Parser = vl::MeshData (*)(std::string_view, std::string_view);

void BM_Format(benchmark::State& state, Formatter format) {
    const vl::MeshData mesh = gridMesh(static_cast<int>(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(format(mesh));
    state.counters["vertices"] = static_cast<double>(mesh.vertexCount());
}

void BM_Parse(benchmark::State& state, Formatter format, Parser parse) {
    const std::string bytes = format(gridMesh(static_cast<int>(state.range(0))));
    for (auto _ : state) benchmark::DoNotOptimize(parse(bytes, "mesh"));
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(bytes.size()));
}

BENCHMARK_CAPTURE(BM_Format, Obj, vl::formatObj)->Arg(39)->Arg(163)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Parse, Obj, vl::formatObj, vl::parseObj)
    ->Arg(39)
    ->Arg(163)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Format, Ply, vl::formatPly)->Arg(39)->Arg(163)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Parse, Ply, vl::formatPly, vl::parsePly)
    ->Arg(39)
    ->Arg(163)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Format, Vrml, vl::formatVrml)->Arg(39)->Arg(163)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Parse, Vrml, vl::formatVrml, vl::parseVrml)
    ->Arg(39)
    ->Arg(163)
    ->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
