#include "core/common/AtomicFileWriter.h"

#include "core/common/Error.h"
#include "core/common/FileWriting.h"
#include "core/common/InputRegistry.h"
#include "core/common/OutputPolicy.h"

#include <system_error>
#include <unistd.h>

namespace vl {

AtomicFileWriter::AtomicFileWriter(const std::filesystem::path& path) : path_(path) {
    open_ = true;
    if (isStandardOutput(path)) {
        toStandardOutput_ = true;
        return;
    }
    refuseOverwritingInput(path);
    target_ = resolveOutputPath(path, false); // a link's target folder exists: it is not created
    const auto folder = target_.has_parent_path() ? target_.parent_path() : std::filesystem::path(".");
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    // Every temporary a killed writer left in this folder (say --wav leaves megabytes), whatever its name.
    fileio::sweepStaleTemporaries(folder);
    const fileio::TemporaryFile temp = fileio::createTemporaryFor(target_, path.string());
    temp_ = temp.path;
    file_ = ::fdopen(temp.fd, "wb");
    if (!file_) {
        open_ = false;
        ::close(temp.fd);
        std::filesystem::remove(temp_, ec);
        throwInputError(path.string(), "cannot open the temporary file for writing");
    }
}

AtomicFileWriter::~AtomicFileWriter() {
    if (!file_) return;
    std::fclose(file_);
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
}

void AtomicFileWriter::fail(const char* what) {
    const std::string problem = fileio::lastSystemError();
    open_ = false;
    if (toStandardOutput_) throwInputError("the standard output", std::string(what) + " (" + problem + ")");
    std::fclose(file_);
    file_ = nullptr;
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
    throwInputError(path_.string(), std::string(what) + " (" + problem + "); the previous file is unchanged");
}

void AtomicFileWriter::write(std::string_view bytes) {
    if (!open_) throwInputError(path_.string(), "write after the file was closed");
    if (toStandardOutput_) {
        pending_.append(bytes);
        size_ += bytes.size();
        return;
    }
    if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) fail("write failed");
    size_ += bytes.size();
}

void AtomicFileWriter::overwrite(std::uint64_t offset, std::string_view bytes) {
    if (!open_) throwInputError(path_.string(), "write after the file was closed");
    if (offset + bytes.size() > size_) throwInputError(path_.string(), "overwrite past the end of the data");
    if (toStandardOutput_) {
        pending_.replace(static_cast<std::size_t>(offset), bytes.size(), bytes);
        return;
    }
    const bool ok = std::fseek(file_, static_cast<long>(offset), SEEK_SET) == 0 &&
                    std::fwrite(bytes.data(), 1, bytes.size(), file_) == bytes.size() &&
                    std::fseek(file_, 0, SEEK_END) == 0;
    if (!ok) fail("write failed");
}

void AtomicFileWriter::commit() {
    if (!open_) throwInputError(path_.string(), "commit after the file was closed");
    if (toStandardOutput_) {
        if (!fileio::writeAll(outputPolicy().standardOutputFd, pending_)) fail("write failed");
        open_ = false;
        pending_ = {};
        return;
    }
    const bool ok = std::fflush(file_) == 0 && ::fsync(fileno(file_)) == 0;
    if (!ok) fail("write failed");
    std::fclose(file_);
    file_ = nullptr;
    open_ = false;
    std::error_code ec;
    std::filesystem::rename(temp_, target_, ec);
    if (ec) {
        std::filesystem::remove(temp_, ec);
        throwInputError(path_.string(), "cannot replace file: " + ec.message());
    }
    fileio::syncFolder(target_.has_parent_path() ? target_.parent_path() : std::filesystem::path("."));
}

} // namespace vl
