#include "ui/session/FaceSamples.h"

#include "core/deform/CascadeSampler.h"
#include "core/face/BundledFace.h"
#include "core/face/HeadParts.h"

#include <algorithm>
#include <optional>

namespace vl::ui {

FaceSamples sampleFace(const DeformationCascade& cascade, const std::vector<Vec2>& uvs) {
    const std::size_t k = cascade.parameters.size();
    // The cascade is linear in q: sample it at q = 0 and at each unit vector e_k. The core's
    // sampler (fields sampled once, sparse sums) does it when 0 and 1 are valid values of every
    // parameter; otherwise the per-point evaluation does.
    const bool unitVectorsValid =
        std::all_of(cascade.parameters.begin(), cascade.parameters.end(),
                    [](const DeformParameter& p) { return p.min <= 0.0 && p.max >= 1.0; });
    std::vector<double> q(k, 0.0);
    std::optional<CascadeSampler> sampler;
    if (unitVectorsValid) sampler.emplace(cascade, uvs);
    auto evaluateAll = [&] {
        if (sampler) return sampler->evaluate(q);
        std::vector<Vec3> points;
        points.reserve(uvs.size());
        for (const Vec2& uv : uvs) points.push_back(cascade.evaluateUnchecked(uv[0], uv[1], q));
        return points;
    };
    FaceSamples out;
    out.rest = evaluateAll();
    for (std::size_t p = 0; p < k; ++p) {
        q.assign(k, 0.0);
        q[p] = 1.0;
        out.targets.push_back(evaluateAll());
    }
    out.colours = face::faceColours(uvs);
    return out;
}

HeadPartSamples sampleHeadParts(const DeformationCascade& cascade) {
    const std::vector<face::HeadPart> parts = face::makeHeadParts(cascade);
    const face::HeadPartsSampler sampler(cascade, parts);
    const MeshData mesh = face::partsMesh(parts);
    HeadPartSamples out;
    for (const face::HeadPart& part : parts)
        out.parts.push_back({part.name,
                             out.parts.empty() ? 0 : out.parts.back().first + out.parts.back().count,
                             part.rest.positions.size()});
    out.rest = sampler.rest();
    out.triangles = mesh.triangles;
    for (std::size_t k = 0; k < cascade.parameters.size(); ++k) {
        std::vector<Vec3> target = sampler.displacement(k);
        for (std::size_t i = 0; i < target.size(); ++i) target[i] += out.rest[i];
        out.targets.push_back(std::move(target));
    }
    out.colours = face::faceColours(mesh.uvs);
    return out;
}

} // namespace vl::ui
