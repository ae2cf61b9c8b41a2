#include "core/reduce/Weights.h"
#include "core/common/Error.h"
#include "core/reduce/Reduction.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

using namespace vl;

namespace {

// A big triangle (v0, v1, v2) and a sliver (v1, v3, v2): v0 has a large area weight, v3 a tiny one.
MeshData twoRegionMesh() {
    MeshData mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 10, 0), Vec3(5.01, 5.01, 0)};
    mesh.triangles = {Triangle{0, 1, 2}, Triangle{1, 3, 2}};
    return mesh;
}

std::filesystem::path writeWeightsTemp(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / ("visemelab_weights_" + name);
    std::ofstream(path) << text;
    return path;
}

} // namespace

TEST(Weights, AreaWeightIsSumOfIncidentTriangleAreas) {
    const auto mesh = twoRegionMesh();
    const auto w = computeWeights(WeightMode::Area, mesh);
    const double big = 50.0;
    EXPECT_DOUBLE_EQ(w[0], big);
    EXPECT_GT(w[1], big);
    EXPECT_LT(w[3], 0.2);
    EXPECT_DOUBLE_EQ(w[1] - big, w[3]);
}

// The paper claims rho1 (uniform) and rho2 (area) always give the same reduction. The merged mesh of a
// fixed group is indeed weight-independent, but the optimal grouping is not: here they differ.
TEST(Weights, UniformAndAreaWeightsCanPickDifferentGroupings) {
    const auto mesh = twoRegionMesh();
    const auto& n = mesh.positions;
    // A1 = neutral; A2 moves the tiny-area vertex v3 by 2; A3 moves the large-area vertex v0 by 1.
    std::vector<std::vector<Vec3>> shapes = {n, n, n};
    shapes[1][3] += Vec3(0, 0, 2);
    shapes[2][0] += Vec3(0, 0, 1);
    const std::vector<double> f = {1, 1, 1};

    const auto uniform = computeWeights(WeightMode::Uniform, mesh);
    const auto area = computeWeights(WeightMode::Area, mesh);
    const auto byUniform = reduceVisemes({shapes, f, uniform, 2}).best().groups;
    const auto byArea = reduceVisemes({shapes, f, area, 2}).best().groups;
    // Uniform: |A1-A3|^2 = 1 < |A1-A2|^2 = 4, so A1 and A3 merge. Area: moving v0 is expensive.
    EXPECT_EQ(byUniform, (std::vector<std::vector<int>>{{0, 2}, {1}}));
    EXPECT_EQ(byArea, (std::vector<std::vector<int>>{{0, 1}, {2}}));
    EXPECT_NE(byUniform, byArea);

    // For a fixed group the merged mesh does not depend on the weights.
    const std::vector<int> group = {0, 1};
    EXPECT_EQ(mergeGroup(shapes, f, group), mergeGroup(shapes, f, group));
}

TEST(Weights, PaintedWeightsAreValidated) {
    const auto mesh = twoRegionMesh();
    EXPECT_NO_THROW(computeWeights(WeightMode::Painted, mesh, {1, 0, 2, 0.5}));
    EXPECT_THROW(computeWeights(WeightMode::Painted, mesh, {1, 2, 3}), InputError);
    EXPECT_THROW(computeWeights(WeightMode::Painted, mesh, {0, 0, 0, 0}), InputError);
    try {
        computeWeights(WeightMode::Painted, mesh, {1, -1, 1, 1}, "paint.json");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "paint.json: weight of vertex 1 is -1; weights must be finite and >= 0");
    }
}

TEST(Weights, LoadsJsonAndTextFilesWithLocatedErrors) {
    EXPECT_EQ(loadWeightsFile(writeWeightsTemp("a.json", "[1, 2.5, 0]")), (std::vector<double>{1, 2.5, 0}));
    EXPECT_EQ(loadWeightsFile(writeWeightsTemp("b.json", "{\"weights\": [3, 4]}")),
              (std::vector<double>{3, 4}));
    EXPECT_EQ(loadWeightsFile(writeWeightsTemp("c.txt", "# weights\n1\n2, 3\n")),
              (std::vector<double>{1, 2, 3}));
    auto expectMessage = [](const std::filesystem::path& path, const std::string& fragment) {
        try {
            loadWeightsFile(path);
            ADD_FAILURE() << "expected error for " << path;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
        }
    };
    expectMessage(writeWeightsTemp("d.txt", "1\n2\nnan\n"), "weights_d.txt:3: non-finite");
    expectMessage(writeWeightsTemp("e.json", "[1, \"x\"]"), ":/1: expected a number");
    expectMessage(writeWeightsTemp("f.json", ""), "empty weights file");
    expectMessage(writeWeightsTemp("g.json", "[1,"), "invalid JSON");
    expectMessage(std::filesystem::temp_directory_path() / "visemelab_no_such_file.json", "file not found");
}

TEST(Weights, HostileFilesAreDataErrorsNamingTheFile) {
    auto expectMessage = [](const std::filesystem::path& path, const std::string& fragment) {
        try {
            loadWeightsFile(path);
            ADD_FAILURE() << "expected error for " << path;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
        }
    };
    expectMessage(writeWeightsTemp("deep.json", std::string(50000, '[')), "weights_deep.json: /0/0/0/0");
    expectMessage(writeWeightsTemp("inf.json", "{\"weights\": [1, 1e999]}"),
                  "weights_inf.json: /weights/1: number out of range: 1e999");
    expectMessage(writeWeightsTemp("inf.txt", "1\n1e999\n"), "weights_inf.txt:2: number out of range");
    expectMessage(writeWeightsTemp("neg.txt", "1\n2 -3\n"), "weights_neg.txt:2: weight -3 is negative");
    expectMessage(writeWeightsTemp("neg.json", "[1, -3]"), "weights_neg.json:/1: weight -3 is negative");
    expectMessage(writeWeightsTemp("bom.txt", "\xEF\xBB\xBF"), "empty weights file");
    expectMessage(writeWeightsTemp("comments.txt", "# only a comment\n"), "no weights in file");
    EXPECT_EQ(loadWeightsFile(writeWeightsTemp("bom2.txt", "\xEF\xBB\xBF"
                                                           "1 2\n")),
              (std::vector<double>{1, 2}));
}

// A stroke starts from the weights shown, scaled to a largest weight of 1, so an "add" stroke over
// area weights raises them (all ones would swallow it); painted weights are kept as they are.
TEST(Weights, PaintingStartsFromTheWeightsShownScaledToOne) {
    const auto mesh = twoRegionMesh();
    const auto area = computeWeights(WeightMode::Area, mesh);
    const auto start = weightsForPainting(WeightMode::Area, mesh);
    const double largest = *std::max_element(area.begin(), area.end());
    ASSERT_EQ(start.size(), area.size());
    for (std::size_t k = 0; k < area.size(); ++k) EXPECT_DOUBLE_EQ(start[k], area[k] / largest);
    EXPECT_LT(start[3], 0.01);
    EXPECT_EQ(weightsForPainting(WeightMode::Uniform, mesh), std::vector<double>(4, 1.0));
    const std::vector<double> painted = {0.2, 3.0, 0.0, 1.0};
    EXPECT_EQ(weightsForPainting(WeightMode::Painted, mesh, painted), painted);
    // Painted mode without painted weights (a new document) starts from all ones.
    EXPECT_EQ(weightsForPainting(WeightMode::Painted, mesh, {}), std::vector<double>(4, 1.0));
}
