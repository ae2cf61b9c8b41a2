// Edits are tagged with the parts they change (changedParts); validation and the memoized inputs
// (DocumentInputs) re-evaluate only what depends on them.
#include "core/document/DocumentInputs.h"
#include "core/document/Commands.h"
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

} // namespace
} // namespace vl
