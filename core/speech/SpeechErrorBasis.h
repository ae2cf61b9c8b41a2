#pragma once
// What the speech error measures (UtteranceError.h, DisplacementError.h) need of two faces, made once
// for any number of utterances: the mouth (the vertices of nonzero weight), a basis of the faces'
// key displacements (key - neutral) on it, stored per coordinate (x, y, z arrays: the per-frame sums
// vectorise), and the basis's weighted Gram matrix G[a][b] = sum_v w_v <b_a(v), b_b(v)>.
// `say` makes one per face, `say --stdin` and `visemelab batch` one for all the sentences they speak.
//
// The basis: every reduced key's displacement r_g, and every full key's displacement f_k as its
// deviation from its partner, the reduced key its phonemes play (f_k = e_k + r_p(k)). A frame's difference
// F(t) - R(t) = sum_k a_k e_k + sum_g (sum_{p(k) = g} a_k - b_g) r_g, with a and b the faces' blend
// weights: while both faces show the same phonemes the r_g coefficients cancel and what is left are
// the small deviations e_k, whose bounds are tight (a frame's maximum visits few vertices). A key
// the reduction left alone has e_k = 0 exactly, and so adds exactly nothing.
#include "core/reduce/ReducedModel.h"

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace vl {

class SpeechErrorBasis {
  public:
    // Throws InputError when the faces and the weights differ in vertex count.
    SpeechErrorBasis(const ReducedModel& full, const ReducedModel& reduced,
                     std::span<const double> vertexWeights);

    // What a cache keeps of a basis (core/project/SpeechCache.h): the parts that cost (the mouth's
    // order, the Gram matrix, the tree); the displacements are taken from the faces again.
    struct Stored {
        std::vector<std::size_t> mouth; // the vertices of nonzero weight, in the basis's order
        std::vector<double> gram;
        std::vector<std::vector<double>> lengths;
    };
    Stored stored() const;
    // The basis `stored` was taken from, for the same faces and weights. Throws InputError when the
    // stored parts do not fit them (sizes, a vertex of zero weight), as a damaged store would not.
    SpeechErrorBasis(const ReducedModel& full, const ReducedModel& reduced,
                     std::span<const double> vertexWeights, const Stored& stored);

    std::size_t vertexCount() const { return vertexCount_; } // of each face
    std::size_t mouthSize() const { return mouthSize_; }     // vertices of nonzero weight
    double totalWeight() const { return totalWeight_; }      // sum of the mouth's weights
    // The per-vertex arrays below are padded with zeros (weight and displacement) to a whole number of
    // leaves (paddedSize()): every leaf is kLeaf values long, which vectorises.
    std::size_t paddedSize() const { return mouthWeights_.size(); }
    const std::vector<double>& mouthWeights() const { return mouthWeights_; }
    std::size_t vectorCount() const { return x_.size(); } // basis vectors: reduced keys + full keys
    // The basis vector of key k of each face (e_k for the full face, r_g for the reduced one), and
    // the partner r_p(k) of a full key (kNoPartner when its phonemes rest on the reduced face).
    static constexpr std::size_t kNoPartner = static_cast<std::size_t>(-1);
    std::size_t fullIndex(std::size_t key) const { return fullIndex_[key]; }
    std::size_t fullPartner(std::size_t key) const { return fullPartner_[key]; }
    std::size_t reducedIndex(std::size_t key) const { return reducedIndex_[key]; }
    std::size_t fullKeys() const { return fullIndex_.size(); }
    std::size_t reducedKeys() const { return reducedIndex_.size(); }
    // Coordinate c (0, 1, 2) of basis vector a at the mouth's vertices, paddedSize() values.
    const double* coordinate(std::size_t a, int c) const {
        return (c == 0 ? x_ : c == 1 ? y_ : z_)[a].data();
    }
    double gram(std::size_t a, std::size_t b) const { return gram_[a * vectorCount() + b]; }
    // A tree over the mouth for a frame's maximum: leaves of kLeaf consecutive vertices, each node of
    // a level above holding kFanout nodes of the level below, up to one root. Every node has the
    // largest length of every basis vector over its vertices, so by the triangle inequality
    // |d(v)| <= sum_a |c_a| length_a(node) for a frame's d = sum_a c_a b_a: a frame's maximum skips
    // whole regions that cannot beat the largest length found. Lengths, not coordinate ranges: a
    // frame is mostly one deviation e_k, whose bound is then its exact maximum; Morton order makes
    // a node a patch of the face.
    static constexpr std::size_t kLeaf = 8, kFanout = 8;
    std::size_t levels() const { return lengths_.size(); } // level 0: the leaves
    std::size_t nodeCount(std::size_t level) const { return lengths_[level].size() / vectorCount(); }
    // Vertices [first, last) of the (padded) mouth under a node.
    std::size_t nodeFirst(std::size_t level, std::size_t node) const { return node * nodeSpan(level); }
    // The largest |b_a(v)| over each node's vertices, per basis vector: length_a of the nodes of a
    // level in order, padded with zeros to whole groups of kFanout (the children of one node), so a
    // node's children's bounds vectorise. (Stored keeps them node by node, as they are built.)
    const double* vectorLengths(std::size_t level, std::size_t a) const {
        return &byVector_[level][a * paddedNodes(level)];
    }
    std::size_t paddedNodes(std::size_t level) const {
        return (nodeCount(level) + kFanout - 1) / kFanout * kFanout;
    }

  private:
    SpeechErrorBasis(const ReducedModel& full, const ReducedModel& reduced,
                     std::span<const double> vertexWeights, const Stored* stored);
    std::size_t vertexCount_ = 0;
    std::vector<std::size_t> mouth_; // the vertex of each mouth position
    std::size_t mouthSize_ = 0;
    std::vector<double> mouthWeights_;
    double totalWeight_ = 0;
    std::vector<std::vector<double>> x_, y_, z_;
    std::vector<std::size_t> fullIndex_, fullPartner_, reducedIndex_;
    std::vector<double> gram_;
    std::vector<std::vector<double>> lengths_;  // per level: node, basis vector
    std::vector<std::vector<double>> byVector_; // per level: basis vector, node (padded)
    std::size_t nodeSpan(std::size_t level) const;
    void buildTree();
    void transposeTree();
    void computeGram();
    void adopt(const Stored& stored);
};

} // namespace vl
