// A slider drag touches only the face's parameters: no tick validates the reduction's inputs
// (frequencies, weights, constraints) or evaluates weights and frequencies again (issue 31).
#include "ui/session/EditorSession.h"

#include <gtest/gtest.h>

namespace vl::ui {
namespace {

TEST(SliderTick, ValidatesOnlyTheParametersAndKeepsTheDerivedInputs) {
    EditorSession session;
    session.autoReduce = false;
    session.loadFace();
    session.generateVisemesFromFace(); // a viseme set: a document-wide validation would cost something
    session.setWeightMode(WeightMode::Area);
    const std::vector<double> weights = session.weights();
    const std::vector<double> frequencies = session.visemeFrequencies();
    const std::uint64_t validations = reductionInputValidations();
    const std::uint64_t evaluations = session.documentInputs().evaluations();
    const std::uint64_t revision = session.documentInputs().revision();

    const double start = session.face().parameters[0];
    for (int tick = 1; tick <= 20; ++tick) {
        session.setParameter(0, start + 0.01 * tick);
        EXPECT_EQ(session.weights(), weights);
        EXPECT_EQ(session.visemeFrequencies(), frequencies);
    }
    EXPECT_EQ(reductionInputValidations(), validations) << "a slider tick validated the whole document";
    EXPECT_EQ(session.documentInputs().evaluations(), evaluations) << "a slider tick recomputed the weights";
    EXPECT_EQ(session.documentInputs().revision(), revision);
    EXPECT_EQ(session.undoName(), "Set " + session.face().cascade->parameters[0].name); // one merged step
}

TEST(SliderTick, AnEditOfTheInputsValidatesAndReevaluatesWhatDependsOnIt) {
    EditorSession session;
    session.autoReduce = false;
    session.loadFace();
    session.generateVisemesFromFace();
    session.useDirectFrequencies(); // the per-viseme frequencies edited below
    session.weights();
    session.visemeFrequencies();
    const std::uint64_t validations = reductionInputValidations();
    const std::uint64_t evaluations = session.documentInputs().evaluations();
    const std::uint64_t revision = session.documentInputs().revision();

    session.setVisemeFrequency(0, 3.0); // frequencies change, the weights stay
    EXPECT_GT(reductionInputValidations(), validations);
    EXPECT_NE(session.documentInputs().revision(), revision);
    session.weights();
    EXPECT_EQ(session.documentInputs().evaluations(), evaluations);
    session.visemeFrequencies();
    EXPECT_EQ(session.documentInputs().evaluations(), evaluations + 1);
    // Bad input is still refused whatever the tags say.
    EXPECT_THROW(session.setParameter(0, 1e9), InputError);
}

} // namespace
} // namespace vl::ui
