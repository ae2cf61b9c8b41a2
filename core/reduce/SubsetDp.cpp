// Cost of every group: c(S) for all 2^n sets of units, each from S minus its highest unit j in
// O(n): Q(S) = Q(S\j) + 2 sum_{i in S\j} H_ij + H_jj, with F and D summed over the same bits. A set
// holding a conflicting pair costs +inf, so no solver step ever picks it.
//
// Partition DP (the paper's eq. 23): best[q][T] = min over V subset of T of c(V) + best[q-1][T\V].
// Fixing the lowest unit of T inside V enumerates every partition exactly once (halving the work);
// every state below the top one then excludes unit 0, so layers are indexed by subsets of
// {1..n-1} (2^(n-1) entries, bit i = unit i+1).
//
// Speed: a layer is 3^(n-1)/2 additions, so the loop around each one decides the run time. Inside a
// layer the split keeps the state's highest unit in V (any fixed unit enumerates each partition once);
// the two lowest units of a state are the four lanes of one SIMD vector, so one vector addition and
// minimum serve four states (9 of every 16 lane sums are splits, the others add +inf; computeLayer
// below), and a pair of tiles serves all splits between two tiles from L1. Against the scalar
// kernel before it: 2.25x fewer instructions on the floating-point ports. Only the values are kept (all
// layers); the groups are recovered afterwards by finding the split that gives each chosen value, which is
// exact because the kernel and the recovery add the same two doubles. Layers run in parallel over tiles with
// TBB; values and groups do not depend on the thread count or the instruction set (each state is a minimum
// over a fixed set, recovery scans in a fixed order).
#include "core/reduce/SubsetDp.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
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

// Layer layout for the kernel: a state t = (hh, tm, l) - tile hh (parallel), its middle bits tm
// (kTileBits), and two lane bits l, the four states of one SIMD vector. A split keeps t's highest unit
// in V = t ^ r, so for hh != 0 the remainder's middle and lane parts are free: r = (rh, rm, s) with
// rh a subset of hh minus its highest unit, rm of tm, s of l. For a fixed s the four lanes l take
// c1[(hh^rh, tm^rm, l^s)] + below[(rh, rm, s)] when s is a subset of l: one vector of the shifted
// costs below (+inf where s is not a subset of l) plus one broadcast value. All splits of a tile pair
// (hh, rh) read one tile of shifted costs and one of the layer below, both in L1.
constexpr int kLaneBits = 2;
constexpr std::uint32_t kLanes = 1u << kLaneBits;
constexpr int kTileBits =
    6; // 2^6 x 4 vectors of shifted costs = 8 KiB; the layer below and the minima 2 KiB each

using Lanes = double __attribute__((vector_size(kLanes * sizeof(double))));

// shifted[(x * kLanes + s) * kLanes + l] = c1[x * kLanes + (l ^ s)] if s is a subset of l, else +inf:
// the four vectors of one x side by side. Layer independent, so built once per run.
std::vector<double> shiftedCosts(const std::vector<double>& c1) {
    std::vector<double> shifted(c1.size() * kLanes);
    for (std::size_t x = 0; x < c1.size() / kLanes; ++x)
        for (std::uint32_t s = 0; s < kLanes; ++s)
            for (std::uint32_t l = 0; l < kLanes; ++l)
                shifted[(x * kLanes + s) * kLanes + l] = (l & s) == s ? c1[x * kLanes + (l ^ s)] : kUnreached;
    return shifted;
}

// The plain submask enumeration of a layer for the states t < 2^bits (they only split into smaller
// ones): the layer's first tile, and whole layers of one tile or less (up to 9 units).
void computeLayerPlain(int bits, const std::vector<double>& c1, const std::vector<double>& below,
                       std::vector<double>& out) {
    out[0] = kUnreached;
    for (std::uint32_t t = 1; t < (1u << bits); ++t) {
        const std::uint32_t others = t ^ std::bit_floor(t);
        double best = kUnreached;
        for (std::uint32_t r = others;; r = (r - 1) & others) {
            best = std::min(best, c1[t ^ r] + below[r]);
            if (r == 0) break;
        }
        out[t] = best;
    }
}

// Helpers take and give vectors by reference: a 32-byte vector passed by value has a different ABI
// with and without AVX, and the kernels are compiled for both.
[[gnu::always_inline]] inline void loadLanes(Lanes& v, const double* p) {
    std::memcpy(&v, p, sizeof(Lanes));
}
[[gnu::always_inline]] inline void storeLanes(double* p, const Lanes& v) {
    std::memcpy(p, &v, sizeof(Lanes));
}
[[gnu::always_inline]] inline void takeMin(Lanes& a, const Lanes& b) {
    a = b < a ? b : a;
}

// A tile pair (hh, rh), hh != 0: t's highest unit is hh's, so every rm subset of tm is allowed.
// acc[tm] = min(acc[tm], the minimum over the splits), with `C` the shifted costs of tile hh ^ rh and
// `B` the layer below at tile rh. Two states per pass, tm and tm | top (top: the highest middle
// bit), sharing loads: for each rm subset of tm, tm takes C[tm ^ rm] + B[rm], and tm | top takes
// C[(tm ^ rm) | top] + B[rm] and C[tm ^ rm] + B[rm | top], which are all of its splits. Four
// minima per state (one per s) keep the min latency off the additions' critical path. Compiled
// for AVX2 and for the baseline (SSE2): the same additions and minima, so the same values to the bit.
[[gnu::target_clones("avx2", "default")]] void splitTilePair(const double* C, const double* B, double* acc) {
    constexpr std::size_t kCostStride = kLanes * kLanes; // the four shifted vectors of one x
    const Lanes inf = {kUnreached, kUnreached, kUnreached, kUnreached};
    constexpr std::uint32_t top = 1u << (kTileBits - 1);
    for (std::uint32_t tm = 0; tm < top; ++tm) {
        Lanes low[kLanes] = {inf, inf, inf, inf}, high[kLanes] = {inf, inf, inf, inf};
        for (std::uint32_t rm = tm;; rm = (rm - 1) & tm) {
            const double* c = C + static_cast<std::size_t>(tm ^ rm) * kCostStride;
            const double* cTop = c + static_cast<std::size_t>(top) * kCostStride;
            const double* b = B + static_cast<std::size_t>(rm) * kLanes;
            const double* bTop = b + static_cast<std::size_t>(top) * kLanes;
#pragma GCC unroll 4
            for (std::uint32_t s = 0; s < kLanes; ++s) {
                Lanes cs, withTop, topInR;
                loadLanes(cs, c + s * kLanes);
                loadLanes(withTop, cTop + s * kLanes);
                topInR = cs + bTop[s];
                cs += b[s];
                withTop += b[s];
                takeMin(low[s], cs);
                takeMin(withTop, topInR);
                takeMin(high[s], withTop);
            }
            if (rm == 0) break;
        }
        for (const auto& [state, part] : {std::pair{tm, &low[0]}, std::pair{tm | top, &high[0]}}) {
            takeMin(part[0], part[1]);
            takeMin(part[2], part[3]);
            takeMin(part[0], part[2]);
            Lanes merged;
            double* dst = acc + static_cast<std::size_t>(state) * kLanes;
            loadLanes(merged, dst);
            takeMin(merged, part[0]);
            storeLanes(dst, merged);
        }
    }
}

// The bits of a tile: its middle bits and the lane bits.
constexpr int kTileShift = kTileBits + kLaneBits;

// One layer: out[t] = min over r subset of t minus its highest unit of c1[t ^ r] + below[r], for all
// t < 2^bits (bits > kTileShift, so at least two tiles); +inf where t has fewer than q units (below is
// +inf there).
void computeLayer(int bits, int q, const std::vector<double>& c1, const std::vector<double>& shifted,
                  const std::vector<double>& below, std::vector<double>& out) {
    constexpr int shift = kTileShift;
    const std::uint32_t tiles = 1u << (bits - shift);
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, tiles, 1), [&](const auto& range) {
        std::vector<double> acc(std::size_t{1} << shift);
        for (std::uint32_t hh = range.begin(); hh != range.end(); ++hh) {
            if (hh == 0) { // t's highest unit is in the tile: the few states of tile 0 one by one
                computeLayerPlain(shift, c1, below, out);
                continue;
            }
            std::fill(acc.begin(), acc.end(), kUnreached);
            if (std::popcount(hh) + shift >= q) {
                const std::uint32_t free = hh ^ std::bit_floor(hh);
                for (std::uint32_t rh = free;; rh = (rh - 1) & free) {
                    // Splits whose remainder has fewer than q - 1 units add +inf: skip them.
                    if (std::popcount(rh) + shift >= q - 1)
                        splitTilePair(&shifted[static_cast<std::size_t>(hh ^ rh) << (shift + kLaneBits)],
                                      &below[static_cast<std::size_t>(rh) << shift], acc.data());
                    if (rh == 0) break;
                }
            }
            std::copy(acc.begin(), acc.end(), &out[static_cast<std::size_t>(hh) << shift]);
        }
    });
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
    const std::vector<double> shifted = bits > kTileShift && m > 2 ? shiftedCosts(c1) : std::vector<double>{};

    // The remainder r (of the units 1..n-1) that gives `value` for state t of layer q (q >= 2), or
    // for the top state (all units, q groups) when top is set: the first in a fixed order.
    auto remainderOf = [&](std::uint32_t t, int q, double value, bool top) {
        const std::vector<double>& below = layer[static_cast<std::size_t>(q - 2)];
        const std::uint32_t others = top ? t : (t ^ std::bit_floor(t));
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
        if (bits > kTileShift)
            computeLayer(bits, q, c1, shifted, layer[static_cast<std::size_t>(q - 2)], out);
        else
            computeLayerPlain(bits, c1, layer[static_cast<std::size_t>(q - 2)], out);
        finish(q + 1);
        if (progress) progress(0.05 + 0.95 * q / (m - 1));
    }
    if (progress) progress(1.0);
    return curve;
}

} // namespace vl
