#include "core/batch/BatchCaches.h"

#include "core/batch/BatchJob.h"
#include "core/common/AtomicFile.h"
#include "core/common/ContentHash.h"
#include "core/common/InputRegistry.h"
#include "core/phonetics/PhonemeMaps.h"

namespace vl::batch {

struct BatchCaches::Slot {
    std::mutex loading;
    bool done = false;
    std::shared_ptr<const void> value;
    std::exception_ptr error;
    std::vector<std::filesystem::path> inputs;
};

namespace {

// "<absolute path>#<content hash>" of a file the load depends on ("" for none). Reads the file: a
// missing one is the load's error to report, so it keys as its path alone.
std::string identity(const std::filesystem::path& file) {
    if (file.empty()) return "-";
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(file, ec).lexically_normal();
    std::string key = absolute.string();
    try {
        key += "#" + hashHex(contentHash(readFileToString(file)));
    } catch (const InputError&) {
    }
    return key;
}

std::string constraintsKey(const ConstraintNames& c) {
    std::string key;
    for (const auto& p : c.pinned) key += "pin " + p + "\n";
    for (const auto& [a, b] : c.apart) key += "apart " + a + "," + b + "\n";
    for (const auto& [a, b] : c.together) key += "together " + a + "," + b + "\n";
    return key;
}

} // namespace

BatchCaches::BatchCaches(const BatchOptions& options) : options_(options) {}
BatchCaches::~BatchCaches() = default;

std::shared_ptr<const void> BatchCaches::entry(const std::string& key,
                                               std::vector<std::filesystem::path>& inputs,
                                               const std::function<std::shared_ptr<const void>()>& load) {
    std::shared_ptr<Slot> slot;
    {
        std::lock_guard lock(mutex_);
        auto& s = slots_[key];
        if (!s) s = std::make_shared<Slot>();
        slot = s;
    }
    std::lock_guard lock(slot->loading);
    if (!slot->done) {
        const InputWatch watch; // what the load read: the entry's inputs for the resume rule
        try {
            slot->value = load();
        } catch (...) {
            slot->error = std::current_exception();
        }
        for (const auto& read : watch.read()) slot->inputs.push_back(read.file);
        for (const auto& referenced : watch.referenced()) slot->inputs.push_back(referenced);
        slot->done = true;
    }
    if (slot->error) std::rethrow_exception(slot->error);
    inputs = slot->inputs;
    return slot->value;
}

Shared<SpeakingFace> BatchCaches::face(const SayJob& job) {
    std::string key = "face\n" + identity(job.project) + "\n" + identity(job.avatar) + "\n" +
                      identity(job.reduced) + "\n" + identity(job.map) + "\n";
    if (!job.avatar.empty())
        key += job.targets + "\n" + std::to_string(job.target) + "\n" + constraintsKey(job.constraints) +
               std::to_string(job.maxErrorMm) + "\n" + job.closure;
    Shared<SpeakingFace> shared;
    const auto value = entry(key, shared.inputs, [&]() -> std::shared_ptr<const void> {
        SpeakingFaceRequest request;
        std::optional<PhonemeVisemeMap> map;
        if (!job.map.empty()) map = loadPhonemeMapFile(job.map);
        if (!job.avatar.empty()) {
            request.avatar = job.avatar;
            AvatarSpeechOptions& a = request.avatarOptions;
            a.targets = job.targets;
            a.reduceTo = job.target;
            a.constraints = job.constraints;
            a.maxErrorMm = job.maxErrorMm;
            a.closure = job.closure;
            a.reduced = job.reduced;
            a.phonemeTable = bundledFrequencies().oculus;
            a.map = map;
        } else {
            request.project = job.project;
            request.map = map;
            request.speechCacheFolder = options_.speechCacheFolder;
        }
        return std::make_shared<const SpeakingFace>(loadSpeakingFace(request));
    });
    shared.value = std::static_pointer_cast<const SpeakingFace>(value);
    return shared;
}

Shared<LoadedAvatar> BatchCaches::avatar(const std::filesystem::path& file, const std::string& targets) {
    Shared<LoadedAvatar> shared;
    const auto value = entry("avatar\n" + identity(file) + "\n" + targets, shared.inputs,
                             [&]() -> std::shared_ptr<const void> {
                                 auto loaded = std::make_shared<LoadedAvatar>();
                                 loaded->doc = loadGltfDocument(file);
                                 loaded->scan = scanAvatar(loaded->doc, {targets});
                                 return loaded;
                             });
    shared.value = std::static_pointer_cast<const LoadedAvatar>(value);
    return shared;
}

const BundledFrequencies& BatchCaches::bundledFrequencies() {
    std::call_once(bundledOnce_, [this] {
        try {
            bundled_ = {loadFrequencyFile(defaultPhonemeTablePath(options_.assetsDir)),
                        bundledPhonemeFrequencies(options_.assetsDir, "oculus")};
        } catch (...) {
            bundledError_ = std::current_exception();
        }
    });
    if (bundledError_) std::rethrow_exception(bundledError_);
    return bundled_;
}

const FreshSpeech& BatchCaches::speech() {
    std::call_once(speechOnce_, [this] {
        try {
            speech_ = std::make_unique<FreshSpeech>();
        } catch (...) {
            speechError_ = std::current_exception();
        }
    });
    if (speechError_) std::rethrow_exception(speechError_);
    return *speech_;
}

std::size_t BatchCaches::loads() const {
    std::lock_guard lock(mutex_);
    return slots_.size();
}

} // namespace vl::batch
