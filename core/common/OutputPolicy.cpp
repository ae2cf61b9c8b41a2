#include "core/common/OutputPolicy.h"

#include "core/common/FileWriting.h"
#include "core/common/InputRegistry.h"

namespace vl {

namespace {

OutputPolicy& policy() {
    static OutputPolicy instance;
    return instance;
}

} // namespace

void setOutputPolicy(const OutputPolicy& value) {
    policy() = value;
}

const OutputPolicy& outputPolicy() {
    return policy();
}

bool isStandardOutput(const std::filesystem::path& path) {
    return policy().standardOutputFd >= 0 && path == "-";
}

std::filesystem::path resolveOutputPath(const std::filesystem::path& path, bool isFolder) {
    std::error_code ec;
    if (!std::filesystem::is_symlink(std::filesystem::symlink_status(path, ec))) return path;
    if (!policy().followSymlinks)
        throw OutputRefusedError(path.string() +
                                 ": the output is a symbolic link; outputs are not written through links "
                                 "(--follow-symlinks writes to its target)");
    const std::filesystem::path target = fileio::writeTarget(path);
    const std::filesystem::path mustExist =
        isFolder ? target : (target.has_parent_path() ? target.parent_path() : std::filesystem::path("."));
    if (!std::filesystem::is_directory(mustExist, ec))
        throw OutputRefusedError(path.string() + ": the symbolic link leads to " + target.string() +
                                 ", whose folder does not exist; no folder is created through a link");
    return target;
}

} // namespace vl
