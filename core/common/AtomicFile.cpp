#include "core/common/AtomicFile.h"

#include "core/common/AtomicFileWriter.h"
#include "core/common/Error.h"
#include "core/common/InputRegistry.h"
#include "core/common/Limits.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <new>
#include <system_error>

namespace vl {

namespace {

// Opens, checks and reads `path` into the buffer `allocate(size)` returns; returns the bytes read
// (fewer when the file shrank since it was measured).
template <class Allocate> std::size_t readWholeFile(const std::filesystem::path& path, Allocate allocate) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) throwInputError(path.string(), "file not found");
    if (std::filesystem::is_directory(status)) throwInputError(path.string(), "is a directory, not a file");
    // A FIFO or device would block or never end. Opened without blocking and checked again on the
    // open file, so a file swapped for a FIFO after the check above cannot block the reader either.
    if (!std::filesystem::is_regular_file(status)) throwInputError(path.string(), "not a regular file");
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throwInputError(path.string(), "cannot open file for reading");
    struct FdCloser {
        int fd;
        ~FdCloser() { ::close(fd); }
    } closer{fd};
    struct stat opened {};
    if (::fstat(fd, &opened) != 0 || !S_ISREG(opened.st_mode))
        throwInputError(path.string(), "not a regular file");
    const auto size = static_cast<std::uintmax_t>(opened.st_size);
    if (size > limits::kMaxInputFileBytes)
        throwInputError(path.string(), "file too large (" + std::to_string(size) + " bytes; the limit is " +
                                           std::to_string(limits::kMaxInputFileBytes) + ")");
    char* data = nullptr;
    try {
        data = allocate(static_cast<std::size_t>(size));
    } catch (const std::bad_alloc&) {
        throwInputError(path.string(), "not enough memory to read the file");
    }
    std::size_t done = 0;
    while (done < size) {
        const ssize_t got = ::read(fd, data + done, size - done);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) throwInputError(path.string(), "read error");
        if (got == 0) break; // shorter than when it was measured: keep what is there
        done += static_cast<std::size_t>(got);
    }
    noteInputFile(path, std::string_view(data, done));
    return done;
}

} // namespace

std::string readFileToString(const std::filesystem::path& path) {
    std::string data;
    data.resize(readWholeFile(path, [&](std::size_t size) {
        data.resize(size);
        return data.data();
    }));
    return data;
}

FileBytes readFileBytes(const std::filesystem::path& path) {
    FileBytes bytes;
    readFileBytesInto(path, bytes);
    return bytes;
}

void readFileBytesInto(const std::filesystem::path& path, FileBytes& buffer) {
    buffer.size = readWholeFile(path, [&](std::size_t size) {
        if (size > buffer.capacity || !buffer.data) {
            buffer.data.reset(); // the old buffer goes before the new one is taken
            buffer.capacity = 0;
            buffer.data = std::make_unique_for_overwrite<char[]>(std::max<std::size_t>(size, 1));
            buffer.capacity = size;
        }
        return buffer.data.get();
    });
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
    AtomicFileWriter file(path);
    file.write(contents);
    file.commit();
}

} // namespace vl
