#include "core/batch/BatchContext.h"

#include "core/batch/BatchCaches.h"

namespace vl::batch {

BatchContext::BatchContext(BatchOptions options)
    : options_(std::move(options)), caches_(std::make_unique<BatchCaches>(options_)) {}

BatchContext::~BatchContext() = default;

} // namespace vl::batch
