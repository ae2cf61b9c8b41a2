// Edits are tagged with the parts they change (changedParts); validation and the memoized inputs
// (DocumentInputs) re-evaluate only what depends on them.
#include "core/document/DocumentInputs.h"
#include "core/document/Commands.h"
#include "core/project/ReduceInputs.h"
#include "tests/document/DocumentTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace vl {
namespace {

TEST(DocumentParts, EachEditIsTaggedWithWhatItChanged) {
    const Document document = test::faceDocument();
    EXPECT_EQ(changedParts(document, document), 0u);
    EXPECT_EQ(changedParts(document, edit::setParameter(document, 0, 0.25)), kFaceParameterPart);
    EXPECT_EQ(changedParts(document, edit::setTarget(document, 2)), kTargetPart);
    EXPECT_EQ(changedParts(document, edit::setWeightMode(document, WeightMode::Area)), kWeightPart);
    EXPECT_EQ(changedParts(document, edit::setVisemeFrequency(document, 0, 2.0)), kFrequencyPart);
}

TEST(DocumentParts, ASliderTickValidatesOnlyTheParameters) {
    const Document document = test::faceDocument();
    const std::uint64_t before = reductionInputValidations();
    Document moved = document;
    for (int tick = 1; tick <= 10; ++tick) moved = edit::setParameter(moved, 0, 0.02 * tick);
    EXPECT_EQ(reductionInputValidations(), before);
    EXPECT_THROW(edit::setParameter(moved, 0, 1e9), InputError); // still checked
    edit::setTarget(document, 2);
    EXPECT_EQ(reductionInputValidations(), before + 1);
}

TEST(DocumentInputs, ReevaluatesOnlyWhatTheChangedPartsFeed) {
    auto document = std::make_shared<const Document>(test::faceDocument());
    DocumentInputs inputs(document);
    const std::vector<double> weights = inputs.weights();
    inputs.frequencies();
    ASSERT_EQ(inputs.evaluations(), 2u);
    const std::uint64_t revision = inputs.reductionRevision();

    auto moved = std::make_shared<const Document>(edit::setParameter(*document, 0, 0.3));
    inputs.update(moved, changedParts(*document, *moved));
    inputs.weights();
    inputs.frequencies();
    EXPECT_EQ(inputs.evaluations(), 2u);
    EXPECT_EQ(inputs.reductionRevision(), revision);

    auto area = std::make_shared<const Document>(edit::setWeightMode(*moved, WeightMode::Area));
    inputs.update(area, changedParts(*moved, *area));
    EXPECT_NE(inputs.reductionRevision(), revision);
    inputs.frequencies();
    EXPECT_EQ(inputs.evaluations(), 2u);
    EXPECT_NE(inputs.weights(), weights);
    EXPECT_EQ(inputs.weights(), documentWeights(*area));
    EXPECT_EQ(inputs.evaluations(), 3u);
}

// Each part's revision changes exactly when that part does: a cache keyed on the face's revision
// (its samples) survives a slider tick, one keyed on the parameters does not.
TEST(DocumentInputs, EachPartsRevisionChangesOnlyWithThatPart) {
    auto document = std::make_shared<const Document>(test::faceDocument());
    DocumentInputs inputs(document);
    const std::uint64_t face = inputs.revision(kFacePart);
    const std::uint64_t parameters = inputs.revision(kFaceParameterPart);
    const std::uint64_t weights = inputs.revision(kWeightPart);

    auto moved = std::make_shared<const Document>(edit::setParameter(*document, 0, 0.3));
    inputs.update(moved, changedParts(*document, *moved));
    EXPECT_EQ(inputs.revision(kFacePart), face);
    EXPECT_NE(inputs.revision(kFaceParameterPart), parameters);
    EXPECT_EQ(inputs.revision(kWeightPart), weights);
    // Several parts: changes when any of them does.
    EXPECT_NE(inputs.revision(kFacePart | kFaceParameterPart), std::max(face, parameters));

    auto area = std::make_shared<const Document>(edit::setWeightMode(*moved, WeightMode::Area));
    inputs.update(area, changedParts(*moved, *area));
    EXPECT_NE(inputs.revision(kWeightPart), weights);
    EXPECT_EQ(inputs.revision(kFacePart), face);

    // A new document: every part is new, even with equal contents.
    inputs.reset(area);
    EXPECT_NE(inputs.revision(kFacePart), face);
}

// The reduction curve of the document's inputs, as a background run would deliver it.
std::shared_ptr<const ReductionResult> curveOf(const Document& document) {
    ReduceInputs inputs{document.visemes, document.frequencies, {}};
    inputs.settings.target = static_cast<int>(document.visemeCount()); // the whole curve, p = 1..n
    return std::make_shared<const ReductionResult>(reduce(inputs, ReducePolicy::batch()).result);
}

// The curve is the one input computed elsewhere: accepted only for the inputs it was computed for,
// dropped when they change, kept when only the target does; the reduced model derives from it and
// equals the one every front end builds (ReduceInputs.h).
TEST(DocumentInputs, HoldTheCurveOfTheirInputsAndTheReducedModelOfTheTarget) {
    auto document = std::make_shared<const Document>(edit::setTarget(test::faceDocument(), 3));
    DocumentInputs inputs(document);
    EXPECT_EQ(inputs.curve(), nullptr);
    EXPECT_EQ(inputs.reducedModel(), nullptr);
    const auto curve = curveOf(*document);

    inputs.setCurve(curve, inputs.reductionRevision() + 1); // computed for other inputs: ignored
    EXPECT_EQ(inputs.curve(), nullptr);
    EXPECT_EQ(inputs.curveRevision(), 0u);
    inputs.setCurve(curve, inputs.reductionRevision());
    ASSERT_EQ(inputs.curve(), curve.get());
    ASSERT_NE(inputs.grouping(), nullptr);
    EXPECT_EQ(inputs.grouping()->groups.size(), 3u);
    const ReducedModel* model = inputs.reducedModel();
    ASSERT_NE(model, nullptr);
    const ReduceInputs direct{document->visemes, document->frequencies, {}};
    const ReducedModel expected = reducedModel(direct, &curve->curve[2], ReducePolicy::batch());
    ASSERT_EQ(model->keys.size(), expected.keys.size());
    EXPECT_EQ(model->keys[0].positions, expected.keys[0].positions);
    EXPECT_EQ(inputs.reducedModel(), model); // memoized

    // A slider tick keeps the curve; a new target picks another grouping of the same curve.
    auto moved = std::make_shared<const Document>(edit::setParameter(*document, 0, 0.3));
    inputs.update(moved, changedParts(*document, *moved));
    EXPECT_EQ(inputs.curve(), curve.get());
    auto two = std::make_shared<const Document>(edit::setTarget(*moved, 2));
    inputs.update(two, changedParts(*moved, *two));
    EXPECT_EQ(inputs.curve(), curve.get());
    ASSERT_NE(inputs.reducedModel(), nullptr);
    EXPECT_EQ(inputs.reducedModel()->keys.size(), 2u);

    // New weights: the curve was computed for other inputs.
    auto area = std::make_shared<const Document>(edit::setWeightMode(*two, WeightMode::Area));
    inputs.update(area, changedParts(*two, *area));
    EXPECT_EQ(inputs.curve(), nullptr);
    EXPECT_EQ(inputs.grouping(), nullptr);
    EXPECT_EQ(inputs.reducedModel(), nullptr);
    const std::uint64_t revision = inputs.curveRevision();
    inputs.setCurve(curveOf(*area), inputs.reductionRevision());
    EXPECT_NE(inputs.curve(), nullptr);
    EXPECT_GT(inputs.curveRevision(), revision);
}

TEST(DocumentInputs, TheFullModelHasOneKeyPerViseme) {
    auto document = std::make_shared<const Document>(test::faceDocument());
    DocumentInputs inputs(document);
    const ReducedModel& full = inputs.fullModel();
    EXPECT_EQ(full.keys.size(), document->visemeCount());
    EXPECT_EQ(&inputs.fullModel(), &full);
}

} // namespace
} // namespace vl
