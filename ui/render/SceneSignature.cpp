#include "ui/render/SceneSignature.h"

#include <atomic>

namespace vl::ui {
namespace {
thread_local SceneSignature* current = nullptr;
std::atomic<std::uint64_t> uploads{0};
} // namespace

void SceneSignature::add(const void* bytes, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(bytes);
    for (std::size_t i = 0; i < size; ++i) {
        hash_ ^= p[i];
        hash_ *= 1099511628211ull; // FNV-1a prime
    }
}

SceneSignature* SceneSignature::recording() {
    return current;
}

SceneSignature::Recording::Recording(SceneSignature& signature) : previous_(current) {
    current = &signature;
}

SceneSignature::Recording::~Recording() {
    current = previous_;
}

std::uint64_t nextUploadRevision() {
    return ++uploads;
}

} // namespace vl::ui
