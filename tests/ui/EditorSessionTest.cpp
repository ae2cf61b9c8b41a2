// Drives the editor's session the way the panels do (load the sample, move a slider, run a
// reduction, paint, undo) and checks the resulting state; bad input must change nothing.
#include "ui/session/EditorSession.h"
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/deform/Visemes.h"
#include "core/export/Export.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"
#include "core/face/FaceFrame.h"
#include "core/face/HeadParts.h"
#include "core/import/VisemeFile.h"
#include "core/io/MeshIO.h"
#include "core/paint/WeightBrush.h"
#include "core/project/ProjectRun.h"
#include "ui/session/BundledAssets.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <thread>

namespace vl::ui {
namespace {

std::filesystem::path tempDir(const char* name) {
    const auto dir = std::filesystem::temp_directory_path() / ("visemelab-ui-" + std::string(name));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// The face's own viseme set (spoken frequencies: the bundled table), switched to direct viseme
// frequencies that the tests edit.
void loadGeneratedSet(EditorSession& session) {
    session.face().load();
    session.face().generateVisemes();
    ASSERT_TRUE(session.document().frequencies.isPhonemeBased());
    session.frequencies().useDirectFrequencies();
    ASSERT_FALSE(session.document().frequencies.isPhonemeBased());
}

// The same with target m and no automatic reduction (no curve until something runs one).
void loadUnreducedSet(EditorSession& session, int m) {
    session.reduction().setAutomatic(false);
    loadGeneratedSet(session);
    session.reduction().setTarget(m);
}

TEST(EditorSession, LoadsTheSampleAsAnInterpolableVisemeSet) {
    EditorSession session;
    session.files().loadSample();
    ASSERT_NE(session.visemes(), nullptr);
    EXPECT_EQ(session.visemeCount(), 15u);
    EXPECT_GT(session.visemes()->vertexCount(), 1000u);
    EXPECT_FALSE(session.history().modified());
    EXPECT_FALSE(session.history().canUndo());
}

TEST(EditorSession, ReductionRunsInTheBackgroundAndMatchesTheCoreReference) {
    EditorSession session;
    session.files().loadSample();
    session.reduction().setTarget(10);
    session.reduction().start();
    session.finishBackgroundWork();
    const ReductionResult* curve = session.reduction().curve();
    ASSERT_NE(curve, nullptr);
    // The sample runs the default model: the rest is free and sil rests, so p = 1..n - 1 keys.
    ASSERT_TRUE(curve->restFree);
    ASSERT_EQ(curve->curve.size(), session.visemeCount() - 1); // p = 1..n - 1 for the plot
    const Grouping* grouping = session.reduction().grouping();
    ASSERT_NE(grouping, nullptr);
    EXPECT_EQ(grouping->groups.size(), 10u);
    const int sil = session.visemes()->find("sil");
    EXPECT_NE(std::find(grouping->rest.begin(), grouping->rest.end(), sil), grouping->rest.end());
    // The cost the panel shows is the slow, obvious evaluation of the same grouping (its keys plus
    // each resting viseme against the neutral).
    std::vector<std::vector<Vec3>> shapes;
    for (const auto& v : session.visemes()->visemes) shapes.push_back(v.positions);
    const double reference =
        restFreeGroupingCost(shapes, session.frequencies().values(), session.weights().values(),
                             grouping->groups, grouping->rest, session.visemes()->neutral.positions);
    EXPECT_NEAR(grouping->cost, reference, 1e-9 * std::max(1.0, reference));
    // Costs decrease with more groups and reach 0 at p = n.
    for (std::size_t p = 1; p < curve->curve.size(); ++p)
        EXPECT_LE(curve->curve[p].cost, curve->curve[p - 1].cost + 1e-12);
    EXPECT_NEAR(curve->curve.back().cost, 0.0, 1e-12);
    const ReducedModel* merged = session.reduction().reducedModel();
    ASSERT_NE(merged, nullptr);
    EXPECT_EQ(merged->keys.size(), 10u);
    // The merged view is the CLI's model: same keys, names and positions, bit for bit.
    const ReduceOutcome cli = reduceProject(session.files().projectSnapshot(), *session.visemes());
    ASSERT_EQ(cli.model.keys.size(), merged->keys.size());
    for (std::size_t k = 0; k < merged->keys.size(); ++k) {
        EXPECT_EQ(merged->keys[k].name, cli.model.keys[k].name);
        EXPECT_EQ(merged->keys[k].positions, cli.model.keys[k].positions);
    }
    EXPECT_EQ(merged->phonemeToKey, cli.model.phonemeToKey);
}

TEST(EditorSession, MergedViewRefusesAPhonemeMapNamingAnUnknownViseme) {
    EditorSession session;
    session.reduction().setAutomatic(false);
    session.files().loadSample();
    ASSERT_TRUE(session.document().frequencies.isPhonemeBased());
    session.reduction().start();
    session.finishBackgroundWork();
    ASSERT_NE(session.reduction().reducedModel(), nullptr);
    // A map entry for a phoneme the table does not count, naming a viseme the set lacks: the
    // frequencies are still valid, but no model is built with a silently dropped entry.
    FrequencySource source = session.document().frequencies;
    source.map.entries.emplace_back("ZZ", "nope");
    session.frequencies().setSource(source, "extra map entry");
    session.reduction().start();
    session.finishBackgroundWork();
    ASSERT_NE(session.reduction().grouping(), nullptr);
    try {
        session.reduction().reducedModel();
        FAIL() << "an unknown viseme in the map was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown viseme 'nope' (phonemes ZZ)"), std::string::npos)
            << e.what();
    }
}

TEST(EditorSession, ChangingAnInputInvalidatesTheCurveUntilTheNextRun) {
    EditorSession session;
    session.reduction().setAutomatic(false);
    loadGeneratedSet(session);
    session.reduction().start();
    session.finishBackgroundWork();
    ASSERT_NE(session.reduction().curve(), nullptr);
    session.frequencies().setVisemeFrequency(session.visemes()->find("aa"), 5.0);
    EXPECT_EQ(session.reduction().curve(), nullptr);
    session.reduction().start();
    session.finishBackgroundWork();
    ASSERT_NE(session.reduction().curve(), nullptr);
    // Changing only m reuses the curve: no recomputation needed.
    session.reduction().setTarget(4);
    ASSERT_NE(session.reduction().grouping(), nullptr);
    EXPECT_EQ(session.reduction().grouping()->groups.size(), 4u);
}

TEST(EditorSession, AutoReduceStartsFromPoll) {
    EditorSession session;
    session.files().loadSample();
    session.poll();
    session.finishBackgroundWork();
    EXPECT_NE(session.reduction().curve(), nullptr);
}

TEST(EditorSession, SliderDragIsOneUndoStep) {
    EditorSession session;
    session.face().load();
    const int jaw = session.document().face.cascade->findParameter("jaw_open");
    ASSERT_GE(jaw, 0);
    const double before = session.document().face.parameters[static_cast<std::size_t>(jaw)];
    const std::size_t steps = 5;
    for (std::size_t i = 1; i <= steps; ++i) session.face().setParameter(jaw, 0.1 * static_cast<double>(i));
    session.history().endEdit();
    EXPECT_DOUBLE_EQ(session.document().face.parameters[static_cast<std::size_t>(jaw)], 0.5);
    session.history().undo();
    EXPECT_DOUBLE_EQ(session.document().face.parameters[static_cast<std::size_t>(jaw)], before);
    session.history().redo();
    EXPECT_DOUBLE_EQ(session.document().face.parameters[static_cast<std::size_t>(jaw)], 0.5);
}

TEST(EditorSession, OutOfRangeParameterIsRefusedAndChangesNothing) {
    EditorSession session;
    session.face().load();
    const auto before = session.document().face.parameters;
    EXPECT_THROW(session.face().setParameter(0, 1e9), InputError);
    EXPECT_EQ(session.document().face.parameters, before);
}

TEST(EditorSession, Viseme_PresetAndFieldEditsAreUndoable) {
    EditorSession session;
    session.face().load();
    session.face().applyVisemePreset("aa");
    const int jaw = session.document().face.cascade->findParameter("jaw_open");
    EXPECT_GT(session.document().face.parameters[static_cast<std::size_t>(jaw)], 0.0);
    // Edit the first analytic region found.
    const auto& stages = session.document().face.cascade->stages;
    int stage = -1;
    for (std::size_t s = 0; s < stages.size() && stage < 0; ++s)
        if (!stages[s].field.influences.empty()) stage = static_cast<int>(s);
    ASSERT_GE(stage, 0);
    const auto* cascadeBefore = session.document().face.cascade.get();
    InfluenceField field = stages[static_cast<std::size_t>(stage)].field.influences[0];
    field.magnitude *= 2.0;
    session.face().setInfluence(stage, 0, field);
    EXPECT_DOUBLE_EQ(session.document()
                         .face.cascade->stages[static_cast<std::size_t>(stage)]
                         .field.influences[0]
                         .magnitude,
                     field.magnitude);
    session.history().undo();
    EXPECT_EQ(session.document().face.cascade.get(), cascadeBefore);
    // An invalid region (zero radius) is refused.
    field.radii = Vec2(0.0, 0.0);
    EXPECT_THROW(session.face().setInfluence(stage, 0, field), InputError);
    EXPECT_EQ(session.document().face.cascade.get(), cascadeBefore);
}

TEST(EditorSession, NonInterpolableImportShowsTheCoreErrorAndChangesNothing) {
    EditorSession session;
    session.files().loadSample();
    const auto dir = tempDir("import");
    MeshData broken;
    broken.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    broken.triangles = {Triangle{0, 1, 2}};
    writeMesh(dir / "broken.obj", broken);
    const VisemeSet* before = session.visemes();
    try {
        session.authoring().importViseme("broken", dir / "broken.obj");
        FAIL() << "import of a non-interpolable mesh succeeded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("not interpolable"), std::string::npos) << e.what();
    }
    EXPECT_EQ(session.visemes(), before);
    EXPECT_FALSE(session.history().canUndo());
    // attempt() turns the same failure into a status message, as the panels do.
    EXPECT_FALSE(
        session.attempt("Import", [&] { session.authoring().importViseme("broken", dir / "broken.obj"); }));
    ASSERT_FALSE(session.messages().empty());
    EXPECT_EQ(session.messages().back().kind, StatusMessage::Kind::Error);

    // An interpolable mesh (a copy of a viseme) imports, and undo removes it again.
    writeMesh(dir / "copy.obj", session.visemes()->meshOf(0));
    session.authoring().importViseme("copy", dir / "copy.obj");
    EXPECT_EQ(session.visemeCount(), 16u);
    session.history().undo();
    EXPECT_EQ(session.visemeCount(), 15u);
    EXPECT_EQ(session.visemes(), before);
}

TEST(EditorSession, NegativeFrequencyIsRefused) {
    EditorSession session;
    loadGeneratedSet(session);
    const auto before = session.frequencies().values();
    EXPECT_THROW(session.frequencies().setVisemeFrequency(0, -1.0), InputError);
    EXPECT_EQ(session.frequencies().values(), before);
}

TEST(EditorSession, PaintStrokeIsOneUndoStep) {
    EditorSession session;
    session.files().loadSample();
    const VisemeSet& set = *session.visemes();
    std::vector<double> weights(set.vertexCount(), 0.5);
    WeightBrush brush;
    brush.radius = 1.0;
    brush.strength = 0.5;
    for (int dab = 0; dab < 3; ++dab)
        applyBrushDab(set.neutral.positions, set.neutral.triangles, brush, set.neutral.positions[100],
                      weights);
    const WeightMode before = session.document().weights.mode;
    session.weights().setPainted(weights, "Paint stroke");
    EXPECT_EQ(session.document().weights.mode, WeightMode::Painted);
    EXPECT_EQ(session.weights().values(), weights);
    session.history().undo();
    EXPECT_EQ(session.document().weights.mode, before);
}

TEST(EditorSession, SaveAndReopenProjectKeepsTheState) {
    const auto dir = tempDir("project");
    EditorSession session;
    loadGeneratedSet(session);
    session.reduction().setTarget(7);
    session.frequencies().setVisemeFrequency(3, 2.5);
    session.reduction().start();
    session.finishBackgroundWork();
    ASSERT_TRUE(session.history().modified());
    session.files().saveProject(dir / "p.vlproj");
    EXPECT_FALSE(session.history().modified());

    EditorSession reopened;
    reopened.files().openProject(dir / "p.vlproj");
    ASSERT_NE(reopened.visemes(), nullptr);
    EXPECT_EQ(reopened.visemeCount(), session.visemeCount());
    EXPECT_EQ(reopened.document().target, 7);
    EXPECT_EQ(reopened.frequencies().values(), session.frequencies().values());
    EXPECT_EQ(reopened.visemes()->visemes[5].positions, session.visemes()->visemes[5].positions);
    // The result the file recorded is shown at once (a fresh reduction replaces it).
    ASSERT_NE(reopened.reduction().grouping(), nullptr);
    EXPECT_EQ(reopened.reduction().grouping()->groups, session.reduction().grouping()->groups);
    // A new document is rest-free (the face's set has sil): its resting visemes come back too.
    EXPECT_EQ(reopened.document().rest, RestChoice::Auto);
    EXPECT_TRUE(reopened.reduction().curve()->restFree);
    EXPECT_FALSE(reopened.reduction().grouping()->rest.empty());
    EXPECT_EQ(reopened.reduction().grouping()->rest, session.reduction().grouping()->rest);
}

TEST(EditorSession, TheRestModelIsOneUndoStepTheReductionFollows) {
    EditorSession session;
    loadGeneratedSet(session);
    session.reduction().setTarget(5);
    session.reduction().start();
    session.finishBackgroundWork();
    ASSERT_TRUE(session.reduction().curve() && session.reduction().curve()->restFree);
    session.reduction().setRest(RestChoice::Key, "");
    EXPECT_EQ(session.history().undoName(), "Rest is a key");
    EXPECT_EQ(session.reduction().curve(), nullptr); // the inputs changed: the curve is computed again
    session.reduction().start();
    session.finishBackgroundWork();
    ASSERT_NE(session.reduction().grouping(), nullptr);
    EXPECT_FALSE(session.reduction().curve()->restFree);
    EXPECT_TRUE(session.reduction().grouping()->rest.empty());
    EXPECT_EQ(session.reduction().grouping()->groups.size(), 5u);
    session.history().undo();
    EXPECT_EQ(session.document().rest, RestChoice::Auto);
}

TEST(EditorSession, ReopenedProjectKeepsTheRetargetingChoice) {
    const auto dir = tempDir("retarget");
    EditorSession session;
    session.reduction().setAutomatic(false);
    session.face().load();
    session.face().setIndividual(face::Individual::Retarget);
    session.files().saveProject(dir / "retarget.vlproj");

    EditorSession reopened;
    reopened.files().openProject(dir / "retarget.vlproj");
    ASSERT_NE(reopened.document().face.cascade, nullptr);
    EXPECT_EQ(reopened.document().face.individual, face::Individual::Retarget);
    // The loaded geometry is the retargeted one, and going back to the bundled face is one edit.
    EXPECT_EQ(reopened.document().face.cascade->stages[0].field.sampled.samples,
              session.document().face.cascade->stages[0].field.sampled.samples);
    reopened.face().setIndividual(face::Individual::Bundled);
    EXPECT_EQ(reopened.document().face.cascade->stages[0].field.sampled.samples,
              face::makeBundledFace().stages[0].field.sampled.samples);
}

TEST(EditorSession, BrokenProjectFileIsReportedAndTheOpenProjectStays) {
    const auto dir = tempDir("broken-project");
    writeFileAtomically(dir / "bad.vlproj",
                        "{ \"format\": \"visemelab-project\", \"version\": 1, \"visemes\": 3 }");
    EditorSession session;
    session.files().loadSample();
    const VisemeSet* before = session.visemes();
    EXPECT_FALSE(session.attempt("Open project", [&] { session.files().openProject(dir / "bad.vlproj"); }));
    EXPECT_EQ(session.visemes(), before);
    EXPECT_NE(session.messages().back().text.find("bad.vlproj"), std::string::npos)
        << session.messages().back().text;
}

} // namespace
} // namespace vl::ui

namespace vl::ui {
namespace {

TEST(EditorSession, RefinementRunsInTheBackgroundAndIsUndoable) {
    EditorSession session;
    session.face().load();
    const MeshData* gridDomain = session.document().face.domain.get();
    CriterionSettings settings = session.document().refinement;
    settings.kind = CriterionKind::Depth;
    settings.depth.depth = 3;
    session.face().setRefinementSettings(settings);
    session.face().startRefinement(RefineAction::Refine);
    session.finishBackgroundWork();
    ASSERT_TRUE(session.face().lastRefinement().has_value());
    const MeshData& refined = *session.document().face.domain;
    EXPECT_NE(&refined, gridDomain);
    EXPECT_EQ(refined.triangles.size(), session.face().lastRefinement()->triangles);
    EXPECT_EQ(refined.uvs.size(), refined.positions.size());
    EXPECT_EQ(session.face().lastRefinement()->maxLevel, 3);
    session.history().undo();
    EXPECT_EQ(session.document().face.domain.get(), gridDomain);
    // Bad thresholds are refused and change nothing.
    settings.contour.averageError = -1.0;
    EXPECT_THROW(session.face().setRefinementSettings(settings), InputError);
    EXPECT_EQ(session.document().refinement.contour.averageError, CriterionSettings{}.contour.averageError);
}

// Issue 13: the refinement worker hands over the display samples it computed for its mesh, so the
// editor thread does not evaluate the cascade again; they equal a fresh evaluation. An edit of the
// face (a new domain by undo) makes them stale until recomputed.
TEST(EditorSession, RefinementHandsOverTheSamplesOfItsMesh) {
    EditorSession session;
    session.face().load();
    (void)session.face().samples();
    EXPECT_TRUE(session.face().samplesReady());
    session.face().startRefinement(RefineAction::Refine);
    session.finishBackgroundWork();
    ASSERT_TRUE(session.face().lastRefinement().has_value());
    EXPECT_TRUE(session.face().samplesReady()); // before any evaluation on this thread
    const FaceSamples fresh =
        sampleFace(*session.document().face.cascade, session.document().face.domain->uvs);
    const FaceSamples& handed = session.face().samples();
    ASSERT_EQ(handed.rest.size(), session.document().face.domain->uvs.size());
    EXPECT_EQ(handed.rest, fresh.rest);
    EXPECT_EQ(handed.targets, fresh.targets);
    EXPECT_EQ(handed.colours, fresh.colours);
    session.history().undo();
    EXPECT_FALSE(session.face().samplesReady());
    EXPECT_EQ(session.face().samples().rest.size(), session.document().face.domain->uvs.size());
    EXPECT_TRUE(session.face().samplesReady());
}

// The parts' centre in morph form at parameters q: rest + sum q_k (target_k - rest).
Vec3 partCentre(const HeadPartSamples& samples, const std::string& name, const std::vector<double>& q) {
    for (const HeadPartSamples::Part& part : samples.parts) {
        if (part.name != name) continue;
        Vec3 sum(0, 0, 0);
        for (std::size_t i = part.first; i < part.first + part.count; ++i) {
            Vec3 p = samples.rest[i];
            for (std::size_t k = 0; k < q.size(); ++k) p += (samples.targets[k][i] - samples.rest[i]) * q[k];
            sum += p;
        }
        return sum / static_cast<double>(part.count);
    }
    ADD_FAILURE() << "no part " << name;
    return Vec3(0, 0, 0);
}

TEST(EditorSession, HeadPartsAreMadeOncePerFaceAndFollowTheParametersAsMorphs) {
    EditorSession session;
    EXPECT_EQ(session.face().parts(), nullptr);
    session.face().load();
    const auto parts = session.face().parts();
    ASSERT_NE(parts, nullptr);
    std::vector<std::string> names;
    for (const auto& part : parts->parts) names.push_back(part.name);
    EXPECT_EQ(names, (std::vector<std::string>{"eye_right", "eye_left", "teeth_upper", "teeth_lower",
                                               "tongue", "mouth_cavity"}));
    ASSERT_EQ(parts->targets.size(), session.document().face.cascade->parameters.size());
    ASSERT_EQ(parts->colours.size(), parts->rest.size());
    ASSERT_FALSE(parts->triangles.empty());
    EXPECT_EQ(parts->parts.back().first + parts->parts.back().count, parts->rest.size());

    // The morph form is the core's evaluation at the face's parameters (here jaw_open at its max).
    const DeformationCascade& cascade = *session.document().face.cascade;
    const int jaw = cascade.findParameter("jaw_open");
    ASSERT_GE(jaw, 0);
    std::vector<double> q = session.document().face.parameters;
    q[static_cast<std::size_t>(jaw)] = cascade.parameters[static_cast<std::size_t>(jaw)].max;
    const auto core = face::makeHeadParts(cascade);
    const std::vector<Vec3> expected = face::HeadPartsSampler(cascade, core).evaluate(q);
    ASSERT_EQ(expected.size(), parts->rest.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        Vec3 morph = parts->rest[i];
        for (std::size_t k = 0; k < q.size(); ++k) morph += (parts->targets[k][i] - parts->rest[i]) * q[k];
        ASSERT_LT((morph - expected[i]).norm(), 1e-9) << "vertex " << i;
    }
    // jaw_open lowers the lower teeth and the tongue; the upper teeth stay with the skull.
    const std::vector<double> rest = session.document().face.parameters;
    EXPECT_LT(partCentre(*parts, "teeth_lower", q)[1], partCentre(*parts, "teeth_lower", rest)[1] - 0.3);
    EXPECT_LT(partCentre(*parts, "tongue", q)[1], partCentre(*parts, "tongue", rest)[1] - 0.2);
    EXPECT_EQ(partCentre(*parts, "teeth_upper", q), partCentre(*parts, "teeth_upper", rest));

    // A slider and a refined skin keep them; another face (retargeting) makes them again.
    session.face().setParameter(jaw, q[static_cast<std::size_t>(jaw)]);
    EXPECT_EQ(session.face().parts(), parts);
    session.face().startRefinement(RefineAction::Refine);
    session.finishBackgroundWork();
    ASSERT_TRUE(session.face().lastRefinement().has_value());
    EXPECT_EQ(session.face().parts(), parts);
    session.face().setIndividual(face::Individual::Retarget);
    const auto retargeted = session.face().parts();
    ASSERT_NE(retargeted, nullptr);
    EXPECT_NE(retargeted, parts);
    EXPECT_NE(retargeted->rest, parts->rest);
    session.history().undo();
    EXPECT_EQ(session.face().parts()->rest, parts->rest);
}

TEST(EditorSession, AFaceBuiltFromTheUsersMeshShowsTheCarriedParts) {
    const std::filesystem::path mediaPipe = std::filesystem::path(VISEMELAB_SHARED_DATA_DIR) /
                                            "mediapipe-canonical-face" / "canonical_face_model.obj";
    if (!std::filesystem::exists(mediaPipe))
        GTEST_SKIP() << "shared data missing: " << mediaPipe << " (set VISEMELAB_SHARED_DATA_DIR)";
    EditorSession session;
    session.face().load();
    const auto bundled = session.face().parts();
    session.face().useOwnFace(loadOwnFaceCandidate(mediaPipe));
    const auto parts = session.face().parts();
    ASSERT_NE(parts, nullptr);
    ASSERT_NE(parts, bundled);
    ASSERT_EQ(parts->parts.size(), bundled->parts.size());
    for (const auto& message : session.messages())
        EXPECT_NE(message.kind, StatusMessage::Kind::Error) << message.text;
    // Carried to this face: the teeth sit between its mouth corners, the eyeballs at its eyes.
    const auto landmarks = face::baseLandmarkPositions(*session.document().face.cascade);
    const auto at = [&](face::Landmark l) { return landmarks[static_cast<std::size_t>(l)]; };
    const std::vector<double> q = session.document().face.parameters;
    const Vec3 mouth = (at(face::Landmark::MouthCornerLeft) + at(face::Landmark::MouthCornerRight)) * 0.5;
    const double mouthWidth =
        (at(face::Landmark::MouthCornerLeft) - at(face::Landmark::MouthCornerRight)).norm();
    EXPECT_LT((partCentre(*parts, "teeth_upper", q) - mouth).norm(), mouthWidth);
    const Vec3 eye = (at(face::Landmark::EyeInnerLeft) + at(face::Landmark::EyeOuterLeft)) * 0.5;
    EXPECT_LT((partCentre(*parts, "eye_left", q) - eye).norm(), 0.5 * mouthWidth);
}

TEST(EditorSession, VisemesGeneratedOnARefinedMeshAreInterpolable) {
    EditorSession session;
    session.face().load();
    session.face().startRefinement(RefineAction::AllVisemes);
    session.finishBackgroundWork();
    ASSERT_TRUE(session.face().lastRefinement().has_value());
    session.face().generateVisemes();
    ASSERT_NE(session.visemes(), nullptr);
    EXPECT_EQ(session.visemes()->vertexCount(), session.document().face.domain->uvs.size());
    session.reduction().start();
    session.finishBackgroundWork();
    EXPECT_NE(session.reduction().curve(), nullptr);
}

} // namespace
} // namespace vl::ui

namespace vl::ui {
namespace {

TEST(EditorSession, ExportsTheReducedModelInEveryFormat) {
    const auto dir = tempDir("export");
    EditorSession session;
    session.files().loadSample();
    session.reduction().setTarget(6);
    session.reduction().start();
    session.finishBackgroundWork();
    const auto glb = session.files().exportProject(ExportFormat::Glb, dir / "face.glb");
    ASSERT_FALSE(glb.empty());
    EXPECT_TRUE(std::filesystem::exists(dir / "face.glb"));
    EXPECT_FALSE(session.files().exportProject(ExportFormat::Runtime, dir / "face.vlrt").empty());
    EXPECT_FALSE(session.files().exportProject(ExportFormat::Obj, dir / "obj").empty());
    EXPECT_FALSE(session.files().exportProject(ExportFormat::Vrml, dir / "vrml").empty());
    // The glb comes back as a viseme set with one morph target per group.
    session.files().importGltf(dir / "face.glb");
    EXPECT_EQ(session.visemeCount(), 6u);
}

TEST(EditorSession, BundledPhonemeMapDrivesTheVisemeFrequencies) {
    EditorSession session;
    session.face().load();
    session.face().generateVisemes(); // visemes named like the Oculus map
    session.frequencies().useBundledPhonemeMap("oculus");
    ASSERT_TRUE(session.document().frequencies.isPhonemeBased());
    const auto f = session.frequencies().values();
    ASSERT_EQ(f.size(), session.visemeCount());
    // Remapping a phoneme moves its frequency from one viseme to the other; undo restores it.
    const auto& table = session.document().frequencies.phonemes.entries;
    int aa = -1;
    for (std::size_t i = 0; i < table.size(); ++i)
        if (table[i].first == "AA") aa = static_cast<int>(i);
    ASSERT_GE(aa, 0);
    session.frequencies().setPhonemeViseme(aa, "PP");
    EXPECT_GT(session.frequencies().values()[static_cast<std::size_t>(session.visemes()->find("PP"))],
              f[static_cast<std::size_t>(session.visemes()->find("PP"))]);
    session.history().undo();
    EXPECT_EQ(session.frequencies().values(), f);
    EXPECT_THROW(session.frequencies().setPhonemeViseme(aa, "no-such-viseme"), InputError);
}

TEST(EditorSession, CountsPhonemesOfATextFileInTheBackground) {
    const auto dir = tempDir("corpus");
    writeFileAtomically(dir / "text.txt", "Hello world. The quick brown fox jumps over the lazy dog.\n");
    EditorSession session;
    session.face().load();
    session.face().generateVisemes();
    session.frequencies().startPhonemeCount(dir / "text.txt");
    session.finishBackgroundWork();
    ASSERT_TRUE(session.document().frequencies.isPhonemeBased()) << session.messages().back().text;
    double total = 0.0;
    for (const auto& entry : session.document().frequencies.phonemes.entries) total += entry.second;
    EXPECT_GT(total, 30.0);
    EXPECT_TRUE(session.history().canUndo());
}

} // namespace
} // namespace vl::ui

namespace vl::ui {
namespace {

TEST(EditorSession, CancellingALargeReductionReturnsAtOnce) {
    // The 40 meshes of the ARPAbet set: branch and bound with the editor's 10 s limit, far from done
    // after 0.3 s. Cancel must stop it then (the searches used to run to their limit while the editor
    // waited); "Run now" starts it again.
    const auto dir = tempDir("cancel-large-reduction");
    const auto face = face::makeBundledFace();
    const auto visemes = bundledVisemeSet("arpabet", assetsDirectory(), face);
    const VisemeSet set = generateVisemeSet(face, face::faceDomainMesh(14), visemes);
    writeFileAtomically(dir / "neutral.obj", formatObj(set.neutral));
    for (std::size_t k = 0; k < set.size(); ++k)
        writeFileAtomically(dir / (set.visemes[k].name + ".obj"), formatObj(set.meshOf(k)));
    EditorSession session;
    session.reduction().setAutomatic(false);
    session.files().startLoadVisemeFolder(dir);
    session.finishBackgroundWork();
    ASSERT_EQ(session.visemeCount(), 40u);
    session.reduction().start();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ASSERT_TRUE(session.reduction().running()) << "finished within 0.3 s: nothing to cancel";
    const auto start = std::chrono::steady_clock::now();
    session.reduction().cancel();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 1.0);
    EXPECT_FALSE(session.reduction().running());
    EXPECT_EQ(session.reduction().curve(), nullptr);
    session.reduction().start();
    EXPECT_TRUE(session.reduction().running());
    session.reduction().cancel();

    // The panel's Cancel stops the search and keeps what it found: a grouping for every p with its
    // proven gap, well before the 10 s limit.
    session.reduction().start();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ASSERT_TRUE(session.reduction().running());
    const auto stopped = std::chrono::steady_clock::now();
    session.reduction().stop();
    session.finishBackgroundWork();
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - stopped).count(), 5.0);
    ASSERT_NE(session.reduction().curve(), nullptr);
    for (const Grouping& g : session.reduction().curve()->curve) {
        EXPECT_TRUE(g.feasible());
        EXPECT_LE(g.lowerBound, g.cost);
    }
    std::filesystem::remove_all(dir);
}

TEST(EditorSession, OpensProjectsAndFoldersOnAWorkerThread) {
    EditorSession session;
    session.files().startOpenProject(assetsDirectory() / "sample" / "sample.vlproj");
    session.finishBackgroundWork();
    ASSERT_NE(session.visemes(), nullptr);
    EXPECT_EQ(session.visemeCount(), 15u);
    EXPECT_FALSE(session.history().modified());
    // A failing load reports the error and keeps the open document.
    const VisemeSet* before = session.visemes();
    session.files().startLoadVisemeFolder(std::filesystem::temp_directory_path() /
                                          "visemelab-no-such-folder");
    session.finishBackgroundWork();
    EXPECT_EQ(session.visemes(), before);
    EXPECT_EQ(session.messages().back().kind, StatusMessage::Kind::Error);
}

} // namespace
} // namespace vl::ui

namespace vl::ui {
namespace {

TEST(EditorSession, SavesOnAWorkerThreadTheStateOfTheRequest) {
    const auto dir = tempDir("background-save");
    EditorSession session;
    loadUnreducedSet(session, 7);
    bool ranEarly = false;
    session.files().startSaveProject(dir / "p.vlproj", [&] { ranEarly = true; });
    session.reduction().setTarget(3); // after the request: not in the file, and still unsaved
    session.finishBackgroundWork();
    EXPECT_FALSE(session.files().saving());
    EXPECT_FALSE(ranEarly); // the guarded action waits for a save of the current document
    EXPECT_TRUE(session.history().modified());
    EXPECT_EQ(session.document().target, 3);
    EXPECT_TRUE(session.history().canUndo());
    EditorSession reopened;
    reopened.files().openProject(dir / "p.vlproj");
    EXPECT_EQ(reopened.document().target, 7);

    // Without edits in between, the saved state is recorded and the held-back action runs.
    bool ran = false;
    session.files().startSaveProject(dir / "q.vlproj", [&] { ran = true; });
    session.finishBackgroundWork();
    EXPECT_TRUE(ran);
    EXPECT_FALSE(session.history().modified());
    EXPECT_EQ(session.files().path(), dir / "q.vlproj");
    EXPECT_EQ(loadProject(dir / "q.vlproj").reduction.target, 3);
}

TEST(EditorSession, FailedBackgroundSaveIsReportedAndChangesNothing) {
    const auto dir = tempDir("background-save-error");
    EditorSession session;
    loadUnreducedSet(session, 5);
    bool ran = false;
    writeFileAtomically(dir / "a-file", "");
    session.files().startSaveProject(dir / "a-file" / "p.vlproj", [&] { ran = true; }); // not a folder
    session.finishBackgroundWork();
    EXPECT_FALSE(ran);
    EXPECT_TRUE(session.history().modified());
    EXPECT_TRUE(session.files().path().empty());
    EXPECT_EQ(session.history().undoName(), "Target m = 5");
    ASSERT_FALSE(session.messages().empty());
    EXPECT_EQ(session.messages().back().kind, StatusMessage::Kind::Error);
    EXPECT_NE(session.messages().back().text.find("p.vlproj"), std::string::npos)
        << session.messages().back().text;
    // Without a file name there is nothing to save to: refused at once.
    EXPECT_THROW(session.files().startSaveProject(), InputError);
}

TEST(EditorSession, ExportsOnAWorkerThreadWithAFreshReduction) {
    const auto dir = tempDir("background-export");
    EditorSession session;
    loadUnreducedSet(session, 5);
    ASSERT_EQ(session.reduction().curve(), nullptr); // the export runs the reduction itself
    session.files().startExport(ExportFormat::Glb, dir / "face.glb");
    session.reduction().setTarget(9); // after the request: the export keeps m = 5
    session.finishBackgroundWork();
    EXPECT_FALSE(session.files().exporting());
    ASSERT_EQ(session.messages().back().kind, StatusMessage::Kind::Info) << session.messages().back().text;
    EditorSession check;
    check.files().importGltf(dir / "face.glb");
    EXPECT_EQ(check.visemeCount(), 5u);
    // A failing export is a message and changes nothing.
    const std::uint64_t generation = session.documentInputs().reductionRevision();
    session.files().startExport(ExportFormat::Glb, dir / "face.glb" / "face.glb"); // a file is no folder
    session.finishBackgroundWork();
    EXPECT_EQ(session.messages().back().kind, StatusMessage::Kind::Error);
    EXPECT_EQ(session.documentInputs().reductionRevision(), generation);
    EXPECT_EQ(session.document().target, 9);
}

TEST(EditorSession, LoadsTheSampleOnAWorkerThread) {
    EditorSession session;
    loadUnreducedSet(session, 3);
    session.files().startLoadSample();
    EXPECT_EQ(session.document().target, 3); // the open document stays until it is loaded
    session.finishBackgroundWork();
    ASSERT_NE(session.visemes(), nullptr);
    EXPECT_EQ(session.visemeCount(), 15u);
    EXPECT_FALSE(session.history().modified());
    EXPECT_FALSE(session.history().canUndo());
    EXPECT_NE(session.messages().back().text.find("sample"), std::string::npos);
}

} // namespace
} // namespace vl::ui

namespace vl::ui {
namespace {

// Whether the face's display mesh is an adaptation for the parameters q (its positions are the
// cascade evaluated at its (u,v) for q).
bool meshShowsParameters(const FaceModel& face, const std::vector<double>& q) {
    const MeshData& mesh = *face.domain;
    if (mesh.positions.size() != mesh.uvs.size()) return false;
    for (std::size_t i = 0; i < mesh.uvs.size(); ++i) {
        const Vec3 expected = face.cascade->evaluate(mesh.uvs[i][0], mesh.uvs[i][1], q);
        for (int c = 0; c < 3; ++c)
            if (std::abs(mesh.positions[i][c] - expected[c]) > 1e-9) return false;
    }
    return true;
}

void waitForRefinement(const EditorSession& session) {
    while (session.face().refinementRunning()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

TEST(EditorSession, AutomaticReAdaptationIsDerivedStateAndNeverAnUndoStep) {
    EditorSession session;
    session.reduction().setAutomatic(false);
    session.face().setAutoRefine(true);
    session.face().load();
    const std::vector<double> q0 = session.document().face.parameters;
    session.finishBackgroundWork();
    ASSERT_TRUE(session.face().lastRefinement().has_value());
    EXPECT_TRUE(meshShowsParameters(session.document().face, q0));
    EXPECT_EQ(session.history().undoName(), "Load face");

    const int jaw = session.document().face.cascade->findParameter("jaw_open");
    ASSERT_GE(jaw, 0);
    session.face().setParameter(jaw, 1.0);
    session.history().endEdit();
    const std::vector<double> q1 = session.document().face.parameters;
    session.finishBackgroundWork();
    EXPECT_TRUE(meshShowsParameters(session.document().face, q1));
    EXPECT_EQ(session.history().undoName(), "Set jaw_open"); // no step of its own
    EXPECT_FALSE(session.history().canRedo());

    // Undo while the re-adaptation for q1 still runs: its result must not land on the q0 step.
    session.face().setParameter(jaw, 0.5);
    session.history().endEdit();
    const std::vector<double> qHalf = session.document().face.parameters;
    session.poll(); // starts the re-adaptation for qHalf
    ASSERT_TRUE(session.face().refinementRunning());
    session.history().undo();
    waitForRefinement(session);
    session.poll();
    EXPECT_EQ(session.document().face.parameters, q1);
    EXPECT_FALSE(meshShowsParameters(session.document().face, qHalf));
    session.finishBackgroundWork();
    EXPECT_TRUE(meshShowsParameters(session.document().face, q1)); // re-adapted to the restored values
    EXPECT_EQ(session.history().undoName(), "Set jaw_open");
    EXPECT_EQ(session.history().redoName(), "Set jaw_open");

    // Undo of the slider change restores q0 and the mesh follows; redo brings q1 back.
    session.history().undo();
    EXPECT_EQ(session.document().face.parameters, q0);
    EXPECT_TRUE(meshShowsParameters(session.document().face, q0)); // the step kept its own mesh
    session.finishBackgroundWork();
    EXPECT_TRUE(meshShowsParameters(session.document().face, q0));
    EXPECT_EQ(session.history().undoName(), "Load face");
    session.history().redo();
    EXPECT_EQ(session.document().face.parameters, q1);
    EXPECT_TRUE(meshShowsParameters(session.document().face, q1));
    session.finishBackgroundWork();
    EXPECT_TRUE(meshShowsParameters(session.document().face, q1));
    session.history().redo();
    EXPECT_EQ(session.document().face.parameters, qHalf);
    session.finishBackgroundWork();
    EXPECT_TRUE(meshShowsParameters(session.document().face, qHalf));
    EXPECT_FALSE(session.history().canRedo());
    // Three steps in all: load, two slider changes.
    for (const char* name : {"Set jaw_open", "Set jaw_open", "Load face"}) {
        EXPECT_EQ(session.history().undoName(), name);
        session.history().undo();
    }
    EXPECT_FALSE(session.history().canUndo());
}

TEST(EditorSession, AutomaticReAdaptationLooksOnlyWhereTheSliderChangedTheFace) {
    EditorSession session;
    session.reduction().setAutomatic(false);
    session.face().setAutoRefine(true);
    CriterionSettings contour;
    contour.kind = CriterionKind::Contour;
    contour.maxDepth = 7;
    session.face().load();
    session.face().setRefinementSettings(contour);
    session.finishBackgroundWork();
    ASSERT_TRUE(session.face().lastRefinement().has_value());
    const std::size_t triangles = session.face().lastRefinement()->triangles;

    // One brow: re-adapted where its field reaches, far fewer tests than faces.
    session.face().setParameter(session.document().face.cascade->findParameter("frontalis_l"), 1.0);
    session.history().endEdit();
    session.finishBackgroundWork();
    ASSERT_TRUE(session.face().lastRefinement().has_value());
    EXPECT_EQ(session.face().lastRefinement()->action, "re-adapted");
    EXPECT_LT(session.face().lastRefinement()->stats.tests, triangles / 2);
    EXPECT_TRUE(meshShowsParameters(session.document().face, session.document().face.parameters));

    // Every muscle at once reaches most of the face: refined again from the base mesh.
    std::vector<double> all;
    for (const auto& p : session.document().face.cascade->parameters) all.push_back(p.max);
    session.face().setParameters(all, "All");
    session.finishBackgroundWork();
    EXPECT_TRUE(session.face().lastRefinement()->stats.rebuilt);
    EXPECT_TRUE(meshShowsParameters(session.document().face, all));

    // New thresholds: all of the mesh is re-adapted (no change box applies to them).
    contour.contour.averageError *= 2;
    session.face().setRefinementSettings(contour);
    session.finishBackgroundWork();
    EXPECT_EQ(session.face().lastRefinement()->action, "re-adapted");
    EXPECT_GE(session.face().lastRefinement()->stats.tests,
              session.face().lastRefinement()->trianglesBefore / 2);
    EXPECT_TRUE(meshShowsParameters(session.document().face, all));
}

} // namespace
} // namespace vl::ui

namespace vl::ui {
namespace {

// Every command type is one undo step: undo gives back exactly the document before it (the same
// value, shared parts the same objects) and redo exactly the document after it.
TEST(EditorSession, EveryCommandUndoesAndRedoesToTheExactDocument) {
    const auto dir = tempDir("undo-every-command");
    EditorSession session;
    session.reduction().setAutomatic(false);
    session.face().load(face::Individual::Bundled, 12);
    session.face().generateVisemes();
    session.frequencies().useDirectFrequencies(); // "viseme frequency" below edits them
    writeMesh(dir / "extra.obj", session.visemes()->meshOf(3));
    const std::vector<std::pair<std::string, std::function<void()>>> commands = {
        {"target", [&] { session.reduction().setTarget(4); }},
        {"viseme frequency", [&] { session.frequencies().setVisemeFrequency(2, 4.5); }},
        {"weight mode", [&] { session.weights().setMode(WeightMode::Area); }},
        {"painted weights",
         [&] {
             session.weights().setPainted(std::vector<double>(session.visemes()->vertexCount(), 0.4),
                                          "Paint");
         }},
        {"parameter", [&] { session.face().setParameter(0, 0.3); }},
        {"parameters",
         [&] { session.face().setParameters(session.document().face.cascade->defaults(), "Reset"); }},
        {"preset", [&] { session.face().applyVisemePreset("oh"); }},
        {"field",
         [&] {
             InfluenceField field = session.document().face.cascade->stages[1].field.influences.at(0);
             field.magnitude *= 1.5;
             session.face().setInfluence(1, 0, field);
         }},
        {"retarget", [&] { session.face().setIndividual(face::Individual::Retarget); }},
        {"refinement settings",
         [&] {
             CriterionSettings settings = session.document().refinement;
             settings.kind = CriterionKind::Normals;
             session.face().setRefinementSettings(settings);
         }},
        {"import viseme", [&] { session.authoring().importViseme("extra", dir / "extra.obj"); }},
        {"remove viseme",
         [&] { session.authoring().removeViseme(static_cast<int>(session.visemeCount()) - 1); }},
        {"bundled phoneme map", [&] { session.frequencies().useBundledPhonemeMap("oculus"); }},
        {"phoneme frequency", [&] { session.frequencies().setPhonemeFrequency(0, 2.0); }},
        {"phoneme map",
         [&] { session.frequencies().setPhonemeViseme(0, session.visemes()->visemes[1].name); }},
        {"generate visemes", [&] { session.face().generateVisemes(); }},
        {"load face", [&] { session.face().load(face::Individual::Bundled, 10); }},
    };
    for (const auto& [what, command] : commands) {
        SCOPED_TRACE(what);
        const Document before = session.document();
        command();
        session.history().endEdit();
        const Document after = session.document();
        ASSERT_NE(after, before) << "the command changed nothing";
        session.history().undo();
        EXPECT_EQ(session.document(), before);
        session.history().redo();
        EXPECT_EQ(session.document(), after);
    }
}

// The export writes the meshes the document shows, even when their files changed on disk since.
TEST(EditorSession, ExportIsWhatTheDocumentShowsNotWhatTheDiskHolds) {
    const auto dir = tempDir("export-from-memory");
    {
        EditorSession maker;
        maker.reduction().setAutomatic(false);
        maker.face().load(face::Individual::Bundled, 12);
        maker.face().generateVisemes();
        writeMesh(dir / "neutral.obj", maker.visemes()->neutral);
        for (std::size_t i = 0; i < 4; ++i)
            writeMesh(dir / (maker.visemes()->visemes[i].name + ".obj"), maker.visemes()->meshOf(i));
    }
    EditorSession session;
    session.reduction().setAutomatic(false);
    session.files().loadVisemeFolder(dir);
    session.reduction().setRest(RestChoice::Key, "");                       // sil is a key too
    session.reduction().setTarget(static_cast<int>(session.visemeCount())); // nothing merged: keys = visemes
    const VisemeSet shown = *session.visemes();
    // Another program rewrites one viseme file.
    MeshData changed = readMesh(dir / (shown.visemes[1].name + ".obj"));
    for (Vec3& p : changed.positions) p += Vec3(0.0, 1.0, 0.0);
    writeMesh(dir / (shown.visemes[1].name + ".obj"), changed);
    session.files().exportProject(ExportFormat::Glb, dir / "out.glb");
    EditorSession check;
    check.files().importGltf(dir / "out.glb");
    ASSERT_EQ(check.visemeCount(), shown.size());
    for (std::size_t i = 0; i < shown.size(); ++i) {
        const int k = check.visemes()->find(shown.visemes[i].name);
        ASSERT_GE(k, 0) << shown.visemes[i].name;
        const auto& exported = check.visemes()->visemes[static_cast<std::size_t>(k)].positions;
        ASSERT_EQ(exported.size(), shown.visemes[i].positions.size());
        for (std::size_t v = 0; v < exported.size(); ++v)
            EXPECT_NEAR((exported[v] - shown.visemes[i].positions[v]).norm(), 0.0, 1e-5)
                << shown.visemes[i].name;
    }
}

// Saving keeps the undo history: the designer can still undo what came before the save.
TEST(EditorSession, SavingKeepsTheUndoHistory) {
    const auto dir = tempDir("save-keeps-undo");
    EditorSession session;
    loadUnreducedSet(session, 5);
    session.history().endEdit(); // a new undo step, not a continued slider drag
    session.reduction().setTarget(6);
    session.files().saveProject(dir / "p.vlproj");
    EXPECT_FALSE(session.history().modified());
    ASSERT_TRUE(session.history().canUndo());
    session.history().undo();
    EXPECT_EQ(session.document().target, 5);
    EXPECT_TRUE(session.history().modified());
    session.history().redo();
    EXPECT_FALSE(session.history().modified());
}

} // namespace
} // namespace vl::ui
