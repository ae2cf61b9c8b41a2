// Cost of every group: c(S) for all 2^n sets of units, each from S minus its highest unit j in
// O(n): Q(S) = Q(S\j) + 2 sum_{i in S\j} H_ij + H_jj, with F and D summed over the same bits. A set
// holding a conflicting pair costs +inf, so no solver step ever picks it. In the rest-free model a set
// holding the rest unit costs the sum of its rest costs instead (GroupCostModel.h); the DP below is a
// minimum over partitions of any set function, so it needs nothing else: into p + 1 groups it gives
// the rest group and p keys.
//
// Partition DP (the paper's eq. 23): best[q][T] = min over V subset of T of c(V) + best[q-1][T\V].
// Fixing the lowest unit of T inside V enumerates every partition exactly once (halving the work);
// every state below the top one then excludes unit 0, so layers are indexed by subsets of
// {1..n-1} (2^(n-1) entries, bit i = unit i+1).
//
// Speed: a layer is 3^(n-1)/2 splits, so the loop around them decides the run time. Each split keeps
// the state's highest unit in V (any fixed unit enumerates each partition once), so its remainder is
// a smaller state; all layers of a state are one row, and one pass over the states in increasing
// order fills every layer: a split adds its group cost to the remainder's whole row (layers 1..K-1)
// and takes the minimum into the state's row (layers 2..K). Every SIMD lane is a wanted sum, and the
// run reads the splits once instead of once per layer: against the layer-by-layer kernel before it
// (two units as the four lanes, 9 of 16 lane sums wanted) 1.8x fewer vector additions at m = 10. A
// pair of tiles serves all splits between two tiles from L1. Only the values are kept; the groups are
// recovered afterwards by finding the split that gives each chosen value, which is exact because the
// kernel and the recovery add the same two doubles. Tiles with the same highest unit run in parallel
// with TBB; values and groups do not depend on the thread count or the instruction set (each state is
// a minimum over a fixed set, recovery scans in a fixed order).
#include "core/reduce/SubsetDp.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>
#include <utility>

namespace vl {

namespace {

constexpr double kUnreached = std::numeric_limits<double>::infinity();

// Row layout: all layers of one state side by side, rows[t * stride + q - 1] = best[q][t << 1] for
// q = 1..K (K = m - 1). Every split r of t (r a subset of t minus its highest unit, so r < t) adds one
// group cost c1[t ^ r] to the whole row of r, giving the row of t one layer up: out[t][q] = min over r
// of c1[t ^ r] + row[r][q - 1] for q = 2..K at once. Rows of smaller states are final before t needs
// them, so one pass in increasing t fills every layer, and every SIMD lane is a wanted sum.
constexpr int kLanes = 4;
using Lanes = double __attribute__((vector_size(kLanes * sizeof(double))));
constexpr int kMaxVectors = 6; // K - 1 <= 21 layers: every m the DP accepts

// A row holds the vectors plus one more: room for the store of layers 2..K at offset 1.
constexpr std::size_t rowStride(int vectors) {
    return static_cast<std::size_t>(kLanes) * static_cast<std::size_t>(vectors + 1);
}

struct Rows {
    int layers = 0;             // K = m - 1
    int vectors = 0;            // SIMD vectors for the K - 1 layers a split updates
    std::size_t stride = 0;     // rowStride(vectors)
    std::vector<Lanes> storage; // 32-byte aligned rows
    double* data() { return reinterpret_cast<double*>(storage.data()); }
    double at(std::uint32_t t, int q) const {
        return reinterpret_cast<const double*>(storage.data())[t * stride + static_cast<std::size_t>(q - 1)];
    }
};

// Tiles of 2^7 states: a tile pair reads one tile of rows (12 KiB at m = 10) and keeps one of
// minima (8 KiB), both in L1.
constexpr int kTileBits = 7;
constexpr std::uint32_t kTileStates = 1u << kTileBits;

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

// Keeps a loaded vector in a register for its two additions: GCC would otherwise fold the load into
// both, one load more per pair. Only a 256-bit register can hold it, so only the AVX2 copy asks;
// clang (sanitizer builds) rejects the constraint there and chooses its own way.
[[gnu::always_inline]] inline void pinInRegister([[maybe_unused]] Lanes& v) {
#if !defined(__clang__)
    asm("" : "+x"(v));
#endif
}

// The states t < limit one by one, in increasing order (each split's row is already final): whole
// DPs of one tile or less, and the first tile (its states split only inside it).
void fillRowsPlain(std::uint32_t limit, const std::vector<double>& c1, Rows& rows) {
    const int K = rows.layers;
    std::vector<double> best(static_cast<std::size_t>(K));
    for (std::uint32_t t = 1; t < limit; ++t) {
        std::fill(best.begin(), best.end(), kUnreached);
        const std::uint32_t others = t ^ std::bit_floor(t);
        for (std::uint32_t r = others;; r = (r - 1) & others) {
            const double c = c1[t ^ r];
            const double* below = rows.data() + r * rows.stride;
            for (int q = 2; q <= K; ++q)
                best[static_cast<std::size_t>(q - 1)] =
                    std::min(best[static_cast<std::size_t>(q - 1)], c + below[q - 2]);
            if (r == 0) break;
        }
        double* row = rows.data() + t * rows.stride;
        row[0] = c1[t];
        std::copy(best.begin() + 1, best.end(), row + 1);
    }
}

// The states of a tile's lowest quarter ordered by their number of units: the split loop of a state
// runs 2^units times, so equal trip counts in a row keep the loop exit predicted.
constexpr auto kLowQuarterByUnitCount = [] {
    std::array<std::uint32_t, kTileStates / 4> order{};
    std::size_t next = 0;
    for (int units = 0; units < kTileBits; ++units)
        for (std::uint32_t tm = 0; tm < order.size(); ++tm)
            if (std::popcount(tm) == units) order[next++] = tm;
    return order;
}();

// A tile pair (hh, rh), hh != 0: t's highest unit is in hh, so every rm subset of tm is a split.
// `C` = c1 of tile hh ^ rh, `B` = the rows of tile rh, acc[tm * V * 4 ...] = the running minima of
// state tm's layers 2..K. Four states per pass, tm | A for A a subset of the tile's two highest bits
// {h1, h2}, sharing loads: with d = tm ^ rm, state tm | A takes C[d | X] + B[rm | Y] for every split
// of A into disjoint X and Y (1, 2, 2 and 4 sums), which are all of its splits. Per pass: 4 group
// costs and 4 V rows loaded for 9 V vector sums. kPin: pinInRegister.
template <int V, bool kPin>
[[gnu::always_inline]] inline void splitTilePairBody(const double* C, const double* B, double* acc) {
    constexpr std::uint32_t h1 = kTileStates / 4, h2 = kTileStates / 2; // tm, rm, d < h1: "|" is "+"
    constexpr std::size_t stride = rowStride(V);
    constexpr std::size_t accStride = static_cast<std::size_t>(V) * kLanes;
    const Lanes inf = {kUnreached, kUnreached, kUnreached, kUnreached};
    for (const std::uint32_t tm : kLowQuarterByUnitCount) {
        Lanes best[4][V]; // by A: {}, {h1}, {h2}, {h1, h2}
        for (auto& state : best)
            for (int v = 0; v < V; ++v) state[v] = inf;
        for (std::uint32_t rm = tm;; rm = (rm - 1) & tm) {
            const double* c = C + (tm ^ rm);
            const double c0 = c[0], c1 = c[h1], c2 = c[h2], c12 = c[h1 + h2];
            const double* b = B + rm * stride;
            for (int v = 0; v < V; ++v) {
                Lanes row;
                loadLanes(row, b + v * kLanes); // Y = {}
                if constexpr (kPin) pinInRegister(row);
                takeMin(best[0][v], row + c0);
                takeMin(best[1][v], row + c1);
                takeMin(best[2][v], row + c2);
                takeMin(best[3][v], row + c12);
                loadLanes(row, b + h1 * stride + v * kLanes); // Y = {h1}
                if constexpr (kPin) pinInRegister(row);
                takeMin(best[1][v], row + c0);
                takeMin(best[3][v], row + c2);
                loadLanes(row, b + h2 * stride + v * kLanes); // Y = {h2}
                if constexpr (kPin) pinInRegister(row);
                takeMin(best[2][v], row + c0);
                takeMin(best[3][v], row + c1);
                loadLanes(row, b + (h1 + h2) * stride + v * kLanes); // Y = {h1, h2}
                takeMin(best[3][v], row + c0);
            }
            if (rm == 0) break;
        }
        constexpr std::uint32_t offset[4] = {0, h1, h2, h1 + h2};
        for (int a = 0; a < 4; ++a) {
            double* dst = acc + (tm + offset[a]) * accStride;
            for (int v = 0; v < V; ++v) {
                Lanes merged;
                loadLanes(merged, dst + v * kLanes);
                takeMin(merged, best[a][v]);
                storeLanes(dst + v * kLanes, merged);
            }
        }
    }
}

using TilePairKernel = void (*)(const double*, const double*, double*);

template <int V>
[[gnu::target("avx2")]] void splitTilePairAvx2(const double* C, const double* B, double* acc) {
    splitTilePairBody<V, true>(C, B, acc);
}
template <int V> void splitTilePairBaseline(const double* C, const double* B, double* acc) {
    splitTilePairBody<V, false>(C, B, acc);
}

// The kernel for V vectors per row, AVX2 when the CPU has it. Both copies do the same additions and
// minima, so they give the same values to the bit.
TilePairKernel tilePairKernel(int vectors) {
    static const bool avx2 = __builtin_cpu_supports("avx2");
    return [&]<int... V>(std::integer_sequence<int, V...>) {
        TilePairKernel kernel = nullptr;
        ((kernel =
              V + 1 == vectors ? (avx2 ? &splitTilePairAvx2<V + 1> : &splitTilePairBaseline<V + 1>) : kernel),
         ...);
        return kernel;
    }
    (std::make_integer_sequence<int, kMaxVectors>{});
}

// Every row of states t < 2^bits (bits > kTileBits). Tiles whose highest unit is the same only read
// rows of lower tiles, so each such level runs in parallel over its tiles; `progress` after each
// level, in proportion to its work (3^level).
void fillRows(int bits, const std::vector<double>& c1, Rows& rows,
              const std::function<void(double)>& progress) {
    fillRowsPlain(kTileStates, c1, rows);
    const TilePairKernel kernel = tilePairKernel(rows.vectors);
    const std::size_t accStride = static_cast<std::size_t>(rows.vectors) * kLanes;
    const int levels = bits - kTileBits;
    const double totalWork = (std::pow(3.0, levels) - 1) / 2;
    double doneWork = 0;
    for (int level = 0; level < levels; ++level) {
        const std::uint32_t first = 1u << level;
        tbb::parallel_for(tbb::blocked_range<std::uint32_t>(first, 2 * first, 1), [&](const auto& range) {
            std::vector<Lanes> accBuffer(kTileStates * static_cast<std::size_t>(rows.vectors));
            const std::span<double> acc(reinterpret_cast<double*>(accBuffer.data()), kTileStates * accStride);
            for (std::uint32_t hh = range.begin(); hh != range.end(); ++hh) {
                std::fill(acc.begin(), acc.end(), kUnreached);
                const std::uint32_t free = hh ^ first;
                for (std::uint32_t rh = free;; rh = (rh - 1) & free) {
                    kernel(&c1[static_cast<std::size_t>(hh ^ rh) << kTileBits],
                           rows.data() + (static_cast<std::size_t>(rh) << kTileBits) * rows.stride,
                           acc.data());
                    if (rh == 0) break;
                }
                for (std::uint32_t tm = 0; tm < kTileStates; ++tm) {
                    const std::size_t t = (static_cast<std::size_t>(hh) << kTileBits) | tm;
                    double* row = rows.data() + t * rows.stride;
                    row[0] = c1[t];
                    std::copy_n(&acc[tm * accStride], rows.layers - 1, row + 1);
                }
            }
        });
        doneWork += std::pow(3.0, level);
        if (progress) progress(doneWork / totalWork);
    }
}

// c(S) of a set holding the rest unit: the sum of its members' rest costs (GroupCostModel.h).
double restCost(const GroupCostModel& model, std::size_t set) {
    double sum = 0;
    for (std::size_t bits = set; bits; bits &= bits - 1)
        sum += model.rest[static_cast<std::size_t>(std::countr_zero(bits))];
    return sum;
}

} // namespace

std::vector<double> allSubsetCosts(const GroupCostModel& model) {
    const int n = model.size();
    const std::size_t count = std::size_t{1} << n;
    std::vector<double> cost(count, 0.0), Q(count, 0.0);
    const std::size_t restBit = model.restUnit >= 0 ? std::size_t{1} << model.restUnit : 0;
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
                if (!conflict && (s & restBit)) cost[s] = restCost(model, s);
            }
        });
    }
    return cost;
}

UnitCurve solveSubsetDp(const GroupCostModel& model, int m, const std::function<void(double)>& progress) {
    const int n = model.size();
    const std::vector<double> cost = allSubsetCosts(model);
    if (progress) progress(0.05);

    const int bits = n - 1;
    const std::uint32_t full = (1u << n) - 1u;
    const std::uint32_t states = 1u << bits;
    std::vector<double> c1(states); // layer 1: the group costs of the states (units 1..n-1)
    for (std::uint32_t t = 0; t < states; ++t)
        c1[t] = t ? cost[static_cast<std::size_t>(t) << 1] : kUnreached;
    Rows rows;
    rows.layers = std::max(m - 1, 1);
    rows.vectors = (rows.layers - 1 + kLanes - 1) / kLanes;
    rows.stride = rowStride(rows.vectors);
    const Lanes inf = {kUnreached, kUnreached, kUnreached, kUnreached};
    rows.storage.assign(states * rows.stride / kLanes, inf); // lanes past layer K read +inf
    if (rows.layers == 1)
        for (std::uint32_t t = 0; t < states; ++t) rows.data()[t * rows.stride] = c1[t];
    else if (bits > kTileBits)
        fillRows(bits, c1, rows, [&](double done) {
            if (progress) progress(0.05 + 0.9 * done);
        });
    else
        fillRowsPlain(states, c1, rows);

    // The top state (all units): its group holds unit 0 and any subset of the others, the remainder r
    // takes p - 1 groups. topValue[p - 2] for p = 2..m in one pass over r, with topRemainder the
    // largest r that gives it (the one the scan below would find first), read in order instead of one
    // strided scan of every row per p.
    std::vector<double> topValue(static_cast<std::size_t>(rows.layers), kUnreached);
    std::vector<std::uint32_t> topRemainder(static_cast<std::size_t>(rows.layers), 0);
    if (m >= 2)
        for (std::uint32_t r = 0; r < states; ++r) {
            const double c = cost[full ^ (r << 1)];
            const double* row = rows.data() + r * rows.stride;
            for (std::size_t k = 0; k < static_cast<std::size_t>(m - 1); ++k)
                if (const double sum = c + row[k]; sum <= topValue[k]) {
                    topValue[k] = sum;
                    topRemainder[k] = r;
                }
        }

    // The remainder r (of the units 1..n-1) that gives `value` for state t of layer q (q >= 2): the
    // first in a fixed order. Exact: the scan adds the same two doubles as the pass that found `value`.
    auto remainderOf = [&](std::uint32_t t, int q, double value) {
        const std::uint32_t others = t ^ std::bit_floor(t);
        for (std::uint32_t r = others;; r = (r - 1) & others) {
            if (c1[t ^ r] + rows.at(r, q - 1) == value) return r;
            if (r == 0) break;
        }
        return std::uint32_t{0}; // unreachable: value is one of the sums scanned
    };

    UnitCurve curve(static_cast<std::size_t>(m));
    for (int p = 1; p <= m; ++p) {
        UnitPartition& entry = curve[static_cast<std::size_t>(p - 1)];
        entry.optimal = true;
        if (p == 1) {
            if (!(cost[full] < kUnreached)) continue; // conflicting units: no single group
            entry.groups.push_back(full);
        } else {
            const double value = topValue[static_cast<std::size_t>(p - 2)];
            if (!(value < kUnreached)) continue; // no partition into p groups respects the conflicts
            std::uint32_t t = topRemainder[static_cast<std::size_t>(p - 2)];
            entry.groups.push_back(full ^ (t << 1));
            for (int q = p - 1; q >= 2; --q) {
                const std::uint32_t r = remainderOf(t, q, rows.at(t, q));
                entry.groups.push_back(static_cast<UnitMask>(t ^ r) << 1);
                t = r;
            }
            entry.groups.push_back(static_cast<UnitMask>(t) << 1);
        }
        std::sort(entry.groups.begin(), entry.groups.end(),
                  [](UnitMask a, UnitMask b) { return std::countr_zero(a) < std::countr_zero(b); });
        entry.cost = partitionCost(model, entry.groups);
        entry.lowerBound = entry.cost;
    }
    if (progress) progress(1.0);
    return curve;
}

} // namespace vl
