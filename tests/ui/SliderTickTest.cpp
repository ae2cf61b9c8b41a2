// A slider drag touches only the face's parameters: no tick validates the reduction's inputs
// (frequencies, weights, constraints), evaluates weights and frequencies again, samples the face
// again or changes the geometry the views upload (issue 31).
#include "ui/session/EditorSession.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace vl::ui {
namespace {

TEST(SliderTick, ValidatesOnlyTheParametersAndKeepsTheDerivedInputs) {
    EditorSession session;
    session.reduction().setAutomatic(false);
    session.face().load();
    session.face().generateVisemes(); // a viseme set: a document-wide validation would cost something
    session.weights().setMode(WeightMode::Area);
    const std::vector<double> weights = session.weights().values();
    const std::vector<double> frequencies = session.frequencies().values();
    const std::uint64_t validations = reductionInputValidations();
    const std::uint64_t evaluations = session.documentInputs().evaluations();
    const std::uint64_t revision = session.documentInputs().reductionRevision();
    // What the views show of the face: sampled once per cascade and mesh, not per tick.
    session.face().samples();
    const std::shared_ptr<const HeadPartSamples> parts = session.face().parts();
    const std::uint64_t samplesRevision = session.face().samplesRevision();
    const std::uint64_t geometryRevision = session.history().geometryRevision();

    const double start = session.document().face.parameters[0];
    for (int tick = 1; tick <= 20; ++tick) {
        session.face().setParameter(0, start + 0.01 * tick);
        EXPECT_EQ(session.weights().values(), weights);
        EXPECT_EQ(session.frequencies().values(), frequencies);
        EXPECT_TRUE(session.face().samplesReady()) << "a slider tick dropped the face's samples";
        EXPECT_EQ(session.face().parts(), parts) << "a slider tick made the head's parts again";
    }
    EXPECT_EQ(session.face().samplesRevision(), samplesRevision);
    EXPECT_EQ(session.history().geometryRevision(), geometryRevision) << "the views would upload the meshes";
    EXPECT_EQ(reductionInputValidations(), validations) << "a slider tick validated the whole document";
    EXPECT_EQ(session.documentInputs().evaluations(), evaluations) << "a slider tick recomputed the weights";
    EXPECT_EQ(session.documentInputs().reductionRevision(), revision);
    EXPECT_EQ(session.history().undoName(),
              "Set " + session.document().face.cascade->parameters[0].name); // one merged step
}

// The same drag on a face of about 100,000 vertices with its generated viseme set: a tick costs the
// edit alone (no validation of the set, no re-sampling, no geometry for the views to upload).
// The tick times are printed (min / median / max), not checked: the machine decides them.
TEST(SliderTick, OnAHundredThousandVertexFaceATickRevalidatesAndReuploadsNothing) {
    EditorSession session;
    session.reduction().setAutomatic(false);
    session.face().load(face::Individual::Bundled, 316); // 317 x 317 (u,v) grid
    ASSERT_GE(session.document().face.domain->uvs.size(), 100000u);
    session.face().generateVisemes();
    session.face().samples();
    session.weights().values();
    session.frequencies().values();
    const std::uint64_t validations = reductionInputValidations();
    const std::uint64_t evaluations = session.documentInputs().evaluations();
    const std::uint64_t geometryRevision = session.history().geometryRevision();

    std::vector<double> milliseconds;
    const double start = session.document().face.parameters[0];
    for (int tick = 1; tick <= 30; ++tick) {
        const auto before = std::chrono::steady_clock::now();
        session.beginFrame();
        session.face().setParameter(0, start + 0.01 * tick);
        session.poll();
        ASSERT_TRUE(session.face().samplesReady());
        milliseconds.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - before).count());
    }
    EXPECT_EQ(reductionInputValidations(), validations);
    EXPECT_EQ(session.documentInputs().evaluations(), evaluations);
    EXPECT_EQ(session.history().geometryRevision(), geometryRevision);
    std::sort(milliseconds.begin(), milliseconds.end());
    std::printf("slider tick on %zu vertices x %zu visemes: min %.3f ms, median %.3f ms, max %.3f ms\n",
                session.document().face.domain->uvs.size(), session.document().visemeCount(),
                milliseconds.front(), milliseconds[milliseconds.size() / 2], milliseconds.back());
}

TEST(SliderTick, AnEditOfTheInputsValidatesAndReevaluatesWhatDependsOnIt) {
    EditorSession session;
    session.reduction().setAutomatic(false);
    session.face().load();
    session.face().generateVisemes();
    session.frequencies().useDirectFrequencies(); // the per-viseme frequencies edited below
    session.weights().values();
    session.frequencies().values();
    const std::uint64_t validations = reductionInputValidations();
    const std::uint64_t evaluations = session.documentInputs().evaluations();
    const std::uint64_t revision = session.documentInputs().reductionRevision();

    session.frequencies().setVisemeFrequency(0, 3.0); // frequencies change, the weights stay
    EXPECT_GT(reductionInputValidations(), validations);
    EXPECT_NE(session.documentInputs().reductionRevision(), revision);
    session.weights().values();
    EXPECT_EQ(session.documentInputs().evaluations(), evaluations);
    session.frequencies().values();
    EXPECT_EQ(session.documentInputs().evaluations(), evaluations + 1);
    // Bad input is still refused whatever the tags say.
    EXPECT_THROW(session.face().setParameter(0, 1e9), InputError);
}

} // namespace
} // namespace vl::ui
