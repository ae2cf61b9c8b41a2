#include "core/speech/SpeechErrorBasis.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <string_view>
#include <utility>

namespace vl {

namespace {

using Lanes = double __attribute__((vector_size(2 * sizeof(double)))); // one SSE2 register

Lanes loadLanes(const double* p) {
    Lanes v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// sum_i ax[i] bx[i] + ay[i] by[i] + az[i] bz[i], four vertices at a time (a plain loop's single sum
// is a dependency chain the compiler may not reorder).
double dot3(const double* ax, const double* ay, const double* az, const double* bx, const double* by,
            const double* bz, std::size_t n) {
    Lanes low = {0, 0}, high = {0, 0};
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {
        low += loadLanes(ax + i) * loadLanes(bx + i) + loadLanes(ay + i) * loadLanes(by + i) +
               loadLanes(az + i) * loadLanes(bz + i);
        high += loadLanes(ax + i + 2) * loadLanes(bx + i + 2) +
                loadLanes(ay + i + 2) * loadLanes(by + i + 2) + loadLanes(az + i + 2) * loadLanes(bz + i + 2);
    }
    double sum = (low[0] + low[1]) + (high[0] + high[1]);
    for (; i < n; ++i) sum += ax[i] * bx[i] + ay[i] * by[i] + az[i] * bz[i];
    return sum;
}

// The vertices of nonzero weight ordered along a Morton (Z-order) curve of their neutral positions,
// so that a block of consecutive ones is a small patch of the face whose displacements are alike:
// the frame maximum's coordinate ranges (nodeLengths) are then tight.
std::vector<std::size_t> mouthInSpaceOrder(const std::vector<Vec3>& neutral,
                                           std::span<const double> weights) {
    std::vector<std::size_t> mouth;
    Vec3 low(std::numeric_limits<double>::max()), high(std::numeric_limits<double>::lowest());
    for (std::size_t v = 0; v < neutral.size(); ++v)
        if (weights[v] > 0) {
            mouth.push_back(v);
            low.minimize(neutral[v]);
            high.maximize(neutral[v]);
        }
    auto spread = [](std::uint64_t value) { // 21 bits to every third of 63
        std::uint64_t x = value & 0x1fffff;
        x = (x | x << 32) & 0x1f00000000ffffULL;
        x = (x | x << 16) & 0x1f0000ff0000ffULL;
        x = (x | x << 8) & 0x100f00f00f00f00fULL;
        x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
        x = (x | x << 2) & 0x1249249249249249ULL;
        return x;
    };
    std::vector<std::pair<std::uint64_t, std::size_t>> keyed;
    keyed.reserve(mouth.size());
    for (const std::size_t v : mouth) {
        std::uint64_t code = 0;
        for (int c = 0; c < 3; ++c) {
            const double extent = high[c] - low[c];
            const double unit = extent > 0 ? (neutral[v][c] - low[c]) / extent : 0.0;
            code |= spread(static_cast<std::uint64_t>(unit * double(0x1fffff))) << c;
        }
        keyed.emplace_back(code, v);
    }
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t i = 0; i < keyed.size(); ++i) mouth[i] = keyed[i].second;
    return mouth;
}

// Each full key's partner: the reduced key its phonemes play on that face (the key of its group),
// kNoPartner when they rest there or when no phoneme plays the key. Any partner gives exact sums;
// the group's key gives small deviations.
std::vector<std::size_t> partnerKeys(const ReducedModel& full, const ReducedModel& reduced) {
    std::vector<std::size_t> partners(full.keys.size(), SpeechErrorBasis::kNoPartner);
    std::vector<bool> assigned(full.keys.size(), false);
    std::map<std::string_view, int> reducedKeyOf;
    for (const auto& [phoneme, key] : reduced.phonemeToKey) reducedKeyOf.emplace(phoneme, key);
    for (const auto& [phoneme, key] : full.phonemeToKey) {
        if (key < 0 || static_cast<std::size_t>(key) >= partners.size() || assigned[std::size_t(key)])
            continue;
        const auto on = reducedKeyOf.find(phoneme);
        if (on == reducedKeyOf.end()) continue;
        assigned[std::size_t(key)] = true;
        if (on->second >= 0 && static_cast<std::size_t>(on->second) < reduced.keys.size())
            partners[std::size_t(key)] = static_cast<std::size_t>(on->second);
    }
    return partners;
}

} // namespace

SpeechErrorBasis::SpeechErrorBasis(const ReducedModel& full, const ReducedModel& reduced,
                                   std::span<const double> vertexWeights)
    : SpeechErrorBasis(full, reduced, vertexWeights, nullptr) {}

SpeechErrorBasis::SpeechErrorBasis(const ReducedModel& full, const ReducedModel& reduced,
                                   std::span<const double> vertexWeights, const Stored& stored)
    : SpeechErrorBasis(full, reduced, vertexWeights, &stored) {}

SpeechErrorBasis::SpeechErrorBasis(const ReducedModel& full, const ReducedModel& reduced,
                                   std::span<const double> vertexWeights, const Stored* stored)
    : vertexCount_(full.neutral.positions.size()) {
    if (reduced.neutral.positions.size() != vertexCount_ || vertexWeights.size() != vertexCount_)
        throwInputError("speech error",
                        "the full face, the reduced face and the weights differ in vertex count");
    if (stored) {
        const auto mouthSize =
            std::count_if(vertexWeights.begin(), vertexWeights.end(), [](double w) { return w > 0; });
        if (stored->mouth.size() != static_cast<std::size_t>(mouthSize) ||
            !std::all_of(stored->mouth.begin(), stored->mouth.end(),
                         [&](std::size_t v) { return v < vertexCount_ && vertexWeights[v] > 0; }))
            throwInputError("speech error", "the stored basis does not fit the faces (its mouth)");
        mouth_ = stored->mouth;
    } else {
        mouth_ = mouthInSpaceOrder(full.neutral.positions, vertexWeights);
    }
    const std::size_t n = mouth_.size();
    // Zeros to a whole number of leaves: a padded vertex has no weight and no displacement.
    mouthSize_ = n;
    const std::size_t padded = (n + kLeaf - 1) / kLeaf * kLeaf;
    mouthWeights_.assign(padded, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        mouthWeights_[i] = vertexWeights[mouth_[i]];
        totalWeight_ += vertexWeights[mouth_[i]];
    }

    // A key's displacement at the mouth's vertices, its three coordinates in one pass over them.
    struct Coordinates {
        std::vector<double> x, y, z;
    };
    auto displacement = [&](const ReducedModel& model, const KeyMesh& key) {
        Coordinates d{std::vector<double>(padded, 0.0), std::vector<double>(padded, 0.0),
                      std::vector<double>(padded, 0.0)};
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 delta = key.positions[mouth_[i]] - model.neutral.positions[mouth_[i]];
            d.x[i] = delta[0];
            d.y[i] = delta[1];
            d.z[i] = delta[2];
        }
        return d;
    };
    // The reduced keys, then each full key as its deviation from its partner.
    const std::vector<std::size_t> partners = partnerKeys(full, reduced);
    const std::size_t fullKeys = full.keys.size(), reducedKeys = reduced.keys.size();
    for (auto* vectors : {&x_, &y_, &z_}) vectors->reserve(fullKeys + reducedKeys);
    for (std::size_t g = 0; g < reducedKeys; ++g) {
        Coordinates d = displacement(reduced, reduced.keys[g]);
        x_.push_back(std::move(d.x));
        y_.push_back(std::move(d.y));
        z_.push_back(std::move(d.z));
        reducedIndex_.push_back(g);
    }
    for (std::size_t k = 0; k < fullKeys; ++k) {
        Coordinates d = displacement(full, full.keys[k]);
        std::vector<double>&dx = d.x, &dy = d.y, &dz = d.z;
        const std::size_t partner = partners[k];
        if (partner != kNoPartner)
            for (std::size_t i = 0; i < n; ++i) {
                dx[i] -= x_[partner][i];
                dy[i] -= y_[partner][i];
                dz[i] -= z_[partner][i];
            }
        fullIndex_.push_back(x_.size());
        fullPartner_.push_back(partner);
        x_.push_back(std::move(dx));
        y_.push_back(std::move(dy));
        z_.push_back(std::move(dz));
    }
    if (stored) {
        adopt(*stored);
    } else {
        buildTree();
        computeGram();
    }
    transposeTree();
}

SpeechErrorBasis::Stored SpeechErrorBasis::stored() const {
    return {mouth_, gram_, lengths_};
}

void SpeechErrorBasis::adopt(const Stored& stored) {
    const std::size_t keys = vectorCount();
    bool fits = stored.gram.size() == keys * keys && !stored.lengths.empty();
    // The levels' sizes as buildTree makes them: a leaf per kLeaf vertices, a node per kFanout below.
    for (std::size_t level = 0, nodes = paddedSize() / kLeaf; fits && level < stored.lengths.size();
         ++level) {
        fits = stored.lengths[level].size() == keys * nodes &&
               (level + 1 < stored.lengths.size()) == (stored.lengths[level].size() > keys);
        nodes = (nodes + kFanout - 1) / kFanout;
    }
    if (!fits) throwInputError("speech error", "the stored basis does not fit the faces (its sizes)");
    gram_ = stored.gram;
    lengths_ = stored.lengths;
}

// G[a][b] = sum_v w_v <b_a(v), b_b(v)>, from the weighted coordinates of a (one pass per pair).
// A vector that is zero (the deviation of a key the reduction left alone) has a zero row.
void SpeechErrorBasis::computeGram() {
    const std::size_t keys = vectorCount(), n = mouthSize_;
    gram_.assign(keys * keys, 0.0);
    std::vector<bool> zero(keys);
    for (std::size_t a = 0; a < keys; ++a) {
        auto isZero = [](const std::vector<double>& v) {
            return std::all_of(v.begin(), v.end(), [](double value) { return value == 0.0; });
        };
        zero[a] = isZero(x_[a]) && isZero(y_[a]) && isZero(z_[a]);
    }
    std::vector<double> wx(n), wy(n), wz(n);
    for (std::size_t a = 0; a < keys; ++a) {
        if (zero[a]) continue;
        for (std::size_t i = 0; i < n; ++i) {
            wx[i] = mouthWeights_[i] * x_[a][i];
            wy[i] = mouthWeights_[i] * y_[a][i];
            wz[i] = mouthWeights_[i] * z_[a][i];
        }
        for (std::size_t b = a; b < keys; ++b)
            if (!zero[b])
                gram_[a * keys + b] = gram_[b * keys + a] =
                    dot3(wx.data(), wy.data(), wz.data(), x_[b].data(), y_[b].data(), z_[b].data(), n);
    }
}

std::size_t SpeechErrorBasis::nodeSpan(std::size_t level) const {
    std::size_t span = kLeaf;
    for (std::size_t l = 0; l < level; ++l) span *= kFanout;
    return span;
}

void SpeechErrorBasis::buildTree() {
    const std::size_t n = paddedSize(), keys = vectorCount();
    std::vector<double> leaves(keys * (n / kLeaf), 0.0);
    for (std::size_t a = 0; a < keys; ++a)
        for (std::size_t v = 0; v < n; ++v) {
            double& length = leaves[(v / kLeaf) * keys + a];
            length =
                std::max(length, std::sqrt(x_[a][v] * x_[a][v] + y_[a][v] * y_[a][v] + z_[a][v] * z_[a][v]));
        }
    lengths_.push_back(std::move(leaves));
    while (lengths_.back().size() > keys) {
        const std::vector<double>& below = lengths_.back();
        const std::size_t children = below.size() / keys;
        std::vector<double> level(keys * ((children + kFanout - 1) / kFanout), 0.0);
        for (std::size_t child = 0; child < children; ++child)
            for (std::size_t a = 0; a < keys; ++a) {
                double& length = level[(child / kFanout) * keys + a];
                length = std::max(length, below[child * keys + a]);
            }
        lengths_.push_back(std::move(level));
    }
}

void SpeechErrorBasis::transposeTree() {
    const std::size_t keys = vectorCount();
    byVector_.assign(lengths_.size(), {});
    for (std::size_t level = 0; level < lengths_.size(); ++level) {
        const std::size_t nodes = nodeCount(level), padded = paddedNodes(level);
        byVector_[level].assign(keys * padded, 0.0);
        for (std::size_t node = 0; node < nodes; ++node)
            for (std::size_t a = 0; a < keys; ++a)
                byVector_[level][a * padded + node] = lengths_[level][node * keys + a];
    }
}

} // namespace vl
