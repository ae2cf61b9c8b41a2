#include "core/common/AtomicFileWriter.h"

#include "core/common/Error.h"

#include <random>
#include <system_error>
#include <unistd.h>

namespace vl {

AtomicFileWriter::AtomicFileWriter(const std::filesystem::path& path) : path_(path) {
    const auto dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    std::random_device rd;
    temp_ = dir / ("." + path.filename().string() + ".tmp" + std::to_string(rd() % 1000000));
    file_ = std::fopen(temp_.c_str(), "wb");
    if (!file_) throwInputError(path.string(), "cannot create temporary file for writing");
}

AtomicFileWriter::~AtomicFileWriter() {
    if (!file_) return;
    std::fclose(file_);
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
}

void AtomicFileWriter::fail(const char* what) {
    std::fclose(file_);
    file_ = nullptr;
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
    throwInputError(path_.string(), what);
}

void AtomicFileWriter::write(std::string_view bytes) {
    if (!file_) throwInputError(path_.string(), "write after the file was closed");
    if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
        fail("write failed (disk full?); the previous file is unchanged");
    size_ += bytes.size();
}

void AtomicFileWriter::overwrite(std::uint64_t offset, std::string_view bytes) {
    if (!file_) throwInputError(path_.string(), "write after the file was closed");
    if (offset + bytes.size() > size_) throwInputError(path_.string(), "overwrite past the end of the data");
    const bool ok = std::fseek(file_, static_cast<long>(offset), SEEK_SET) == 0 &&
                    std::fwrite(bytes.data(), 1, bytes.size(), file_) == bytes.size() &&
                    std::fseek(file_, 0, SEEK_END) == 0;
    if (!ok) fail("write failed; the previous file is unchanged");
}

void AtomicFileWriter::commit() {
    if (!file_) throwInputError(path_.string(), "commit after the file was closed");
    const bool ok = std::fflush(file_) == 0 && ::fsync(fileno(file_)) == 0;
    if (!ok) fail("write failed (disk full?); the previous file is unchanged");
    std::fclose(file_);
    file_ = nullptr;
    std::error_code ec;
    std::filesystem::rename(temp_, path_, ec);
    if (ec) {
        std::filesystem::remove(temp_, ec);
        throwInputError(path_.string(), "cannot replace file: " + ec.message());
    }
}

} // namespace vl
