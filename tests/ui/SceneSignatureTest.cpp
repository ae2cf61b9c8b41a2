// The signature a 3D view compares before drawing its scene again (ui/render/SceneSignature.h).
#include "ui/render/SceneSignature.h"

#include <gtest/gtest.h>

#include <set>

namespace vl::ui {
namespace {

TEST(SceneSignature, EqualInputsGiveEqualSignaturesAndAnyChangedByteAnother) {
    const float weights[] = {0.0f, 0.25f, 1.0f};
    SceneSignature a, b;
    a.add(weights, sizeof weights);
    b.add(weights, sizeof weights);
    EXPECT_EQ(a.value(), b.value());

    float changed[] = {0.0f, 0.25f, 1.0f};
    changed[1] = 0.2500001f;
    SceneSignature c;
    c.add(changed, sizeof changed);
    EXPECT_NE(a.value(), c.value());

    // Order matters: the same draws in another order are another picture (blending, overlays).
    SceneSignature ab, ba;
    ab.addValue(1);
    ab.addValue(2);
    ba.addValue(2);
    ba.addValue(1);
    EXPECT_NE(ab.value(), ba.value());
}

TEST(SceneSignature, RecordingIsScopedAndNests) {
    EXPECT_EQ(SceneSignature::recording(), nullptr);
    SceneSignature outer, inner;
    {
        const SceneSignature::Recording recordOuter(outer);
        EXPECT_EQ(SceneSignature::recording(), &outer);
        {
            const SceneSignature::Recording recordInner(inner);
            EXPECT_EQ(SceneSignature::recording(), &inner);
        }
        EXPECT_EQ(SceneSignature::recording(), &outer);
    }
    EXPECT_EQ(SceneSignature::recording(), nullptr);
}

TEST(SceneSignature, UploadRevisionsNeverRepeat) {
    std::set<std::uint64_t> seen;
    for (int i = 0; i < 1000; ++i) EXPECT_TRUE(seen.insert(nextUploadRevision()).second);
}

} // namespace
} // namespace vl::ui
