// A slider drag touches only the face's parameters: no tick validates the reduction's inputs
// (frequencies, weights, constraints), evaluates weights and frequencies again, samples the face
// again or changes the geometry the views upload (issue 31).
#include "ui/session/EditorSession.h"

#include <gtest/gtest.h>

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
