#pragma once
// A user's own face as the deformable model (paper "Adaptive Deformable Models", sections 3.3 and 6):
// the base geometry field is the user's mesh sampled over the normalised (u,v) domain (through the
// landmark alignment, core/face/FaceAlignment.h), and the bundled face's expression fields act on it
// unchanged in (u,v), rotated into the face's frame and scaled with its size. Parameter names stay
// those of the bundled face, so viseme parameter vectors apply as they are.
//
// The steps, each reported: choose the UV islands the face lies on (those holding landmarks, then
// islands sharing vertices with them whose (u,v) do not overlap), align, sample the geometry image,
// fill enclosed holes (eye openings become sockets behind the eyeballs, the mouth opening a membrane
// that the mouth's rim never shows), rotate and scale the fields.
#include "core/deform/DeformationCascade.h"
#include "core/face/FaceAlignment.h"
#include "core/face/FaceFrame.h"
#include "core/face/Landmarks.h"
#include "core/face/UvMesh.h"

#include <string>
#include <vector>

namespace vl::face {

struct FaceBuildOptions {
    int gridSize = 257; // geometry image samples per side (the base geometry field), 17..2049
    std::string name = "own face";
};

struct IslandUse {
    UvIsland island;
    bool used = false;
    std::size_t landmarks = 0; // landmarks on it
    std::string reason;        // why it is used or not
};

struct FaceBuildReport {
    std::vector<IslandUse> islands;
    std::size_t droppedTriangles = 0; // without (u,v)
    std::vector<CoverageHole> holes;  // enclosed gaps the build filled
    double domainCoverage = 0.0;      // FaceAlignment::domainCoverage
    double retracted = 0.0;           // FaceAlignment::retractedFraction
    double closedGap = 0.0;
    std::size_t foldedSamples = 0;
    std::size_t filledSamples = 0; // geometry image samples taken from hole filling
    FaceFrame frame;               // of the user's face, in mesh units
    double scale = 1.0;            // mesh units per bundled-face centimetre
    std::vector<std::string> warnings;
};

struct BuiltFace {
    DeformationCascade cascade;
    FaceLandmarks landmarks; // those used, resolved on the mesh
    FaceBuildReport report;
};

// Throws InputError for missing required landmarks, landmarks that do not determine an alignment,
// or a grid size out of range.
BuiltFace buildFace(const UvMesh& mesh, const FaceLandmarks& landmarks, const FaceBuildOptions& options = {});

// The bundled face's expression fields carried over to a face with `frame`: directions rotated into
// it, magnitudes scaled by `scale`, on `base` as the base geometry.
DeformationCascade retargetedCascade(const SampledField& base, const FaceFrame& frame, double scale,
                                     std::string name);

// The islands a face lies on, best first (see the header comment), with the reasons.
std::vector<IslandUse> chooseFaceIslands(const UvMesh& mesh, const FaceLandmarks& landmarks);

} // namespace vl::face
