#pragma once
// Shared pieces of the project tests: a scratch folder, random valid project states and an
// expectation helper for InputError messages.
#include "core/common/Error.h"
#include "core/deform/VectorField.h"
#include "core/io/JsonRead.h"
#include "core/project/Project.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

namespace vl::test {

// A fresh folder under the system temp dir, removed with its contents at the end of the test.
struct ScratchDir {
    std::filesystem::path path;
    explicit ScratchDir(const std::string& name) {
        path = std::filesystem::temp_directory_path() /
               ("visemelab_project_" + name + "_" + std::to_string(std::random_device{}()));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    std::filesystem::path operator/(const std::string& name) const { return path / name; }
};

inline void writeText(const std::filesystem::path& file, const std::string& text) {
    std::filesystem::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary);
    out << text;
}

// The message of the InputError `f` throws; fails the test when it throws nothing.
template <class F> std::string inputErrorOf(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected an InputError";
    return {};
}

#define EXPECT_INPUT_ERROR(statement, expected)                                                              \
    do {                                                                                                     \
        const std::string message_ = ::vl::test::inputErrorOf([&] { (void)(statement); });                   \
        EXPECT_NE(message_.find(expected), std::string::npos)                                                \
            << "message: " << message_ << "\nexpected: " << (expected);                                      \
    } while (0)

// A project document edited in a test and loaded as a file of a scratch folder.
class DocumentTest : public ::testing::Test {
  protected:
    DocumentTest(const std::string& name, std::string_view json)
        : dir(name), doc(parseJsonStrict(json, "test")) {}

    Project load() const {
        const auto file = dir / "p.vlproj";
        writeText(file, doc.dump(2));
        return loadProject(file);
    }
    std::string errorOf() const {
        return inputErrorOf([&] { load(); });
    }

    ScratchDir dir;
    Json doc;
};

// In a DocumentTest: loading the document fails with a message containing `expected`.
#define EXPECT_LOAD_ERROR(expected) EXPECT_INPUT_ERROR(load(), expected)

// Doubles that stress exact printing: tiny, huge, subnormal, negative zero, non-terminating binary.
inline double randomDouble(std::mt19937_64& rng, bool nonNegative) {
    static const double specials[] = {0.0,
                                      -0.0,
                                      0.1,
                                      1.0 / 3.0,
                                      5e-324,
                                      2.2250738585072014e-308,
                                      1.7976931348623157e308,
                                      123456789.123456789,
                                      1e-7,
                                      0.5};
    double v = 0;
    switch (rng() % 4) {
    case 0:
        v = specials[rng() % std::size(specials)];
        break;
    case 1:
        v = std::uniform_real_distribution<double>(-10.0, 10.0)(rng);
        break;
    case 2:
        v = std::ldexp(std::uniform_real_distribution<double>(0.5, 1.0)(rng),
                       static_cast<int>(rng() % 200) - 100);
        break;
    default:
        v = static_cast<double>(static_cast<std::int64_t>(rng() % 2000) - 1000);
        break;
    }
    return nonNegative ? std::fabs(v) : v;
}

inline std::string randomName(std::mt19937_64& rng, const std::string& prefix) {
    // Characters JSON and JSON paths must escape: quotes, backslash, slash, tilde, non-ASCII.
    static const char* pieces[] = {"a", "B", "_", "~", "/", "\"", "\\", "\xc3\xa6", "\xc9\x99", "1", " "};
    std::string name = prefix;
    const auto length = 1 + rng() % 4;
    for (std::size_t i = 0; i < length; ++i) name += pieces[rng() % std::size(pieces)];
    return name;
}

inline std::vector<Vec3> randomPoints(std::mt19937_64& rng, std::size_t n) {
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < n; ++i)
        points.emplace_back(randomDouble(rng, false), randomDouble(rng, false), randomDouble(rng, false));
    return points;
}

// A random partition of 0..n-1 into p groups, in canonical order (members ascending, groups by first).
inline std::vector<std::vector<int>> randomPartition(std::mt19937_64& rng, int n, int p) {
    std::vector<int> order(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) order[static_cast<std::size_t>(i)] = i;
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<std::vector<int>> groups(static_cast<std::size_t>(p));
    for (int i = 0; i < n; ++i)
        groups[static_cast<std::size_t>(i < p ? i : static_cast<int>(rng() % static_cast<std::uint64_t>(p)))]
            .push_back(order[static_cast<std::size_t>(i)]);
    for (auto& g : groups) std::sort(g.begin(), g.end());
    std::sort(groups.begin(), groups.end(),
              [](const auto& a, const auto& b) { return a.front() < b.front(); });
    return groups;
}

// A rest-free result: in some groupings a member that is not its group's first rests instead (the
// groups stay canonical and p of them).
inline void makeRandomRestFree(std::mt19937_64& rng, ReductionResult& result) {
    result.restFree = true;
    for (Grouping& grouping : result.curve)
        for (auto& group : grouping.groups)
            if (group.size() > 1 && rng() % 2 == 0) {
                grouping.rest.push_back(group.back());
                group.pop_back();
            }
    for (Grouping& grouping : result.curve) std::sort(grouping.rest.begin(), grouping.rest.end());
}

inline InfluenceField randomInfluence(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    InfluenceField r;
    r.centre = {unit(rng), unit(rng)};
    r.radii = {0.01 + unit(rng), 0.01 + unit(rng)};
    if (rng() % 2) r.plateau = {r.radii[0] * 0.5, r.radii[1] * unit(rng) * 0.9 + 1e-9};
    r.rotation = randomDouble(rng, false);
    r.direction = {randomDouble(rng, false), randomDouble(rng, false), 1.0 + unit(rng)};
    r.magnitude = randomDouble(rng, false);
    r.falloff = static_cast<Falloff>(rng() % 4);
    return r;
}

inline ProjectDeformation randomDeformation(std::mt19937_64& rng) {
    ProjectDeformation d;
    if (rng() % 3 == 0) return d; // no face model
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    d.cascade.name = randomName(rng, "cascade");
    const int parameters = static_cast<int>(rng() % 5);
    for (int k = 0; k < parameters; ++k) {
        DeformParameter p;
        p.name = randomName(rng, "q" + std::to_string(k));
        p.min = -unit(rng);
        p.max = unit(rng) * 3;
        p.defaultValue = rng() % 2 ? 0.0 : p.max;
        d.cascade.parameters.push_back(p);
        d.values.push_back(p.min + (p.max - p.min) * unit(rng));
    }
    DeformationStage base;
    base.kind = StageKind::Constant;
    base.name = "base";
    if (rng() % 2) {
        base.field.sampled =
            sampleGrid(1 + static_cast<int>(rng() % 4), 1 + static_cast<int>(rng() % 4),
                       [&](double u, double v) { return Vec3(u, v, randomDouble(rng, false)); });
    }
    for (int i = static_cast<int>(rng() % 3); i > 0; --i)
        base.field.influences.push_back(randomInfluence(rng));
    d.cascade.stages.push_back(base);
    for (int k = 0; k < parameters; ++k) {
        DeformationStage stage;
        stage.name = randomName(rng, "field");
        stage.parameter = rng() % static_cast<std::size_t>(parameters);
        for (int i = 1 + static_cast<int>(rng() % 2); i > 0; --i)
            stage.field.influences.push_back(randomInfluence(rng));
        d.cascade.stages.push_back(stage);
    }
    for (int v = static_cast<int>(rng() % 4); v > 0; --v) {
        VisemeParameters viseme{randomName(rng, "pv" + std::to_string(v)), {}};
        for (const auto& p : d.cascade.parameters)
            if (rng() % 2) viseme.values.emplace_back(p.name, p.min + (p.max - p.min) * unit(rng));
        d.visemes.push_back(viseme);
    }
    return d;
}

// A random valid project saved as `projectFile`'s state; mesh files it references are created
// (empty: loading a project only checks that they exist).
inline Project randomProject(std::mt19937_64& rng, const std::filesystem::path& projectFile) {
    Project project;
    project.path = projectFile;
    const auto folder = projectFile.parent_path();
    const bool embedded = rng() % 2 == 0;
    const std::size_t vertices = 3 + rng() % 6;
    const int n = static_cast<int>(rng() % 7); // 0 = a new, empty project

    if (n > 0 || rng() % 2 == 0) {
        if (embedded) {
            project.neutral.embedded.positions = randomPoints(rng, vertices);
            if (rng() % 2 == 0)
                for (std::size_t i = 0; i < vertices; ++i)
                    project.neutral.embedded.uvs.emplace_back(randomDouble(rng, false),
                                                              randomDouble(rng, false));
            for (std::uint32_t i = 0; i + 2 < vertices; ++i)
                project.neutral.embedded.triangles.push_back({0, i + 1, i + 2});
        } else {
            project.neutral.file = "meshes/neutral.obj";
            writeText(folder / project.neutral.file, "");
        }
    }
    std::vector<std::string> names;
    for (int i = 0; i < n; ++i) {
        ProjectViseme viseme;
        viseme.name = randomName(rng, "v" + std::to_string(i));
        if (embedded && rng() % 3 != 0) {
            viseme.positions = randomPoints(rng, vertices);
        } else {
            viseme.file = std::filesystem::path("meshes") / ("viseme" + std::to_string(i) + ".ply");
            writeText(folder / viseme.file, "");
        }
        names.push_back(viseme.name);
        project.visemes.push_back(std::move(viseme));
    }

    if (n > 0 && rng() % 2 == 0) {
        const int phonemes = 1 + static_cast<int>(rng() % 8);
        for (int k = 0; k < phonemes; ++k) {
            const std::string phoneme = randomName(rng, "p" + std::to_string(k));
            project.frequencies.phonemes.entries.emplace_back(phoneme, randomDouble(rng, true));
            project.frequencies.map.entries.emplace_back(phoneme, names[rng() % names.size()]);
        }
        std::shuffle(project.frequencies.map.entries.begin(), project.frequencies.map.entries.end(), rng);
    } else {
        for (const auto& name : names)
            if (rng() % 4 != 0)
                project.frequencies.visemeFrequencies.entries.emplace_back(name, randomDouble(rng, true));
    }

    project.weights.mode = static_cast<WeightMode>(rng() % 3);
    if (project.weights.mode == WeightMode::Painted || rng() % 2 == 0) {
        const std::size_t count = embedded && project.neutral.isSet() ? vertices : 1 + rng() % 10;
        for (std::size_t i = 0; i < count; ++i) project.weights.painted.push_back(randomDouble(rng, true));
        project.weights.painted[rng() % count] = 0.25; // not all zero
    }

    project.reduction.target = 1 + static_cast<int>(rng() % static_cast<std::uint64_t>(std::max(n, 1)));
    if (n > 0 && rng() % 3 != 0) {
        ReductionResult result;
        const int m = 1 + static_cast<int>(rng() % static_cast<std::uint64_t>(n));
        for (int p = 1; p <= m; ++p) {
            Grouping grouping;
            switch (rng() % 4) {
            case 0: // ruled out by constraints
                grouping = {std::numeric_limits<double>::infinity(),
                            std::numeric_limits<double>::infinity(),
                            true,
                            {},
                            {}};
                break;
            case 1: // best found with a bound, no proof
                grouping.cost = randomDouble(rng, true);
                grouping.lowerBound = grouping.cost * std::uniform_real_distribution<double>(0.0, 1.0)(rng);
                grouping.groups = randomPartition(rng, n, p);
                break;
            default:
                grouping.cost = grouping.lowerBound = randomDouble(rng, true);
                grouping.optimal = true;
                grouping.groups = randomPartition(rng, n, p);
            }
            result.curve.push_back(std::move(grouping));
        }
        if (const auto pick = rng() % 3; pick > 0)
            result.method = pick == 1 ? ReductionMethod::BranchAndBound : ReductionMethod::ColumnGeneration;
        project.reduction.result = std::move(result);
    }
    if (n > 1 && rng() % 2 == 0) {
        auto name = [&] { return names[rng() % names.size()]; };
        auto pair = [&] {
            const std::string a = name();
            std::string b = name();
            while (b == a) b = name();
            return std::pair{a, b};
        };
        for (auto k = rng() % 3; k > 0; --k) project.reduction.constraints.pinned.push_back(name());
        for (auto k = rng() % 3; k > 0; --k) project.reduction.constraints.apart.push_back(pair());
        for (auto k = rng() % 3; k > 0; --k) project.reduction.constraints.together.push_back(pair());
    }
    project.deformation = randomDeformation(rng);
    project.refinement.kind = static_cast<CriterionKind>(rng() % 3);
    project.refinement.maxDepth = static_cast<int>(rng() % 31);
    project.refinement.depth.depth = static_cast<int>(rng() % 12);
    project.refinement.normals = {randomDouble(rng, true), randomDouble(rng, true)};
    project.refinement.contour = {randomDouble(rng, true), randomDouble(rng, true),
                                  1 + static_cast<int>(rng() % 32)};
    if (n > 0 && rng() % 2 == 0) project.editor.selectedViseme = names[rng() % names.size()];
    if (rng() % 2 == 0) { // the rest model (version 3)
        project.reduction.rest = static_cast<RestChoice>(rng() % 3);
        if (n > 0 && rng() % 2 == 0) project.reduction.restViseme = names[rng() % names.size()];
        if (project.reduction.result && rng() % 2 == 0) makeRandomRestFree(rng, *project.reduction.result);
    }
    return project;
}

} // namespace vl::test
