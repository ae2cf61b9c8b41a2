// Cost of every group: c(S) for all 2^n sets of units, each from S minus its highest unit j in
// O(n): Q(S) = Q(S\j) + 2 sum_{i in S\j} H_ij + H_jj, with F and D summed over the same bits. A set
// holding a conflicting pair costs +inf, so no solver step ever picks it.
//
// Partition DP (the paper's eq. 23): best[q][T] = min over V subset of T of c(V) + best[q-1][T\V].
// Fixing the lowest unit of T inside V enumerates every partition exactly once (halving the work);
// every state below the top one then excludes unit 0, so layers are indexed by subsets of
// {1..n-1} (2^(n-1) entries, bit i = unit i+1).
//
// Speed: a layer is 3^(n-1)/2 additions, so the loop around each one decides the run time. The
// state T and the remainder R are split into tile, block and the lowest three bits: the 8 states of
// a block take their 13 candidate splits from two blocks of 8 contiguous values (costs at T^R, the
// layer below at R), unrolled with the 8 minima in registers - no loop-carried submask chain per
// addition - and a pair of tiles (4 KiB each) serves all blocks of a tile from L1. Only the values are kept
// (all layers); the groups are recovered afterwards by finding the split that gives each chosen value, which
// is exact because the kernel and the recovery add the same two doubles. Layers run in parallel over hi with
// TBB; values and groups do not depend on the thread count (each state is a minimum over a fixed set,
// recovery scans in a fixed order).
#include "core/reduce/SubsetDp.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace vl {

namespace {

constexpr double kUnreached = std::numeric_limits<double>::infinity();

std::vector<double> allGroupCosts(const GroupCostModel& model) {
    const int n = model.size();
    const std::size_t count = std::size_t{1} << n;
    std::vector<double> cost(count, 0.0), Q(count, 0.0);
    // Parallel over blocks of the high bits: each block only reads sets with a smaller highest unit,
    // which earlier blocks (sequential in the outer loop over j) have finished.
    for (int j = 0; j < n; ++j) {
        const std::size_t lo = std::size_t{1} << j;
        const double* row = &model.cross[static_cast<std::size_t>(j) * static_cast<std::size_t>(n)];
        const double fj = model.weight[static_cast<std::size_t>(j)],
                     dj = model.self[static_cast<std::size_t>(j)];
        const UnitMask conflictsJ = model.conflicts[static_cast<std::size_t>(j)];
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, lo, 4096), [&](const auto& range) {
            for (std::size_t rest = range.begin(); rest != range.end(); ++rest) {
                const std::size_t s = rest | lo;
                double cross = 0, F = fj, D = dj;
                for (std::size_t bits = rest; bits; bits &= bits - 1) {
                    const int i = std::countr_zero(bits);
                    cross += row[i];
                    F += model.weight[static_cast<std::size_t>(i)];
                    D += model.self[static_cast<std::size_t>(i)];
                }
                Q[s] = Q[rest] + 2 * cross + row[j];
                const bool conflict = std::isinf(cost[rest]) || (rest & conflictsJ) != 0;
                // Rounding may push D - Q/F slightly below 0.
                cost[s] = conflict ? kUnreached : (F > 0 ? std::max(0.0, D - Q[s] / F) : 0.0);
            }
        });
    }
    return cost;
}

// The 13 splits of the nonzero low parts lo = 1..7 of a block: V's low part v = lo ^ rl with rl a
// subset of lo minus its lowest bit (the state's lowest unit stays in V). `acc[lo]` takes
// cost[v] + below[rl] from the blocks `c` (costs of hi^rh) and `b` (layer below at rh).
inline void splitBlock(const double* c, const double* b, double* acc) {
    acc[1] = std::min(acc[1], c[1] + b[0]);
    acc[2] = std::min(acc[2], c[2] + b[0]);
    acc[3] = std::min(acc[3], std::min(c[3] + b[0], c[1] + b[2]));
    acc[4] = std::min(acc[4], c[4] + b[0]);
    acc[5] = std::min(acc[5], std::min(c[5] + b[0], c[1] + b[4]));
    acc[6] = std::min(acc[6], std::min(c[6] + b[0], c[2] + b[4]));
    acc[7] =
        std::min(acc[7], std::min(std::min(c[7] + b[0], c[5] + b[2]), std::min(c[3] + b[4], c[1] + b[6])));
}

constexpr int kBlockBits = 3;
constexpr std::uint32_t kBlock = 1u << kBlockBits;
constexpr int kTileBits = 6; // blocks per tile: 2^6 x 8 doubles = 4 KiB, so three tiles stay in L1

// One layer: out[t] = min over r subset of t minus its lowest bit of c1[t ^ r] + below[r], for all
// t < 2^bits (bits >= kBlockBits); +inf where t has fewer than q units (below is +inf there).
// t = (hh, hl, lo): the tile hh (parallel), its block hl, the block's state lo; r = (rh, rl, -).
// For each tile pair (hh, rh subset of hh) the whole tile's splits read one tile of costs (hh ^ rh)
// and one of the layer below (rh), both in L1, into the tile's minima.
void computeLayer(int bits, int q, const std::vector<double>& c1, const std::vector<double>& below,
                  std::vector<double>& out) {
    const int tileBits = std::min(kTileBits, bits - kBlockBits);
    const int shift = tileBits + kBlockBits;
    const std::uint32_t tiles = 1u << (bits - shift), blocks = 1u << tileBits;
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, tiles, 1), [&](const auto& range) {
        std::vector<double> acc(std::size_t{1} << shift);
        for (std::uint32_t hh = range.begin(); hh != range.end(); ++hh) {
            double* dst = &out[static_cast<std::size_t>(hh) << shift];
            std::fill(acc.begin(), acc.end(), kUnreached);
            if (std::popcount(hh) + shift >= q) {
                const std::uint32_t lowHh = hh & (~hh + 1);
                for (std::uint32_t rh = hh;; rh = (rh - 1) & hh) {
                    const double* C = &c1[static_cast<std::size_t>(hh ^ rh) << shift];
                    const double* B = &below[static_cast<std::size_t>(rh) << shift];
                    // States (hh, 0, 0) have their lowest unit in hh: it must stay out of rh.
                    const bool rhKeepsLowest = hh != 0 && (rh & lowHh) == 0;
                    for (std::uint32_t hl = 0; hl < blocks; ++hl) {
                        double a[kBlock];
                        std::copy_n(&acc[static_cast<std::size_t>(hl) << kBlockBits], kBlock, a);
                        if (hl == 0) {
                            splitBlock(C, B, a);
                            if (rhKeepsLowest) a[0] = std::min(a[0], C[0] + B[0]);
                        } else {
                            const std::uint32_t lowHl = hl & (~hl + 1), rest = hl ^ lowHl;
                            for (std::uint32_t rl = rest;; rl = (rl - 1) & rest) {
                                const double* c = C + (static_cast<std::size_t>(hl ^ rl) << kBlockBits);
                                const double* b = B + (static_cast<std::size_t>(rl) << kBlockBits);
                                splitBlock(c, b, a);
                                a[0] = std::min(a[0], c[0] + b[0]); // hl's lowest unit stays in V
                                splitBlock(C + (static_cast<std::size_t>(hl ^ rl ^ lowHl) << kBlockBits),
                                           B + (static_cast<std::size_t>(rl | lowHl) << kBlockBits), a);
                                if (rl == 0) break;
                            }
                        }
                        std::copy_n(a, kBlock, &acc[static_cast<std::size_t>(hl) << kBlockBits]);
                    }
                    if (rh == 0) break;
                }
                if (hh == 0) acc[0] = kUnreached; // the empty state
            }
            std::copy(acc.begin(), acc.end(), dst);
        }
    });
}

// The same layer by plain submask enumeration, for fewer than kBlockBits bits.
void computeLayerPlain(int bits, const std::vector<double>& c1, const std::vector<double>& below,
                       std::vector<double>& out) {
    out[0] = kUnreached;
    for (std::uint32_t t = 1; t < (1u << bits); ++t) {
        const std::uint32_t others = t & (t - 1);
        double best = kUnreached;
        for (std::uint32_t r = others;; r = (r - 1) & others) {
            best = std::min(best, c1[t ^ r] + below[r]);
            if (r == 0) break;
        }
        out[t] = best;
    }
}

} // namespace

UnitCurve solveSubsetDp(const GroupCostModel& model, int m, const std::function<void(double)>& progress) {
    const int n = model.size();
    const std::vector<double> cost = allGroupCosts(model);
    if (progress) progress(0.05);

    const int bits = n - 1;
    const std::uint32_t full = (1u << n) - 1u;
    const std::size_t states = std::size_t{1} << bits;
    // layer[q - 1][t] = best[q][t << 1] for q = 1..m-1 (layer 1: the group costs themselves).
    std::vector<std::vector<double>> layer(static_cast<std::size_t>(std::max(m - 1, 1)));
    std::vector<double>& c1 = layer[0];
    c1.resize(states);
    for (std::size_t t = 0; t < states; ++t) c1[t] = t ? cost[t << 1] : kUnreached;

    // The remainder r (of the units 1..n-1) that gives `value` for state t of layer q (q >= 2), or
    // for the top state (all units, q groups) when top is set: the first in a fixed order.
    auto remainderOf = [&](std::uint32_t t, int q, double value, bool top) {
        const std::vector<double>& below = layer[static_cast<std::size_t>(q - 2)];
        const std::uint32_t others = top ? t : (t & (t - 1));
        for (std::uint32_t r = others;; r = (r - 1) & others) {
            const double c = top ? cost[full ^ (r << 1)] : c1[t ^ r];
            if (c + below[r] == value) return r;
            if (r == 0) break;
        }
        return std::uint32_t{0}; // unreachable: value is one of the sums scanned
    };

    UnitCurve curve(static_cast<std::size_t>(m));
    auto finish = [&](int p) {
        UnitPartition& entry = curve[static_cast<std::size_t>(p - 1)];
        entry.optimal = true;
        const std::uint32_t all = static_cast<std::uint32_t>(states - 1);
        if (p == 1) {
            if (!(cost[full] < kUnreached)) return; // conflicting units: no single group
            entry.groups.push_back(full);
        } else {
            // The top state: V holds unit 0 and any subset of the others.
            const std::vector<double>& below = layer[static_cast<std::size_t>(p - 2)];
            double value = kUnreached;
            for (std::uint32_t r = 0; r <= all; ++r)
                value = std::min(value, cost[full ^ (r << 1)] + below[r]);
            if (!(value < kUnreached)) return; // no partition into p groups respects the conflicts
            std::uint32_t t = remainderOf(all, p, value, true);
            entry.groups.push_back(full ^ (t << 1));
            for (int q = p - 1; q >= 2; --q) {
                const std::uint32_t r = remainderOf(t, q, layer[static_cast<std::size_t>(q - 1)][t], false);
                entry.groups.push_back(static_cast<UnitMask>(t ^ r) << 1);
                t = r;
            }
            entry.groups.push_back(static_cast<UnitMask>(t) << 1);
        }
        std::sort(entry.groups.begin(), entry.groups.end(),
                  [](UnitMask a, UnitMask b) { return std::countr_zero(a) < std::countr_zero(b); });
        entry.cost = partitionCost(model, entry.groups);
        entry.lowerBound = entry.cost;
    };
    finish(1);
    if (m >= 2) finish(2);
    for (int q = 2; q <= m - 1; ++q) {
        auto& out = layer[static_cast<std::size_t>(q - 1)];
        out.resize(states);
        if (bits >= kBlockBits)
            computeLayer(bits, q, c1, layer[static_cast<std::size_t>(q - 2)], out);
        else
            computeLayerPlain(bits, c1, layer[static_cast<std::size_t>(q - 2)], out);
        finish(q + 1);
        if (progress) progress(0.05 + 0.95 * q / (m - 1));
    }
    if (progress) progress(1.0);
    return curve;
}

} // namespace vl
