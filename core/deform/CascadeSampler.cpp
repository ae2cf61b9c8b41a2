#include "core/deform/CascadeSampler.h"

#include "core/common/Error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <string>

namespace vl {

namespace {

// Vertices per block: big enough that a block is worth a task, small enough to balance two cores.
constexpr std::size_t kBlockSize = 8192;

std::size_t blockCount(std::size_t vertices) {
    return (vertices + kBlockSize - 1) / kBlockSize;
}

} // namespace

CascadeSampler::CascadeSampler(const DeformationCascade& cascade, std::span<const Vec2> uvs) {
    validateCascade(cascade);
    if (uvs.size() > UINT32_MAX) throwInputError("cascade sampler", "too many vertices");
    ranges_.name = cascade.name;
    ranges_.parameters = cascade.parameters;
    const std::size_t n = uvs.size();
    baseX_.assign(n, 0.0);
    baseY_.assign(n, 0.0);
    baseZ_.assign(n, 0.0);
    fields_.assign(cascade.parameters.size(), {});

    // Only AddVector stages after the last Constant stage contribute.
    std::size_t first = 0;
    for (std::size_t k = 0; k < cascade.stages.size(); ++k)
        if (cascade.stages[k].kind == StageKind::Constant) first = k;

    std::vector<Vec3> dense(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 p = cascade.stages[first].field.at(uvs[i][0], uvs[i][1]);
        baseX_[i] = p[0];
        baseY_[i] = p[1];
        baseZ_[i] = p[2];
    }
    for (std::size_t k = 0; k < fields_.size(); ++k) {
        bool used = false;
        std::fill(dense.begin(), dense.end(), Vec3(0.0, 0.0, 0.0));
        for (std::size_t s = first + 1; s < cascade.stages.size(); ++s) {
            const auto& stage = cascade.stages[s];
            if (stage.parameter != k) continue;
            used = true;
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const auto& r) {
                for (std::size_t i = r.begin(); i != r.end(); ++i)
                    dense[i] += stage.field.at(uvs[i][0], uvs[i][1]);
            });
        }
        auto& f = fields_[k];
        if (used)
            for (std::size_t i = 0; i < n; ++i) {
                const Vec3& d = dense[i];
                if (d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0) continue;
                f.index.push_back(static_cast<std::uint32_t>(i));
                f.x.push_back(d[0]);
                f.y.push_back(d[1]);
                f.z.push_back(d[2]);
            }
        // blockStart[b] = first entry whose vertex is in block b or later.
        const std::size_t blocks = blockCount(n);
        f.blockStart.resize(blocks + 1);
        for (std::size_t b = 0; b <= blocks; ++b)
            f.blockStart[b] = static_cast<std::uint32_t>(
                std::lower_bound(f.index.begin(), f.index.end(), std::min(b * kBlockSize, n)) -
                f.index.begin());
    }
}

void CascadeSampler::evaluateBlock(std::size_t block, std::span<const double> q, std::span<Vec3> out) const {
    const std::size_t begin = block * kBlockSize;
    const std::size_t end = std::min(begin + kBlockSize, vertexCount());
    for (std::size_t i = begin; i < end; ++i) out[i] = Vec3(baseX_[i], baseY_[i], baseZ_[i]);
    for (std::size_t k = 0; k < fields_.size(); ++k) {
        const double w = q[k];
        if (w == 0.0) continue;
        const auto& f = fields_[k];
        const std::uint32_t* index = f.index.data();
        const double* x = f.x.data();
        const double* y = f.y.data();
        const double* z = f.z.data();
        const std::uint32_t first = f.blockStart[block], last = f.blockStart[block + 1];
        if (last - first == end - begin) {
            // The field covers the whole block: entry first + k is vertex begin + k, no index needed.
            for (std::size_t j = 0; j < end - begin; ++j) {
                Vec3& p = out[begin + j];
                p[0] += w * x[first + j];
                p[1] += w * y[first + j];
                p[2] += w * z[first + j];
            }
            continue;
        }
        for (std::uint32_t e = first; e < last; ++e) {
            Vec3& p = out[index[e]];
            p[0] += w * x[e];
            p[1] += w * y[e];
            p[2] += w * z[e];
        }
    }
}

void CascadeSampler::evaluate(std::span<const double> q, std::span<Vec3> out) const {
    checkParameterValues(ranges_, q);
    if (out.size() != vertexCount())
        throwInputError("cascade sampler", "output has " + std::to_string(out.size()) +
                                               " positions, expected " + std::to_string(vertexCount()));
    const std::size_t blocks = blockCount(vertexCount());
    if (blocks <= 1) {
        for (std::size_t b = 0; b < blocks; ++b) evaluateBlock(b, q, out);
        return;
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks, 1), [&](const auto& r) {
        for (std::size_t b = r.begin(); b != r.end(); ++b) evaluateBlock(b, q, out);
    });
}

std::vector<Vec3> CascadeSampler::evaluate(std::span<const double> q) const {
    std::vector<Vec3> out(vertexCount());
    evaluate(q, out);
    return out;
}

} // namespace vl
