#include "core/common/FileWriting.h"

#include "core/common/Error.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <random>
#include <signal.h>
#include <string>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

namespace vl::fileio {

namespace {

constexpr std::string_view kTempMarker = ".vltmp-";
// Long names are cut in the temporary's name, which must stay within NAME_MAX (255).
constexpr std::size_t kMaxNameInTemp = 200;

std::string tempPrefix(std::string_view name) {
    return "." + std::string(name.substr(0, kMaxNameInTemp)) + std::string(kTempMarker);
}

// The pid in ".<name>.vltmp-<pid>-<random>", or -1 when the name is not such a temporary.
long ownerOfTemporary(std::string_view fileName) {
    if (!fileName.starts_with('.')) return -1;
    const auto marker = fileName.rfind(kTempMarker);
    if (marker == std::string_view::npos) return -1;
    return pidBeforeDash(fileName.substr(marker + kTempMarker.size()));
}

} // namespace

long pidBeforeDash(std::string_view text) {
    const auto dash = text.find('-');
    if (dash == 0 || dash == std::string_view::npos) return -1;
    long pid = 0;
    for (const char c : text.substr(0, dash)) {
        if (c < '0' || c > '9' || pid > 100'000'000) return -1;
        pid = pid * 10 + (c - '0');
    }
    return pid;
}

// A temporary's random part: one seed per process, then a counter mixed by splitmix64. Unique within
// the process (the pid in the name separates processes) and hard to guess for other writers, without
// opening the random device for every file (that was 1 % of a `reduce` run's CPU time).
std::uint64_t nextTemporarySuffix() {
    static const std::uint64_t seed = [] {
        std::random_device device;
        return (std::uint64_t{device()} << 32) ^ device();
    }();
    static std::atomic<std::uint64_t> counter{0};
    std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (counter.fetch_add(1, std::memory_order_relaxed) + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

bool processExists(long pid) {
    return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

void ContentHash::update(std::string_view bytes) {
    // 64-bit multiply-rotate over 8-byte words (the tail buffered): fast enough to hash every output,
    // and any change of the bytes changes it with overwhelming probability. Not a cryptographic hash.
    size_ += bytes.size();
    auto mix = [this](std::uint64_t word) {
        state_ ^= word * 0x87C37B91114253D5ull;
        state_ = ((state_ << 31) | (state_ >> 33)) * 0x4CF5AD432745937Full;
    };
    while (!bytes.empty()) {
        const std::size_t take = std::min(bytes.size(), sizeof tail_ - tailSize_);
        std::memcpy(tail_ + tailSize_, bytes.data(), take);
        tailSize_ += take;
        bytes.remove_prefix(take);
        if (tailSize_ == sizeof tail_) {
            std::uint64_t word;
            std::memcpy(&word, tail_, sizeof word);
            mix(word);
            tailSize_ = 0;
        }
        // Whole words straight from the input.
        while (tailSize_ == 0 && bytes.size() >= sizeof tail_) {
            std::uint64_t word;
            std::memcpy(&word, bytes.data(), sizeof word);
            mix(word);
            bytes.remove_prefix(sizeof word);
        }
    }
}

std::string ContentHash::hex() const {
    std::uint64_t h = state_ ^ size_;
    for (std::size_t i = 0; i < tailSize_; ++i)
        h = (h ^ static_cast<unsigned char>(tail_[i])) * 0x100000001B3ull;
    h ^= h >> 33;
    h *= 0xFF51AFD7ED558CCDull;
    h ^= h >> 33;
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

std::string hashOfFile(const std::filesystem::path& file) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (fd < 0) return {};
    struct stat info {};
    ContentHash hash;
    bool ok = ::fstat(fd, &info) == 0 && S_ISREG(info.st_mode);
    char chunk[1 << 15];
    while (ok) {
        const ssize_t n = ::read(fd, chunk, sizeof chunk);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            ok = n == 0;
            break;
        }
        hash.update(std::string_view(chunk, static_cast<std::size_t>(n)));
    }
    ::close(fd);
    return ok ? hash.hex() : std::string();
}

std::string lastSystemError() {
    return std::strerror(errno);
}

std::filesystem::path writeTarget(const std::filesystem::path& path) {
    std::filesystem::path target = path;
    std::error_code ec;
    for (int links = 0; std::filesystem::is_symlink(std::filesystem::symlink_status(target, ec)); ++links) {
        if (links == 40) throwInputError(path.string(), "too many levels of symbolic links");
        const std::filesystem::path next = std::filesystem::read_symlink(target, ec);
        if (ec) throwInputError(path.string(), "cannot read the symbolic link: " + ec.message());
        target = next.is_absolute() ? next : target.parent_path() / next;
    }
    return target;
}

TemporaryFile createTemporaryFor(const std::filesystem::path& target, std::string_view reportAs) {
    const auto folder = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
    struct stat existing {};
    const bool exists = ::stat(target.c_str(), &existing) == 0;
    if (exists && S_ISDIR(existing.st_mode))
        throwInputError(reportAs, "is a folder; cannot write a file there");
    for (int attempt = 0; attempt < 16; ++attempt) {
        TemporaryFile temp;
        temp.path = folder / (tempPrefix(target.filename().string()) + std::to_string(::getpid()) + "-" +
                              std::to_string(nextTemporarySuffix() % 1'000'000'000));
        temp.fd = ::open(temp.path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (temp.fd < 0 && errno == EEXIST) continue;
        if (temp.fd < 0)
            throwInputError(reportAs, "cannot create a temporary file in " + folder.string() + ": " +
                                          lastSystemError());
        // Replacing a file keeps its permissions (a script stays executable, a private file private).
        if (exists) (void)::fchmod(temp.fd, existing.st_mode & 07777);
        return temp;
    }
    throwInputError(reportAs, "cannot create a temporary file in " + folder.string());
}

bool writeAll(int fd, std::string_view data) {
    while (!data.empty()) {
        const ssize_t n = ::write(fd, data.data(), data.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n == 0) errno = ENOSPC;
            return false;
        }
        data.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
}

bool writeAll(int fd, std::span<const std::string_view> parts) {
    // A writev for up to kBatch parts at a time; a short write finishes part by part.
    constexpr std::size_t kBatch = 16;
    while (!parts.empty()) {
        iovec vectors[kBatch];
        const std::size_t count = std::min(parts.size(), kBatch);
        std::size_t total = 0;
        for (std::size_t i = 0; i < count; ++i) {
            vectors[i] = {const_cast<char*>(parts[i].data()), parts[i].size()};
            total += parts[i].size();
        }
        const ssize_t n = ::writev(fd, vectors, static_cast<int>(count));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return false;
        std::size_t written = static_cast<std::size_t>(n);
        if (written == total) {
            parts = parts.subspan(count);
            continue;
        }
        if (written == 0) {
            errno = ENOSPC;
            return false;
        }
        std::size_t i = 0;
        for (; written >= parts[i].size(); ++i) written -= parts[i].size();
        if (!writeAll(fd, parts[i].substr(written))) return false;
        parts = parts.subspan(i + 1);
    }
    return true;
}

bool holdsExactly(const std::filesystem::path& target, std::span<const std::string_view> parts) {
    std::size_t expected = 0;
    for (const std::string_view part : parts) expected += part.size();
    auto sameSizeFile = [expected](const struct stat& info) {
        return S_ISREG(info.st_mode) && static_cast<std::uint64_t>(info.st_size) == expected;
    };
    // Only a regular file is opened: opening a FIFO would block and a device may act on open.
    // O_NONBLOCK too, should the path change into one between the lstat and the open.
    struct stat info {};
    if (::lstat(target.c_str(), &info) != 0 || !sameSizeFile(info)) return false;
    const int fd = ::open(target.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (fd < 0) return false;
    bool same = ::fstat(fd, &info) == 0 && sameSizeFile(info);
    // Compares chunk by chunk: memory stays small for any file, and a difference stops the read.
    char chunk[1 << 15];
    std::size_t part = 0, offsetInPart = 0, compared = 0;
    while (same && compared < expected) {
        const ssize_t n = ::read(fd, chunk, std::min(sizeof chunk, expected - compared));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            same = false;
            break;
        }
        for (std::size_t at = 0; same && at < static_cast<std::size_t>(n);) {
            while (offsetInPart == parts[part].size()) ++part, offsetInPart = 0;
            const std::size_t length =
                std::min(parts[part].size() - offsetInPart, static_cast<std::size_t>(n) - at);
            same = std::memcmp(chunk + at, parts[part].data() + offsetInPart, length) == 0;
            at += length;
            offsetInPart += length;
        }
        compared += static_cast<std::size_t>(n);
    }
    // The file may still be in the page cache only (written by another program): durable now, like a
    // new copy. A clean file costs no writing.
    same = same && ::fsync(fd) == 0;
    ::close(fd);
    return same;
}

void syncFolder(const std::filesystem::path& folder) {
    const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    (void)::fsync(fd);
    ::close(fd);
}

void sweepStaleTemporaries(const std::filesystem::path& folder, std::string_view name) {
    std::error_code ec;
    const std::string wanted = name.empty() ? std::string() : tempPrefix(name);
    for (std::filesystem::directory_iterator it(folder.empty() ? "." : folder, ec), end; !ec && it != end;
         it.increment(ec)) {
        const std::string fileName = it->path().filename().string();
        if (!wanted.empty() && !fileName.starts_with(wanted)) continue;
        const long owner = ownerOfTemporary(fileName);
        if (owner <= 0 || owner == ::getpid() || processExists(owner)) continue;
        std::error_code ignored;
        if (std::filesystem::is_regular_file(it->symlink_status(ignored)))
            std::filesystem::remove(it->path(), ignored);
    }
}

} // namespace vl::fileio
