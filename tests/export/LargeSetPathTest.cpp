// The large-set path of `reduce` (a FloatVisemeSet, keys merged as they are written) against the
// double pipeline it replaces for sets written as binary PLY: bit for bit on float32 inputs (what a
// float32 PLY holds), within the bound stated in core/mesh/VisemeSet.h on rounded double inputs.
#include "core/common/OutputSet.h"
#include "core/export/ReductionOutputs.h"
#include "core/io/MeshIO.h"
#include "core/io/PlyKeyWriter.h"
#include "core/io/VisemeSetFiles.h"
#include "core/reduce/GramMatrix.h"
#include "core/reduce/ReduceRun.h"
#include "tests/common/TempFolder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace vl;

namespace {

// n visemes over a strip of triangles; with `floatExact` every coordinate is a float32 value. The
// first viseme is "sil", so the default run (rest auto) takes the rest-free model.
VisemeSet randomSet(std::mt19937& rng, int n, std::size_t vertices, bool floatExact) {
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    const auto round = [&](double x) { return floatExact ? static_cast<double>(static_cast<float>(x)) : x; };
    VisemeSet set;
    for (std::size_t v = 0; v < vertices; ++v)
        set.neutral.positions.emplace_back(round(10 * coord(rng)), round(10 * coord(rng)),
                                           round(10 * coord(rng)));
    for (std::uint32_t v = 0; v + 2 < vertices; ++v)
        set.neutral.triangles.push_back(Triangle{v, v + 1, v + 2});
    for (int i = 0; i < n; ++i) {
        Viseme viseme{i == 0 ? "sil" : "v" + std::to_string(i), set.neutral.positions};
        const double reach = i == 0 ? 0.01 : 1.0;
        for (auto& p : viseme.positions)
            for (int axis = 0; axis < 3; ++axis) p[axis] = round(p[axis] + reach * coord(rng));
        set.visemes.push_back(std::move(viseme));
    }
    return set;
}

FloatVisemeSet floatsOf(const VisemeSet& set) {
    FloatVisemeSet floats;
    floats.neutral = set.neutral;
    const std::size_t count = 3 * set.vertexCount();
    floats.positions = std::make_unique<float[]>(set.size() * count);
    for (std::size_t i = 0; i < set.size(); ++i) {
        floats.names.push_back(set.visemes[i].name);
        for (std::size_t v = 0; v < set.vertexCount(); ++v)
            for (int axis = 0; axis < 3; ++axis)
                floats.positions[i * count + 3 * v + static_cast<std::size_t>(axis)] =
                    static_cast<float>(set.visemes[i].positions[v][axis]);
    }
    return floats;
}

FrequencySource randomFrequencies(std::mt19937& rng, const VisemeSet& set) {
    std::uniform_real_distribution<double> f(0.01, 1.0);
    FrequencySource source;
    for (const auto& v : set.visemes) source.visemeFrequencies.entries.emplace_back(v.name, f(rng));
    return source;
}

ReduceSettings settingsFor(int target, WeightMode weights) {
    ReduceSettings settings;
    settings.target = target;
    settings.weightMode = weights;
    settings.rest = RestChoice::Auto;
    return settings;
}

} // namespace

TEST(LargeSetPath, FloatExactInputsGiveTheDoublePipelinesResultsAndFilesBitForBit) {
    std::mt19937 rng(33);
    for (int round = 0; round < 6; ++round) {
        const int n = 4 + round;
        const VisemeSet set = randomSet(rng, n, 300 + 50 * static_cast<std::size_t>(round), true);
        const FloatVisemeSet floats = floatsOf(set);
        const FrequencySource frequencies = randomFrequencies(rng, set);
        const ReduceSettings settings =
            settingsFor(2 + round % 3, round % 2 ? WeightMode::Area : WeightMode::Uniform);

        const ReduceOutcome exact = runReduction(set, frequencies, settings);
        const ReduceOutcome fast =
            runReduction(shapesOf(floats), frequencies, settings, {}, KeyPositions::Deferred);
        EXPECT_EQ(centredGram(shapesOf(floats).shapes, exact.frequencies, exact.weights),
                  centredGram(shapesOf(set).shapes, exact.frequencies, exact.weights));
        EXPECT_EQ(fast.result, exact.result) << "round " << round;
        ASSERT_EQ(fast.visemeErrors.size(), exact.visemeErrors.size());
        for (std::size_t i = 0; i < exact.visemeErrors.size(); ++i) {
            EXPECT_EQ(fast.visemeErrors[i].max, exact.visemeErrors[i].max) << i;
            EXPECT_EQ(fast.visemeErrors[i].rms, exact.visemeErrors[i].rms) << i;
            EXPECT_EQ(fast.visemeErrors[i].largestDisplacement, exact.visemeErrors[i].largestDisplacement)
                << i;
        }
        ASSERT_EQ(fast.model.keys.size(), exact.model.keys.size());
        for (std::size_t k = 0; k < exact.model.keys.size(); ++k) {
            EXPECT_EQ(fast.model.keys[k].name, exact.model.keys[k].name);
            EXPECT_TRUE(fast.model.keys[k].positions.empty()); // deferred: no key held as doubles
        }

        // The files: the merged model's binary PLY against the keys merged as they are written.
        test::TempFolder folder;
        const KeyMeshFormats ply{false, false, true};
        OutputSet a(folder / "double", "reduce");
        const auto written = writeReductionOutputs(a, exact, ply);
        a.commit();
        OutputSet b(folder / "float", "reduce");
        EXPECT_EQ(writeReductionOutputs(b, fast, ply, shapesOf(floats)), written);
        b.commit();
        for (const std::string& name : written)
            EXPECT_EQ(test::readText(folder / "float" / name), test::readText(folder / "double" / name))
                << name;
        OutputSet c(folder / "text", "reduce");
        EXPECT_THROW(writeReductionOutputs(c, fast, KeyMeshFormats{}, shapesOf(floats)),
                     std::invalid_argument);
    }
}

TEST(LargeSetPath, RoundedDoubleInputsStayWithinTheStatedBound) {
    // VisemeSet.h: |rho~ - rho| <= sum_k w_k (2u |d_k| (|a_k| + |b_k|) + u^2 (|a_k| + |b_k|)^2), u = 2^-24,
    // then double rounding (a relative 1e-12 here is generous for a few hundred terms).
    std::mt19937 rng(34);
    const double u = std::ldexp(1.0, -24);
    double largestShare = 0; // of the bound used: a loose bound would pass whatever the rounding did
    for (int round = 0; round < 4; ++round) {
        const VisemeSet set = randomSet(rng, 6, 400, false);
        const FloatVisemeSet floats = floatsOf(set);
        const SetShapes view = shapesOf(floats);
        std::vector<double> weights(set.vertexCount());
        std::uniform_real_distribution<double> w(0.0, 2.0);
        for (double& x : weights) x = w(rng);
        for (std::size_t i = 0; i < set.size(); ++i)
            for (std::size_t j = i + 1; j < set.size(); ++j) {
                const auto& a = set.visemes[i].positions;
                const auto& b = set.visemes[j].positions;
                double bound = 0;
                for (std::size_t k = 0; k < a.size(); ++k) {
                    const double size = a[k].norm() + b[k].norm();
                    bound += weights[k] * (2 * u * (a[k] - b[k]).norm() * size + u * u * size * size);
                }
                const double exact = dissimilarity(a, b, weights);
                const double rounded = dissimilarity(view.shapes[i], view.shapes[j], weights);
                EXPECT_LE(std::abs(rounded - exact), bound + 1e-12 * exact) << i << ", " << j;
                largestShare = std::max(largestShare, std::abs(rounded - exact) / bound);
            }
        // The run itself: same groupings here (the rounding moves costs by ~1e-7 relative).
        const FrequencySource frequencies = randomFrequencies(rng, set);
        const ReduceSettings settings = settingsFor(3, WeightMode::Uniform);
        const ReduceOutcome exact = runReduction(set, frequencies, settings);
        const ReduceOutcome fast = runReduction(view, frequencies, settings, {}, KeyPositions::Deferred);
        EXPECT_EQ(fast.result.groupOf(), exact.result.groupOf());
        EXPECT_NEAR(fast.result.best().cost, exact.result.best().cost, 1e-5 * exact.result.best().cost);
    }
    EXPECT_GT(largestShare, 1e-3); // the rounding is there and the bound is not vacuous
}

TEST(LargeSetPath, LoaderCopiesFloatPlyAndRoundsOtherFilesWithTheSameErrors) {
    std::mt19937 rng(35);
    const VisemeSet set = randomSet(rng, 3, 200, true);
    test::TempFolder folder;
    const PlyKeyWriter writer(set.neutral); // float32 x, y, z and uchar/int faces: the bulk layout
    std::string buffer;
    const auto writeFloatPly = [&](const std::filesystem::path& file, const std::vector<Vec3>& positions) {
        test::writeText(file, std::string(writer.head()) + std::string(writer.positions(positions, buffer)) +
                                  std::string(writer.faces()));
    };
    writeFloatPly(folder / "neutral.ply", set.neutral.positions);
    writeFloatPly(folder / "sil.ply", set.visemes[0].positions);
    MeshData obj = set.neutral;
    obj.positions = set.visemes[1].positions;
    obj.positions[5][0] += 1e-9; // not a float32 value: rounded
    writeMesh(folder / "v1.obj", obj);
    obj.positions = set.visemes[2].positions;
    writeMesh(folder / "v2.ply", obj); // double PLY: the general reader, then rounded (exact here)
    const std::vector<std::pair<std::string, std::filesystem::path>> files{
        {"sil", folder / "sil.ply"}, {"v1", folder / "v1.obj"}, {"v2", folder / "v2.ply"}};

    const VisemeSet doubles = loadVisemeSet(folder / "neutral.ply", files);
    const FloatVisemeSet floats = loadFloatVisemeSet(folder / "neutral.ply", files);
    ASSERT_EQ(floats.names, (std::vector<std::string>{"sil", "v1", "v2"}));
    EXPECT_EQ(floats.neutral.positions, doubles.neutral.positions);
    EXPECT_EQ(floats.neutral.triangles, doubles.neutral.triangles);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t v = 0; v < floats.vertexCount(); ++v)
            for (int axis = 0; axis < 3; ++axis)
                EXPECT_EQ(floats.visemePositions(i)[3 * v + static_cast<std::size_t>(axis)],
                          static_cast<float>(doubles.visemes[i].positions[v][axis]));
    EXPECT_NE(doubles.visemes[1].positions[5][0], static_cast<float>(doubles.visemes[1].positions[5][0]));

    // Errors name the file, as loadVisemeSet's do.
    const auto errorOf = [&](const std::vector<std::pair<std::string, std::filesystem::path>>& given) {
        try {
            loadFloatVisemeSet(folder / "neutral.ply", given);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    std::vector<Vec3> huge = set.visemes[0].positions;
    huge[7][2] = 3e30;
    writeFloatPly(folder / "huge.ply", huge);
    std::string message = errorOf({{"sil", folder / "sil.ply"}, {"h", folder / "huge.ply"}});
    EXPECT_NE(message.find("huge.ply: vertex 8: coordinate"), std::string::npos) << message;
    MeshData fewer = set.neutral;
    fewer.triangles.pop_back();
    writeMesh(folder / "fewer.ply", fewer);
    message = errorOf({{"sil", folder / "sil.ply"}, {"f", folder / "fewer.ply"}});
    EXPECT_NE(message.find("fewer.ply: not interpolable"), std::string::npos) << message;
    message = errorOf({{"sil", folder / "sil.ply"}, {"sil", folder / "v2.ply"}});
    EXPECT_NE(message.find("duplicate viseme name 'sil'"), std::string::npos) << message;
}
