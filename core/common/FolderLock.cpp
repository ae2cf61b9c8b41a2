#include "core/common/FolderLock.h"

#include "core/common/Error.h"
#include "core/common/FileWriting.h"
#include "core/common/InputRegistry.h"
#include "core/common/OutputPolicy.h"

#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

namespace vl::fileio {

namespace {

int openFolder(const std::filesystem::path& folder, const std::filesystem::path& shownAs) {
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) throwInputError(shownAs.string(), "cannot open the output folder: " + lastSystemError());
    return fd;
}

bool sameFile(const struct stat& a, const struct stat& b) {
    return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

// The command line of process `pid`, arguments separated by spaces, cut at 200 characters.
std::string commandOf(long pid) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/cmdline", std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    while (!text.empty() && text.back() == '\0') text.pop_back();
    for (char& c : text)
        if (c == '\0') c = ' ';
    if (text.size() > 200) text = text.substr(0, 200) + "...";
    return text;
}

} // namespace

std::string describeLockHolder(const std::filesystem::path& folder) {
    struct stat info {};
    if (::stat(folder.c_str(), &info) != 0) return "another process";
    char wanted[64];
    std::snprintf(wanted, sizeof wanted, "%02x:%02x:%lu", major(info.st_dev), minor(info.st_dev),
                  static_cast<unsigned long>(info.st_ino));
    // Lines like "1: FLOCK  ADVISORY  WRITE 1234 fd:01:5678 0 EOF"; waiters' lines hold "->".
    std::ifstream locks("/proc/locks");
    for (std::string line; std::getline(locks, line);) {
        std::istringstream fields(line);
        std::string number, kind, mode, access, device;
        long pid = 0;
        if (!(fields >> number >> kind >> mode >> access >> pid >> device) || kind != "FLOCK") continue;
        if (device != wanted) continue;
        const std::string command = commandOf(pid);
        return "pid " + std::to_string(pid) + (command.empty() ? std::string() : " (" + command + ")");
    }
    return "another process";
}

FolderLock::FolderLock(const std::filesystem::path& folder, const std::filesystem::path& shownAs) {
    bool announced = false;
    for (;;) {
        const int fd = openFolder(folder, shownAs);
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const std::string holder = describeLockHolder(folder);
            if (holder.starts_with("pid " + std::to_string(::getpid()) + " ")) {
                ::close(fd); // waiting for ourselves would never end
                throwInputError(shownAs.string(), "this run is already writing the folder");
            }
            if (!outputPolicy().waitForBusyFolder) {
                ::close(fd);
                throw OutputRefusedError(shownAs.string() + ": another run is writing this folder: " +
                                         holder + " (without --no-wait this run waits for it)");
            }
            if (!announced)
                std::fprintf(stderr, "visemelab: waiting for %s to finish writing %s\n", holder.c_str(),
                             shownAs.string().c_str());
            announced = true;
            while (::flock(fd, LOCK_EX) != 0 && errno == EINTR) {
            }
        }
        // The holder may have swapped a new folder in: the lock must be on the one at the path.
        struct stat locked = {}, current = {};
        if (::fstat(fd, &locked) == 0 && ::stat(folder.c_str(), &current) == 0 && sameFile(locked, current)) {
            fds_.push_back(fd);
            return;
        }
        ::close(fd);
    }
}

FolderLock::~FolderLock() {
    release();
}

void FolderLock::alsoLock(const std::filesystem::path& other) {
    const int fd = openFolder(other, other);
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        ::close(fd);
        throwInputError(other.string(), "cannot lock the staging folder");
    }
    fds_.push_back(fd);
}

void FolderLock::release() {
    for (const int fd : fds_) ::close(fd); // closing the last descriptor drops the flock
    fds_.clear();
}

} // namespace vl::fileio
