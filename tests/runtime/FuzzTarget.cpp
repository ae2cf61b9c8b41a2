#include "FuzzTarget.h"

#include "core/runtime/Animation.h"
#include "core/runtime/Crc32.h"
#include "core/runtime/PackageFormat.h"

#include <cstdlib>
#include <vector>

namespace vl::test {

namespace {

int loadAndAnimate(const std::uint8_t* data, std::size_t size) {
    runtime::Package package;
    std::string error;
    if (!package.load(data, size, error)) {
        if (error.empty()) std::abort(); // a rejection must say why
        return 0;
    }
    std::vector<float> out(3ull * package.vertexCount());
    for (std::uint32_t corner = 0; corner < 3 * package.triangleCount(); ++corner)
        if (package.index(corner) >= package.vertexCount()) std::abort();
    for (std::uint32_t p = 0; p < package.phonemeCount(); ++p)
        // A phoneme maps to a key or rests (kRestKey: the neutral face).
        if (package.keyOfPhoneme(p) >= package.keyCount() && package.keyOfPhoneme(p) != runtime::kRestKey)
            std::abort();
    std::vector<runtime::Keyframe> keyframes{{0.0, runtime::kRestKey}};
    for (std::uint32_t k = 0; k < package.keyCount() && k < 8; ++k) keyframes.push_back({0.1 * (k + 1), k});
    for (auto interpolation :
         {runtime::Interpolation::Linear, runtime::Interpolation::Cubic, runtime::Interpolation::Dominance}) {
        runtime::KeyframeAnimation animation;
        if (!animation.setKeyframes(package, keyframes, interpolation, error)) std::abort();
        for (double t = -0.05; t <= animation.endTime() + 0.05; t += 0.037) animation.evaluate(t, out.data());
    }
    return 1;
}

} // namespace

int fuzzRuntimePackage(const std::uint8_t* data, std::size_t size) {
    int loaded = loadAndAnimate(data, size);
    // Random bytes almost never carry a matching CRC-32; load a copy with the CRC repaired too, so
    // the fuzzer reaches the structural checks behind it.
    if (size >= runtime::kHeaderSize) {
        std::vector<std::uint8_t> repaired(data, data + size);
        repairPayloadCrc(repaired.data(), repaired.size());
        loaded |= loadAndAnimate(repaired.data(), repaired.size());
    }
    return loaded;
}

void repairPayloadCrc(std::uint8_t* data, std::size_t size) {
    if (size < runtime::kHeaderSize) return;
    const std::uint32_t crc = runtime::crc32(data + runtime::kHeaderSize, size - runtime::kHeaderSize);
    for (std::size_t i = 0; i < 4; ++i)
        data[runtime::header::kPayloadCrc + i] = static_cast<std::uint8_t>(crc >> (8 * i));
}

void repairPayloadCrc(std::string& bytes) {
    repairPayloadCrc(reinterpret_cast<std::uint8_t*>(bytes.data()), bytes.size());
}

} // namespace vl::test
