// The reduction's rest model as document state: new documents are rest-free when the set has a rest
// viseme, setRest is one edit that changes the reduction inputs, names follow renames and removals,
// and projects carry it both ways.
#include "DocumentTestSupport.h"

#include <gtest/gtest.h>

namespace vl {
namespace {

TEST(RestCommands, NewDocumentsAreRestFreeWithTheirSil) {
    const Document document = test::faceDocument();
    EXPECT_EQ(document.rest, RestChoice::Auto);
    const RestPose rest = documentRestPose(document);
    EXPECT_TRUE(rest.free);
    EXPECT_EQ(rest.viseme, document.visemes->find("sil"));
    EXPECT_EQ(rest.neutral.data(), document.visemes->neutral.positions.data()); // a view, no copy
    // sil rests, so it is no key: one key fewer than visemes.
    EXPECT_EQ(documentMaxKeys(document), static_cast<int>(document.visemeCount()) - 1);
}

TEST(RestCommands, SetRestChangesTheModelTheRestVisemeAndTheReductionInputs) {
    const Document start = test::faceDocument();
    const Document keyed = edit::setRest(start, RestChoice::Key, "");
    EXPECT_FALSE(documentRestPose(keyed).free);
    EXPECT_FALSE(sameReductionInputs(start, keyed)); // the curve is computed again
    EXPECT_EQ(documentMaxKeys(keyed), static_cast<int>(keyed.visemeCount()));

    const Document pp = edit::setRest(start, RestChoice::Free, "PP");
    EXPECT_EQ(documentRestPose(pp).viseme, start.visemes->find("PP"));
    EXPECT_FALSE(sameReductionInputs(start, pp));

    EXPECT_EQ(test::refusal([&] { edit::setRest(start, RestChoice::Free, "nope"); }),
              "rest viseme: the set has no viseme 'nope'");
    // With every viseme a key, a rest that takes one away lowers the target to what is possible.
    const int n = static_cast<int>(start.visemeCount());
    const Document all = edit::setTarget(keyed, n);
    EXPECT_EQ(edit::setRest(all, RestChoice::Free, "").target, n - 1);
    EXPECT_EQ(test::refusal([&] { edit::setTarget(start, n); }),
              "target: m = " + std::to_string(n) + ": with the rest free, sil rests, so at most " +
                  std::to_string(n - 1) + " keys");
}

TEST(RestCommands, TheRestVisemeFollowsRenamesAndRemovals) {
    const Document start = edit::setRest(test::faceDocument(), RestChoice::Free, "PP");
    const int pp = start.visemes->find("PP");
    EXPECT_EQ(edit::renameViseme(start, pp, "closed").restViseme, "closed");
    const Document removed = edit::removeViseme(start, pp);
    EXPECT_TRUE(removed.restViseme.empty()); // back to sil
    EXPECT_EQ(documentRestPose(removed).viseme, removed.visemes->find("sil"));
}

TEST(RestCommands, ProjectsCarryTheModelBothWays) {
    const Document start = edit::setRest(test::faceDocument(), RestChoice::Free, "PP");
    const Project project = projectFromDocument(start);
    EXPECT_EQ(project.reduction.rest, RestChoice::Free);
    EXPECT_EQ(project.reduction.restViseme, "PP");
    const Document loaded = documentFromProject(project).document;
    EXPECT_EQ(loaded.rest, RestChoice::Free);
    EXPECT_EQ(loaded.restViseme, "PP");
    // A project file without the field (the keyed model) opens keyed.
    Project old = project;
    old.reduction.rest = RestChoice::Key;
    old.reduction.restViseme.clear();
    EXPECT_FALSE(documentRestPose(documentFromProject(old).document).free);
}

} // namespace
} // namespace vl
