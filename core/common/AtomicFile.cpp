#include "core/common/AtomicFile.h"

#include "core/common/AtomicFileWriter.h"
#include "core/common/Error.h"
#include "core/common/InputRegistry.h"
#include "core/common/Limits.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <new>
#include <system_error>

namespace vl {

std::string readFileToString(const std::filesystem::path& path) {
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
    std::string data;
    try {
        data.resize(static_cast<std::size_t>(size));
    } catch (const std::bad_alloc&) {
        throwInputError(path.string(), "not enough memory to read the file");
    }
    std::size_t done = 0;
    while (done < data.size()) {
        const ssize_t got = ::read(fd, data.data() + done, data.size() - done);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) throwInputError(path.string(), "read error");
        if (got == 0) { // shorter than when it was measured: keep what is there
            data.resize(done);
            break;
        }
        done += static_cast<std::size_t>(got);
    }
    noteInputFile(path);
    return data;
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
    AtomicFileWriter file(path);
    file.write(contents);
    file.commit();
}

} // namespace vl
