#include "core/reduce/GramMatrix.h"

#include "core/common/Error.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace vl {

namespace {

constexpr std::size_t kBlockVertices = 128;

// Upper triangle of the Gram matrix of one block of vertices [begin, end), added into `gram`.
void addBlock(const ShapeView& shapes, std::span<const double> frequencies, std::span<const double> weights,
              double total, std::size_t begin, std::size_t end, std::vector<double>& gram) {
    const std::size_t n = shapes.size();
    const std::size_t count = end - begin;
    // The block's positions, each read once (a float32 row widened here, not at every use).
    std::vector<Vec3> block(n * count);
    for (std::size_t i = 0; i < n; ++i) {
        const ShapeRow shape = shapes[i];
        for (std::size_t k = 0; k < count; ++k) block[i * count + k] = shape[begin + k];
    }
    // Centred, sqrt(w)-scaled coordinates, one row of 3 * count values per shape.
    std::vector<double> rows(n * 3 * count);
    for (std::size_t k = 0; k < count; ++k) {
        const std::size_t v = begin + k;
        Vec3 centre(0, 0, 0);
        for (std::size_t i = 0; i < n; ++i) centre += frequencies[i] * block[i * count + k];
        centre /= total;
        const double s = std::sqrt(weights[v]);
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 d = (block[i * count + k] - centre) * s;
            double* row = &rows[i * 3 * count + 3 * k];
            row[0] = d[0], row[1] = d[1], row[2] = d[2];
        }
    }
    const std::size_t length = 3 * count;
    for (std::size_t i = 0; i < n; ++i) {
        const double* a = &rows[i * length];
        for (std::size_t j = i; j < n; ++j) {
            const double* b = &rows[j * length];
            // Four partial sums, combined in a fixed order: the additions no longer wait on one another
            // (the sum is latency-bound otherwise), and the result stays independent of scheduling.
            double sum[4] = {0, 0, 0, 0};
            std::size_t t = 0;
            for (; t + 4 <= length; t += 4)
                for (std::size_t lane = 0; lane < 4; ++lane) sum[lane] += a[t + lane] * b[t + lane];
            for (; t < length; ++t) sum[0] += a[t] * b[t];
            gram[i * n + j] += (sum[0] + sum[1]) + (sum[2] + sum[3]);
        }
    }
}

} // namespace

std::vector<double> centredGram(const ShapeView& shapes, std::span<const double> frequencies,
                                std::span<const double> weights) {
    const std::size_t n = shapes.size();
    const std::size_t vertices = weights.size();
    double total = 0;
    for (const double f : frequencies) total += f;
    // A fixed split into chunks of consecutive vertex blocks, one partial matrix each, summed in chunk
    // order: the result is the same whatever the scheduling.
    const std::size_t blocks = (vertices + kBlockVertices - 1) / kBlockVertices;
    const std::size_t chunks = std::min<std::size_t>(blocks, 32);
    std::vector<std::vector<double>> partial(chunks);
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
        partial[c].assign(n * n, 0.0);
        for (std::size_t b = c * blocks / chunks; b < (c + 1) * blocks / chunks; ++b) {
            const std::size_t begin = b * kBlockVertices;
            addBlock(shapes, frequencies, weights, total, begin, std::min(vertices, begin + kBlockVertices),
                     partial[c]);
        }
    });
    std::vector<double> gram(n * n, 0.0);
    for (const auto& p : partial)
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i; j < n; ++j) gram[i * n + j] += p[i * n + j];
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < i; ++j) gram[i * n + j] = gram[j * n + i];
    // Readers bound coordinates; huge weights or frequencies can still overflow: never a silent 0.
    for (std::size_t k = 0; k < n * n; ++k)
        if (!std::isfinite(gram[k]))
            throwInputError("viseme set", "the weighted squared distances between shapes " +
                                              std::to_string(k / n + 1) + " and " +
                                              std::to_string(k % n + 1) +
                                              " overflow (coordinates, weights or frequencies too large)");
    return gram;
}

} // namespace vl
